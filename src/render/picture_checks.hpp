// What every picture writer checks before and after drawing: the size in pixels and Cairo's
// status.
#pragma once

#include <fmt/format.h>

#include <cairo.h>

#include "dragon/errors.hpp"
#include "dragon/picture_size.hpp"

namespace dragon::render {

// The sides dragon/picture_size.hpp allows (an ARGB32 surface stays under 1 GiB).
inline void check_picture_size(int w, int h) {
    if (w < kMinPictureSide || h < kMinPictureSide || w > kMaxPictureSide || h > kMaxPictureSide)
        throw InputError(fmt::format("image size {} x {} px is not allowed: each side must be {}..{}", w, h,
                                     kMinPictureSide, kMaxPictureSide));
}

inline void check_cairo(cairo_status_t st, const char* what) {
    if (st != CAIRO_STATUS_SUCCESS) throw SolverError(fmt::format("{}: {}", what, cairo_status_to_string(st)));
}

}  // namespace dragon::render
