// libFuzzer target: scenario TOML files and the scenario flags of the CLI.
//
// Input: CLI words, one per line, up to a line "%%"; the rest is a TOML file. The word @FILE
// stands for that file's path. With no "%%" line the whole input is the TOML file.
//
// Properties:
//  - load_scenario returns or throws InputError: no other exception escapes (toml++'s parse
//    errors, std::out_of_range, ...);
//  - the flags parse or throw CLI::ParseError, and ScenarioFlags::resolve() returns a
//    scenario validate() accepts or throws InputError;
//  - a scenario validate() accepts is usable: its Simulation builds and the chain at the start
//    (and at the spiral's centre) has finite positions, tangents and speeds.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/scenario_flags.hpp"
#include "dragon/chain.hpp"
#include "dragon/input_files.hpp"
#include "dragon/scenario.hpp"
#include "fuzz_check.hpp"

namespace {

using namespace dragon;

// One file per fuzzing process, rewritten for every input (load_scenario reads a path).
const std::string& scenario_path() {
    static const std::string path = "/tmp/dragon-fuzz-scenario-" + std::to_string(::getpid()) + ".toml";
    return path;
}

void write_file(const std::string& path, const std::string& text) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    FUZZ_CHECK(f != nullptr, "cannot write %s", path.c_str());
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
}

void check_frame(const Frame& f, const Scenario& s) {
    FUZZ_CHECK(f.handles.size() == static_cast<size_t>(s.bench.handle_count()), "handle count");
    for (const Handle& h : f.handles) {
        FUZZ_CHECK(std::isfinite(h.pos.x()) && std::isfinite(h.pos.y()) && std::isfinite(h.speed),
                   "handle at (%g, %g) speed %g", h.pos.x(), h.pos.y(), h.speed);
        FUZZ_CHECK(std::isfinite(h.tangent.x()) && std::isfinite(h.tangent.y()), "tangent");
    }
}

// A validated scenario must simulate. Long chains are cut to 64 benches: the start and the
// path do not depend on the chain's length, and a million benches per input would starve
// the fuzzer.
void check_usable(Scenario s) {
    s.bench.bench_count = std::min(s.bench.bench_count, 64);
    try {
        validate(s);
    } catch (const InputError&) {
        return;  // a shorter chain may not fit a rule the longer one met: nothing to check
    }
    const Simulation sim(s);
    check_frame(sim.frame(0.0), s);
    // As far as the dragon can follow its path (the centre, or where its valid motion ends).
    if (const double end = sim.valid_end(); std::isfinite(end)) check_frame(sim.frame(end), s);
}

void fuzz_file(const std::string& toml) {
    write_file(scenario_path(), toml);
    Scenario s;
    try {
        s = load_scenario(scenario_path());
        validate(s);
    } catch (const InputError&) {
        return;
    }
    check_usable(s);
}

void fuzz_flags(const std::vector<std::string>& words) {
    CLI::App app{"fuzz"};
    CLI::App* sub = app.add_subcommand("simulate", "");
    cli::ScenarioFlags flags;
    cli::Registry reg;  // where the command would keep its reason for flags it does not take
    flags.add_to(sub, cli::ScenarioUse::either_path(), reg);  // simulate's: every flag, either path
    std::vector<std::string> args = {"dragon", "simulate"};
    args.insert(args.end(), words.begin(), words.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    try {
        app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError&) {
        return;
    }
    Scenario s;
    try {
        s = flags.resolve(nullptr);  // no run: the fuzzer checks values, not outputs
    } catch (const InputError&) {
        return;
    }
    validate(s);  // resolve() promised a valid scenario: this must not throw
    check_usable(s);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find("\n%%\n");
    const std::string toml = split == std::string::npos ? input : input.substr(split + 4);
    try {
        fuzz_file(toml);
        if (split != std::string::npos) {
            std::vector<std::string> words;
            std::size_t at = 0;
            while (at <= split) {
                std::size_t end = input.find('\n', at);
                if (end == std::string::npos || end > split) end = split;
                std::string w = input.substr(at, end - at);
                if (w == "@FILE") w = scenario_path();
                words.push_back(w);
                at = end + 1;
            }
            fuzz_flags(words);
        }
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "unexpected exception: %s", e.what());
    }
    return 0;
}
