#pragma once
/// \file transform.h
/// A rigid 2D transform (rotation then translation), with the rotation's cosine and sine cached.

#include "model/body.h"
#include "model/scalar.h"

#include <cmath>

namespace impetus::controller {

/// world = position + R·local, where R rotates counter-clockwise by the angle whose cosine and sine
/// are `c` and `s`.
struct Transform {
    Vec2 position = Vec2::Zero(); ///< m
    Scalar c = 1; ///< cos(angle)
    Scalar s = 0; ///< sin(angle)

    /// The transform of a body's frame in `state` (origin at the centre of mass).
    static Transform of(const model::BodyState& state)
    {
        return Transform{state.position, std::cos(state.angle), std::sin(state.angle)};
    }

    /// R·v: a body-frame direction in world coordinates.
    Vec2 rotate(const Vec2& v) const { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); }

    /// Rᵀ·v: a world direction in body-frame coordinates.
    Vec2 inverseRotate(const Vec2& v) const { return Vec2(c * v.x() + s * v.y(), -s * v.x() + c * v.y()); }

    /// position + R·local: a body-frame point in world coordinates.
    Vec2 apply(const Vec2& local) const { return position + rotate(local); }

    /// Rᵀ·(world − position): a world point in body-frame coordinates.
    Vec2 inverseApply(const Vec2& world) const { return inverseRotate(Vec2(world - position)); }
};

} // namespace impetus::controller
