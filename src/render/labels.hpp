// Placing and drawing labels: each goes where it is clearest of everything else, near its point.
#pragma once

#include <functional>
#include <vector>

#include <cairo.h>

#include "dragon/render.hpp"
#include "clip.hpp"
#include "furniture.hpp"

namespace dragon::render {

// The scene's labels, after everything else is drawn: `px` maps the world to the picture,
// `taken` are the boxes (pixels) the screen furniture covers, `world` the part of the picture
// the drawing has (below a title band).
void draw_labels(cairo_t* cr, const Scene& s, const Units& un, const std::function<Vec2(Vec2)>& px,
                 const std::vector<Box>& taken, const Box& world);

}  // namespace dragon::render
