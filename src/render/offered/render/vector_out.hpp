// Pictures written as files: the same painting onto a PNG, SVG or PDF surface.
#pragma once

#include <functional>
#include <string>

#include <cairo.h>

#include "dragon/picture_bytes.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/picture_size.hpp"

namespace dragon::render {

using PictureFormat = PictureType;
// By the path's extension (.png, .svg, .pdf); InputError for any other.
PictureFormat picture_format(const std::string& path);

// A picture of w x h px painted by `paint` onto a vector surface, all-or-nothing (AtomicFile).
// SVG sizes are in px, as asked; a PDF page is in points at 96 px per inch (CSS pixels: a
// 1600 px picture is 1200 pt, 16.7 in, wide), its fonts embedded as subsets and its text real
// text, selectable and searchable. With a page size (a print size's), the PDF page and the SVG
// are exactly that many points, the w x h px drawing scaled onto them.
void write_vector(const std::string& path, PictureFormat format, int w, int h,
                  const std::function<void(cairo_t*)>& paint, const Page& page = {}, RunOutputs* outputs = nullptr);
// The same picture's bytes (what write_vector writes). Throws SolverError if Cairo fails.
std::string vector_bytes(PictureFormat format, int w, int h, const std::function<void(cairo_t*)>& paint,
                         const Page& page = {});

}  // namespace dragon::render
