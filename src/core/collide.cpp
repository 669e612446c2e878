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
    if (out.contact && out.contact->travel <= cut.from) out.overlapping = clearance(out.contact->frame).distance < 0.0;
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
    CollideAnswer out = search(sim, window, options);
    if (out.overlapping) {
        const Clearance now = clearance(out.contact->frame);
        throw OverlapAtStart(given_start(window), now.bench_a, now.bench_b, -now.distance);
    }
    return out;
}

CollideAnswer first_contact_of_motion(const Simulation& sim, Executor* executor) {
    return collide(sim, default_window(sim.scenario().path.kind), executor);
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
