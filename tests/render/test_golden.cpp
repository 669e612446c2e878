// Golden images of fixed scenes, 256 x 256, no text (so no font enters the comparison); and one
// in Chinese, its text drawn from outlines in the fonts scripts/install-deps.sh installs (DejaVu
// Sans, Noto Sans CJK SC), so that real glyphs, not empty boxes, are what it holds.
// File names carry the parameters. DRAGON_REBASELINE=1 rewrites the references.
#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "dragon/analyses.hpp"
#include "dragon/render.hpp"
#include "golden.hpp"

namespace dragon {
namespace {

constexpr int side = 256;

Theme theme(const std::string& name) {
    return load_theme(name, std::string(DRAGON_SOURCE_DIR) + "/assets");
}

void expect_golden(const Scene& scene, const std::string& name) {
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, side, side));
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), scene, side, side);
    ASSERT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS);
    const auto r = test::compare_golden(surface.get(), name);
    if (r.rebaselined) std::printf("%s\n", r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
}

SceneOptions no_text(const std::string& theme_name) {
    SceneOptions o;
    o.theme = theme(theme_name);
    o.show_text = false;
    return o;
}

TEST(Golden, SpiralWholeDragonAt300sLight) {
    const Simulation sim(Scenario{});
    expect_golden(make_scene(sim, sim.frame(300.0), no_text("light")), "spiral_t300_light_fit_256x256.png");
}

TEST(Golden, SpiralSpeedColoursAt300sDark) {
    const Simulation sim(Scenario{});
    SceneOptions o = no_text("dark");
    o.colour_by_speed = true;
    expect_golden(make_scene(sim, sim.frame(300.0), o), "spiral_t300_dark_speed_fit_256x256.png");
}

TEST(Golden, TurnaroundAtTurnStartLight) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    SceneOptions o = no_text("light");
    o.camera = Camera::at({0, 0}, 12.0);
    expect_golden(make_scene(sim, sim.frame(0.0), o), "turnaround_t0_light_centre12m_256x256.png");
}

// A close view with the collision styling, the contact marker and highlighted benches. The
// marked pair is the head and the bench whose centre is nearest the head's on the next ring out
// (no collision solver here: this tests the drawing, not the physics); its neighbours are
// highlighted.
TEST(Golden, CloseViewWithCollisionMarkLight) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(300.0);
    int nearest = 3;
    for (int k = 3; k <= static_cast<int>(f.benches.size()); ++k)
        if (distance(f.benches[k - 1].centre, f.benches[0].centre) <
            distance(f.benches[nearest - 1].centre, f.benches[0].centre))
            nearest = k;
    SceneOptions o = no_text("light");
    o.camera = Camera::follow(6.0);
    o.collision = CollisionMark{1, nearest, 0.5 * (f.benches[0].centre + f.benches[nearest - 1].centre)};
    o.highlight_benches = {nearest - 1, nearest + 1};
    expect_golden(make_scene(sim, f, o), "spiral_t300_light_head6m_collision-nearest_256x256.png");
}

// The first contact in Chinese: the annotation, the legend, the touching benches' names and a
// caption, each in the contest's terms (龙头, 龙身, 龙尾, 调头空间, 板凳).
TEST(Golden, FirstContactInChinese) {
    const Simulation sim(Scenario{});
    const Contact c = *first_contact_of_motion(sim).contact;
    SceneOptions o;
    o.theme = theme("light");
    o.language = Language::zh;
    o.camera = Camera::at(c.point, 5.0);
    o.collision = CollisionMark{c.bench_a, c.bench_b, c.point};
    o.name_touching = true;
    o.show_legend = true;
    o.title_band = true;
    Scene scene = make_scene(sim, c.frame, o);
    scene.captions.push_back({"\u9f99\u5934\u4e0e\u9f99\u8eab\u76f8\u78b0", 1.0});  // 龙头与龙身相碰
    constexpr int w = 480, h = 360;
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    test::outline_fonts(cr.get());
    draw(cr.get(), scene, w, h);
    ASSERT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS);
    const auto r = test::compare_golden(surface.get(), "contact_zh_legend_names_caption_480x360.png");
    if (r.rebaselined) std::printf("%s\n", r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
}

}  // namespace
}  // namespace dragon
