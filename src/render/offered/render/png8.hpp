// Palette PNGs for the gallery: a drawing holds a few flat colours and their anti-aliased
// blends, so 256 colours chosen by median cut look the same and take a third of the bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/atomic_file.hpp"

namespace dragon::render {

// Writes an image surface (RGB24 or opaque ARGB32) as an 8-bit palette PNG, all-or-nothing.
// At most `max_colours` (2..256) palette entries.
// `dpi` > 0: the resolution stated in the file (its pHYs chunk), for a picture at a print size.
// `keep` (0xRRGGBB): colours kept exactly, each an entry of its own, where the picture holds
// them (the theme's role colours: role_colours).
void write_png8(cairo_surface_t* surface, const std::string& path, int max_colours = 256, double dpi = 0,
                const std::vector<std::uint32_t>& keep = {}, RunOutputs* outputs = nullptr);

// An image surface (RGB24 or opaque ARGB32) as a 24-bit PNG's bytes, stating `dpi` (> 0) as
// its resolution. Throws SolverError if libpng fails.
std::string png_bytes(cairo_surface_t* surface, double dpi);
// The same PNG into `out`'s temporary file. The caller commits `out`.
void write_png(cairo_surface_t* surface, AtomicFile& out, double dpi);

}  // namespace dragon::render
