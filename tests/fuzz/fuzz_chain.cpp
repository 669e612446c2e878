// libFuzzer target: the chain solver and the collision tests.
//
// From the input: a bench spec and a path (any values; those validate() refuses end the run,
// since refusing is allowed), a time on the path, and two free rectangles.
//
// Properties of a validated scenario's frame:
//  - every position, tangent and speed is finite and every tangent a unit vector;
//  - each handle lies on the path where its Place says, behind the one before it;
//  - every chord equals its link length (1e-9 relative, plus rounding of the coordinates);
//  - the chord is the nearest one: no sampled point of the path between two handles is
//    farther from the front handle than the link;
//  - clearance() through the broad phase equals the all-pairs clearance, for a non-adjacent pair.
// Properties of separation(a, b) on any two rectangles:
//  - symmetric: separation(b, a) has the same distance;
//  - its sign agrees with an independent overlap test (corners inside, edges crossing), and
//    when apart its distance equals the smallest corner-to-edge distance.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>

#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "fuzz_check.hpp"

namespace {

using namespace dragon;

// A length near `nominal`, spread over 10^-spread .. 10^spread of it; now and then any double
// at all (negative, zero, subnormal, huge, inf, NaN) to probe validate().
double consume_scaled(FuzzedDataProvider& p, double nominal, double spread) {
    if (p.ConsumeIntegralInRange(0, 15) == 0) {
        const std::uint64_t bits = p.ConsumeIntegral<std::uint64_t>();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    return nominal * std::pow(10.0, p.ConsumeFloatingPointInRange(-spread, spread));
}

Scenario consume_scenario(FuzzedDataProvider& p) {
    Scenario s;
    s.path.kind = p.ConsumeBool() ? PathKind::spiral : PathKind::turnaround;
    s.bench.bench_count = p.ConsumeIntegralInRange(1, 40);
    s.bench.head_length = consume_scaled(p, 3.41, 1.5);
    s.bench.body_length = consume_scaled(p, 2.2, 1.5);
    s.bench.width = consume_scaled(p, 0.3, 1.5);
    s.bench.hole_offset = consume_scaled(p, 0.275, 1.5);
    s.path.pitch = consume_scaled(p, 0.55, 1.5);
    s.path.start_turn = consume_scaled(p, 16.0, 2.0);
    s.path.turn_radius = consume_scaled(p, 4.5, 1.5);
    s.path.turn_pitch = consume_scaled(p, 1.7, 1.5);
    s.path.arc_ratio = consume_scaled(p, 2.0, 1.5);
    s.head_speed = consume_scaled(p, 1.0, 6.0);
    return s;
}

Rect consume_rect(FuzzedDataProvider& p) {
    Rect r;
    r.centre = {p.ConsumeFloatingPointInRange(-20.0, 20.0), p.ConsumeFloatingPointInRange(-20.0, 20.0)};
    const double phi = p.ConsumeFloatingPointInRange(0.0, 6.283185307179586);
    r.axis = {std::cos(phi), std::sin(phi)};
    r.half_length = p.ConsumeFloatingPointInRange(1e-3, 10.0);
    r.half_width = p.ConsumeFloatingPointInRange(1e-3, 10.0);
    return r;
}

std::string describe(const Scenario& s) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s, %d benches, head %.17g m, body %.17g m, width %.17g m, hole offset %.17g m, "
                  "pitch %.17g m, start turn %.17g, turn radius %.17g m, turn pitch %.17g m, "
                  "arc ratio %.17g, head speed %.17g m/s",
                  to_string(s.path.kind), s.bench.bench_count, s.bench.head_length, s.bench.body_length,
                  s.bench.width, s.bench.hole_offset, s.path.pitch, s.path.start_turn, s.path.turn_radius,
                  s.path.turn_pitch, s.path.arc_ratio, s.head_speed);
    return text;
}

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// How well a handle's coordinates can be known: a few ulps of its distance from the centre, times
// the size of its path parameter (on a spiral the angle theta: cos and sin of theta carry
// theta's own rounding, |theta| ulp, into the position).
double rounding(const Handle& h) {
    constexpr double eps = std::numeric_limits<double>::epsilon();
    return 8.0 * eps * (1.0 + norm(h.pos)) * (1.0 + std::abs(h.place.u));
}

