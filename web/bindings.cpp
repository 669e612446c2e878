// The page's engine: JavaScript calls mapped onto the library's, and nothing else (embind).
// The page sets a scenario by the CLI's flag names, asks for frames (numbers in a typed array) and
// for the questions' answers (the same JSON text as `dragon <command> --json`, built by the same
// functions), and reads refusals as the library's own sentences with the flags they concern.
// Single-threaded: every search runs on the calling thread (a Web Worker, for the long ones).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "dragon/analyses.hpp"
#include "dragon/answers.hpp"
#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "dragon/contest.hpp"
#include "dragon/executor.hpp"
#include "dragon/json.hpp"
#include "dragon/scenario.hpp"
#include "dragon/sweep.hpp"
#include "dragon/turnaround.hpp"

using emscripten::val;

namespace {

// The flags of a set of values, in the table's order.
val flags_of(dragon::ScenarioValues values) {
    val out = val::array();
    for (const dragon::SweepParameter& p : dragon::sweep_parameters())
        if (values & p.value) out.call<void>("push", std::string(p.name));
    return out;
}

// A refusal for the page: the library's sentence, and the flags of the values it concerns.
val refusal(const std::string& message, dragon::ScenarioValues values) {
    val out = val::object();
    out.set("error", message);
    out.set("flags", flags_of(values));
    return out;
}

// An answer for the page: its JSON text as json_text writes it, and the text of each leaf inside
// it by its key path ("first_contact.time"; arrays are leaves), taken from that same text as it
// is written (each number printed once).
val answer_val(const dragon::Json& j) {
    val leaves = val::object();
    const std::string text = dragon::json_text_with_leaves(
        j, [&leaves](const std::string& path, std::string_view leaf) { leaves.set(path, std::string(leaf)); });
    val out = val::object();
    out.set("json", text);
    out.set("leaves", leaves);
    return out;
}


class Engine {
public:
    Engine() = default;

    // The contest's values, by flag name.
    static val defaults() {
        dragon::Scenario s;
        val out = val::object();
        for (const dragon::SweepParameter& p : dragon::sweep_parameters()) out.set(p.name, dragon::get_parameter(s, p));
        return out;
    }

    // Sets the scenario from {flag: number} and "path" ("spiral" or "turnaround"), checked for
    // what the scene shows on that path (its values and the turning space). Returns null, or a
    // refusal ({error, flags}) and keeps the scenario it had.
    val set_scenario(val keys) {
        dragon::Scenario s;
        const std::string kind = keys["path"].isString() ? keys["path"].as<std::string>() : "spiral";
        s.path.kind = kind == "turnaround" ? dragon::PathKind::turnaround : dragon::PathKind::spiral;
        try {
            // The library's scenario keys by their flags' names, each set by the library's own
            // setter (a bench count is checked before it becomes an int).
            for (const dragon::SweepParameter& p : dragon::sweep_parameters()) {
                const val v = keys[p.name];
                if (v.isUndefined() || v.isNull()) continue;
                const double x = v.as<double>();
                if (p.whole && x != std::floor(x))
                    return refusal("bench count " + dragon::error_value(x) + " is not allowed: give a whole number", p.value);
                dragon::set_parameter(s, p, x);
            }
            dragon::validate(s, dragon::values_read(s.path.kind) | dragon::value::turn_radius);
            sim_.emplace(s);
            range_ = sim_->valid_range();
        } catch (const dragon::ScenarioError& e) {
            return refusal(e.what(), e.values);
        } catch (const dragon::InputError& e) {
            return refusal(e.what(), 0);
        }
        return val::null();
    }

    // The valid motion: {from, to, from_travel, to_travel} (s, m; infinite ends as +-Infinity)
    // and the jams that end it ({time, handle, sentence}, or null).
    val range() const {
        val out = val::object();
        out.set("from", range_.from);
        out.set("to", range_.to);
        out.set("from_travel", range_.from_travel);
        out.set("to_travel", range_.to_travel);
        out.set("before", jam_val(range_.before));
        out.set("after", jam_val(range_.after));
        out.set("end_time", sim_->end_time());
        return out;
    }

    // The chain at time t into a buffer: per handle x, y, speed (N + 1 of them), then per bench
    // centre x, y, axis x, y, half length, half width (N). A view of the engine's memory, valid
    // until the next call. Throws (to JS) for a t outside the valid motion.
    val frame(double t) {
        sim_->frame_into(t, frame_);
        const std::size_t h = frame_.handles.size(), b = frame_.benches.size();
        buffer_.resize(3 * h + 6 * b);
        double* p = buffer_.data();
        for (const dragon::Handle& x : frame_.handles) {
            *p++ = x.pos.x();
            *p++ = x.pos.y();
            *p++ = x.speed;
        }
        for (const dragon::Rect& r : frame_.benches) {
            *p++ = r.centre.x();
            *p++ = r.centre.y();
            *p++ = r.axis.x();
            *p++ = r.axis.y();
            *p++ = r.half_length;
            *p++ = r.half_width;
        }
        return val(emscripten::typed_memory_view(buffer_.size(), buffer_.data()));
    }

