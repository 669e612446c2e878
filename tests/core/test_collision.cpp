// The separating-axis test against an independent polygon oracle, the broad phase against all
// pairs, and which bench pairs need testing at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "dragon/chain.hpp"
#include "dragon/collision.hpp"

using namespace dragon;

namespace {

using Poly = std::vector<Vec2>;

Poly polygon(const Rect& r) {
    const Corners c = corners(r);
    return {c.p[0], c.p[1], c.p[2], c.p[3]};
}

// Sutherland-Hodgman: clip `subject` by the convex counter-clockwise `clip`.
Poly clip(const Poly& subject, const Poly& clipper) {
    Poly out = subject;
    for (size_t e = 0; e < clipper.size() && !out.empty(); ++e) {
        const Vec2 a = clipper[e], b = clipper[(e + 1) % clipper.size()];
        const Poly in = out;
        out.clear();
        auto inside = [&](const Vec2& p) { return cross(b - a, p - a) >= 0.0; };
        for (size_t k = 0; k < in.size(); ++k) {
            const Vec2 p = in[k], q = in[(k + 1) % in.size()];
            const bool pi = inside(p), qi = inside(q);
            if (pi) out.push_back(p);
            if (pi != qi) {
                const double t = cross(b - a, a - p) / cross(b - a, q - p);
                out.push_back(p + t * (q - p));
            }
        }
    }
    return out;
}

double area(const Poly& p) {
    double s = 0.0;
    for (size_t k = 0; k < p.size(); ++k) s += cross(p[k], p[(k + 1) % p.size()]);
    return 0.5 * s;
}

double point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return distance(p, a + t * ab);
}

// Distance between two disjoint polygons: the smallest vertex-to-edge distance either way.
double poly_distance(const Poly& a, const Poly& b) {
    double d = INFINITY;
    for (int pass = 0; pass < 2; ++pass) {
        const Poly& p = pass ? b : a;
        const Poly& q = pass ? a : b;
        for (const Vec2& v : p)
            for (size_t k = 0; k < q.size(); ++k) d = std::min(d, point_segment(v, q[k], q[(k + 1) % q.size()]));
    }
    return d;
}

// Distance from a point to a convex polygon (counter-clockwise): 0 inside, else to the nearest edge.
double point_polygon(const Vec2& p, const Poly& q) {
    bool inside = true;
    double d = INFINITY;
    for (size_t k = 0; k < q.size(); ++k) {
        const Vec2 a = q[k], b = q[(k + 1) % q.size()];
        inside &= cross(b - a, p - a) >= 0.0;
        d = std::min(d, point_segment(p, a, b));
    }
    return inside ? 0.0 : d;
}

bool overlaps(const Rect& a, const Rect& b) { return area(clip(polygon(a), polygon(b))) > 1e-14; }

Rect shifted(Rect r, const Vec2& by) {
    r.centre = r.centre + by;
    return r;
}

Rect random_rect(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> pos(-2.0, 2.0), ang(0.0, 6.283185307179586), len(0.05, 2.0);
    const double a = ang(rng);
    return {{pos(rng), pos(rng)}, {std::cos(a), std::sin(a)}, len(rng), 0.5 * len(rng)};
}

}  // namespace

TEST(Separation, AgreesWithPolygonOracleOnRandomPairs) {
    std::mt19937_64 rng(20240906);
    int apart = 0, overlapping = 0;
    for (int k = 0; k < 4000; ++k) {
        const Rect a = random_rect(rng), b = random_rect(rng);
        const Separation s = separation(a, b);
        const bool oracle_overlap = overlaps(a, b);
        if (std::abs(s.distance) < 1e-9) continue;  // touching within rounding: either answer is right
        ASSERT_EQ(s.distance < 0.0, oracle_overlap) << "pair " << k << " distance " << s.distance;
        EXPECT_NEAR(norm(s.axis), 1.0, 1e-12);
        if (s.distance > 0.0) {
            ++apart;
            EXPECT_NEAR(s.distance, poly_distance(polygon(a), polygon(b)), 1e-12) << "pair " << k;
            // Moving b towards a along the axis by the distance makes them touch, not overlap.
            EXPECT_FALSE(overlaps(a, shifted(b, -(s.distance - 1e-7) * s.axis))) << "pair " << k;
        } else {
            ++overlapping;
            const double depth = -s.distance;
            // Pushing b out along the axis by the depth (plus a hair) separates them...
            EXPECT_FALSE(overlaps(a, shifted(b, (depth + 1e-7) * s.axis))) << "pair " << k;
            // ...and no direction separates them with a shorter push.
            for (int dir = 0; dir < 64; ++dir) {
                const double ang = 6.283185307179586 * dir / 64.0;
                const Vec2 u{std::cos(ang), std::sin(ang)};
                EXPECT_TRUE(overlaps(a, shifted(b, (depth - 1e-6) * u))) << "pair " << k << " dir " << dir;
            }
        }
    }
    EXPECT_GT(apart, 500);
    EXPECT_GT(overlapping, 500);
}

