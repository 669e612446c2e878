// The part of a path between two places, piece by piece: what the proofs read of the arcs a
// handle or a link sweeps over a step (motion_proof.cpp, handle_accel.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "dragon/path.hpp"

namespace dragon {

// The parameter range of `piece` between places a (behind) and b.
inline std::pair<double, double> part_of(const Path& path, int piece, const Place& a, const Place& b) {
    const auto [begin, end] = path.piece_span(piece);
    return {piece == a.piece ? a.u : begin, piece == b.piece ? b.u : end};
}

// The least and largest signed curvature between places a (behind) and b (1/m; {inf, -inf} when
// b is behind a): on each piece it is monotone and of one sign (constant on an arc, monotone in
// theta on a spiral: docs/methods.md 10.1), so both are among its values at the ends of each
// piece's part.
inline std::pair<double, double> curvature_range(const Path& path, const Place& a, const Place& b) {
    double lo = INFINITY, hi = -INFINITY;
    for (int piece = a.piece; piece <= b.piece; ++piece) {
        const auto [u0, u1] = part_of(path, piece, a, b);
        for (const double u : {u0, u1}) {
            const double k = path.curvature({piece, u});
            lo = std::min(lo, k);
            hi = std::max(hi, k);
        }
    }
    return {lo, hi};
}

}  // namespace dragon