    // The last frame's head arc position, m.
    double head_arc() const { return frame_.head_arc; }
    double head_arc_at(double t) const { return sim_->head_arc(t); }

    // The last frame's nearest non-adjacent pair {distance, a, b, x, y} and its overlapping pairs
    // [{a, b, depth, x, y}] (past the first contact).
    val gaps() const {
        val out = val::object();
        const dragon::Clearance c = dragon::clearance(frame_);
        out.set("distance", c.distance);
        out.set("a", c.bench_a);
        out.set("b", c.bench_b);
        out.set("x", c.point.x());
        out.set("y", c.point.y());
        val list = val::array();
        if (c.distance < 0)
            for (const dragon::Overlap& o : dragon::overlaps(frame_)) {
                val v = val::object();
                v.set("a", o.bench_a);
                v.set("b", o.bench_b);
                v.set("depth", o.depth);
                v.set("x", o.point.x());
                v.set("y", o.point.y());
                list.call<void>("push", v);
            }
        out.set("overlaps", list);
        return out;
    }

    // Bench k's nearest other non-adjacent bench in the last frame: {bench, distance, x, y}.
    val nearest_to(int k) const {
        val out = val::object();
        const int n = static_cast<int>(frame_.benches.size());
        if (k < 1 || k > n) k = 0;  // no such bench: nothing near it
        double best = std::numeric_limits<double>::infinity();
        int who = 0;
        dragon::Vec2 at = dragon::Vec2::Zero();
        for (int j = 1; k > 0 && j <= n; ++j) {
            if (std::abs(j - k) < 2) continue;
            const dragon::Separation sep = dragon::separation(frame_.benches[k - 1], frame_.benches[j - 1]);
            if (sep.distance < best) {
                best = sep.distance;
                who = j;
                at = sep.point;
            }
        }
        out.set("bench", who);
        out.set("distance", best);
        out.set("x", at.x());
        out.set("y", at.y());
        return out;
    }

    // Points of the path every `step` metres of arc from s0 to s1 (cut to the path), x, y pairs.
    val path_points(double s0, double s1, double step) {
        const dragon::Path& p = sim_->path();
        s0 = std::max(s0, p.s_min());
        s1 = std::min(s1, p.s_max());
        points_.clear();
        if (s1 > s0 && step > 0) {
            const int n = static_cast<int>(std::min(2e5, std::ceil((s1 - s0) / step)));
            for (int i = 0; i <= n; ++i) {
                const dragon::Located l = p.at_arc(s0 + (s1 - s0) * i / n);
                points_.push_back(l.pos.x());
                points_.push_back(l.pos.y());
            }
        }
        return val(emscripten::typed_memory_view(points_.size(), points_.data()));
    }

    // The nearest gap between non-adjacent benches at `count` moments evenly over [t0, t1]
    // (negative: overlapping, past the first contact), m; gaps wider than 1 m are given as 1 m.
    val gap_curve(double t0, double t1, int count) {
        gaps_.assign(static_cast<std::size_t>(std::max(count, 0)), 0.0);
        dragon::Frame f;
        dragon::BroadPhase scratch;
        for (int i = 0; i < count; ++i) {
            sim_->frame_into(count > 1 ? t0 + (t1 - t0) * i / (count - 1) : t0, f);
            gaps_[i] = std::min(1.0, dragon::clearance(f, 1.0, scratch).distance);
        }
        return val(emscripten::typed_memory_view(gaps_.size(), gaps_.data()));
    }

    // The S-curve of the turnaround path: {c1x, c1y, r1, c2x, c2y, r2, ax, ay, bx, by, jx, jy}.
    val s_curve() const {
        const dragon::SCurve d = dragon::design_s_curve(sim_->scenario());
        val out = val::object();
        out.set("c1x", d.c1.x());
        out.set("c1y", d.c1.y());
        out.set("r1", d.r1);
        out.set("c2x", d.c2.x());
        out.set("c2y", d.c2.y());
        out.set("r2", d.r2);
        out.set("ax", d.entry.x());
        out.set("ay", d.entry.y());
        out.set("bx", d.exit.x());
        out.set("by", d.exit.y());
        out.set("jx", d.joint.x());
        out.set("jy", d.joint.y());
        out.set("length", d.length);
        return out;
    }

