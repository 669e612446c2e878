// A moment drawn as the render command draws it (dragon/still.hpp).
#include "dragon/still.hpp"

#include <fmt/format.h>

#include "dragon/collision.hpp"
#include "render/words.hpp"

namespace dragon {

namespace {
// A still's title gets a band of its own: over the drawing it would hide benches (the head, at a
// contact zoomed in).
SceneOptions still_options(SceneOptions so) {
    so.title_band = true;
    return so;
}
}  // namespace

Still still_at(const Simulation& sim, double t, SceneOptions so, Key time_field) {
    so = still_options(std::move(so));
    sim.require_valid(t, time_field);
    Frame frame = sim.frame(t);
    // Past the first contact the benches overlap (drawn marked): the annotation says so.
    const std::optional<Contact> c = first_contact_covering(sim, t, t).contact;
    if (!so.annotation && c && c->time < t)
        so.annotation = fmt::format(fmt::runtime(render::words(so.language).still_past_contact), frame.time,
                                    sim.scenario().coil_pitch(), c->bench_a, c->bench_b, c->time);
    Scene scene = make_scene(sim, frame, so);
    return {std::move(frame), std::move(scene)};
}

std::optional<Still> still_at_first_contact(const Simulation& sim, SceneOptions so, std::optional<double> zoom,
                                            CollideAnswer* searched) {
    CollideAnswer a = first_contact_of_motion(sim);
    if (!a.contact) {
        if (searched) *searched = std::move(a);
        return std::nullopt;
    }
    const Contact& c = *a.contact;
    // Marked where the boards meet: the corner of one nearest the other.
    const Vec2 at = contact_point(c.frame.benches[c.bench_a - 1], c.frame.benches[c.bench_b - 1]);
    so = still_options(std::move(so));
    so.collision = CollisionMark{c.bench_a, c.bench_b, at};
    so.name_touching = true;  // which magenta bench is the head, without the legend
    if (!so.annotation)
        so.annotation = fmt::format(fmt::runtime(render::words(so.language).still_contact), c.time, c.bench_a, c.bench_b);
    if (zoom) so.camera = Camera::at(at, *zoom);
    Scene scene = make_scene(sim, c.frame, so);
    if (searched) *searched = a;
    return Still{c.frame, std::move(scene)};
}

}  // namespace dragon
