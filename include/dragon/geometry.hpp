// Small plane-geometry value types: points, directions and oriented rectangles.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace dragon {

// Points and directions are Eigen's fixed-size 2-vectors, so a caller's Eigen code takes them as
// they are. Eigen leaves a default-constructed vector uninitialised: every Vec2 here is given its
// value where it is declared (the sanitized test build fills defaults with NaN to keep it so).
using Vec2 = Eigen::Vector2d;

// The few operations the geometry is written in, named as a reader of the maths says them.
// dot is written out: Eigen's a.dot(b) multiplies both lanes in one SSE register and then adds
// its halves across it, two instructions more than the scalar form on the clearance pass's path.
inline double dot(const Vec2& a, const Vec2& b) { return a.x() * b.x() + a.y() * b.y(); }
// z component of the 3-D cross product: positive when b is counter-clockwise of a.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
// a turned by +90 degrees (counter-clockwise).
inline Vec2 perp(const Vec2& a) { return {-a.y(), a.x()}; }
// Eigen's norm is a plain sqrt of the squared sum, not std::hypot: lengths here are metres, far
// from overflow, and hypot is ~10x slower.
inline double norm(const Vec2& a) { return a.norm(); }
inline double distance(const Vec2& a, const Vec2& b) { return norm(a - b); }  // |a - b|
inline Vec2 normalized(const Vec2& a) { return a / norm(a); }                // a / |a|, for a != 0

// An oriented rectangle: a bench board seen from above.
struct Rect {
    Vec2 centre = Vec2::Zero();  // m
    Vec2 axis = Vec2::Zero();  // unit vector along the long side (from the rear handle to the front one)
    double half_length = 0;  // along axis
    double half_width = 0;   // across axis
};

// Centre to corner: the radius of the rectangle's bounding circle.
inline double half_diagonal(const Rect& r) { return std::sqrt(r.half_length * r.half_length + r.half_width * r.half_width); }

// The distance from p to rectangle r (0 inside it) and the point of r nearest p.
struct PointToRect {
    double distance;              // m; 0 inside the rectangle
    Vec2 nearest = Vec2::Zero();  // the point of the rectangle nearest p
};
// The distance from p to r and r's point nearest p.
inline PointToRect point_to_rect(const Vec2& p, const Rect& r) {
    const Vec2 n = perp(r.axis);
    const Vec2 w = p - r.centre;
    const double x = dot(w, r.axis), y = dot(w, n);
    const double cx = x < -r.half_length ? -r.half_length : x > r.half_length ? r.half_length : x;
    const double cy = y < -r.half_width ? -r.half_width : y > r.half_width ? r.half_width : y;
    return {std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy)), r.centre + cx * r.axis + cy * n};
}

// The four corners, counter-clockwise when axis points right.
struct Corners {
    Vec2 p[4];  // the corners in order
};
// The four corners of r, in that order.
inline Corners corners(const Rect& r) {
    const Vec2 a = r.half_length * r.axis;
    const Vec2 n = r.half_width * perp(r.axis);
    return {{r.centre - a - n, r.centre + a - n, r.centre + a + n, r.centre - a + n}};
}

}  // namespace dragon
