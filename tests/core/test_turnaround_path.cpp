// The composite turnaround path: continuity at the joins, arc positions, and the chord search
// against a brute-force scan.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "dragon/chain.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

TurnaroundPath default_path() { return TurnaroundPath(design_s_curve(1.7, 4.5, 2.0)); }

// Nearest arc position behind s_from whose point is at `chord` from q, by walking back in
// steps of `h` and bisecting the first sign change (uses only at_arc).
double brute_behind(const Path& path, double s_from, double chord, double h = 1e-3) {
    const Vec2 q = path.at_arc(s_from).pos;
    auto f = [&](double s) { return distance(path.at_arc(s).pos, q) - chord; };
    double hi = s_from, lo = s_from - h;
    while (f(lo) < 0.0) {
        hi = lo;
        lo -= h;
    }
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0.0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

TEST(TurnaroundPath, ContinuousInPositionAndDirectionAtEveryJoin) {
    for (double ratio : {2.0, 0.7, 3.5}) {
        const TurnaroundPath path(design_s_curve(1.7, 4.5, ratio));
        for (int piece = 1; piece <= 3; ++piece) {
            SCOPED_TRACE(piece);
            const Located end = path.at({piece - 1, path.piece_range(piece - 1).second});
            const Located start = path.at({piece, path.piece_range(piece).first});
            EXPECT_NEAR(distance(end.pos, start.pos), 0.0, 1e-12);
            EXPECT_NEAR(distance(end.tangent, start.tangent), 0.0, 1e-12);
            // Arc positions agree at the join, and at_arc is continuous across it.
            EXPECT_NEAR(path.arc(end.place), path.join_arc(piece), 1e-12);
            EXPECT_NEAR(path.arc(start.place), path.join_arc(piece), 1e-12);
            const double s = path.join_arc(piece);
            EXPECT_NEAR(distance(path.at_arc(s - 1e-9).pos, path.at_arc(s + 1e-9).pos), 2e-9, 1e-12);
        }
    }
}

TEST(TurnaroundPath, EndsAtTheDesignPoints) {
    const TurnaroundPath path = default_path();
    const SCurve& d = path.design();
    EXPECT_NEAR(distance(path.at_arc(0.0).pos, d.entry), 0.0, 1e-12);
    EXPECT_NEAR(distance(path.at_arc(d.length1).pos, d.joint), 0.0, 1e-12);
    EXPECT_NEAR(distance(path.at_arc(d.length).pos, d.exit), 0.0, 1e-12);
    EXPECT_EQ(path.at_arc(-1e-9).place.piece, 0);
    EXPECT_EQ(path.at_arc(0.0).place.piece, 1);
    EXPECT_EQ(path.at_arc(d.length1).place.piece, 2);
    EXPECT_EQ(path.at_arc(d.length).place.piece, 3);
}

TEST(TurnaroundPath, ArcPositionRoundTrips) {
    const TurnaroundPath path = default_path();
    for (double s = -300.0; s <= 300.0; s += 0.37) {
        const Located l = path.at_arc(s);
        EXPECT_NEAR(path.arc(l.place), s, 1e-11 * (1.0 + std::abs(s)));
        EXPECT_NEAR(norm(l.tangent), 1.0, 1e-14);
    }
}

// Unit speed and curvature against differences of the points: |dP/ds| = 1, and the turn of the
// tangent per arc length is the signed curvature.
TEST(TurnaroundPath, ArcLengthAndCurvatureMatchFiniteDifferences) {
    const TurnaroundPath path = default_path();
    const double h = 1e-5;
    for (double s = -40.0; s <= 60.0; s += 0.113) {
        const Located a = path.at_arc(s - h), m = path.at_arc(s), b = path.at_arc(s + h);
        if (a.place.piece != b.place.piece) continue;  // curvature jumps at the joins
        EXPECT_NEAR(distance(a.pos, b.pos) / (2.0 * h), 1.0, 1e-8);
        EXPECT_NEAR(dot(normalized(b.pos - a.pos), m.tangent), 1.0, 1e-9);
        const double turn = std::asin(cross(a.tangent, b.tangent)) / (2.0 * h);
        EXPECT_NEAR(turn, path.curvature(m.place), 1e-5);
    }
}

// The chord search against the brute-force scan for many places, including both sides of each
// join and places right on it, for the chain's links and for longer chords that cut the path
// several times.
TEST(TurnaroundPath, BehindMatchesABruteForceScan) {
    // The contest's design, a tiny turn (entry angle below 1 rad: the general march on the
    // coil-out spiral), and a tight pitch with a big second arc.
    for (const SCurve& design : {design_s_curve(1.7, 4.5, 2.0), design_s_curve(1.7, 0.2, 2.0),
                                 design_s_curve(0.55, 4.5, 0.5)}) {
        const TurnaroundPath path(design);
        std::vector<double> from;
        std::mt19937_64 rng(20240906);
        std::uniform_real_distribution<double> any(-30.0, 60.0);
        for (int i = 0; i < 60; ++i) from.push_back(any(rng));
        for (int piece = 1; piece <= 3; ++piece)
            for (double off : {-0.5, -1e-7, 0.0, 1e-7, 0.5}) from.push_back(path.join_arc(piece) + off);
        for (double s : from) {
            for (double chord : {0.3, 1.65, 2.86, 4.0, 6.5}) {
                SCOPED_TRACE(::testing::Message() << "entry radius " << design.entry_radius << ", pitch "
                                                  << design.pitch << ", from s = " << s << ", chord " << chord);
                const Located f = path.at_arc(s);
                const auto r = path.behind(f, chord);
                ASSERT_TRUE(r.has_value());
                EXPECT_NEAR(distance(r->pos, f.pos), chord, 1e-10);
                EXPECT_NEAR(path.arc(r->place), brute_behind(path, s, chord), 1e-8);
            }
        }
    }
}

// A place at a join has two names (end of one piece, start of the next): both give the same
// next handle.
TEST(TurnaroundPath, BehindIsTheSameFromEitherNameOfAJoin) {
    const TurnaroundPath path = default_path();
    for (int piece = 1; piece <= 3; ++piece) {
        const Located end = path.at({piece - 1, path.piece_range(piece - 1).second});
        const Located start = path.at({piece, path.piece_range(piece).first});
        for (double chord : {1.65, 2.86, 5.0}) {
            const auto a = path.behind(end, chord), b = path.behind(start, chord);
            ASSERT_TRUE(a && b);
            EXPECT_NEAR(distance(a->pos, b->pos), 0.0, 1e-10);
        }
    }
}

// Whole chains across the turn: every link exact, handles on every piece and on both sides of
// each join, and placed exactly on the joins.
TEST(TurnaroundPath, ChainLinksAreExactAcrossTheTurn) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    const TurnaroundPath path(design_s_curve(sc));
    Frame f;
    int on_piece[4] = {0, 0, 0, 0};
    std::vector<double> heads;
    for (double s = -20.0; s <= 120.0; s += 0.0731) heads.push_back(s);
    // Heads that put handle 1 (and so the whole chain's first links) exactly on each join.
    for (int piece = 1; piece <= 3; ++piece) heads.push_back(path.join_arc(piece) + 2.86);
    for (double s : heads) {
        solve_chain(path, sc.bench, s, 1.0, f);
        for (size_t i = 0; i + 1 < f.handles.size(); ++i) {
            EXPECT_NEAR(distance(f.handles[i].pos, f.handles[i + 1].pos),
                        sc.bench.link_after(static_cast<int>(i)), 1e-10);
            EXPECT_LT(path.arc(f.handles[i + 1].place), path.arc(f.handles[i].place));
            ++on_piece[f.handles[i].place.piece];
        }
    }
    for (int c : on_piece) EXPECT_GT(c, 100);
}

