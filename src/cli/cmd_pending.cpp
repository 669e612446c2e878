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

void register_figures(CLI::App& app, Registry& reg) { pending(app, reg, "figures", "The figure gallery"); }

}  // namespace dragon::cli
