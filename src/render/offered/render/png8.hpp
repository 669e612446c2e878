// Palette PNGs for the gallery: a drawing holds a few flat colours and their anti-aliased
// blends, so 256 colours chosen by median cut look the same and take a third of the bytes.
#pragma once

#include <string>

#include <cairo.h>

namespace dragon::render {

// Writes an image surface (RGB24 or opaque ARGB32) as an 8-bit palette PNG, all-or-nothing.
// At most `max_colours` (2..256) palette entries.
void write_png8(cairo_surface_t* surface, const std::string& path, int max_colours = 256);

}  // namespace dragon::render
