#pragma once
/// \file scalar.h
/// The one precision switch of Impetus: every quantity in the engine is a `Scalar` (double) and
/// every 2D vector a `Vec2` (Eigen). Units are SI throughout: metres, kilograms, seconds, radians.

#include <Eigen/Core>

#include <cmath>

namespace impetus {

/// The floating-point type of every physical quantity.
using Scalar = double;

/// A 2D vector in metres (positions), m/s (velocities), N (forces), ... The world's y axis points up.
using Vec2 = Eigen::Vector2d;

/// The 2D cross product a × b = a.x·b.y − a.y·b.x (the z component of the 3D cross product).
inline Scalar cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// ω × r for a scalar angular velocity ω (rad/s) about z: (−ω·r.y, ω·r.x).
inline Vec2 cross(Scalar w, const Vec2& r) { return Vec2(-w * r.y(), w * r.x()); }

/// r rotated counter-clockwise by `angle` radians.
inline Vec2 rotate(const Vec2& r, Scalar angle)
{
    const Scalar c = std::cos(angle);
    const Scalar s = std::sin(angle);
    return Vec2(c * r.x() - s * r.y(), s * r.x() + c * r.y());
}

/// True when both components are finite (neither NaN nor infinite).
inline bool isFinite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

} // namespace impetus
