#pragma once
/// \file small_turn.h
/// The cosine and sine of an angle kept up to date as it turns by small amounts, without calling
/// std::cos and std::sin: the batched position passes turn their poses this way, and the contact
/// solver its bodies' rotations between the substeps of a step.

#include "model/scalar.h"

#include <cmath>

namespace impetus::controller::detail {

/// Below this turn (rad) the cosine and sine are updated by the angle-sum formulas with Taylor
/// polynomials of the turn, whose first neglected terms (δ⁹/9!, δ¹⁰/10!) stay below 1e-17; a
/// larger turn takes std::cos and std::sin of the new angle.
inline constexpr Scalar kSmallTurn = 0.05;

/// The Taylor coefficients of sin δ = δ Σ sₖ δ²ᵏ and cos δ = Σ cₖ δ²ᵏ: 1/n! with its sign, as
/// constants, so that the polynomials cost multiplications alone (written as divisions by 6, 20,
/// 42…, they compiled to seven divisions a turn).
inline constexpr Scalar kSin3 = -1.0 / 6;
inline constexpr Scalar kSin5 = 1.0 / 120;
inline constexpr Scalar kSin7 = -1.0 / 5040;
inline constexpr Scalar kCos2 = -1.0 / 2;
inline constexpr Scalar kCos4 = 1.0 / 24;
inline constexpr Scalar kCos6 = -1.0 / 720;
inline constexpr Scalar kCos8 = 1.0 / 40320;

/// Turns (cosine, sine) by δ (|δ| ≤ kSmallTurn): one number, or a vector of lanes, each lane with
/// the same arithmetic as one number. Horner's rule in δ²: the rounding of each coefficient (a
/// relative 1e-16) is multiplied by δ² ≤ 0.0025 at least, far below the first neglected term.
template <class T>
[[gnu::always_inline]] inline void turnSmall(T& cosine, T& sine, const T& delta)
{
    const T d2 = delta * delta;
    const T sinDelta = delta + delta * (d2 * (kSin3 + d2 * (kSin5 + d2 * kSin7)));
    const T cosDelta = 1 + d2 * (kCos2 + d2 * (kCos4 + d2 * (kCos6 + d2 * kCos8)));
    const T turnedCosine = cosine * cosDelta - sine * sinDelta;
    const T turnedSine = sine * cosDelta + cosine * sinDelta;
    cosine = turnedCosine;
    sine = turnedSine;
}

/// Brings `rotation`, the cosine and sine of `turnedAngle`, to `angle`: by the turn between them
/// where it is small (≤ kSmallTurn) and `small` allows, else with std::cos and std::sin of
/// `angle` (a NaN angle lands there too); nothing where the angle has not changed.
inline void turnTo(Vec2& rotation, Scalar& turnedAngle, Scalar angle, bool small = true)
{
    const Scalar delta = angle - turnedAngle;
    if (delta == 0)
        return;
    if (small && std::abs(delta) <= kSmallTurn) {
        Scalar cosine = rotation.x();
        Scalar sine = rotation.y();
        turnSmall(cosine, sine, delta);
        rotation = Vec2(cosine, sine);
    } else {
        rotation = Vec2(std::cos(angle), std::sin(angle));
    }
    turnedAngle = angle;
}

} // namespace impetus::controller::detail
