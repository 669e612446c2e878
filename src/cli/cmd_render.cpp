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
#include "dragon/still.hpp"
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
Still contact_still(const Simulation& sim, const SceneOptions& so, std::optional<double> zoom) {
    CollideAnswer a;
    if (std::optional<Still> still = still_at_first_contact(sim, so, zoom, &a)) return std::move(*still);
    throw InputError(fmt::format("--collision: no two benches touch between t = {} s and {} s on this scenario{}; "
                                 "use --time instead", format_time(a.window.from), format_time(a.window.to),
                                 a.jam ? " (" + jam_sentence(*a.jam) + ")" : ""));
}
}  // namespace

void register_render(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<RenderOptions>();
    CLI::App* sub = app.add_subcommand("render", "Draw one moment of the dragon to PNG, SVG or PDF");
    opt->scenario.add_to(sub, ScenarioUse::drawing(), reg);
    auto* when = sub->add_option("--time", opt->time, "The moment to draw, s (or --collision, not both)");
    auto* hit = sub->add_flag("--collision", opt->collision,
                              "Draw the first contact (the termination of coiling in), touching benches marked (in "
                              "place of --time)");
    when->excludes(hit);
    sub->add_option("-o,--out", opt->out, "Output file: .png, .svg or .pdf (vector, fonts embedded, for papers)")->required();
    opt->look.add_to(sub);
    opt->print.add_to(sub);
    add_quiet_flag(sub, opt->quiet);
    reg.runners["render"] = [opt](ToolRun& run) {
        RunOutputs& outputs = run.outputs;
        const std::string ext = extension_of(opt->out);
        if (ext != ".png" && ext != ".svg" && ext != ".pdf")
            throw InputError(fmt::format("--out {} has extension '{}': use .png, .svg or .pdf", opt->out, ext));
        if (!opt->time && !opt->collision)
            throw InputError("render needs --time T (seconds) or --collision");
        AtomicFile probe(opt->out, &outputs);  // fail on an unwritable path before any work
        const Scenario s = opt->scenario.resolve(&outputs);
        const Simulation sim(s);
        SceneOptions so = opt->look.scene_options(run.assets, &outputs);
        const std::optional<PrintSize> print = opt->print.resolve();
        auto [w, h] = opt->look.size();
        Page page;
        if (print) {  // --size gives the shape; the print size, the pixels and the text
            const PrintLayout layout = print_layout(*print, static_cast<double>(h) / w, ext == ".png");
            so.text_px = layout.text_px;
            w = layout.width_px, h = layout.height_px, page = layout.page;
        }
        const Still still = opt->collision ? contact_still(sim, so, opt->look.zoom()) : still_at(sim, *opt->time, so);
        const Scene& scene = still.scene;
        const Frame& frame = still.frame;
        if (opt->look.zoom()) require_zoom_resolves(scene, w, h, *opt->look.zoom());
        if (ext == ".png") render_png(scene, w, h, opt->out, page, &outputs);
        else if (ext == ".svg") render_svg(scene, w, h, opt->out, page, &outputs);
        else render_pdf(scene, w, h, opt->out, page, &outputs);
        if (print)
            run.wrote(opt->quiet, "wrote {} ({:g} x {:g} in, text {:g} pt{}, t = {:.6f} s)", opt->out, print->width_in,
                   print->width_in * h / w, print->font_pt, ext == ".png" ? fmt::format(", {} x {} px at {:g} dpi", w, h, print->dpi) : "",
                   frame.time);
        else run.wrote(opt->quiet, "wrote {} ({} x {} px, t = {:.6f} s)", opt->out, w, h, frame.time);
        return 0;
    };
}

}  // namespace dragon::cli
