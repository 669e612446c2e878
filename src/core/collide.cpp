// Q2 as a question: the first contact over a window of the motion, cut to the valid motion.
#include <fmt/format.h>

#include "dragon/analyses.hpp"

namespace dragon {

namespace {

std::string given_start(const RunWindow& w) {
    return w.from.unit == Along::Unit::seconds ? error_value(w.from.value) : fmt::format("{} m", error_value(w.from.value));
}

}  // namespace

OverlapAtStart::OverlapAtStart(const std::string& start, int a, int b, double overlap)
    : InputError("time range start", start,
                 fmt::format("benches {} and {} already overlap there (by {:.6f} m): their first contact is before it",
                             a, b, overlap)),
      bench_a(a), bench_b(b), depth(overlap) {}

CollideAnswer collide(const Simulation& sim, const RunWindow& window, Executor* executor) {
    const WindowCut cut = cut_window(sim, window);
    CollideAnswer out;
    out.asked = window;
    out.window = cut.searched(sim.scenario().head_speed);
    ContactSearchOptions options;
    options.executor = executor;
    out.contact = first_contact_travel(sim, cut.from, cut.to, options);
    if (out.contact && out.contact->travel <= cut.from) {
        // Touching exactly where the search starts is a contact there; overlapping is not a
        // first contact: the benches met before the window.
        const Clearance now = clearance(out.contact->frame);
        if (now.distance < 0.0) throw OverlapAtStart(given_start(window), now.bench_a, now.bench_b, -now.distance);
    }
    // The end of the valid motion matters only where nothing touched before it.
    if (!out.contact) out.jam = cut.after;
    return out;
}

CollideAnswer first_contact_of_motion(const Simulation& sim, Executor* executor) {
    return collide(sim, default_window(sim.scenario().path.kind), executor);
}

}  // namespace dragon
