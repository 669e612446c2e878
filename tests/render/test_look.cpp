// The look a user asks (dragon/look.hpp): the rules the render and video commands, Python and
// the page share, checked here on the library's own request.
#include <gtest/gtest.h>

#include "dragon/chain.hpp"
#include "dragon/look.hpp"
#include "dragon/still.hpp"

namespace dragon {
namespace {

const std::string assets = std::string(DRAGON_SOURCE_DIR) + "/assets";

Key refused_key(const LookRequest& look, bool clip) {
    try {
        if (clip) clip_scene_options(look, assets);
        else picture_scene_options(look, assets);
    } catch (const InputError& e) {
        return e.key();
    }
    return Key::none;
}

TEST(Look, APictureFramesWhatItIsAsked) {
    LookRequest look;
    EXPECT_EQ(picture_scene_options(look, assets).camera.mode, Camera::Mode::fit_dragon);
    look.follow_head = true;
    Camera c = picture_scene_options(look, assets).camera;
    EXPECT_EQ(c.mode, Camera::Mode::follow_head);
    EXPECT_EQ(c.extent, kFollowedPictureWidth);
    look.zoom = 3.5;
    c = picture_scene_options(look, assets).camera;
    EXPECT_EQ(c.mode, Camera::Mode::follow_head);
    EXPECT_EQ(c.extent, 3.5);
    look.centre = Vec2(1.25, -2.0);
    c = picture_scene_options(look, assets).camera;
    EXPECT_EQ(c.mode, Camera::Mode::fixed);
    EXPECT_EQ(c.centre, Vec2(1.25, -2.0));
    EXPECT_EQ(c.extent, 3.5);
}

TEST(Look, AClipFollowsTheHeadOrHoldsTheOrigin) {
    LookRequest look;
    look.follow_head = true;
    Camera c = clip_scene_options(look, assets).camera;
    EXPECT_EQ(c.mode, Camera::Mode::follow_head);
    EXPECT_EQ(c.extent, kFollowedClipWidth);
    look.follow_head = false;
    look.zoom = 6.0;
    c = clip_scene_options(look, assets).camera;
    EXPECT_EQ(c.mode, Camera::Mode::fixed);
    EXPECT_EQ(c.centre, Vec2(0.0, 0.0));
    EXPECT_EQ(c.extent, 6.0);
}

TEST(Look, EachRefusalNamesItsKey) {
    LookRequest centre_alone;
    centre_alone.centre = Vec2(1.0, 1.0);
    EXPECT_EQ(refused_key(centre_alone, false), Key::centre);
    EXPECT_EQ(refused_key(centre_alone, true), Key::centre);  // a clip takes no centre at all
    LookRequest far = centre_alone;
    far.zoom = 1.0;
    far.centre = Vec2(2 * kMaxViewCentre, 0.0);
    EXPECT_EQ(refused_key(far, false), Key::centre);
    for (const double zoom : {0.0, kMinViewExtent / 2, 2 * kMaxViewExtent, std::nan("")}) {
        LookRequest z;
        z.zoom = zoom;
        EXPECT_EQ(refused_key(z, false), Key::zoom) << zoom;
        EXPECT_EQ(refused_key(z, true), Key::zoom) << zoom;
    }
    LookRequest edges;
    edges.zoom = kMinViewExtent;
    EXPECT_EQ(refused_key(edges, false), Key::none);
    edges.zoom = kMaxViewExtent;
    EXPECT_EQ(refused_key(edges, false), Key::none);
    LookRequest lang;
    lang.lang = "fr";
    EXPECT_EQ(refused_key(lang, false), Key::lang);
}

TEST(Look, AZoomWhosePixelsDoublesCannotResolveIsRefused) {
    const Simulation sim(Scenario{});
    LookRequest look;
    look.zoom = kMinViewExtent;  // a nanometre square 8.8 m from the origin, at 720 px
    look.follow_head = true;
    const Still still = still_at(sim, 0.0, picture_scene_options(look, assets));
    try {
        require_zoom_resolves(still.scene, 1280, 720, *look.zoom);
        ADD_FAILURE() << "a view of 1e-9 m at 8.8 m was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), Key::zoom);
        // The narrowest zoom it names is one that resolves there.
        const double narrowest = narrowest_view(still.scene.view_centre, 1280, 720);
        EXPECT_GT(narrowest, *look.zoom);
        LookRequest wider = look;
        wider.zoom = narrowest * 1.01;
        const Still there = still_at(sim, 0.0, picture_scene_options(wider, assets));
        EXPECT_NO_THROW(require_zoom_resolves(there.scene, 1280, 720, *wider.zoom));
    }
    look.zoom = 1.0;  // a metre resolves anywhere on the path
    EXPECT_NO_THROW(require_zoom_resolves(still_at(sim, 0.0, picture_scene_options(look, assets)).scene, 1280, 720, 1.0));
}

}  // namespace
}  // namespace dragon
