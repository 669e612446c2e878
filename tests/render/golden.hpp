// Golden-image comparison: an image surface against a reference PNG in tests/golden/, with a
// tolerance on both the largest channel difference and the number of differing pixels, so
// anti-aliasing differences between machines pass but a moved bench does not.
// DRAGON_REBASELINE=1 writes the actual image as the new reference instead of comparing.
#pragma once

#include <string>

#include <cairo.h>

namespace dragon::test {

struct GoldenTolerance {
    int channel = 4;           // a pixel differs if any channel differs by more than this (0..255)
    double max_fraction = 0.01;  // at most this fraction of the pixels may differ
    int max_difference = 128;    // and no channel anywhere by more than this
};

struct GoldenResult {
    bool ok = false;
    bool rebaselined = false;
    std::string message;  // what differed, and where the actual and diff images were written
};

// Compares `actual` (ARGB32) with tests/golden/<name>. On a mismatch writes <name> and
// <name>-diff.png into DRAGON_TEST_TMP/golden/.
GoldenResult compare_golden(cairo_surface_t* actual, const std::string& name,
                            const GoldenTolerance& tol = {});

// Text drawn from the glyphs' outlines alone, for pictures compared with a golden image: hinting
// snaps glyphs to the pixel grid by rules a font library may change between versions.
void outline_fonts(cairo_t* cr);

}  // namespace dragon::test
