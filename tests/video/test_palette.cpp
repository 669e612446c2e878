// The GIF palette: flat colours come back exactly, a small distinct patch keeps its own entry,
// and colours the samples never showed map to their nearest entry.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "video/palette.hpp"

namespace {

using dragon::video::Palette;
using dragon::video::PaletteBuilder;

struct Picture {
    int w, h;
    std::vector<std::uint32_t> px;
    const std::uint8_t* bytes() const { return reinterpret_cast<const std::uint8_t*>(px.data()); }
};

// A large white field, a large orange band with a soft (anti-aliased-like) edge, and a small
// red patch: the shape of our frames.
Picture sample() {
    Picture p{200, 100, std::vector<std::uint32_t>(200 * 100, 0xffffffffu)};
    for (int y = 40; y < 60; ++y)
        for (int x = 0; x < 200; ++x) p.px[static_cast<size_t>(y) * 200 + x] = 0xfff5b84cu;
    for (int x = 0; x < 200; ++x)
        for (int k = 0; k < 8; ++k) {  // a ramp from orange to white above the band
            const std::uint32_t g = 0xb8u + (0xffu - 0xb8u) * static_cast<std::uint32_t>(k + 1) / 9;
            const std::uint32_t b = 0x4cu + (0xffu - 0x4cu) * static_cast<std::uint32_t>(k + 1) / 9;
            const std::uint32_t r = 0xf5u + (0xffu - 0xf5u) * static_cast<std::uint32_t>(k + 1) / 9;
            p.px[static_cast<size_t>(39 - k) * 200 + x] = 0xff000000u | (r << 16) | (g << 8) | b;
        }
    for (int y = 80; y < 84; ++y)
        for (int x = 10; x < 20; ++x) p.px[static_cast<size_t>(y) * 200 + x] = 0xffcc2929u;  // 40 px of red
    return p;
}

std::uint32_t mapped(const Palette& pal, std::uint32_t argb) { return pal.colours[pal.index_of(argb)]; }

int distance(std::uint32_t a, std::uint32_t b) {
    int d = 0;
    for (int shift : {0, 8, 16}) d += std::abs(static_cast<int>((a >> shift) & 0xffu) - static_cast<int>((b >> shift) & 0xffu));
    return d;
}

TEST(Palette, FlatColoursComeBackExactly) {
    const Picture p = sample();
    PaletteBuilder builder;
    builder.add(p.bytes(), p.w, p.h, p.w * 4);
    const Palette pal = builder.build(256);
    EXPECT_EQ(mapped(pal, 0xffffffffu), 0xffffffffu);
    EXPECT_EQ(mapped(pal, 0xfff5b84cu), 0xfff5b84cu);
    EXPECT_EQ(mapped(pal, 0xffcc2929u), 0xffcc2929u);
}

TEST(Palette, SmallDistinctPatchKeepsItsColourInAFewEntries) {
    const Picture p = sample();
    PaletteBuilder builder;
    builder.add(p.bytes(), p.w, p.h, p.w * 4);
    // 11 colours in: white, orange, red (0.2% of the pixels) and a ramp of 8 between orange
    // and white; 8 entries out.
    const Palette pal = builder.build(8);
    EXPECT_LE(pal.size, 8);
    EXPECT_LE(distance(mapped(pal, 0xffcc2929u), 0xffcc2929u), 12);
    EXPECT_LE(distance(mapped(pal, 0xfff5b84cu), 0xfff5b84cu), 12);
}

TEST(Palette, UnseenColoursMapToTheNearestEntry) {
    const Picture p = sample();
    PaletteBuilder builder;
    builder.add(p.bytes(), p.w, p.h, p.w * 4);
    const Palette pal = builder.build(256);
    EXPECT_EQ(mapped(pal, 0xffd03030u), 0xffcc2929u);  // a red the samples lacked
    EXPECT_EQ(mapped(pal, 0xfffafafau), 0xffffffffu);
}

TEST(Palette, MapWritesOneIndexPerPixel) {
    const Picture p = sample();
    PaletteBuilder builder;
    builder.add(p.bytes(), p.w, p.h, p.w * 4);
    const Palette pal = builder.build(256);
    std::vector<std::uint8_t> out(static_cast<size_t>(p.w) * p.h);
    pal.map(p.bytes(), p.w, p.h, p.w * 4, out.data(), p.w);
    for (size_t i = 0; i < out.size(); ++i) ASSERT_EQ(out[i], pal.index_of(p.px[i])) << i;
}

}  // namespace