// The witness point is where the boards meet: on the surface of both when apart (the nearest
// point of b, at the reported distance from a), inside both when they overlap with a corner in.
TEST(Separation, WitnessPointIsWhereTheBoardsMeet) {
    std::mt19937_64 rng(11);
    int with_corner_inside = 0;
    for (int k = 0; k < 2000; ++k) {
        const Rect a = random_rect(rng), b = random_rect(rng);
        const Separation s = separation(a, b);
        const Poly pa = polygon(a), pb = polygon(b);
        if (s.distance > 1e-9) {
            EXPECT_NEAR(point_polygon(s.point, pb), 0.0, 1e-12) << "pair " << k;
            EXPECT_NEAR(point_polygon(s.point, pa), s.distance, 1e-12) << "pair " << k;
        } else if (s.distance < -1e-9) {
            bool corner_inside = false;
            for (const Vec2& c : pa) corner_inside |= point_polygon(c, pb) == 0.0;
            for (const Vec2& c : pb) corner_inside |= point_polygon(c, pa) == 0.0;
            if (!corner_inside) continue;
            ++with_corner_inside;
            EXPECT_NEAR(point_polygon(s.point, pa), 0.0, 1e-12) << "pair " << k;
            EXPECT_NEAR(point_polygon(s.point, pb), 0.0, 1e-12) << "pair " << k;
        }
    }
    EXPECT_GT(with_corner_inside, 200);
}

TEST(Separation, SymmetricInItsArguments) {
    std::mt19937_64 rng(7);
    for (int k = 0; k < 500; ++k) {
        const Rect a = random_rect(rng), b = random_rect(rng);
        EXPECT_NEAR(separation(a, b).distance, separation(b, a).distance, 1e-12);
    }
}

TEST(Clearance, AdjacentBenchesAlwaysOverlapSoAreExcluded) {
    // Neighbours share a handle and each reaches 0.275 m past it: their boards always overlap,
    // whatever the curve, so a test that included them would report a collision at every moment.
    for (double pitch : {0.45, 0.55, 1.7}) {
        Scenario s;
        s.path.pitch = pitch;
        const Simulation sim(s);
        for (double frac : {0.0, 0.5, 0.9}) {
            const Frame f = sim.frame(frac * sim.valid_end());
            for (size_t k = 0; k + 1 < f.benches.size(); ++k)
                EXPECT_LT(separation(f.benches[k], f.benches[k + 1]).distance, 0.0);
        }
    }
}

// A chain whose handles sit on a circle of radius `radius`, links of 1.65 m (contest body benches).
Frame chain_on_circle(double radius, int benches) {
    BenchSpec spec;
    spec.bench_count = benches;
    spec.head_length = spec.body_length;
    const double d = spec.link_length(2);
    const double step = 2.0 * std::asin(d / (2.0 * radius));
    Frame f;
    for (int k = 0; k <= benches; ++k) {
        const double a = -step * k;
        f.handles.push_back({{radius * std::cos(a), radius * std::sin(a)}, Vec2::Zero(), 1.0, {}});
    }
    for (int k = 1; k <= benches; ++k)
        f.benches.push_back(bench_rect(spec, k, f.handles[static_cast<size_t>(k - 1)].pos, f.handles[static_cast<size_t>(k)].pos));
    return f;
}

