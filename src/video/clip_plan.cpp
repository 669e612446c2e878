// A clip asked in words made exact (dragon/clip_plan.hpp).
#include "dragon/clip_plan.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/decimals.hpp"
#include "dragon/path.hpp"
#include "dragon/window.hpp"

namespace dragon {

namespace {

struct End {
    double time;
    std::optional<CollisionMark> mark;
};

Along moment(Key name, const std::string& text) {
    if (const std::optional<Along> a = parse_along(text)) return *a;
    throw InputError(name, text.empty() ? "''" : text,
                     "give a time in seconds (12.5, or 12.5s) or a length of the head's travel in metres (-100m)");
}

End resolve_end(const std::string& to, const Simulation& sim, double from, const ClipWords& words) {
    const bool turn = sim.scenario().path.kind == PathKind::turnaround;
    const std::string what = to.empty() ? (turn ? "100m" : "collision") : to;
    if (what == "collision") {
        sim.require_valid(from, Key::from);
        const CollideAnswer a = first_contact_of_motion(sim);
        if (!a.contact)
            throw InputError(Key::to, "collision",
                             fmt::format("no two benches touch between t = {} s and {} s{}", format_time(a.window.from),
                                         format_time(a.window.to), a.jam ? " (" + jam_sentence(*a.jam) + ")" : ""));
        const Contact& c = *a.contact;
        // The chain collided before it moved: no stretch of motion ends at a first contact.
        if (a.overlap)
            throw InputError(Key::to, "collision",
                             "the chain collides before it moves: " + overlap_sentence(*a.overlap, a.asked.from));
        if (!(c.time > from))
            throw InputError(Key::to, "collision",
                             fmt::format("not with {} {}: the first contact, bench {} touching bench {}, is at t = {} s, "
                                         "before it", words.from, from, c.bench_a, c.bench_b,
                                         format_resolved(c.time, c.tolerance)));
        return {c.time, CollisionMark{c.bench_a, c.bench_b, c.point}};
    }
    if (what == "boundary") {
        const double t = boundary_time(sim);
        if (t <= from) {
            const double r = norm(sim.path().at_arc(sim.head_arc(from)).pos);
            throw InputError(Key::to, "boundary",
                             fmt::format("the head is already inside the turning space at {} {} s (radius {:.6f} m, "
                                         "turning space {} m) and never reaches its boundary after that", words.from,
                                         from, r, sim.scenario().path.turn_radius));
        }
        return {t, std::nullopt};
    }
    if (what == "end") {
        const double end = sim.valid_end();
        if (!std::isfinite(end))
            throw InputError(Key::to, "end", "the dragon follows this path for ever here; give a time");
        return {end, std::nullopt};
    }
    const std::optional<Along> a = parse_along(what);
    if (!a)
        throw InputError(Key::to, to,
                         "give a time in seconds (12.5), head travel in metres (100m), collision, boundary or end");
    require_valid_at(sim, *a, Key::to);
    return {a->time(sim.scenario().head_speed), std::nullopt};
}

}  // namespace

ClipPlan plan_clip(const Simulation& sim, const ClipRequest& request, const ClipWords& words) {
    const Scenario& s = sim.scenario();
    const bool turn = s.path.kind == PathKind::turnaround;
    const Along start = request.from ? moment(Key::from, *request.from) : Along::metres(turn ? -100.0 : 0.0);
    require_valid_at(sim, start, Key::from);
    const double from = start.time(s.head_speed);
    const End end = resolve_end(request.to, sim, from, words);
    if (std::isfinite(from) && std::isfinite(end.time) && !(end.time > from))
        throw InputError(fmt::format("time range {} {} {} {} is empty: {} must be after {}", words.from, from, words.to,
                                     end.time, words.to, words.from));
    ClipPlan plan;
    plan.clip = Clip{from, end.time, request.speedup, request.hold.value_or(end.mark ? 1.0 : 0.0)};
    plan.end_mark = end.mark;
    plan.events = clip_events(sim, plan.clip.from, plan.clip.to, end.mark, request.language);
    return plan;
}

}  // namespace dragon
