// The first contact after a moment, as collide, render --collision and video --to collision ask
// for it. A chain that already overlaps where the search starts has no first contact after that
// moment: the search would report the start itself, which is not a first contact.
#pragma once

#include <optional>

#include "dragon/analyses.hpp"

namespace dragon::cli {

// first_contact(sim, from, to, options), but throws InputError (one line: which benches, by how
// much) when two benches already overlap at `from`.
std::optional<Contact> first_contact_after(const Simulation& sim, double from, double to,
                                           const ContactSearchOptions& options = {});

}  // namespace dragon::cli
