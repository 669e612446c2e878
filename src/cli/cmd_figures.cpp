// dragon figures: the gallery (the paper's five figures done right, and the plots behind them).
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/scenario_flags.hpp"
#include "dragon/figures.hpp"

namespace dragon::cli {

namespace {
struct FiguresOptions {
    ScenarioFlags scenario;
    std::string out = "renders";
    std::string theme = "light";
    double scale = 1.0;
    std::vector<std::string> only;
    bool list = false;
};
}  // namespace

void register_figures(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<FiguresOptions>();
    CLI::App* sub = app.add_subcommand("figures", "The figure gallery: the paper's figures done right, and plots");
    opt->scenario.add_to(sub);
    sub->add_option("-o,--out", opt->out, "Folder for the PNG files (default renders)");
    sub->add_option("--theme", opt->theme, "Colour theme: light, dark or a .toml file (default light)");
    sub->add_option("--scale", opt->scale, "Pixel size relative to the gallery's ~1000 px (0.25..8, default 1)");
    sub->add_option("--only", opt->only, "Make only these figures (names as --list prints them)");
    sub->add_flag("--list", opt->list, "List the figures and exit");
    reg["figures"] = [opt]() {
        if (opt->list) {
            for (const auto& f : figure_list()) fmt::print("{:<22} {}\n", f.name, f.caption);
            return 0;
        }
        FigureOptions fo;
        fo.theme = load_theme(opt->theme, DRAGON_ASSET_DIR);
        fo.scale = opt->scale;
        fo.only = opt->only;
        write_figures(opt->out, opt->scenario.resolve(), fo,
                      [](const FigureInfo&, const std::string& path) { fmt::print(stderr, "wrote {}\n", path); });
        return 0;
    };
}

}  // namespace dragon::cli
