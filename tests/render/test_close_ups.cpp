// Close-ups: a view thousands of times smaller than the shapes in it is drawn right (Cairo's
// fixed point wraps beyond ~8 million pixels) and costs what it shows, not the whole path.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "dragon/render.hpp"
#include "support/scratch.hpp"

namespace dragon {
namespace {

struct Rgb8 {
    int r, g, b;
};

Rgb8 pixel(cairo_surface_t* s, int x, int y) {
    cairo_surface_flush(s);
    const auto* row = cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s);
    const std::uint32_t v = reinterpret_cast<const std::uint32_t*>(row)[x];
    return {static_cast<int>((v >> 16) & 255), static_cast<int>((v >> 8) & 255), static_cast<int>(v & 255)};
}

// The colour a straight fill of `c` over `bg` leaves, 0..255.
Rgb8 over(Rgba c, Rgba bg) {
    auto mix = [&](double f, double b) { return static_cast<int>(std::lround(255 * (c.a * f + (1 - c.a) * b))); };
    return {mix(c.r, bg.r), mix(c.g, bg.g), mix(c.b, bg.b)};
}

void expect_colour(Rgb8 got, Rgb8 want, const char* where) {
    EXPECT_NEAR(got.r, want.r, 2) << where;
    EXPECT_NEAR(got.g, want.g, 2) << where;
    EXPECT_NEAR(got.b, want.b, 2) << where;
}

// A 0.1 mm view on the turning space's edge, 4.5 m out: its circle is 9 million pixels across
// here. Left of the edge is inside the disk (its fill), right of it outside (the background),
// at t = 0 when no bench and no ring of the spiral is near.
TEST(CloseUp, TurningSpaceEdgeAtATenthOfAMillimetre) {
    const Simulation sim(Scenario{});
    SceneOptions o;
    o.camera = Camera::at({4.5, 0.0}, 1e-4);
    o.show_text = false;
    o.show_scale_bar = false;
    const Scene scene = make_scene(sim, sim.frame(0.0), o);
    const int size = 200;
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, size, size));
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), scene, size, size);
    const Theme& th = scene.theme;
    for (int y : {10, 100, 190}) {
        expect_colour(pixel(surface.get(), 20, y), over(th.turning_fill, th.background), "inside the disk");
        expect_colour(pixel(surface.get(), 180, y), over(th.background, th.background), "outside the disk");
    }
}

// The SVG of a 0.1 mm view around the head holds only what the view shows: a few kilobytes
// (the whole path at that scale was gigabytes), every coordinate within a few picture sizes.
TEST(CloseUp, SvgOfATinyViewHoldsOnlyWhatItShows) {
    const Simulation sim(Scenario{});
    SceneOptions o;
    o.camera = Camera::follow(1e-4);
    const Scene scene = make_scene(sim, sim.frame(0.0), o);
    const auto file = dragon_test::scratch_dir() / "head.svg";
    render_svg(scene, 400, 400, file.string());
    EXPECT_LT(std::filesystem::file_size(file), 200'000u);
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string svg = ss.str();
    const std::regex path_data(R"( d=\"([^\"]*)\")");
    const std::regex number(R"(-?[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?)");
    double largest = 0;
    int numbers = 0;
    for (auto d = std::sregex_iterator(svg.begin(), svg.end(), path_data); d != std::sregex_iterator(); ++d) {
        const std::string data = (*d)[1];
        for (auto n = std::sregex_iterator(data.begin(), data.end(), number); n != std::sregex_iterator(); ++n, ++numbers)
            largest = std::max(largest, std::abs(std::stod(n->str())));
    }
    EXPECT_GT(numbers, 0);
    EXPECT_LT(largest, 10 * 400);
}

TEST(CloseUp, CamerasOutsideTheDrawableViewsAreInputErrors) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(0.0);
    for (const Camera& cam : {Camera::at({0, 0}, 1e-12), Camera::at({0, 0}, 1e12), Camera::at({NAN, 0}, 1),
                              Camera::at({1e9, 0}, 1), Camera::follow(INFINITY)}) {
        SceneOptions o;
        o.camera = cam;
        EXPECT_THROW(make_scene(sim, f, o), InputError) << cam.centre.x() << " " << cam.extent;
    }
    // Drawable alone, but not at 1600 px 8.8 m out: render refuses it before any file.
    SceneOptions o;
    o.camera = Camera::follow(2e-9);
    const Scene scene = make_scene(sim, f, o);
    const auto file = dragon_test::scratch_dir() / "fine.png";
    std::filesystem::remove(file);
    EXPECT_THROW(render_png(scene, 1600, 1600, file.string()), InputError);
    EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace dragon
