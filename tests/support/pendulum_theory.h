#pragma once
/// \file pendulum_theory.h
/// The textbook period of a pendulum at any amplitude, for the tests that check the engine against
/// it (tests/controller/joint_test.cpp, tests/scenes/examples_test.cpp).

#include "model/scalar.h"

#include <cmath>
#include <numbers>

namespace impetus::testing {

/// Complete elliptic integral of the first kind K(k) by the arithmetic–geometric mean:
/// K(k) = π / (2·AGM(1, √(1 − k²))). Precondition: 0 ≤ k < 1.
inline Scalar ellipticK(Scalar k)
{
    Scalar a = 1;
    Scalar b = std::sqrt(1 - k * k);
    for (int i = 0; i < 30; ++i) {
        const Scalar next = (a + b) / 2;
        b = std::sqrt(a * b);
        a = next;
    }
    return std::numbers::pi_v<Scalar> / (2 * a);
}

/// Period of a simple pendulum of length L (m) released from rest at amplitude θ₀ (rad) under
/// gravity g (m/s²): T = 4√(L/g)·K(sin(θ₀/2)), s. It tends to 2π√(L/g) as θ₀ → 0.
inline Scalar pendulumPeriod(Scalar length, Scalar gravity, Scalar amplitude)
{
    return 4 * std::sqrt(length / gravity) * ellipticK(std::sin(amplitude / 2));
}

} // namespace impetus::testing
