// dragon turnaround (Q4): the S-curve's design, whether it can be shorter, and how close the
// benches come on the way through it.
#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/scenario_flags.hpp"
#include "cli/status.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

namespace {

constexpr double kDegrees = 57.295779513082320876798154814105;

struct TurnaroundOptions {
    ScenarioFlags scenario;
    bool json = false;
    bool skip_clearance = false;
    double from = -100.0, to = 100.0;
    std::string out;
    bool quiet = false;
};

std::string point(Vec2 p) { return fmt::format("[{}, {}]", p.x, p.y); }

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string rows_json(const std::vector<TurnStudyRow>& rows) {
    std::string out = "[";
    for (size_t i = 0; i < rows.size(); ++i) {
        const TurnStudyRow& r = rows[i];
        out += fmt::format("{}{{\"ratio\": {}, \"entry_radius\": {}, \"r1\": {}, \"r2\": {}, \"angle\": {}, "
                           "\"s_curve_length\": {}, \"inside_length\": {}, \"max_radius\": {}}}",
                           i ? ", " : "", r.ratio, r.entry_radius, r.r1, r.r2, r.angle,
                           r.s_curve_length, r.inside_length, r.max_radius);
    }
    return out + "]";
}

void print_json(const TurnaroundStudy& st, const std::optional<RunClearance>& clear, double from,
                double to) {
    const SCurve& d = st.design;
    std::string s = fmt::format(
        "{{\"r1\": {}, \"r2\": {}, \"length\": {}, \"ratio\": {}, \"pitch\": {}, \"entry_radius\": {}, "
        "\"entry\": {}, \"exit\": {}, \"c1\": {}, \"c2\": {}, \"joint\": {}, \"angle1\": {}, "
        "\"angle2\": {}, \"length1\": {}, \"length2\": {}, \"max_radius\": {}, "
        "\"length_vs_ratio\": {}, \"length_vs_entry_radius\": {}, \"ratio_spread\": {}, "
        "\"conclusion\": {}",
        d.r1, d.r2, d.length, d.ratio, d.pitch, d.entry_radius, point(d.entry), point(d.exit),
        point(d.c1), point(d.c2), point(d.joint), d.angle1, d.angle2, d.length1, d.length2,
        d.max_radius, rows_json(st.by_ratio), rows_json(st.by_entry), st.ratio_spread,
        json_string(st.conclusion));
    if (clear) {
        // No pair within the scan's cutoff: the distance is only a lower bound, with no pair or time.
        const bool near = clear->bench_a > 0;
        s += fmt::format(", \"clearance\": {{\"distance\": {}, \"at_least\": {}, \"time\": {}, "
                         "\"benches\": {}, \"collision_free\": {}, \"from\": {}, \"to\": {}}}",
                         clear->distance, near ? "false" : "true", near ? fmt::format("{}", clear->time) : "null",
                         near ? fmt::format("[{}, {}]", clear->bench_a, clear->bench_b) : "null",
                         clear->collision_free ? "true" : "false", from, to);
    }
    fmt::print("{}}}\n", s);
}

void print_text(const TurnaroundStudy& st, const std::optional<RunClearance>& clear, double from,
                double to) {
    const SCurve& d = st.design;
    fmt::print("Turnaround S-curve (pitch {} m, turning space radius {} m, r1/r2 = {})\n", d.pitch,
               d.entry_radius, d.ratio);
    fmt::print("  entry A   ({:.6f}, {:.6f})    exit B ({:.6f}, {:.6f})\n", d.entry.x, d.entry.y,
               d.exit.x, d.exit.y);
    fmt::print("  arc 1     centre ({:.6f}, {:.6f})  r1 = {:.6f} m  {:.6f} rad ({:.2f} deg)  {:.6f} m\n",
               d.c1.x, d.c1.y, d.r1, d.angle1, d.angle1 * kDegrees, d.length1);
    fmt::print("  arc 2     centre ({:.6f}, {:.6f})  r2 = {:.6f} m  {:.6f} rad ({:.2f} deg)  {:.6f} m\n",
               d.c2.x, d.c2.y, d.r2, d.angle2, d.angle2 * kDegrees, d.length2);
    fmt::print("  joint     ({:.6f}, {:.6f})\n", d.joint.x, d.joint.y);
    fmt::print("  length    {:.6f} m (farthest from the centre: {:.6f} m)\n\n", d.length, d.max_radius);

    fmt::print("Can the turning curve be shorter?\n");
    fmt::print("  {:>7}  {:>10}  {:>10}  {:>14}\n", "r1/r2", "r1 (m)", "r2 (m)", "S-curve (m)");
    for (const TurnStudyRow& r : st.by_ratio)
        fmt::print("  {:>7.3f}  {:>10.6f}  {:>10.6f}  {:>14.9f}\n", r.ratio, r.r1, r.r2, r.s_curve_length);
    fmt::print("\n  {:>12}  {:>14}  {:>22}\n", "entry r (m)", "S-curve (m)", "inside the space (m)");
    for (const TurnStudyRow& r : st.by_entry)
        fmt::print("  {:>12.4f}  {:>14.6f}  {:>22.6f}\n", r.entry_radius, r.s_curve_length, r.inside_length);
    fmt::print("\n  {}\n", st.conclusion);

    if (clear && clear->bench_a == 0) {
        fmt::print("\nClearance over t = {}..{} s: no two benches come within {:.6f} m; {}\n", from, to,
                   clear->distance, clear->collision_free ? "collision-free" : "benches COLLIDE");
    } else if (clear) {
        fmt::print("\nClearance over t = {}..{} s: smallest {:.6f} m, benches {} and {} at t = {:.6f} s; {}\n",
                   from, to, clear->distance, clear->bench_a, clear->bench_b, clear->time,
                   clear->collision_free ? "collision-free" : "benches COLLIDE");
    }
}

}  // namespace

