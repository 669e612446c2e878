// Pictures in memory, for a program that shows or sends them rather than writing files (the
// Python package's pictures, a notebook's inline figures): the same draw() as the files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dragon/picture_size.hpp"
#include "dragon/render.hpp"

namespace dragon {

// The file formats a picture's bytes come in.
enum class PictureType { png, svg, pdf };
// "png", "svg" or "pdf"; InputError (field "format") for anything else.
PictureType picture_type(const std::string& name);

// The scene as a whole PNG, SVG or PDF file's bytes: what render_png / render_svg / render_pdf
// write (they write these). With a page (a print size's: print_layout), the SVG and PDF are that
// many points and the PNG states its dpi. Throws InputError for a bad size or a view
// require_drawable refuses, SolverError if Cairo or libpng fails.
std::string render_bytes(const Scene& scene, int width_px, int height_px, PictureType type, const Page& page = {});

// The scene's pixels: height_px rows of width_px RGBA quadruples (8 bits each, top row first;
// the pictures are opaque, alpha 255). Throws as render_bytes does.
std::vector<std::uint8_t> render_rgba(const Scene& scene, int width_px, int height_px);

}  // namespace dragon
