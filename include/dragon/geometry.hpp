// Small plane-geometry value types: points, directions and oriented rectangles.
#pragma once

#include <cmath>

namespace dragon {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
constexpr Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
constexpr Vec2 operator*(Vec2 a, double k) { return {k * a.x, k * a.y}; }
constexpr Vec2 operator/(Vec2 a, double k) { return {a.x / k, a.y / k}; }
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
// z component of the 3-D cross product: positive when b is counter-clockwise of a.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
// a turned by +90 degrees (counter-clockwise).
constexpr Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
// Plain sqrt, not std::hypot: lengths here are metres, far from overflow, and hypot is ~10x slower.
inline double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
inline double distance(Vec2 a, Vec2 b) { return norm(a - b); }
inline Vec2 normalized(Vec2 a) { return a / norm(a); }
// Rotation by angle phi (radians, counter-clockwise).
inline Vec2 rotated(Vec2 a, double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return {c * a.x - s * a.y, s * a.x + c * a.y};
}

// An oriented rectangle: a bench board seen from above.
struct Rect {
    Vec2 centre;
    Vec2 axis;             // unit vector along the long side (from the rear handle to the front one)
    double half_length = 0;  // along axis
    double half_width = 0;   // across axis
};

// Centre to corner: the radius of the rectangle's bounding circle.
inline double half_diagonal(const Rect& r) { return std::sqrt(r.half_length * r.half_length + r.half_width * r.half_width); }

// The distance from p to rectangle r (0 inside it) and the point of r nearest p.
struct PointToRect {
    double distance;
    Vec2 nearest;
};
inline PointToRect point_to_rect(Vec2 p, const Rect& r) {
    const Vec2 n = perp(r.axis);
    const Vec2 w = p - r.centre;
    const double x = dot(w, r.axis), y = dot(w, n);
    const double cx = x < -r.half_length ? -r.half_length : x > r.half_length ? r.half_length : x;
    const double cy = y < -r.half_width ? -r.half_width : y > r.half_width ? r.half_width : y;
    return {std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy)), r.centre + cx * r.axis + cy * n};
}

// The four corners, counter-clockwise when axis points right.
struct Corners {
    Vec2 p[4];
};
inline Corners corners(const Rect& r) {
    const Vec2 a = r.half_length * r.axis;
    const Vec2 n = r.half_width * perp(r.axis);
    return {{r.centre - a - n, r.centre + a - n, r.centre + a + n, r.centre - a + n}};
}

}  // namespace dragon
