// The scenario's own answers the figures cite (its first contact, its minimum pitch) and the
// one place that decides what stretch of time a figure may show.
#pragma once

#include <optional>

#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"

namespace dragon::fig {

// A stretch of simulated time, s.
struct TimeSpan {
    double from = 0.0, to = 0.0;
};

// [from, to] cut to what a figure of `sim` may show: within the dragon's valid motion (no
// further than it can follow its path: the spiral's centre, or where a handle would jump) and,
// given the run's first contact, no further than that (the dragon stops there). Every time and time range a figure picks comes through here, so that one change
// reaches them all.
TimeSpan shown_span(const Simulation& sim, double from, double to, const std::optional<Contact>& contact);

// The pitches searched for the scenario's minimum: from the narrowest that can work (the
// board width, below which neighbouring rings overlap; and the head must start outside the
// turning space) to the first found collision-free doubling from twice that, at most 16 times
// it (hi is then the last tried, and nothing in the window is feasible).
struct PitchWindow {
    double lo = 0.0, hi = 0.0;
};
PitchWindow pitch_window(const Scenario& s);
// First-scan spacing of that search: a hundred steps over the window (2.5 to 3 mm for
// contest-sized boards, the spacing `dragon min-pitch` uses).
inline constexpr int kPitchScanSteps = 100;

// The coil-in's answers, each computed on first use and kept for every figure of one run.
class Answers {
public:
    explicit Answers(const Scenario& coil_in);
    // The first contact coiling in (first_contact_of_motion); nullopt when there is none.
    const std::optional<Contact>& contact();
    // The minimum pitch over pitch_window() (pitch NaN when nothing in it is collision-free).
    const MinPitch& min_pitch();

private:
    Scenario scenario_;
    std::optional<std::optional<Contact>> contact_;
    std::optional<MinPitch> min_pitch_;
};

}  // namespace dragon::fig
