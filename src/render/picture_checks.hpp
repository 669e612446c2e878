// What every picture writer checks before and after drawing: the size in pixels and Cairo's
// status.
#pragma once

#include <fmt/format.h>

#include <cairo.h>

#include "dragon/errors.hpp"

namespace dragon::render {

// 16K on a side is far beyond any screen and keeps an ARGB32 surface under 1 GiB.
inline constexpr int kMaxPictureSide = 16384;

inline void check_picture_size(int w, int h) {
    if (w < 16 || h < 16 || w > kMaxPictureSide || h > kMaxPictureSide)
        throw InputError(fmt::format("image size {} x {} px is not allowed: each side must be 16..{}", w, h,
                                     kMaxPictureSide));
}

inline void check_cairo(cairo_status_t st, const char* what) {
    if (st != CAIRO_STATUS_SUCCESS) throw SolverError(fmt::format("{}: {}", what, cairo_status_to_string(st)));
}

}  // namespace dragon::render
