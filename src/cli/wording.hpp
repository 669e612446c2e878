// What the CLI says in sentences about results the library gives as data: how the minimum-pitch
// search guarantees what it reports, and the answer to Q4's question.
#pragma once

#include <string>

#include "dragon/analyses.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

// "1 frame", "2 frames", "0 frames": a count and its noun, singular for one; `many` for a
// plural that is not the noun plus "s" ("local maxima").
std::string count_of(long long n, const std::string& one, const std::string& many = "");

// One sentence: the grid, how each change is narrowed, and what a window narrower than the grid means.
std::string min_pitch_guarantee(const MinPitch& m);

// One paragraph: can the turning curve be shorter, and which of the studied turns this dragon
// can follow at all.
std::string turnaround_conclusion(const TurnaroundStudy& st);

}  // namespace dragon::cli
