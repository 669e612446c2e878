// dragon solve: all five contest questions on one scenario: the workbooks, summary.json and
// the paper-style tables.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/commands.hpp"
#include "cli/report.hpp"
#include "cli/scenario_flags.hpp"
#include "cli/status.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

namespace {

struct SolveOptions {
    ScenarioFlags scenario;
    std::string dir = "out";
    std::vector<std::string> only;
    bool quiet = false;
};

// Every `every`-th frame of a table sampled each `step` seconds, for the printed excerpt.
std::vector<const Frame*> pick(const std::vector<Frame>& frames, double step, double every) {
    std::vector<const Frame*> out;
    const int stride = static_cast<int>(std::lround(every / step));
    for (size_t k = 0; k < frames.size(); k += static_cast<size_t>(stride)) out.push_back(&frames[k]);
    return out;
}

void write_text(AtomicFile& out, const std::string& text) {
    errno = 0;
    std::FILE* f = std::fopen(out.temp_path().c_str(), "wb");
    if (!f) throw out.write_error(std::strerror(errno));
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const int err = errno;
    if (std::fclose(f) != 0 || !ok) throw out.write_error(std::strerror(ok ? errno : err));
}

// The scenario values the questions asked for read: a value none of them reads is not checked
// (a file's pitch does not matter to --only q4), and a flag for one is refused.
ScenarioValues values_read_by(const std::function<bool(const char*)>& wanted) {
    ScenarioValues v = 0;
    if (wanted("q1") || wanted("q2")) v |= values_read(PathKind::spiral);
    if (wanted("q3")) v |= value::bench | value::head_speed | value::start_turn | value::turn_radius;
    if (wanted("q4") || wanted("q5")) v |= values_read(PathKind::turnaround);
    return v;
}

}  // namespace

