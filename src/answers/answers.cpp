// The --json answers of the question commands, built in one place (dragon/answers.hpp).
#include "dragon/answers.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dragon/tables.hpp"

namespace dragon {

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

// The jam's enclosure: proved continuous up to one end, past the jam at the other.
Json jam_enclosure_json(const Jam& j) {
    const double past = j.ahead ? j.travel + j.travel_tolerance : j.travel - j.travel_tolerance;
    const double past_time = j.ahead ? j.time + j.tolerance : j.time - j.tolerance;
    return {{"travel", {std::min(j.proved_travel, past), std::max(j.proved_travel, past)}},
            {"time", {std::min(j.proved_time, past_time), std::max(j.proved_time, past_time)}}};
}

}  // namespace

Json jam_json(const std::optional<Jam>& j) {
    if (!j) return nullptr;
    return Json{{"time", j->time},
                {"travel", j->travel},
                {"handle", j->handle},
                {"kind", to_string(j->kind)},
                {"ahead", j->ahead},
                {"point", {j->point.x(), j->point.y()}},
                {"tolerance", j->tolerance},
                {"enclosure", jam_enclosure_json(*j)},
                {"proof", {{"method", j->method()}, {"steps", j->proved_steps}, {"unproved_steps", j->unproved_steps}}}};
}

void add_window(Json& answer, const Searched& w) {
    answer["from"] = w.from;
    answer["to"] = w.to;
    answer["from_travel"] = w.from_travel;
    answer["to_travel"] = w.to_travel;
}


Json contact_json(const Contact& c) {
    return {{"time", c.time},
            {"travel", c.travel},
            {"benches", {c.bench_a, c.bench_b}},
            {"head_radius", c.head_radius},
            {"point", point(c.point)},
            {"tolerance", c.tolerance}};
}

Json overlap_json(const std::optional<Overlap>& o) {
    if (!o) return nullptr;
    return {{"benches", {o->bench_a, o->bench_b}}, {"depth", o->depth}};
}

// Where a first contact is proved to lie: {"travel": [lo, hi], "time": [lo, hi]}, or null.
Json enclosure_json(const std::optional<Contact>& c) {
    return c ? Json{{"travel", {c->enclosure_lo, c->enclosure_hi}}, {"time", {c->enclosure_time_lo, c->enclosure_time_hi}}}
             : Json(nullptr);
}

// What a walk asked to prove every step proved of the valid motion.
Json motion_json(const JamSearchStats& m) {
    return {{"method", m.unproved_steps == 0 ? "proved" : "proved+rate"},
            {"steps", m.proved_steps},
            {"unproved_steps", m.unproved_steps},
            {"unproved_travel", m.unproved_travel}};
}

Json proof_json(const ContactProof& p) {
    return {{"method", p.method()},
            {"steps", p.proved_steps},
            {"subdivisions", p.subdivisions},
            {"unproved_steps", p.unproved_steps},
            {"unproved_travel", p.unproved_travel},
            {"least_separation", std::isfinite(p.least_gap) ? Json(p.least_gap) : Json(nullptr)},
            {"covered_travel", {p.proved_from, p.proved_to}},
            {"motion", p.motion_checked ? motion_json(p.motion) : Json(nullptr)}};
}

Json collide_answer(const CollideAnswer& r, bool with_handles) {
    const std::optional<Contact>& c = r.contact;
    Json answer = c ? contact_json(*c)
                    : Json{{"time", nullptr}, {"travel", nullptr}, {"benches", nullptr}, {"head_radius", nullptr},
                           {"point", nullptr}, {"tolerance", nullptr}};
    answer["evaluations"] = c ? Json(c->steps) : Json(nullptr);
    answer["enclosure"] = enclosure_json(c);
    answer["proof"] = proof_json(r.proof);
    add_window(answer, r.window);
    answer["jam"] = jam_json(r.jam);
    answer["overlap_at_start"] = overlap_json(r.overlap);
    if (with_handles) {
        Json handles = c ? Json::array() : Json(nullptr);
        if (c)
            for (const Handle& h : c->frame.handles)
                handles.push_back({{"x", round6(h.pos.x())}, {"y", round6(h.pos.y())}, {"speed", round6(h.speed)}});
        answer["handles"] = handles;
    }
    return answer;
}

