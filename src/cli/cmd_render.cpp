// dragon render: one moment of any scenario drawn to PNG, SVG or PDF.
#include <cstdio>

#include <fmt/format.h>

#include "commands.hpp"
#include "render_flags.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "print_flags.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/render.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {
struct RenderOptions {
    ScenarioFlags scenario;
    RenderFlags look;
    PrintFlags print;
    std::optional<double> time;
    bool collision = false;
    std::string out;
    bool quiet = false;
};

// The motion's first contact (the plain spiral from t = 0 as far as the dragon can follow it, the
// turnaround 100 m of head travel either side of the turn): the one every command reports.
Contact find_contact(const Simulation& sim) {
    const CollideAnswer a = first_contact_of_motion(sim);
    if (!a.contact)
        throw InputError(fmt::format("--collision: no two benches touch between t = {} s and {} s on this scenario{}; "
                                     "use --time instead", format_time(a.window.from), format_time(a.window.to),
                                     a.jam ? " (" + jam_sentence(*a.jam) + ")" : ""));
    return *a.contact;
}
}  // namespace

void register_render(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<RenderOptions>();
    CLI::App* sub = app.add_subcommand("render", "Draw one moment of the dragon to PNG, SVG or PDF");
    opt->scenario.add_to(sub, ScenarioUse::drawing());
    auto* when = sub->add_option("--time", opt->time, "The moment to draw, s (or --collision, not both)");
    auto* hit = sub->add_flag("--collision", opt->collision,
                              "Draw the first contact (the termination of coiling in), touching benches marked (in "
                              "place of --time)");
    when->excludes(hit);
    sub->add_option("-o,--out", opt->out, "Output file: .png, .svg or .pdf (vector, fonts embedded, for papers)")->required();
    opt->look.add_to(sub);
    opt->print.add_to(sub);
    add_quiet_flag(sub, opt->quiet);
    reg["render"] = [opt]() {
        const std::string ext = extension_of(opt->out);
        if (ext != ".png" && ext != ".svg" && ext != ".pdf")
            throw InputError(fmt::format("--out {} has extension '{}': use .png, .svg or .pdf", opt->out, ext));
        if (!opt->time && !opt->collision)
            throw InputError("render needs --time T (seconds) or --collision");
        AtomicFile probe(opt->out);  // fail on an unwritable path before any work
        const Scenario s = opt->scenario.resolve();
        const Simulation sim(s);
        SceneOptions so = opt->look.scene_options();
        Frame frame;
        if (opt->collision) {
            const Contact c = find_contact(sim);
            frame = c.frame;
            // Marked where the boards meet: the corner of one nearest the other.
            const Vec2 at = contact_point(frame.benches[c.bench_a - 1], frame.benches[c.bench_b - 1]);
            so.collision = CollisionMark{c.bench_a, c.bench_b, at};
            so.name_touching = true;  // which magenta bench is the head, without the legend
            if (!so.annotation)
                so.annotation = fmt::format(fmt::runtime(so.language == Language::zh ? "首次碰撞 t = {:.6f} s：第 {} 与第 {} 节板凳"
                                                                                      : "first contact t = {:.6f} s: benches {} and {}"),
                                            c.time, c.bench_a, c.bench_b);
            if (opt->look.zoom()) so.camera = Camera::at(at, *opt->look.zoom());
        } else {
            sim.require_valid(*opt->time, "time");
            frame = sim.frame(*opt->time);
            // Past the first contact the benches overlap (drawn marked): the annotation says so.
            const std::optional<Contact> c = first_contact_covering(sim, *opt->time, *opt->time).contact;
            if (!so.annotation && c && c->time < *opt->time)
                so.annotation = fmt::format(fmt::runtime(so.language == Language::zh
                                                             ? "t = {:.3f} s   螺距 = {:.3g} m   已过首次碰撞（第 {} 与第 {} 节板凳，"
                                                               "t = {:.3f} s）"
                                                             : "t = {:.3f} s   pitch = {:.3g} m   past the first contact "
                                                               "(benches {} and {}, t = {:.3f} s)"),
                                            frame.time, s.coil_pitch(), c->bench_a, c->bench_b, c->time);
        }
        // A still's title gets a band of its own: over the drawing it would hide benches (the
        // head, at a contact zoomed in).
        so.title_band = true;
        const std::optional<PrintSize> print = opt->print.resolve();
        auto [w, h] = opt->look.size();
        Page page;
        if (print) {  // --size gives the shape; the print size, the pixels and the text
            const PrintLayout layout = print_layout(*print, static_cast<double>(h) / w, ext == ".png");
            so.text_px = layout.text_px;
            w = layout.width_px, h = layout.height_px, page = layout.page;
        }
        const Scene scene = make_scene(sim, frame, so);
        if (opt->look.zoom()) require_zoom_resolves(scene, w, h, *opt->look.zoom());
        if (ext == ".png") render_png(scene, w, h, opt->out, page);
        else if (ext == ".svg") render_svg(scene, w, h, opt->out, page);
        else render_pdf(scene, w, h, opt->out, page);
        if (print)
            status(opt->quiet, "wrote {} ({:g} x {:g} in, text {:g} pt{}, t = {:.6f} s)", opt->out, print->width_in,
                   print->width_in * h / w, print->font_pt, ext == ".png" ? fmt::format(", {} x {} px at {:g} dpi", w, h, print->dpi) : "",
                   frame.time);
        else status(opt->quiet, "wrote {} ({} x {} px, t = {:.6f} s)", opt->out, w, h, frame.time);
        return 0;
    };
}

}  // namespace dragon::cli