void register_solve(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<SolveOptions>();
    CLI::App* sub = app.add_subcommand(
        "solve", "All five questions: result1/2/4.xlsx, summary.json and the paper-style tables");
    opt->scenario.add_to(sub, ScenarioUse::both_paths("it answers Q1-Q3 on the plain spiral and Q4-Q5 on the "
                                                      "turnaround path"));
    sub->add_option("-o,--out", opt->dir, "Output folder (created if missing; default out)");
    sub->add_option("--only", opt->only, "Answer only these questions: q1 q2 q3 q4 q5 (default all)")
        ->delimiter(',');
    add_quiet_flag(sub, opt->quiet);
    reg["solve"] = [opt]() {
        const std::set<std::string> all{"q1", "q2", "q3", "q4", "q5"};
        for (const std::string& q : opt->only)
            if (!all.count(q))
                throw InputError(fmt::format("--only {} is not allowed: the questions are q1, q2, q3, q4, q5", q));
        const std::function<bool(const char*)> wanted = [&](const char* q) {
            return opt->only.empty() || std::find(opt->only.begin(), opt->only.end(), q) != opt->only.end();
        };
        Scenario s = opt->scenario.resolve(values_read_by(wanted),
                                           fmt::format("no question of --only {} reads it", fmt::join(opt->only, ",")));
        s.path.kind = PathKind::spiral;
        namespace fs = std::filesystem;
        if (!make_output_folder(opt->dir))
            throw InputError(fmt::format("-o {} is not allowed: the folder cannot be created", opt->dir));

        // Every target is checked, and its temporary file made, before any work: a folder or an
        // unwritable name in the way fails here with no file touched. They are renamed into
        // place together at the end, so the set is all new or all old.
        std::vector<std::unique_ptr<AtomicFile>> files;
        std::vector<std::string> written;
        const auto target = [&](bool needed, const char* name) -> AtomicFile* {
            if (!needed) return nullptr;
            files.push_back(std::make_unique<AtomicFile>((fs::path(opt->dir) / name).string()));
            written.push_back(name);
            return files.back().get();
        };
        AtomicFile* result1 = target(wanted("q1"), "result1.xlsx");
        AtomicFile* result2 = target(wanted("q2"), "result2.xlsx");
        AtomicFile* result4 = target(wanted("q4"), "result4.xlsx");
        AtomicFile* summary_json = target(true, "summary.json");
        Json summary = Json::object();

        // The two long tables and their workbooks (most of the time: libxlsxwriter formats and
        // deflates every cell) are made on threads of their own while this one answers Q2, Q3
        // and Q5; everything is printed afterwards, in the questions' order. (Nothing is written
        // on stderr meanwhile: libxlsxwriter's closing mutes it, see tables/workbooks.cpp.)
        Scenario turn = s;
        turn.path.kind = PathKind::turnaround;
        // Q1: coiling in, 0..300 s (the simulation only if Q1 or Q2 reads it: --only q4 does
        // not read the plain spiral's values, which may not even make one).
        std::optional<Simulation> coil;
        if (result1 || result2) coil.emplace(s);
        const double q1_end = result1 ? std::min(300.0, std::floor(coil->valid_end())) : 0.0;
        std::future<std::vector<Frame>> q1_table, q4_table;
        if (result1) {
            q1_table = std::async(std::launch::async, [&] {
                std::vector<Frame> q1 = simulate_table(*coil, 0.0, q1_end, 1.0);
                write_result_xlsx(q1, *result1);
                return q1;
            });
        }
        // Q4: the turnaround, -100..100 s.
        if (result4) {
            q4_table = std::async(std::launch::async, [&] {
                const Simulation tsim(turn);
                std::vector<Frame> q4 = simulate_table(tsim, -100.0, 100.0, 1.0);
                write_result_xlsx(q4, *result4);
                return q4;
            });
        }
        // Meanwhile, here: Q2, Q3 and Q5.
        std::optional<Contact> q2;
        if (result2) {
            q2 = first_contact(*coil, 0.0, coil->valid_end());
            // With no contact, the contest's layout with no rows, so no older answer is left
            // looking like this one's.
            write_result2_xlsx(q2 ? q2->frame : Frame{}, *result2);
        }
        std::optional<MinPitch> q3;
        if (wanted("q3")) q3 = min_pitch(s, 0.35, 0.55);
        std::optional<MaxSpeed> q5;
        if (wanted("q5")) q5 = max_head_speed(turn, 2.0);

        if (result1) {
            const std::vector<Frame> q1 = q1_table.get();
            print_frame_table("Q1: positions (m) and speeds (m/s) while coiling in", pick(q1, 1.0, 60.0));
            summary["q1"] = {{"file", "result1.xlsx"}, {"times", {0, q1_end}}};
        }

        // Q2: the termination time.
        if (result2) {
            const Simulation& sim = *coil;
            if (const std::optional<Contact>& c = q2) {
                fmt::print("\nQ2: benches {} and {} touch at t = {} s (head radius {:.6f} m)\n", c->bench_a,
                           c->bench_b, format_resolved(c->time, c->tolerance), c->head_radius);
                print_single_frame("", c->frame);
                summary["q2"] = {{"file", "result2.xlsx"},
                                 {"time", c->time},
                                 {"benches", {c->bench_a, c->bench_b}},
                                 {"head_radius", c->head_radius}};
            } else {
                fmt::print("\nQ2: no collision as far as the dragon can follow the spiral (t = {} s)\n",
                           format_time(sim.valid_end()));
                summary["q2"] = {{"file", "result2.xlsx"}, {"time", nullptr}, {"jam", jam_json(sim.valid_range().after)}};
            }
        }

        // Q3: the minimum pitch.
        if (q3) {
            const MinPitch& m = *q3;
            // Resolved to 1e-9 m: ten decimals.
            if (std::isnan(m.pitch))
                fmt::print("\nQ3: no change from collision to collision-free in 0.35..0.55 m (the minimum pitch lies {})\n",
                           m.below_range ? "at or below 0.35 m" : "above 0.55 m");
            else
                fmt::print("\nQ3: minimum pitch {:.10f} m to reach radius {} m collision-free\n", m.pitch,
                           s.path.turn_radius);
            Json intervals = Json::array();
            for (const PitchInterval& i : m.intervals) {
                fmt::print("  [{:.10f}, {:.10f}] m  {}\n", i.lo, i.hi, i.feasible ? "collision-free" : "collides");
                intervals.push_back({{"lo", i.lo}, {"hi", i.hi}, {"feasible", i.feasible}});
            }
            summary["q3"] = {{"pitch", std::isnan(m.pitch) ? Json(nullptr) : Json(m.pitch)},
                             {"below_range", m.below_range},
                             {"above_range", m.above_range},
                             {"intervals", intervals}};
        }

        // Q4 and Q5 run on the turnaround path.
        if (result4) {
            const std::vector<Frame> q4 = q4_table.get();
            const SCurve sc = design_s_curve(turn);
            fmt::print("\nQ4: S-curve r1 = {:.6f} m, r2 = {:.6f} m, length {:.6f} m\n", sc.r1, sc.r2, sc.length);
            print_frame_table("Q4: positions (m) and speeds (m/s) around the turn", pick(q4, 1.0, 50.0));
            summary["q4"] = {{"file", "result4.xlsx"}, {"r1", sc.r1}, {"r2", sc.r2}, {"length", sc.length}};
        }

        // Q5: the speed limit.
        if (q5) {
            const MaxSpeed& v = *q5;
            fmt::print("\nQ5: largest head speed {:.6f} m/s (speed ratio {:.6f} at handle {}, t = {:.6f} s)\n",
                       v.max_head_speed, v.ratio, v.handle, v.time);
            summary["q5"] = {{"max_head_speed", v.max_head_speed},
                             {"ratio", v.unbounded ? Json(nullptr) : Json(v.ratio)},
                             {"handle", v.handle},
                             {"time", v.time},
                             {"jam", jam_json(v.jam)}};
        }
        write_text(*summary_json, summary.dump(2) + "\n");
        std::vector<AtomicFile*> set;
        for (const auto& f : files) set.push_back(f.get());
        require_stdout_written();  // the tables all printed, or no file changes
        commit_together(set);
        status(opt->quiet, "wrote {} in {}", fmt::join(written, ", "), opt->dir);
        return 0;
    };
}

}  // namespace dragon::cli
