#include "cli/answers.hpp"
#include "cli/wording.hpp"

#include <cmath>

#include <fmt/format.h>

#include "cli/contact_search.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {

Json point(const Vec2& p) { return {p.x(), p.y()}; }

Json rows_json(const std::vector<TurnStudyRow>& rows) {
    Json out = Json::array();
    for (const TurnStudyRow& r : rows)
        out.push_back({{"ratio", r.ratio},
                       {"entry_radius", r.entry_radius},
                       {"r1", r.r1},
                       {"r2", r.r2},
                       {"angle", r.angle},
                       {"s_curve_length", r.s_curve_length},
                       {"inside_length", r.inside_length},
                       {"max_radius", r.max_radius},
                       {"followable", r.followable()},
                       {"jam", jam_json(r.jam)}});
    return out;
}

}  // namespace

void check_collide_range(double from, std::optional<double> to) {
    if (!std::isfinite(from))
        throw InputError(fmt::format("--from {} is not allowed: give a finite time in seconds", from));
    if (to && !std::isfinite(*to))
        throw InputError(fmt::format("--to {} is not allowed: give a finite time in seconds, or leave --to out "
                                     "to search as far as the dragon can follow its path", *to));
    if (to && !(*to > from))
        throw InputError(fmt::format("--to {} is not allowed: it must be after --from {}", *to, from));
}

CollideSearch search_collision(const Simulation& sim, double from, std::optional<double> to, Executor* executor) {
    check_collide_range(from, to);
    CollideSearch out;
    out.from = from;
    if (to) {
        const Simulation::Span span = sim.clip_to_valid(from, *to, "time range start", "time range end");
        out.to = span.to;
        out.jam = span.jam;
    } else {
        const ValidRange valid = sim.valid_range();
        if (!std::isfinite(valid.to))
            throw InputError("--to is needed here: on the turnaround path the dragon's motion never ends");
        sim.require_valid(from, "time range start");
        out.to = valid.to;
        out.jam = valid.after;
        if (!(out.to > from))
            throw InputError(fmt::format("--from {} is not allowed: the search would be empty, {}", from,
                                         out.jam ? jam_sentence(*out.jam) : "the head reaches the spiral's centre then"));
    }
    ContactSearchOptions options;
    options.executor = executor;
    out.contact = first_contact_after(sim, from, out.to, options);
    if (out.contact) out.jam.reset();  // the contact comes first: the range was not cut short before it
    return out;
}

Json collide_answer(const CollideSearch& r, bool with_handles) {
    const std::optional<Contact>& c = r.contact;
    Json answer = {{"time", c ? Json(c->time) : Json(nullptr)},
                   {"benches", c ? Json({c->bench_a, c->bench_b}) : Json(nullptr)},
                   {"head_radius", c ? Json(c->head_radius) : Json(nullptr)},
                   {"point", c ? point(c->point) : Json(nullptr)},
                   {"tolerance", c ? Json(c->tolerance) : Json(nullptr)},
                   {"evaluations", c ? Json(c->steps) : Json(nullptr)},
                   {"from", r.from},
                   {"to", r.to},
                   {"jam", jam_json(r.jam)}};
    if (with_handles) {
        Json handles = c ? Json::array() : Json(nullptr);
        if (c)
            for (const Handle& h : c->frame.handles)
                handles.push_back({{"x", round6(h.pos.x())}, {"y", round6(h.pos.y())}, {"speed", round6(h.speed)}});
        answer["handles"] = handles;
    }
    return answer;
}

Json min_pitch_answer(const MinPitch& m, double turn_radius) {
    Json intervals = Json::array();
    for (const PitchInterval& i : m.intervals) intervals.push_back({{"lo", i.lo}, {"hi", i.hi}, {"feasible", i.feasible}});
    Json jam = jam_json(m.jam ? std::optional<Jam>(m.jam->jam) : std::nullopt);
    if (m.jam) jam["pitch"] = m.jam->pitch;
    return {{"pitch", std::isnan(m.pitch) ? Json(nullptr) : Json(m.pitch)},
            {"below_range", m.below_range},
            {"above_range", m.above_range},
            {"turn_radius", turn_radius},
            {"search", {m.search_lo, m.search_hi}},
            {"grid", m.grid},
            {"intervals", intervals},
            {"jam", jam},
            {"guarantee", min_pitch_guarantee(m)}};
}

Json turnaround_answer(const SCurve& d, const std::optional<Jam>& design_jam, const std::optional<RunClearance>& clear,
                       const TurnaroundStudy* study) {
    Json answer = {{"r1", d.r1},
                   {"r2", d.r2},
                   {"length", d.length},
                   {"ratio", d.ratio},
                   {"pitch", d.pitch},
                   {"entry_radius", d.entry_radius},
                   {"entry", point(d.entry)},
                   {"exit", point(d.exit)},
                   {"c1", point(d.c1)},
                   {"c2", point(d.c2)},
                   {"joint", point(d.joint)},
                   {"angle1", d.angle1},
                   {"angle2", d.angle2},
                   {"length1", d.length1},
                   {"length2", d.length2},
                   {"max_radius", d.max_radius},
                   {"followable", !design_jam}};
    if (study) {
        answer["length_vs_ratio"] = rows_json(study->by_ratio);
        answer["length_vs_entry_radius"] = rows_json(study->by_entry);
        answer["ratio_spread"] = study->ratio_spread;
        answer["conclusion"] = turnaround_conclusion(*study);
    }
    if (clear) {
        // No pair within the scan's cutoff: the distance is only a lower bound, with no pair or time.
        const bool near = clear->bench_a > 0;
        answer["clearance"] = {{"distance", clear->distance},
                               {"at_least", !near},
                               {"time", near ? Json(clear->time) : Json(nullptr)},
                               {"benches", near ? Json({clear->bench_a, clear->bench_b}) : Json(nullptr)},
                               {"collision_free", clear->collision_free},
                               {"from", clear->from},
                               {"to", clear->to}};
    }
    // The end of the valid motion where it cuts the clearance run short, else on the design.
    answer["jam"] = jam_json(clear && clear->jam ? clear->jam : design_jam);
    return answer;
}

Json max_speed_answer(const MaxSpeed& m, double limit) {
    return {{"max_head_speed", m.max_head_speed},
            {"ratio", m.unbounded ? Json(nullptr) : Json(m.ratio)},
            {"unbounded", m.unbounded},
            {"handle", m.handle},
            {"time", m.time},
            {"tied", m.tied},
            {"head_arc", m.head_arc},
            {"limit", limit},
            {"from", m.from},
            {"to", m.to},
            {"jam", jam_json(m.jam)},
            {"scan_step", m.unbounded ? Json(nullptr) : Json(m.scan_step)},
            {"candidates", m.candidates},
            {"evaluations", m.evaluations}};
}

}  // namespace dragon::cli
