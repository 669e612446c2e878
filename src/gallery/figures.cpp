// The gallery: which figures exist and writing them.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "figure_kit.hpp"

namespace dragon {

namespace {
using Maker = void (*)(const fig::Context&, const std::string&);
struct Entry {
    FigureInfo info;
    Maker make;
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> list{
        {{"fig1_link_geometry", "One link: the chord equation's roots and the rigid-link speed relation"}, fig::link_geometry},
        {{"fig2_dragon_300s", "The whole dragon at 300 s (at the first contact if sooner), coloured by exact speed"}, fig::dragon_at_300s},
        {{"fig3_broad_phase", "The broad phase around the head at the first contact"}, fig::broad_phase},
        {{"fig4_first_contact", "The touching rectangles at the first contact, zoomed in"}, fig::first_contact_zoom},
        {{"fig5_pitch_states", "Contact or clearance at six pitches around the true minimum"}, fig::pitch_states},
        {{"plot_speeds", "Speed of every handle against its index at six times"}, fig::speeds_by_handle},
        {{"plot_clearance", "Clearance against time up to the termination"}, fig::clearance_over_time},
        {{"plot_s_curve", "The S-curve: centres, radii and tangent points"}, fig::s_curve_geometry},
        {{"plot_speed_ratio", "Largest handle speed over head speed on the turnaround"}, fig::speed_ratio_on_turnaround},
        {{"turnaround_dark", "The turnaround 1 s after the head leaves the S-curve, dark theme, coloured by speed"},
         fig::turnaround_scene},
    };
    return list;
}
}  // namespace

std::vector<FigureInfo> figure_list() {
    std::vector<FigureInfo> out;
    for (const auto& e : entries()) out.push_back(e.info);
    return out;
}

void write_figures(const std::string& dir, const Scenario& base, const FigureOptions& opt,
                   const std::function<void(const FigureInfo&, const std::string&)>& done) {
    for (const auto& name : opt.only) {
        const bool known = std::any_of(entries().begin(), entries().end(), [&](const Entry& e) { return e.info.name == name; });
        if (!known) {
            std::string all;
            for (const auto& e : entries()) all += (all.empty() ? "" : ", ") + e.info.name;
            throw InputError(fmt::format("figure \"{}\" is unknown: choose from {}", name, all));
        }
    }
    if (opt.format != "png" && opt.format != "svg" && opt.format != "pdf")
        throw InputError(Key::format, opt.format, "use png, svg or pdf");
    if (!(opt.scale >= kMinFigureScale && opt.scale <= 8))
        throw InputError(Key::scale, error_value(opt.scale),
                         fmt::format("use {}..8 (smaller, the plots' text would fall under the {:g} px floor)",
                                     kMinFigureScale, kMinTextPx));
    if (!make_output_folder(dir, opt.outputs)) throw InputError(fmt::format("cannot create the figure folder {}", dir));
    fig::Context ctx{base, opt, nullptr, ""};
    ctx.base.path.kind = PathKind::spiral;
    ctx.answers = std::make_shared<fig::Answers>(ctx.base);
    for (const auto& e : entries()) {
        if (!opt.only.empty() && std::find(opt.only.begin(), opt.only.end(), e.info.name) == opt.only.end()) continue;
        const std::string path = (std::filesystem::path(dir) / (e.info.name + "." + opt.format)).string();
        ctx.figure = e.info.name;
        std::vector<std::string> data_files;
        ctx.data_files = &data_files;
        e.make(ctx, path);
        if (done) {
            done(e.info, path);
            for (const std::string& d : data_files) done(e.info, d);
        }
    }
}

}  // namespace dragon
