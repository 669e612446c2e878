// Subcommands whose layer is still being written: each registers a runner that reports it.
// Remove a line here when its cmd_*.cpp lands.
#include <stdexcept>

#include "cli/commands.hpp"

namespace dragon::cli {

namespace {
void pending(CLI::App& app, Registry& reg, const char* name, const char* what) {
    app.add_subcommand(name, what);
    reg[name] = [name]() -> int { throw std::runtime_error(std::string(name) + " is not built yet"); };
}
}  // namespace

void register_simulate(CLI::App& app, Registry& reg) { pending(app, reg, "simulate", "Q1 tables"); }
void register_solve(CLI::App& app, Registry& reg) { pending(app, reg, "solve", "All questions"); }
void register_collide(CLI::App& app, Registry& reg) { pending(app, reg, "collide", "Q2"); }
void register_min_pitch(CLI::App& app, Registry& reg) { pending(app, reg, "min-pitch", "Q3"); }
void register_turnaround(CLI::App& app, Registry& reg) { pending(app, reg, "turnaround", "Q4: the S-curve turnaround"); }
void register_render(CLI::App& app, Registry& reg) { pending(app, reg, "render", "Draw one moment to PNG or SVG"); }
void register_figures(CLI::App& app, Registry& reg) { pending(app, reg, "figures", "The figure gallery"); }
void register_video(CLI::App& app, Registry& reg) { pending(app, reg, "video", "Animate to MP4, WebM or GIF"); }

}  // namespace dragon::cli
