#pragma once
/// \file impact_record.h
/// What one impact of the contact solver did, recorded where the impulse is computed when a log
/// is attached (Simulation::setImpactLog): the numbers the collision inspector fills into the
/// impulse formula (docs/explainers.md, "The collision inspector"). The step attaches none.

#include "model/scalar.h"

#include <array>
#include <cstdint>

namespace impetus::controller {

/// One point of an impact: where it struck and what it took.
struct ImpactPointRecord {
    Vec2 rA = Vec2::Zero(); ///< lever arm from A's centre of mass to the point at impact, m
    Vec2 rB = Vec2::Zero(); ///< lever arm from B's centre of mass, m
    Scalar tau = 0; ///< time of impact as a fraction of the (sub)step
    Scalar approachSpeed = 0; ///< relative normal velocity vₙ at impact (< 0: approaching), m/s
    Scalar targetSpeed = 0; ///< the normal speed the impulse aims for: −e·vₙ (or 0 below the threshold), m/s
    Scalar normalImpulse = 0; ///< j along the normal, N·s
    Scalar tangentSpeed = 0; ///< relative tangential velocity after the normal impulse, m/s
    Scalar tangentMass = 0; ///< 1/(1/mA + 1/mB + (rA×t)²/IA + (rB×t)²/IB), kg
    Scalar frictionLimit = 0; ///< μ·j, N·s
    Scalar frictionImpulse = 0; ///< along the tangent, clamped to ±frictionLimit, N·s
};

/// A body's velocity and inverse mass properties at one moment of an impact.
struct ImpactBodyState {
    Scalar invMass = 0; ///< 1/kg (0: fixed)
    Scalar invInertia = 0; ///< 1/(kg·m²) (0: fixed, or cannot turn)
    Vec2 velocity = Vec2::Zero(); ///< of the centre of mass, m/s
    Scalar angularVelocity = 0; ///< rad/s
};

/// One impact resolved by ContactSolver::solveImpacts: one or two points of one contact, struck
/// at once.
struct ImpactRecord {
    std::uint32_t ownerA = 0; ///< World::bodies index owning piece A (lower than ownerB)
    std::uint32_t ownerB = 0; ///< World::bodies index owning piece B
    Vec2 normal = Vec2::Zero(); ///< unit, from A to B
    Vec2 tangent = Vec2::Zero(); ///< unit, the friction direction
    Scalar restitution = 0; ///< mixed e
    Scalar friction = 0; ///< mixed μ
    int count = 0; ///< points struck together (1 or 2)
    std::array<ImpactPointRecord, 2> points{};
    /// The effective-mass matrix K (1/kg): K(i, j) = 1/mA + 1/mB + (rAi×n)(rAj×n)/IA + (rBi×n)(rBj×n)/IB.
    std::array<std::array<Scalar, 2>, 2> k{};
    ImpactBodyState beforeA; ///< A just before the impact
    ImpactBodyState beforeB;
    ImpactBodyState afterNormalA; ///< after the normal impulse, before friction
    ImpactBodyState afterNormalB;
    ImpactBodyState afterA; ///< after the normal and friction impulses
    ImpactBodyState afterB;
};

} // namespace impetus::controller