void register_turnaround(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<TurnaroundOptions>();
    CLI::App* sub = app.add_subcommand(
        "turnaround", "Q4: the S-curve turnaround, whether it can be shorter, and its clearance");
    opt->scenario.add_to(sub, ScenarioUse::turnaround_only());
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    sub->add_option("-o,--out", opt->out, "Write the length study as CSV to this file");
    auto* skip = sub->add_flag("--no-clearance", opt->skip_clearance, "Skip the clearance check over the run");
    // The range is the clearance check's: without the check it would do nothing.
    sub->add_option("--from", opt->from, "Clearance check from this time, s (default -100)")->excludes(skip);
    sub->add_option("--to", opt->to, "Clearance check to this time, s (default 100)")->excludes(skip);
    add_quiet_flag(sub, opt->quiet);
    reg["turnaround"] = [opt]() {
        Scenario s = opt->scenario.resolve();
        s.path.kind = PathKind::turnaround;
        if (!opt->out.empty() && extension_of(opt->out) != ".csv")
            throw InputError(fmt::format("--out {} is not allowed: the length study is written as .csv",
                                         opt->out));
        if (!std::isfinite(opt->from) || !std::isfinite(opt->to) || opt->to <= opt->from)
            throw InputError(fmt::format("--from {} --to {} is not allowed: the time range must be "
                                         "finite and non-empty", opt->from, opt->to));
        if (!opt->out.empty()) AtomicFile probe(opt->out);  // fail on an unwritable path first
        const TurnaroundStudy st = study_turnaround(s);
        std::optional<RunClearance> clear;
        if (!opt->skip_clearance) {
            ProgressLine progress("samples", opt->quiet);  // long chains and fast heads take seconds
            clear = min_clearance(s, opt->from, opt->to,
                                  [&progress](std::int64_t done, std::int64_t total) { progress.update(done, total); });
        }
        if (!opt->out.empty()) write_study_csv(st, opt->out);
        if (opt->json) print_json(st, clear, opt->from, opt->to);
        else print_text(st, clear, opt->from, opt->to);
        if (!opt->out.empty()) status(opt->quiet, "wrote {}", opt->out);
        return 0;
    };
}

}  // namespace dragon::cli
