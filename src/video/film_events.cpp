// The moments a film says in words, and how a frame carries them (clock, rate, captions).
#include <cmath>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/video.hpp"

namespace dragon {

std::string contact_caption(const CollisionMark& mark, double time) {
    return fmt::format("first contact: bench {} touches bench {}, t = {:.6f} s", mark.bench_a, mark.bench_b, time);
}

std::vector<FilmEvent> clip_events(const Simulation& sim, double from, double to,
                                   const std::optional<CollisionMark>& contact) {
    std::vector<FilmEvent> out;
    const Scenario& s = sim.scenario();
    if (s.path.kind == PathKind::spiral) {
        const double t = boundary_time(sim);
        if (t > from && t <= to)
            out.push_back({t, fmt::format("head reaches the turning space (r = {:g} m), t = {:.6f} s",
                                          s.path.turn_radius, t)});
    }
    if (contact) {
        out.push_back({to, contact_caption(*contact, to)});
    } else if (const std::optional<Contact> c = first_contact_covering(sim, from, to).contact; c && c->time <= to) {
        // The range passes the first contact: from there on the benches overlap.
        const CollisionMark mark{c->bench_a, c->bench_b, c->point};
        if (c->time > from) out.push_back({c->time, contact_caption(mark, c->time)});
        else
            out.push_back({from, fmt::format("past the first contact (bench {} touches bench {} at t = {:.6f} s): "
                                             "benches overlap", c->bench_a, c->bench_b, c->time)});
    }
    const ValidRange valid = sim.valid_range();
    if (valid.after && to == valid.to)
        out.push_back({to, fmt::format("end of the valid motion, t = {:.6f} s: {}", to, describe(*valid.after))});
    return out;
}

}  // namespace dragon
