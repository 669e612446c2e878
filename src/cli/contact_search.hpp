// The first contact after a moment, as collide, render --collision and video --to collision ask
// for it. A chain that already overlaps where the search starts has no first contact after that
// moment: the search would report the start itself, which is not a first contact.
#pragma once

#include <optional>

#include "dragon/analyses.hpp"

namespace dragon::cli {

// Benches that already overlap where a search for the first contact starts: the chain collides
// (before that moment), so there is no first contact after it to report. An InputError for the
// commands (the range asked for holds no first contact); a verdict for a sweep's row and map.
class OverlapAtStart : public InputError {
public:
    OverlapAtStart(int bench_a, int bench_b, double time, double depth);
    int bench_a, bench_b;
    double time, depth;  // s; m, how deep they overlap
};

// first_contact(sim, from, to, options), but throws OverlapAtStart (one line: which benches, by
// how much) when two benches already overlap at `from`.
std::optional<Contact> first_contact_after(const Simulation& sim, double from, double to,
                                           const ContactSearchOptions& options = {});

}  // namespace dragon::cli
