#include "figure_answers.hpp"

#include <algorithm>
#include <cmath>

namespace dragon::fig {

TimeSpan shown_span(const Simulation& sim, double from, double to, const std::optional<Contact>& contact) {
    // Never past the end of the valid motion (a handle would jump there), nor the path's end.
    const ValidRange valid = sim.valid_range();
    from = std::max(from, valid.from);
    to = std::min(to, valid.to);
    if (contact && contact->time >= from) to = std::min(to, contact->time);
    return {from, std::max(from, to)};
}

PitchWindow pitch_window(const Scenario& s) {
    // Just above each limit: min_pitch needs lo > width, and a head starting on the turning
    // space's boundary has no run to check.
    const double start_limit = s.path.turn_radius / s.path.start_turn;
    const double lo = std::max(s.bench.width, start_limit) * (1.0 + 1e-6);
    double hi = 2.0 * lo;
    for (int doubling = 0; doubling < 3 && contact_before_boundary(s, hi); ++doubling) hi *= 2.0;
    return {lo, hi};
}

Answers::Answers(const Scenario& coil_in) : scenario_(coil_in) { scenario_.path.kind = PathKind::spiral; }

const std::optional<Contact>& Answers::contact() {
    if (!contact_) {
        // The motion's first contact, as every command reports it.
        contact_ = first_contact_of_motion(Simulation(scenario_)).contact;
    }
    return *contact_;
}

const MinPitch& Answers::min_pitch() {
    if (!min_pitch_) {
        const PitchWindow w = pitch_window(scenario_);
        MinPitchOptions options;
        options.grid = (w.hi - w.lo) / kPitchScanSteps;
        min_pitch_ = dragon::min_pitch(scenario_, w.lo, w.hi, options);
    }
    return *min_pitch_;
}

}  // namespace dragon::fig
