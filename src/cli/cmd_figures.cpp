// dragon figures: the gallery (the paper's five figures done right, and the plots behind them).
#include <cstdint>

#include <fmt/format.h>

#include "commands.hpp"
#include "progress.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "print_flags.hpp"
#include "render_flags.hpp"
#include "gallery/figures.hpp"

namespace dragon::cli {

namespace {
struct FiguresOptions {
    ScenarioFlags scenario;
    PrintFlags print;
    std::string out = "renders";
    std::string theme = "light";
    std::string format = "png";
    double scale = 1.0;
    std::vector<std::string> only;
    bool list = false;
    bool titles = false, no_titles = false, data = false;
    std::string lang = "en";
    bool quiet = false;
};
}  // namespace

void register_figures(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<FiguresOptions>();
    CLI::App* sub = app.add_subcommand("figures", "The figure gallery: the paper's figures done right, and plots");
    opt->scenario.add_to(sub, ScenarioUse::both_paths("the gallery draws both paths: the coil-in figures on the "
                                                      "plain spiral, the turnaround ones on the turnaround path"), reg);
    auto* list = sub->add_flag("--list", opt->list, "List the figures and exit (takes no other option)");
    // --list makes nothing: every option that shapes the figures would do nothing with it.
    for (CLI::Option* o : sub->get_options())
        if (o != list && o->get_name() != "--help") o->excludes(list);
    sub->add_option("-o,--out", opt->out, "Folder for the files (default renders)")->excludes(list);
    sub->add_option("--format", opt->format, "png (palette PNGs, default), svg or pdf (vector, fonts embedded, "
                                             "text selectable: for papers)")
        ->excludes(list);
    sub->add_option("--theme", opt->theme, "Colour theme: light, dark or a .toml file (default light)")->excludes(list);
    sub->add_option("--scale", opt->scale, "Pixel size relative to the gallery's ~1000 px (0.65..8, default 1)")
        ->excludes(list);
    sub->add_option("--only", opt->only, "Make only these figures, e.g. fig1_link_geometry,plot_speeds (as --list "
                                         "names them)")
        ->delimiter(',')  // as solve --only q1,q2
        ->excludes(list);
    opt->print.add_to(sub);
    add_language_flag(sub, opt->lang);
    sub->add_flag("--data", opt->data, "Also write beside each figure, as NAME.csv, the numbers it draws (a header with "
                                       "each column's unit): to redraw it in a paper's own style");
    auto* titles = sub->add_flag("--titles", opt->titles, "Titles and notes on the figures at a print size too (on "
                                                          "screen they are there by default)");
    sub->add_flag("--no-titles", opt->no_titles, "No titles or notes on the figures (at a print size the default: a "
                                                 "paper sets its own captions)")
        ->excludes(titles);
    // --list makes nothing: every option that shapes the figures would do nothing with it.
    for (CLI::Option* o : sub->get_options())
        if (o != list && o->get_name() != "--help" && !o->get_name().empty()) o->excludes(list);
    add_quiet_flag(sub, opt->quiet);
    reg.runners["figures"] = [opt](ToolRun& run) {
        RunOutputs& outputs = run.outputs;
        if (opt->list) {
            for (const auto& f : figure_list()) fmt::print("{:<22} {}\n", f.name, f.caption);
            return 0;
        }
        FigureOptions fo;
        fo.theme = load_theme(opt->theme, run.assets, &outputs);
        fo.asset_dir = run.assets;
        fo.outputs = &outputs;
        fo.scale = opt->scale;
        fo.only = opt->only;
        fo.format = opt->format;
        fo.print = opt->print.resolve();
        fo.language = parse_language(opt->lang);
        fo.data = opt->data;
        if (opt->titles) fo.titles = true;
        if (opt->no_titles) fo.titles = false;
        if (fo.print && opt->scale != 1.0)
            throw InputError("--scale sizes the figures in pixels: leave it out with a print size (--print, "
                             "--width-in, --width-cm, --font-pt, --dpi)");
        const std::int64_t total = static_cast<std::int64_t>(fo.only.empty() ? figure_list().size() : fo.only.size());
        std::int64_t done = 0;
        ProgressLine progress("figures", opt->quiet);
        write_figures(opt->out, opt->scenario.resolve(&outputs), fo, [&](const FigureInfo&, const std::string& path) {
            run.wrote(opt->quiet, "wrote {}", path);  // said once the run's files are in place
            if (!path.ends_with(".csv")) progress.update(++done, total);  // a figure, not its data
        });
        return 0;
    };
}

}  // namespace dragon::cli
