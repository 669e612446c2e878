// The one median cut (render/median_cut.hpp) behind the gallery's palette PNGs and the GIF
// palettes: boxes that partition the colours, its two weightings and its two box orders, and
// the palette PNG it makes.
#include <cstdint>
#include <filesystem>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "render/median_cut.hpp"
#include "render/png8.hpp"

using namespace dragon;
using namespace dragon::render;

namespace {

std::uint32_t rgb(int r, int g, int b) { return static_cast<std::uint32_t>(r << 16 | g << 8 | b); }

// Each colour in exactly one box, each box a non-empty range: together they cover [0, n).
void expect_partition(const std::vector<ColourBox>& boxes, std::size_t n) {
    std::vector<int> seen(n, 0);
    for (const ColourBox& b : boxes) {
        EXPECT_LT(b.begin, b.end);
        ASSERT_LE(b.end, n);
        for (std::size_t i = b.begin; i < b.end; ++i) ++seen[i];
    }
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(seen[i], 1) << i;
}

// Our frames' shape: a large white field, a large orange band with a ramp of blends to the
// white, and a small red patch (0.2% of the pixels).
std::vector<ColourCount> frame_like() {
    std::vector<ColourCount> c = {{rgb(255, 255, 255), 12400}, {rgb(245, 184, 76), 4000}, {rgb(204, 41, 41), 40}};
    for (int k = 1; k <= 8; ++k)
        c.push_back({rgb(245 + 10 * k / 9, 184 + 71 * k / 9, 76 + 179 * k / 9), 200});
    return c;
}

TEST(MedianCut, BoxesPartitionTheColours) {
    for (CutWeight w : {CutWeight::pixels, CutWeight::sqrt_pixels})
        for (BoxOrder o : {BoxOrder::lower_in_place, BoxOrder::both_last})
            for (std::size_t max : {1u, 2u, 5u, 11u, 256u}) {
                std::vector<ColourCount> colours = frame_like();
                const std::vector<ColourBox> boxes = median_cut(colours, max, w, o);
                EXPECT_EQ(boxes.size(), std::min<std::size_t>(max, 11));
                expect_partition(boxes, colours.size());
                EXPECT_EQ(colours.size(), 11u);  // reordered, not lost
            }
}

TEST(MedianCut, NoColoursNoBoxesOneColourOneBox) {
    std::vector<ColourCount> none;
    EXPECT_TRUE(median_cut(none, 256, CutWeight::pixels, BoxOrder::lower_in_place).empty());
    std::vector<ColourCount> one = {{rgb(1, 2, 3), 7}};
    const auto boxes = median_cut(one, 256, CutWeight::sqrt_pixels, BoxOrder::both_last);
    ASSERT_EQ(boxes.size(), 1u);
    EXPECT_EQ(boxes[0].end - boxes[0].begin, 1u);
}

// Where a box splits: at its median by pixels, or by their square roots. On the red channel,
// 0 (4 px), 100, 200 and 255 (1 px each): half of 7 px is reached with the first colour, half of
// 2 + 1 + 1 + 1 with the second.
TEST(MedianCut, WeightsMoveTheMedian) {
    const auto lower_half = [](CutWeight w) {
        std::vector<ColourCount> colours = {{rgb(0, 0, 0), 4}, {rgb(100, 0, 0), 1}, {rgb(200, 0, 0), 1}, {rgb(255, 0, 0), 1}};
        const auto boxes = median_cut(colours, 2, w, BoxOrder::lower_in_place);
        EXPECT_EQ(boxes.size(), 2u);
        return boxes[0].end - boxes[0].begin;
    };
    EXPECT_EQ(lower_half(CutWeight::pixels), 1u);
    EXPECT_EQ(lower_half(CutWeight::sqrt_pixels), 2u);
}

// Split first: 0..100..200 at its median, {0, 100} | {200}; then {0, 100}. The lower half of
// the second split takes its box's place, or both halves go last.
TEST(MedianCut, BoxOrders) {
    const auto order = [](BoxOrder o) {
        std::vector<ColourCount> colours = {{rgb(200, 0, 0), 1}, {rgb(0, 0, 0), 1}, {rgb(100, 0, 0), 1}};
        std::vector<int> reds;
        for (const ColourBox& b : median_cut(colours, 3, CutWeight::pixels, o)) {
            EXPECT_EQ(b.end - b.begin, 1u);
            reds.push_back(static_cast<int>(colours[b.begin].rgb >> 16));
        }
        return reds;
    };
    EXPECT_EQ(order(BoxOrder::lower_in_place), (std::vector<int>{0, 200, 100}));
    EXPECT_EQ(order(BoxOrder::both_last), (std::vector<int>{200, 0, 100}));
}

// The palette PNG: a drawing's flat colours come back exactly, and no more colours than asked.
TEST(MedianCut, PalettePngKeepsFlatColoursAndItsSize) {
    const std::filesystem::path dir = std::filesystem::path(DRAGON_TEST_TMP) / "median_cut";
    std::filesystem::create_directories(dir);
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 64, 48));
    {
        cairo::Context cr(cairo_create(s.get()));
        cairo_set_source_rgb(cr.get(), 1, 1, 1);
        cairo_paint(cr.get());
        cairo_set_source_rgb(cr.get(), 0.8, 0.16, 0.16);
        cairo_arc(cr.get(), 20, 20, 12, 0, 6.3);  // anti-aliased: blends with the white
        cairo_fill(cr.get());
        cairo_set_source_rgb(cr.get(), 0.3, 0.45, 0.75);
        cairo_rectangle(cr.get(), 40, 10, 16, 30);
        cairo_fill(cr.get());
    }
    cairo_surface_flush(s.get());
    const auto colours_of = [](cairo_surface_t* img) {
        std::set<std::uint32_t> c;
        const int stride = cairo_image_surface_get_stride(img);
        const unsigned char* data = cairo_image_surface_get_data(img);
        for (int y = 0; y < cairo_image_surface_get_height(img); ++y)
            for (int x = 0; x < cairo_image_surface_get_width(img); ++x)
                c.insert(reinterpret_cast<const std::uint32_t*>(data + y * stride)[x] & 0xffffffu);
        return c;
    };
    const std::set<std::uint32_t> drawn = colours_of(s.get());
    const auto pixel = [&s](int x, int y) {
        const unsigned char* row = cairo_image_surface_get_data(s.get()) + y * cairo_image_surface_get_stride(s.get());
        return reinterpret_cast<const std::uint32_t*>(row)[x] & 0xffffffu;
    };
    const std::uint32_t flats[] = {pixel(0, 0), pixel(20, 20), pixel(48, 25)};  // white, red, blue
    ASSERT_GT(drawn.size(), 8u);
    for (int max : {256, 4}) {
        const std::string path = (dir / ("palette" + std::to_string(max) + ".png")).string();
        render::write_png8(s.get(), path, max);
        cairo::Surface back(cairo_image_surface_create_from_png(path.c_str()));
        ASSERT_EQ(cairo_surface_status(back.get()), CAIRO_STATUS_SUCCESS);
        const std::set<std::uint32_t> read = colours_of(back.get());
        EXPECT_LE(read.size(), static_cast<std::size_t>(max));
        for (std::uint32_t flat : flats)
            EXPECT_TRUE(read.count(flat)) << std::hex << flat << " at " << std::dec << max << " colours";
        if (max == 256) {
            EXPECT_EQ(read, drawn);  // fewer colours drawn than the palette holds
        }
    }
}

}  // namespace