    // One question's answer for this scenario as its command computes it with default options
    // ("collide", "min-pitch", "turnaround", "max-speed"): {json, leaves}, or a refusal
    // ({error, flags}). `progress` (a function or undefined) hears (done, total) of the long scans.
    val answer(const std::string& command, val progress) const {
        dragon::Scenario s = sim_->scenario();
        const dragon::WorkProgress report = [progress](std::int64_t done, std::int64_t total) {
            if (progress.typeOf().as<std::string>() == "function")
                progress(static_cast<double>(done), static_cast<double>(total));
        };
        try {
            if (command == "collide") {
                // On this engine's simulation: the valid motion set_scenario found is the one the
                // search is cut to (a new Simulation would search it again, a seventh of Q2).
                return answer_val(dragon::collide_answer(
                    dragon::collide(*sim_, dragon::default_window(s.path.kind), nullptr), true));
            }
            if (command == "min-pitch") {
                s.path.kind = dragon::PathKind::spiral;
                dragon::validate(s, dragon::value::bench | dragon::value::head_speed | dragon::value::start_turn |
                                        dragon::value::turn_radius);
                dragon::MinPitchOptions options;
                options.progress = report;
                // The command's default range for this scenario (moved up for a wide dragon).
                const dragon::PitchRange range = dragon::pitch_search_range(s, std::nullopt, std::nullopt);
                return answer_val(dragon::min_pitch_answer(dragon::min_pitch(s, range.lo, range.hi, options),
                                                           s.path.turn_radius));
            }
            if (command == "turnaround") {
                s.path.kind = dragon::PathKind::turnaround;
                dragon::validate(s);
                const dragon::TurnaroundStudy st = dragon::study_turnaround(s);
                const dragon::RunClearance clear = dragon::min_clearance(s, dragon::kTurnaroundWindow, report, nullptr);
                return answer_val(dragon::turnaround_answer(st.design, st.design_jam, clear, &st));
            }
            if (command == "max-speed") {
                s.path.kind = dragon::PathKind::turnaround;
                dragon::validate(s);
                return answer_val(dragon::max_speed_answer(
                    dragon::max_head_speed(s, 2.0, dragon::kTurnaroundWindow, nullptr), 2.0));
            }
            return refusal("no such question: " + command, 0);
        } catch (const dragon::ScenarioError& e) {
            return refusal(e.what(), e.values);
        } catch (const std::exception& e) {  // InputError (a window past the motion, say), SolverError
            return refusal(e.what(), 0);
        }
    }

    // One cell of a minimum-pitch map: Q3 for this scenario with another width and body length,
    // searched over [lo, hi] on a first scan of `grid` (as `dragon sweep --measure min-pitch`):
    // {pitch (NaN when the range holds no change), below, above}, or {error}.
    val min_pitch_cell(double width, double body_length, double lo, double hi, double grid) const {
        dragon::Scenario s = sim_->scenario();
        s.path.kind = dragon::PathKind::spiral;
        s.bench.width = width;
        s.bench.body_length = body_length;
        val out = val::object();
        try {
            dragon::MinPitchOptions options;
            options.grid = grid;
            options.executor = nullptr;
            const dragon::MinPitch m = dragon::min_pitch(s, lo, hi, options);
            out.set("pitch", m.pitch);
            out.set("below", m.below_range);
            out.set("above", m.above_range);
        } catch (const std::exception& e) {
            out.set("error", std::string(e.what()));
        }
        return out;
    }

private:
    static val jam_val(const std::optional<dragon::Jam>& j) {
        if (!j) return val::null();
        val out = val::object();
        out.set("time", j->time);
        out.set("travel", j->travel);
        out.set("handle", j->handle);
        out.set("kind", std::string(dragon::to_string(j->kind)));
        out.set("ahead", j->ahead);
        out.set("x", j->point.x());
        out.set("y", j->point.y());
        out.set("sentence", dragon::jam_sentence(*j));
        return out;
    }

    std::optional<dragon::Simulation> sim_;
    dragon::ValidRange range_;
    dragon::Frame frame_;
    std::vector<double> buffer_;
    std::vector<double> points_;
    std::vector<double> gaps_;
};

}  // namespace

EMSCRIPTEN_BINDINGS(dragon_engine) {
    emscripten::class_<Engine>("Engine")
        .constructor<>()
        .class_function("defaults", &Engine::defaults)
        .function("setScenario", &Engine::set_scenario)
        .function("range", &Engine::range)
        .function("frame", &Engine::frame)
        .function("headArc", &Engine::head_arc)
        .function("headArcAt", &Engine::head_arc_at)
        .function("gaps", &Engine::gaps)
        .function("nearestTo", &Engine::nearest_to)
        .function("pathPoints", &Engine::path_points)
        .function("sCurve", &Engine::s_curve)
        .function("gapCurve", &Engine::gap_curve)
        .function("answer", &Engine::answer)
        .function("minPitchCell", &Engine::min_pitch_cell);
}
