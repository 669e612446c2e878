// Counted nouns in the CLI's sentences (the library's own sentences: dragon/answers.hpp).
#pragma once

#include <string>

#include "dragon/analyses.hpp"
#include "dragon/answers.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

// "1 frame", "2 frames", "0 frames": a count and its noun, singular for one; `many` for a
// plural that is not the noun plus "s" ("local maxima").
std::string count_of(long long n, const std::string& one, const std::string& many = "");

// x rounded to `decimals` decimals up (not below x) or down (not above it): a proved bound
// printed so that it stays proved.
double rounded_to(double x, int decimals, bool up);

// An interval [lo, hi] as "[lo, hi]" with `decimals` decimals, rounded so that what it says
// stays proved: outwards (lo down, hi up) for an enclosure of an unknown value, or for what a
// proof left open; inwards for a range all of whose values a proof established, so that the
// printed range claims none it did not (one too narrow for the decimals: all 17 digits).
enum class Rounding { outward, inward };
std::string proved_interval(double lo, double hi, int decimals, Rounding r = Rounding::outward);

// What a first-contact search proved, in words: one line (`c`: its contact, or null).
std::string proof_words(const ContactProof& p, const Contact* c);

// What the minimum-pitch search proved, in words: a line, two with the least feasible pitch enclosed.
std::string pitch_proof_words(const MinPitch& m);

// What the largest-head-speed search proved, in words: one line.
std::string speed_proof_words(const MaxSpeed& m);

}  // namespace dragon::cli