TEST(Clearance, BenchesTwoApartTouchOnlyOnATightCurve) {
    // Bench i against i+2 is not excluded, because on a tight enough curve they meet: find the
    // radius below which they overlap, and check the clearance reports such a pair there.
    double lo = 0.83, hi = 10.0;  // 0.83 m: just over half a link, the tightest circle a link fits
    ASSERT_LT(separation(chain_on_circle(lo, 3).benches[0], chain_on_circle(lo, 3).benches[2]).distance, 0.0);
    ASSERT_GT(separation(chain_on_circle(hi, 3).benches[0], chain_on_circle(hi, 3).benches[2]).distance, 0.0);
    for (int k = 0; k < 60; ++k) {
        const double m = 0.5 * (lo + hi);
        const Frame f = chain_on_circle(m, 3);
        (separation(f.benches[0], f.benches[2]).distance < 0.0 ? lo : hi) = m;
    }
    std::printf("benches i and i+2 overlap on circles of radius below %.4f m\n", lo);
    const Frame tight = chain_on_circle(0.95 * lo, 8);
    const Clearance c = clearance(tight);
    EXPECT_LT(c.distance, 0.0);
    EXPECT_LE(c.distance, separation(tight.benches[0], tight.benches[2]).distance);
    // The contest's tightest curve before its first contact is far wider than that: the head's
    // radius at Q2 is about 2.29 m, and the path's radius of curvature there larger still.
    EXPECT_LT(lo, 2.0);
}

TEST(Clearance, BroadPhaseNeverMissesAPair) {
    // On many frames (apart, nearly touching and overlapping), every non-adjacent pair within the
    // margin of each other is among the candidates, and the clearance equals the all-pairs one.
    std::vector<Frame> frames;
    const Simulation sim(Scenario{});
    for (double t = 0.0; t <= sim.valid_end(); t += 13.7) frames.push_back(sim.frame(t));
    for (double t : {412.4738, 412.4739, 412.5, 415.0}) frames.push_back(sim.frame(t));
    for (double pitch : {0.36, 0.42, 0.45}) {
        Scenario s;
        s.path.pitch = pitch;
        const Simulation other(s);
        for (double frac : {0.3, 0.7, 0.95}) frames.push_back(other.frame(frac * other.valid_end()));
    }
    int touching = 0;
    for (const Frame& f : frames) {
        for (double margin : {0.0, 0.1, 0.5}) {
            const auto cand = candidate_pairs(f, margin);
            const std::set<std::pair<int, int>> set(cand.begin(), cand.end());
            const int n = static_cast<int>(f.benches.size());
            for (int i = 0; i < n; ++i)
                for (int j = i + 2; j < n; ++j) {
                    const double d = separation(f.benches[static_cast<size_t>(i)], f.benches[static_cast<size_t>(j)]).distance;
                    if (d <= margin) {
                        EXPECT_TRUE(set.count({i + 1, j + 1})) << "t " << f.time << " pair " << i + 1 << "," << j + 1;
                        if (d <= 0.0) ++touching;
                    }
                }
        }
        const Clearance fast = clearance(f), slow = clearance_all_pairs(f);
        EXPECT_DOUBLE_EQ(fast.distance, slow.distance) << "t " << f.time;
    }
    EXPECT_GT(touching, 0);
}

// The mark of a contact: the corner of one board that touches the other, whichever board it
// belongs to; for boards apart, the corner nearest the other board.
TEST(ContactPoint, TheCornerThatTouches) {
    const Rect a{{0.0, 0.0}, {1.0, 0.0}, 1.0, 0.25};
    // b tilted, its lowest corner resting on a's top edge at x = 0.3.
    const Vec2 axis = normalized(Vec2{1.0, 1.0});
    const Vec2 corner{0.3, 0.25};
    const Vec2 centre = corner + 1.0 * axis + 0.25 * perp(axis);
    const Rect b{centre, axis, 1.0, 0.25};
    ASSERT_NEAR(std::min({corners(b).p[0].y(), corners(b).p[1].y(), corners(b).p[2].y(), corners(b).p[3].y()}), 0.25, 1e-12);
    const Vec2 p = contact_point(a, b);
    EXPECT_NEAR(p.x(), 0.3, 1e-12);
    EXPECT_NEAR(p.y(), 0.25, 1e-12);
    EXPECT_NEAR(point_to_rect(p, a).distance, 0.0, 1e-12);
    // The same from the other side: the point does not depend on the order.
    const Vec2 q = contact_point(b, a);
    EXPECT_EQ(q.x(), p.x());
    EXPECT_EQ(q.y(), p.y());
    // Apart: the corner nearest the other board, lifted with b.
    Rect lifted = b;
    lifted.centre = b.centre + Vec2{0.0, 0.1};
    const Vec2 r = contact_point(a, lifted);
    EXPECT_NEAR(r.y(), 0.35, 1e-12);
    EXPECT_NEAR(point_to_rect(r, a).distance, 0.1, 1e-12);
}