Json pitch_proof_json(const std::optional<PitchProof>& p) {
    const auto ranges = [](const std::vector<PitchInterval>& v) {
        Json out = Json::array();
        for (const PitchInterval& i : v) out.push_back({i.lo, i.hi});
        return out;
    };
    if (!p) return {{"method", "runs"}, {"proved", Json::array()}, {"unproved", nullptr},
                    {"proved_colliding", Json::array()}, {"unproved_colliding", nullptr},
                    {"least_feasible", nullptr}, {"cells", 0},
                    {"pitch_ranges", 0}, {"subdivisions", 0}, {"least_separation", nullptr}};
    return {{"method", p->method()},
            {"proved", ranges(p->proved)},
            {"unproved", ranges(p->unproved)},
            {"proved_colliding", ranges(p->proved_colliding)},
            {"unproved_colliding", ranges(p->unproved_colliding)},
            {"least_feasible", std::isnan(p->least_lo) ? Json(nullptr) : Json::array({p->least_lo, p->least_hi})},
            {"cells", p->cells},
            {"pitch_ranges", p->pitch_ranges},
            {"subdivisions", p->subdivisions},
            {"least_separation", std::isfinite(p->least_gap) ? Json(p->least_gap) : Json(nullptr)}};
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
            {"guarantee", min_pitch_guarantee(m)},
            {"proof", pitch_proof_json(m.proof)}};
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
        answer["first_contact"] = clear->first_contact ? contact_json(*clear->first_contact) : Json(nullptr);
        // No pair within the scan's cutoff: the distance is only a lower bound, with no pair or time.
        const bool near = clear->bench_a > 0;
        Json c = {{"distance", clear->distance},
                  {"at_least", !near},
                  {"time", near ? Json(clear->time) : Json(nullptr)},
                  {"travel", near ? Json(clear->travel) : Json(nullptr)},
                  {"benches", near ? Json({clear->bench_a, clear->bench_b}) : Json(nullptr)},
                  {"collision_free", clear->collision_free()},
                  {"evaluations", clear->evaluations}};
        add_window(c, clear->window);
        answer["clearance"] = c;
        answer["enclosure"] = enclosure_json(clear->first_contact);
        answer["proof"] = proof_json(clear->proof);
        // The smallest clearance's proved lower bound (with `prove` and no contact).
        const std::optional<ClearanceProof>& cp = clear->clearance_proof;
        answer["proof"]["clearance"] = cp ? Json{{"proved", cp->proved},
                                                 {"at_least", cp->proved ? Json(cp->lower) : Json(nullptr)},
                                                 {"steps", cp->steps},
                                                 {"subdivisions", cp->subdivisions}}
                                          : Json(nullptr);
    }
    // The end of the valid motion where it cuts the clearance run short, else on the design.
    answer["jam"] = jam_json(clear && clear->jam ? clear->jam : design_jam);
    return answer;
}

Json max_speed_answer(const MaxSpeed& m, double limit) {
    // A window cut short by the end of the valid motion has no largest speed: the dragon cannot
    // make the turn at any speed (the motion's validity does not depend on it), and the largest
    // speed over the part before the jam would answer another question.
    Json answer = {{"max_head_speed", m.jam ? Json(nullptr) : Json(m.max_head_speed)},
                   {"ratio", m.unbounded ? Json(nullptr) : Json(m.ratio)},
                   {"unbounded", m.unbounded},
                   {"handle", m.handle},
                   {"time", m.time},
                   {"travel", m.travel},
                   {"tied", m.tied},
                   {"head_arc", m.head_arc},
                   {"limit", limit}};
    add_window(answer, m.window);
    answer["jam"] = jam_json(m.jam);
    answer["scan_step"] = m.unbounded ? Json(nullptr) : Json(m.scan_step);
    answer["scan_travel"] = m.unbounded ? Json(nullptr) : Json(m.scan_travel);
    answer["candidates"] = m.candidates;
    answer["evaluations"] = m.evaluations;
    // What is proved: with the proof asked for, the largest head speed's enclosure (every head
    // speed up to its lower end keeps to the limit; any over its upper end does not) and how the
    // branch and bound went; without it, the maximum is the scan's and its refinement's.
    if (m.proof && !m.unbounded) {
        const MaxSpeedProof& p = *m.proof;
        answer["enclosure"] = p.proved && !m.jam ? Json::array({p.max_head_speed_lo, p.max_head_speed_hi}) : Json(nullptr);
        answer["proof"] = {{"method", p.method()},
                           {"ratio", {p.ratio_lo, p.proved ? Json(p.ratio_hi) : Json(nullptr)}},
                           {"tolerance", p.tolerance},
                           {"stretches", p.stretches},
                           {"subdivisions", p.subdivisions},
                           {"evaluations", p.evaluations},
                           {"unproved", p.unproved},
                           {"unproved_travel", p.unproved_travel},
                           {"narrowest", p.narrowest},
                           {"motion", motion_json(p.motion)}};
    } else {
        answer["enclosure"] = nullptr;
        answer["proof"] = {{"method", "sampled"}};
    }
    return answer;
}

namespace {

Json table_json(const ContestTable& t, const char* file) {
    Json j = {{"file", file},
              {"times", t.frames.empty() ? Json(nullptr) : Json::array({t.frames.front().time, t.frames.back().time})},
              {"rows", t.frames.size()},
              {"rows_left_out", t.rows_left_out}};
    add_window(j, t.window);
    j["jam"] = jam_json(t.jam);
    j["past_contact"] = t.past_contact ? contact_json(*t.past_contact) : Json(nullptr);
    return j;
}

}  // namespace

Json contest_summary(const ContestAnswers& a, const ContestOptions& options) {
    Json summary = Json::object();
    if (a.q1) summary["q1"] = table_json(*a.q1, "result1.xlsx");
    if (a.q2) {
        summary["q2"] = collide_answer(*a.q2, false);
        summary["q2"]["file"] = "result2.xlsx";
    }
    if (a.q3) {
        summary["q3"] = min_pitch_answer(*a.q3, a.scenario.path.turn_radius);
        summary["q3"]["range_moved"] = a.q3_range->moved.empty() ? Json(nullptr) : Json(a.q3_range->moved);
    }
    if (a.q4) {
        Json& q4 = summary["q4"] = table_json(*a.q4, "result4.xlsx");
        q4["r1"] = a.q4_design->r1;
        q4["r2"] = a.q4_design->r2;
        q4["length"] = a.q4_design->length;
        q4["followable"] = !a.q4_jam;
        q4["design_jam"] = jam_json(a.q4_jam);
        if (a.q4_proof) q4["proof"] = proof_json(*a.q4_proof);  // with `prove` only: the table's own keys otherwise
    }
    if (a.q5) summary["q5"] = max_speed_answer(*a.q5, options.speed_limit);
    return summary;
}

}  // namespace dragon