void check_frame(const Simulation& sim, const Frame& f) {
    const BenchSpec& spec = sim.scenario().bench;
    const Path& path = sim.path();
    FUZZ_CHECK(f.handles.size() == static_cast<size_t>(spec.handle_count()), "handle count");
    FUZZ_CHECK(f.benches.size() == static_cast<size_t>(spec.bench_count), "bench count");
    for (size_t i = 0; i < f.handles.size(); ++i) {
        const Handle& h = f.handles[i];
        FUZZ_CHECK(finite(h.pos) && finite(h.tangent) && std::isfinite(h.speed),
                   "handle %zu at (%g, %g), tangent (%g, %g), speed %g", i, h.pos.x(), h.pos.y(),
                   h.tangent.x(), h.tangent.y(), h.speed);
        FUZZ_CHECK(std::abs(norm(h.tangent) - 1.0) < 1e-9, "handle %zu tangent length %.17g", i, norm(h.tangent));
        const Located on = path.at(h.place);
        // On the plain spiral each handle's cos and sin come from the one before by the angle-sum
        // rule, while its place is theta rounded afresh: the two drift apart by about one
        // rounding per handle.
        FUZZ_CHECK(distance(on.pos, h.pos) <= (1.0 + i) * rounding(h), "handle %zu is %g m off its place", i,
                   distance(on.pos, h.pos));
    }
    for (size_t i = 0; i + 1 < f.handles.size(); ++i) {
        const Handle &front = f.handles[i], &rear = f.handles[i + 1];
        const double link = spec.link_after(static_cast<int>(i));
        const double chord = distance(front.pos, rear.pos);
        const double slack = 1e-9 * link + rounding(front) + rounding(rear);
        FUZZ_CHECK(std::abs(chord - link) <= slack, "chord %zu-%zu is %.17g, link %.17g", i, i + 1, chord, link);
        const double s_front = path.arc(front.place), s_rear = path.arc(rear.place);
        FUZZ_CHECK(s_rear < s_front, "handle %zu (s = %.17g) is not behind handle %zu (s = %.17g)", i + 1,
                   s_rear, i, s_front);
        // The nearest chord: the path between the two stays within the link of the front handle.
        for (int k = 1; k < 8; ++k) {
            const double s = s_rear + (s_front - s_rear) * k / 8.0;
            const double d = distance(path.at_arc(s).pos, front.pos);
            FUZZ_CHECK(d <= link + slack, "between handles %zu and %zu the path reaches %.17g from the front, "
                       "beyond the link %.17g: a nearer chord was skipped", i, i + 1, d, link);
        }
    }
    const Clearance fast = clearance(f), all = clearance_all_pairs(f);
    if (f.benches.size() < 3) {
        FUZZ_CHECK(std::isinf(fast.distance) && std::isinf(all.distance), "clearance of a short chain");
        return;
    }
    FUZZ_CHECK(std::abs(fast.distance - all.distance) <= 1e-12 * (1.0 + std::abs(all.distance)),
               "clearance %.17g (benches %d, %d) but all pairs give %.17g (benches %d, %d)", fast.distance,
               fast.bench_a, fast.bench_b, all.distance, all.bench_a, all.bench_b);
    FUZZ_CHECK(fast.bench_b - fast.bench_a >= 2 && fast.bench_a >= 1 && fast.bench_b <= spec.bench_count,
               "clearance pair %d, %d", fast.bench_a, fast.bench_b);
}

// Distance from p to segment ab.
double point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return distance(p, a + t * ab);
}

bool inside(const Vec2& p, const Rect& r) {
    const Vec2 w = p - r.centre;
    return std::abs(dot(w, r.axis)) <= r.half_length && std::abs(cross(r.axis, w)) <= r.half_width;
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

void check_separation(const Rect& a, const Rect& b) {
    const Separation ab = separation(a, b), ba = separation(b, a);
    const double scale = 1.0 + norm(a.centre) + norm(b.centre) + a.half_length + b.half_length;
    FUZZ_CHECK(std::isfinite(ab.distance) && finite(ab.axis) && finite(ab.point), "separation not finite");
    FUZZ_CHECK(std::abs(ab.distance - ba.distance) <= 1e-12 * scale, "separation(a, b) = %.17g but "
               "separation(b, a) = %.17g", ab.distance, ba.distance);
    const Corners ca = corners(a), cb = corners(b);
    // A centre inside the other counts too: corners on the other's very edge may round outside.
    bool overlap = inside(a.centre, b) || inside(b.centre, a);
    double corner_edge = INFINITY;
    for (int i = 0; i < 4; ++i) {
        overlap = overlap || inside(ca.p[i], b) || inside(cb.p[i], a);
        for (int j = 0; j < 4; ++j) {
            overlap = overlap || segments_cross(ca.p[i], ca.p[(i + 1) % 4], cb.p[j], cb.p[(j + 1) % 4]);
            corner_edge = std::min({corner_edge, point_segment(ca.p[i], cb.p[j], cb.p[(j + 1) % 4]),
                                    point_segment(cb.p[i], ca.p[j], ca.p[(j + 1) % 4])});
        }
    }
    if (std::abs(ab.distance) <= 1e-9 * scale) return;  // touching: either answer is right
    FUZZ_CHECK((ab.distance < 0.0) == overlap, "separation %.17g but the oracle says %s", ab.distance,
               overlap ? "overlapping" : "apart");
    if (!overlap)
        FUZZ_CHECK(std::abs(ab.distance - corner_edge) <= 1e-12 * scale, "distance %.17g, corner to edge %.17g",
                   ab.distance, corner_edge);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider p(data, size);
    const Scenario s = consume_scenario(p);
    const double when = p.ConsumeProbability<double>();
    const Rect ra = consume_rect(p), rb = consume_rect(p);
    char text[400];
    std::snprintf(text, sizeof text, "rectangles centre (%.17g, %.17g) axis (%.17g, %.17g) half %.17g x %.17g "
                  "and centre (%.17g, %.17g) axis (%.17g, %.17g) half %.17g x %.17g", ra.centre.x(), ra.centre.y(),
                  ra.axis.x(), ra.axis.y(), ra.half_length, ra.half_width, rb.centre.x(), rb.centre.y(), rb.axis.x(),
                  rb.axis.y(), rb.half_length, rb.half_width);
    fuzz_context() = text;
    check_separation(ra, rb);
    fuzz_context() = describe(s);
    try {
        validate(s);
    } catch (const InputError&) {
        return 0;
    }
    try {
        const Simulation sim(s);
        // A time on the path: anywhere from the start to the spiral's centre, or within 300 m
        // of head travel around the turn (the turnaround path has no end).
        const double t = std::isfinite(sim.end_time()) ? when * sim.end_time()
                                                       : (600.0 * when - 300.0) / s.head_speed;
        fuzz_context() += ", t = " + std::to_string(t) + " s";
        try {
            sim.require_valid(t, Key::time);
        } catch (const InputError&) {
            return 0;  // refused (too far out, or past the end of the valid motion): allowed
        }
        check_frame(sim, sim.frame(t));
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "a validated scenario failed: %s", e.what());
    }
    return 0;
}
