// dragon: the Bench Dragon command-line tool. A thin layer over the benchdragon library.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <system_error>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "asset_dir.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "error_words.hpp"
#include "kill_cleanup.hpp"
#include "status.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/executor.hpp"
#include "dragon/input_file.hpp"
#include "dragon/scenario.hpp"

namespace {

// stdout holds the answers: a run whose answers did not all reach it (a full disk, a closed
// pipe, `> /dev/full`) has failed, whatever it wrote to files. Buffered output fails only when
// flushed, so the check is at the end. Returns false, with errno set, if anything was lost.
bool stdout_intact() { return std::fflush(stdout) == 0 && std::ferror(stdout) == 0; }

// One line on `to`, whatever the message holds: control characters escaped (a NUL would cut it
// short, a newline make two lines), and cut if it is very long (a file's 10 MB key quoted back).
void say(std::FILE* to, const std::string& message) {
    const std::string line = dragon::shown_text(message, 2000) + "\n";
    std::fwrite(line.data(), 1, line.size(), to);
}

int stdout_failed(int err) {
    std::fprintf(stderr, "dragon: failed: cannot write the answers to standard output: %s\n", std::strerror(err));
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace dragon;
    cli::install_kill_cleanup();  // first: a kill at any moment leaves no temporary file
    CLI::App app{"dragon: exact simulation, collisions and pictures of the Bench Dragon (CUMCM 2024 A)"};
    app.name("dragon");
    app.require_subcommand(1);
    app.set_version_flag("--version", "dragon 0.1.0");
    cli::use_help_formatter(app);
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
    cli::register_film(app, reg);
    cli::register_sweep(app, reg);
    cli::register_keys(app, reg);

    if (const std::optional<int> done = cli::parse_command_line(app, argc, argv, reg.scenario_flags_unused))
        return stdout_intact() ? *done : stdout_failed(errno);
    int code = 0;
    try {
        // The command's files are put in place only when the whole run has succeeded, its
        // answers on stdout included: a run that fails leaves no new output. No output may be
        // one of the files it reads.
        RunOutputs outputs;
        const std::string name = app.get_subcommands().front()->get_name();
        ThreadPool pool;  // the run's workers, one per core, made for this run and joined with it
        cli::ToolRun run{pool, outputs, cli::find_tool_assets(argv[0]), {}};
        code = reg.runners.at(name)(run);
        if (!stdout_intact()) return stdout_failed(errno);
        if (code == 0) {
            outputs.commit();
            // "wrote ...", now that it is true (each line already shown as one: ToolRun::wrote)
            for (const std::string& line : run.wrote_lines) std::fprintf(stderr, "%s\n", line.c_str());
        }
    } catch (const InputError& e) {
        say(stderr, "dragon: error: " + cli::word(e));
        return 2;
    } catch (const std::exception& e) {
        // A SolverError (no answer reached) or a FileError (a file that cannot be written) are
        // failures of the run, not of its input: exit 1.
        // A write to stdout that failed (fmt::print throws then): the one cause worth naming.
        const auto* sys = dynamic_cast<const std::system_error*>(&e);
        if (std::ferror(stdout)) return stdout_failed(sys ? sys->code().value() : errno);
        say(stderr, std::string("dragon: failed: ") + e.what());
        return 1;
    }
    return code;
}
