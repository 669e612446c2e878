// Text in any script: characters the theme's font lacks are set in a fallback font with real
// glyphs (not the empty box of a missing glyph), and Chinese lines wrap between characters.
#include <gtest/gtest.h>

#include <string>

#include "render/cairo_handles.hpp"
#include "render/paint.hpp"

namespace dragon::render {
namespace {

struct Canvas {
    cairo::Surface surface{cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 400, 100)};
    cairo::Context cr = cairo::make_context(surface.get());
};

// The ink a text leaves on a white canvas: the count of pixels darker than mid-grey.
int ink(const std::string& s) {
    Canvas c;
    cairo_set_source_rgb(c.cr.get(), 1, 1, 1);
    cairo_paint(c.cr.get());
    cairo_set_source_rgb(c.cr.get(), 0, 0, 0);
    text(c.cr.get(), "DejaVu Sans", 40, 10, 60, s);
    cairo_surface_flush(c.surface.get());
    const unsigned char* px = cairo_image_surface_get_data(c.surface.get());
    const int stride = cairo_image_surface_get_stride(c.surface.get());
    int n = 0;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 400; ++x)
            if (px[y * stride + 4 * x + 1] < 128) ++n;
    return n;
}

TEST(Text, ChineseIsSetInAFontThatHasItsGlyphs) {
    Canvas c;
    // An ideograph is a full em wide in every CJK font; DejaVu's missing-glyph box is narrower.
    const double w = text_width(c.cr.get(), "DejaVu Sans", 40, "\u9f99\u5934");  // 龙头
    EXPECT_NEAR(w, 80.0, 1.0);
    // Real glyphs differ from each other; missing ones would all be the same box.
    EXPECT_NE(ink("\u9f99"), ink("\u5934"));  // 龙, 头
    EXPECT_GT(ink("\u9f99\u5934"), 200);
    // Latin stays in the theme's font beside it: the same width alone or next to Chinese.
    EXPECT_NEAR(text_width(c.cr.get(), "DejaVu Sans", 40, "pitch \u87ba\u8ddd"),
                text_width(c.cr.get(), "DejaVu Sans", 40, "pitch ") + 80.0, 1.0);
}

TEST(Text, ChineseWrapsBetweenCharactersAndNotBeforeClosingPunctuation) {
    Canvas c;
    // 十二个字，没有空格 (twelve characters, no spaces), at 20 px in 130 px: six a line at most.
    const std::string s = "\u677f\u51f3\u9f99\u7684\u9f99\u5934\u3001\u9f99\u8eab\u548c\u9f99\u5c3e";
    const FittedText t = fit_text(c.cr.get(), "DejaVu Sans", 20, s, 130, false, 3);
    ASSERT_GE(t.lines.size(), 2u);
    std::string joined;
    for (const auto& l : t.lines) {
        EXPECT_LE(text_width(c.cr.get(), "DejaVu Sans", t.size, l), 130.0);
        EXPECT_FALSE(l.starts_with("\u3001")) << l;  // 、 never opens a line
        joined += l;
    }
    EXPECT_EQ(joined, s);  // nothing lost, no space added
}

TEST(Text, BrokenUtf8NeitherStallsNorThrows) {
    Canvas c;
    const std::string broken = "ab\xe9\xbe" "c\xff";
    EXPECT_GT(text_width(c.cr.get(), "DejaVu Sans", 20, broken), 0.0);
    text(c.cr.get(), "DejaVu Sans", 20, 0, 50, broken);
    EXPECT_EQ(cairo_status(c.cr.get()), CAIRO_STATUS_SUCCESS);
}

}  // namespace
}  // namespace dragon::render