// A link far shorter than the arcs' radii, with the rear handle across a join from the front
// one: the circle-circle intersection must not cancel (the fuzzer found such chords 1e-9 off,
// 2e-11 m on a 0.02 m link; its spec is kept here). Every link straddling a join, at many heads.
TEST(TurnaroundPath, ShortLinksAcrossAJoinAreExact) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    sc.bench.bench_count = 38;
    sc.bench.head_length = 3.4655045599328278;
    sc.bench.body_length = 0.21784931422687723;
    sc.bench.width = 0.18022954703338087;
    sc.bench.hole_offset = 0.099073305445957771;  // body links 0.0197 m
    sc.path.turn_radius = 83.056350042714996;
    sc.path.turn_pitch = 37.386267420845435;
    sc.path.arc_ratio = 0.50078201243756304;
    const TurnaroundPath path(design_s_curve(sc));
    Frame f;
    int straddling = 0;
    for (int piece = 1; piece <= 3; ++piece) {
        for (int k = 0; k < 400; ++k) {
            // Heads that walk the chain's body over the join a few microns at a time.
            solve_chain(path, sc.bench, path.join_arc(piece) + 3.4 + 0.0005 * k, 1.0, f);
            for (size_t i = 0; i + 1 < f.handles.size(); ++i) {
                if (f.handles[i].place.piece == f.handles[i + 1].place.piece) continue;
                ++straddling;
                const double link = sc.bench.link_after(static_cast<int>(i));
                // Positions are ~80 m from the centre: a few roundings of them, nothing more.
                const double slack = 8.0 * std::numeric_limits<double>::epsilon() * norm(f.handles[i].pos);
                EXPECT_NEAR(distance(f.handles[i].pos, f.handles[i + 1].pos), link, slack)
                    << "handles " << i << " (piece " << f.handles[i].place.piece << ") and " << i + 1
                    << " (piece " << f.handles[i + 1].place.piece << ")";
            }
        }
    }
    EXPECT_GT(straddling, 300);
}
