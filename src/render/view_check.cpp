// Which views a picture can mean (see kMinViewExtent in render.hpp), and the sentence that
// refuses the others.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dragon/render.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

namespace {
double radius(const Vec2& c) { return std::hypot(c.x(), c.y()); }
}  // namespace

ViewError check_view(const Vec2& centre, double view_width, double view_height, int width_px, int height_px) {
    if (!std::isfinite(centre.x()) || !std::isfinite(centre.y()) || !std::isfinite(view_width) ||
        !std::isfinite(view_height))
        return ViewError::not_finite;
    const double extent = std::max(view_width, view_height);
    if (!(std::min(view_width, view_height) > 0) || extent < kMinViewExtent) return ViewError::too_narrow;
    if (extent > kMaxViewExtent) return ViewError::too_wide;
    if (std::max(std::abs(centre.x()), std::abs(centre.y())) > kMaxViewCentre) return ViewError::too_far;
    // draw() fits the view inside the picture: the pixel is the larger of the two ratios.
    const double pixel = std::max(view_width / std::max(width_px, 1), view_height / std::max(height_px, 1));
    if (pixel < kMinPixelOverRadius * radius(centre)) return ViewError::too_fine;
    return ViewError::none;
}

double narrowest_view(const Vec2& centre, int width_px, int height_px) {
    return std::max(kMinViewExtent, kMinPixelOverRadius * radius(centre) * std::min(width_px, height_px));
}

void require_drawable(const Scene& s, int w, int h) {
    const Vec2 c = s.view_centre;
    const std::string view = fmt::format("a view {:g} x {:g} m about ({:g}, {:g})", s.view_width, s.view_height, c.x(), c.y());
    switch (check_view(c, s.view_width, s.view_height, w, h)) {
    case ViewError::none: return;
    case ViewError::not_finite:
        throw InputError(fmt::format("{} is not allowed: its centre and size must be finite numbers", view));
    case ViewError::too_narrow:
    case ViewError::too_wide:
        throw InputError(fmt::format("{} is not allowed: a view must be {:g}..{:g} m across", view, kMinViewExtent,
                                     kMaxViewExtent));
    case ViewError::too_far:
        throw InputError(fmt::format("{} is not allowed: its centre must lie within {:g} m of the origin on each axis",
                                     view, kMaxViewCentre));
    case ViewError::too_fine:
        throw InputError(fmt::format("{} is not allowed at {} x {} px: its pixels would be finer than doubles "
                                     "resolve {:g} m from the origin; make it at least {:.3g} m across",
                                     view, w, h, radius(c), narrowest_view(c, w, h)));
    }
}

}  // namespace dragon
