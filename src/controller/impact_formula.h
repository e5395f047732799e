#pragma once
/// \file impact_formula.h
/// The impulse formula of an impact with its numbers filled in, from the engine's own record of
/// the impact (dynamics/impact_record.h): what the collision inspector shows (docs/explainers.md).

#include "controller/dynamics/impact_record.h"
#include "model/scalar.h"

#include <array>

namespace impetus::controller {

/// The formula's terms at one point of an impact.
struct ImpactFormulaPoint {
    Scalar rnA = 0; ///< rA × n, m
    Scalar rnB = 0; ///< rB × n, m
    /// The denominator K = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB, 1/kg.
    Scalar denominator = 0;
    Scalar approachSpeed = 0; ///< vₙ before, m/s (< 0: approaching)
    /// Whether vₙ was fast enough to bounce (|vₙ| > constants::kRestitutionThreshold); otherwise
    /// the impulse only stops the approach (e counts as 0).
    bool bounces = false;
    /// j = −(1 + e)·vₙ / K (or −vₙ / K without a bounce), N·s: the single-point formula. For two
    /// points struck together it is what the point would take alone, not what it took.
    Scalar formulaImpulse = 0;
    Scalar engineImpulse = 0; ///< the impulse the engine applied at this point, N·s
    /// vₙ after the normal impulses: vₙ + Σⱼ K(i, j)·jⱼ with the engine's impulses, m/s.
    Scalar speedAfter = 0;
    Scalar tangentSpeed = 0; ///< relative tangential speed after the normal impulse, m/s
    /// Kₜ = 1/mA + 1/mB + (rA×t)²/IA + (rB×t)²/IB, 1/kg.
    Scalar tangentDenominator = 0;
    Scalar frictionNeeded = 0; ///< −vₜ / Kₜ: the impulse that would stop the sliding, N·s
    Scalar frictionLimit = 0; ///< μ·j, N·s
    Scalar frictionImpulse = 0; ///< the needed impulse clamped to ±μ·j, N·s
    bool slid = false; ///< |needed| > μ·j: the point slid (friction at its limit); else it stuck
};

/// Momentum and kinetic energy of the movable bodies of the pair (a fixed body has neither).
struct PairTotals {
    Vec2 momentum = Vec2::Zero(); ///< Σ m·v, kg·m/s
    Scalar energy = 0; ///< Σ ½m·v² + ½I·ω², J
};

/// An impact's formula, evaluated.
struct ImpactFormula {
    Scalar massA = 0; ///< kg; +∞ for a fixed body
    Scalar massB = 0;
    Scalar invInertiaA = 0; ///< 1/(kg·m²)
    Scalar invInertiaB = 0;
    Scalar restitution = 0; ///< e
    Scalar friction = 0; ///< μ
    int count = 0; ///< points struck together
    std::array<ImpactFormulaPoint, 2> points{};
    PairTotals before; ///< just before the impact
    PairTotals after; ///< after its normal and friction impulses
};

/// The pair's momentum and energy in `a` and `b`.
PairTotals pairTotals(const ImpactBodyState& a, const ImpactBodyState& b);

/// Evaluates the impulse formula (seed S0; docs/physics.md) on the pre-impact state of `record`.
ImpactFormula impactFormula(const ImpactRecord& record);

} // namespace impetus::controller
