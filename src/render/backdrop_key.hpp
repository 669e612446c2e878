// draw()'s side of the backdrop cache (render/backdrop.hpp): the key of a scene's backdrop on a
// target the cache can serve, and the copies in and out of the target's pixels.
#pragma once

#include <optional>

#include <cairo.h>

#include "render/backdrop.hpp"
#include "view.hpp"

namespace dragon::render {

// The backdrop's key when `cr` draws straight onto a whole image surface of width x height
// pixels (identity transform, no clip, no device offset, ARGB32 or RGB24) small enough to keep;
// nullopt otherwise. `top` and `right` are the bands draw() keeps the world out of, px.
std::optional<BackdropKey> backdrop_key(cairo_t* cr, const Scene& s, const View& v, double u, double top,
                                        double right, int width, int height);

// Copies the cached backdrop into the target; false if the cache has none for this key.
bool copy_backdrop(cairo_t* cr, BackdropCache& cache, const BackdropKey& key);

// Keeps the target's pixels as the backdrop of `key` if the cache finds it worth keeping (call
// once the backdrop is drawn).
void keep_backdrop(cairo_t* cr, BackdropCache& cache, BackdropKey key);

}  // namespace dragon::render
