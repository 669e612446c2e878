// Test pictures drawn with Cairo directly: flat colours and anti-aliased edges like the
// renderer's, moving with the frame index so every frame differs.
#pragma once

#include <cmath>

#include <cairo.h>

namespace dragon::test {

inline void paint_synthetic(int index, cairo_t* cr, int width, int height) {
    cairo_set_source_rgb(cr, 0.97, 0.96, 0.92);  // opaque background
    cairo_paint(cr);
    const double t = index / 10.0;
    // A ring of boards turning slowly.
    for (int k = 0; k < 12; ++k) {
        const double a = t + k * 2.0 * M_PI / 12.0;
        cairo_save(cr);
        cairo_translate(cr, width * (0.5 + 0.3 * std::cos(a)), height * (0.5 + 0.3 * std::sin(a)));
        cairo_rotate(cr, a);
        cairo_rectangle(cr, -width * 0.06, -height * 0.02, width * 0.12, height * 0.04);
        cairo_set_source_rgb(cr, 0.55 + 0.03 * k, 0.25, 0.12);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.15, 0.1, 0.05);
        cairo_set_line_width(cr, 1.0);
        cairo_stroke(cr);
        cairo_restore(cr);
    }
    // A red dot crossing the picture.
    cairo_arc(cr, width * (0.1 + 0.8 * std::fmod(t / 3.0, 1.0)), height * 0.5, height * 0.05, 0, 2 * M_PI);
    cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    cairo_fill(cr);
}

}  // namespace dragon::test
