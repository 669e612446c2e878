// Q2 as a question: the first contact over a window of the motion, cut to the valid motion.
#include <fmt/format.h>

#include "dragon/analyses.hpp"

namespace dragon {

std::string overlap_sentence(const Overlap& o, const Along& start) {
    const std::string at = start.unit == Along::Unit::metres ? fmt::format("{} m of head travel", error_value(start.value))
                                                             : fmt::format("t = {} s", error_value(start.value));
    return fmt::format("benches {} and {} already overlap at {}, where the search starts (by {:.6f} m): their first "
                       "contact is before it", o.bench_a, o.bench_b, at, o.depth);
}

namespace {

// The search itself: a contact at the window's start with the benches overlapping is reported
// with `overlapping` set.
CollideAnswer search(const Simulation& sim, const RunWindow& window, ContactSearchOptions options) {
    const WindowCut cut = cut_window(sim, window);
    CollideAnswer out;
    out.asked = window;
    out.window = cut.searched(sim.scenario().head_speed);
    options.proof = &out.proof;
    out.contact = first_contact_travel(sim, cut.from, cut.to, options);
    // Touching exactly where the search starts is a contact there; overlapping is not a first
    // contact: the benches met before the window.
    if (out.contact && out.contact->travel <= cut.from) {
        const Clearance now = clearance(out.contact->frame);
        out.overlapping = now.distance < 0.0;
        if (out.overlapping) out.overlap = Overlap{now.bench_a, now.bench_b, -now.distance, now.point};
    }
    // The end of the valid motion matters only where nothing touched before it.
    if (!out.contact) out.jam = cut.after;
    return out;
}

}  // namespace

CollideAnswer collide(const Simulation& sim, const RunWindow& window, Executor* executor) {
    ContactSearchOptions options;
    options.executor = executor;
    return collide(sim, window, options);
}

CollideAnswer collide(const Simulation& sim, const RunWindow& window, const ContactSearchOptions& options) {
    return search(sim, window, options);
}

CollideAnswer first_contact_of_motion(const Simulation& sim, Executor* executor) {
    return collide(sim, default_window(sim.scenario().path.kind), executor);
}

CollideAnswer first_contact_of_motion(const Simulation& sim, const ContactSearchOptions& options) {
    return collide(sim, default_window(sim.scenario().path.kind), options);
}

CollideAnswer first_contact_covering(const Simulation& sim, double t_from, double t_to, Executor* executor) {
    RunWindow w = default_window(sim.scenario().path.kind);
    const double v = sim.scenario().head_speed;
    if (t_from < w.from.time(v)) w.from = Along::seconds(t_from);
    if (t_to > w.to.time(v)) w.to = Along::seconds(t_to);
    ContactSearchOptions options;
    options.executor = executor;
    return search(sim, w, options);
}

}  // namespace dragon
