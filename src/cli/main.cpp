// dragon: the Bench Dragon command-line tool. A thin layer over the benchdragon library.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/kill_cleanup.hpp"
#include "dragon/scenario.hpp"

int main(int argc, char** argv) {
    using namespace dragon;
    cli::install_kill_cleanup();  // first: a kill at any moment leaves no temporary file
    CLI::App app{"dragon: exact simulation, collisions and pictures of the Bench Dragon (CUMCM 2024 A)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "dragon 0.1.0");
    cli::Registry reg;
    cli::register_simulate(app, reg);
    cli::register_solve(app, reg);
    cli::register_collide(app, reg);
    cli::register_min_pitch(app, reg);
    cli::register_turnaround(app, reg);
    cli::register_max_speed(app, reg);
    cli::register_render(app, reg);
    cli::register_figures(app, reg);
    cli::register_video(app, reg);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, naming the bad value; CLI11's own exit codes are not ours.
        std::fprintf(stderr, "dragon: error: %s (see dragon --help)\n", e.what());
        return 2;
    }
    try {
        const std::string name = app.get_subcommands().front()->get_name();
        return reg.at(name)();
    } catch (const InputError& e) {
        std::fprintf(stderr, "dragon: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dragon: failed: %s\n", e.what());
        return 1;
    }
}
