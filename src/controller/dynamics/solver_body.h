#pragma once
/// \file solver_body.h
/// A body as the contact and joint solvers see it, and the impulse arithmetic they share.

#include "model/scalar.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impetus::controller {

/// A body as the constraint solvers see it: velocity, pose and inverse mass properties. Fixed
/// bodies have zero inverse mass and zero velocity. The fields the solvers read most come first and
/// fill one cache line: velocity, angular velocity and the inverse mass properties, which is all
/// the velocity passes read (contact_batches.h).
struct alignas(64) SolverBody {
    Vec2 velocity = Vec2::Zero(); ///< m/s
    Scalar angularVelocity = 0; ///< rad/s
    Scalar invMass = 0; ///< 1/kg
    Vec2 position = Vec2::Zero(); ///< centre of mass, m (moved by position correction)
    Scalar angle = 0; ///< rad (moved by position correction)
    Scalar invInertia = 0; ///< 1/(kg·m²)
    /// Impact impulses applied at time of impact τ·h, summed as Σ τ·Δv: the part of the impact's
    /// velocity change that must not count for the time before the impact (m/s, rad/s).
    Vec2 impactLateVelocity = Vec2::Zero();
    Scalar impactLateAngularVelocity = 0;
    /// The impacts' whole velocity change this step, Σ Δv (m/s, rad/s).
    Vec2 impactVelocity = Vec2::Zero();
    Scalar impactAngularVelocity = 0;
    bool hadImpact = false; ///< an impact impulse acted on this body this step
    /// The latest impact on this body, as a fraction of the step: its contact and joint impulses
    /// act at that time, after the impacts they answer (Simulation::finishBodyPosition).
    Scalar lastImpactTau = 0;
    /// Where the body is at lastImpactTau·h (ContactSolver::solveImpacts), m: the contact and
    /// joint impulses take their lever arms from there, so that each acts at one point in space
    /// on both its bodies and keeps the angular momentum (docs/physics.md, "Conservation").
    Vec2 impulseOrigin = Vec2::Zero();
    bool hadContactForce = false; ///< a contact-force or joint impulse acted on this body this step
    /// The material its contacts mix (its own, or for a soft body's ellipse the soft body's): kept
    /// here because building a contact would otherwise fetch it from the large model::Body.
    Scalar friction = 0;
    Scalar restitution = 0;
    /// A rigid circle's radius, m; 0 for every other shape and for a soft body's ellipse. A
    /// circle's contact point facing the other piece does not turn with it (ContactSolver::refresh);
    /// kept here for the same reason as the material.
    Scalar round = 0;
};

/// The velocity of B's material point at rB relative to A's at rA, m/s.
inline Vec2 relativeVelocity(const SolverBody& a, const SolverBody& b, const Vec2& rA, const Vec2& rB)
{
    return b.velocity + cross(b.angularVelocity, rB) - a.velocity - cross(a.angularVelocity, rA);
}

/// A body that can move (a fixed body has zero inverse mass and inertia).
inline bool movable(const SolverBody& body) { return body.invMass > 0 || body.invInertia > 0; }

/// ½m·v² + ½I·ω² of a body, J; 0 for what cannot move (a fixed body's own surface velocity).
inline Scalar kineticEnergyOf(const SolverBody& body)
{
    Scalar kinetic = 0;
    if (body.invMass > 0)
        kinetic += 0.5 * body.velocity.squaredNorm() / body.invMass;
    if (body.invInertia > 0)
        kinetic += 0.5 * body.angularVelocity * body.angularVelocity / body.invInertia;
    return kinetic;
}

/// Where a body's contact and joint impulses take their lever arms from this step: its place at
/// its last impact, or at the start of the step if it had none, m.
inline const Vec2& impulseOrigin(const SolverBody& body) { return body.hadImpact ? body.impulseOrigin : body.position; }

/// Applies the impulse P (N·s) at the contact: −P on A at rA, +P on B at rB. A fixed body is not
/// written to (for a finite P its velocity would not change anyway, v − 0·P = v), so the two
/// halves of a split world (docs/physics.md, "Two threads"), which share the ground, never write
/// to the same memory.
inline void applyImpulse(SolverBody& a, SolverBody& b, const Vec2& rA, const Vec2& rB, const Vec2& impulse)
{
    if (movable(a)) {
        a.velocity -= a.invMass * impulse;
        a.angularVelocity -= a.invInertia * cross(rA, impulse);
    }
    if (movable(b)) {
        b.velocity += b.invMass * impulse;
        b.angularVelocity += b.invInertia * cross(rB, impulse);
    }
}

/// Moves the bodies as the position-level impulse P would (non-linear Gauss–Seidel): −P on A at
/// rA, +P on B at rB, in m·kg. Fixed bodies are left untouched, as in applyImpulse.
inline void applyPositionImpulse(SolverBody& a, SolverBody& b, const Vec2& rA, const Vec2& rB, const Vec2& impulse)
{
    if (movable(a)) {
        a.position -= a.invMass * impulse;
        a.angle -= a.invInertia * cross(rA, impulse);
    }
    if (movable(b)) {
        b.position += b.invMass * impulse;
        b.angle += b.invInertia * cross(rB, impulse);
    }
}

/// Takes back what a position correction did to the angular momentum. Moving A by −P/m_A and B
/// by +P/m_B (a linear position impulse P, m·kg) while their velocities stay changes the angular
/// momentum about any point by `change` = P × (v_B − v_A) (kg·m²/s). This turns the pair's relative
/// velocity w = v_B − v_A, at its present length, by the angle φ that gives μ·r × w back its value
/// less that change (r = x_B − x_A, μ the reduced mass): the pair's momentum and kinetic energy
/// stay exactly, and the spins are untouched. Of the two angles that do, the one that leaves the
/// pair separating faster along the push P (`push`), among those under a quarter turn, so that the
/// turn never sends a pushed pair back into contact; else the smaller. Where no turn can
/// (|μ·r × w − change| > μ·|r|·|w|: a pair pulled closer while it turns about itself, as a pin
/// does, must spin faster, like a skater pulling in her arms; or w = 0) it adds the smallest
/// relative velocity that does, across r, or of it what adds at most a millionth of the pair's
/// relative kinetic energy. Both bodies must have mass (a fixed body takes any angular momentum
/// anyway).
inline void restoreAngularMomentum(SolverBody& a, SolverBody& b, Scalar change, const Vec2& push)
{
    constexpr Scalar kMaxPushEnergy = 1e-6;
    const Scalar reduced = 1 / (a.invMass + b.invMass);
    const Vec2 r = b.position - a.position;
    const Vec2 w = b.velocity - a.velocity;
    const Scalar along = r.dot(w);
    const Scalar across = cross(r, w);
    const Scalar size = std::hypot(along, across);
    const Scalar target = across - change / reduced;
    const auto apply = [&](const Vec2& dw) {
        a.velocity -= (reduced * a.invMass) * dw;
        b.velocity += (reduced * b.invMass) * dw;
    };
    if (!(std::abs(target) <= size)) {
        const Scalar squared = r.squaredNorm();
        if (!(squared > 0))
            return;
        const Vec2 dw = ((target - across) / squared) * Vec2(-r.y(), r.x()); // r × (−r_y, r_x) = |r|²
        // It adds μ·(w·dw + ½|dw|²) of kinetic energy, which no force paid for. At most
        // kMaxPushEnergy of the pair's relative kinetic energy ½μ|w|²: two bodies whose centres a
        // weld (a pin and a rod) holds nearly together have |r| → 0 and asked for thousands of m/s
        // (soak seed 188); beyond it the pair keeps the rest of the change.
        const Scalar quadratic = 0.5 * dw.squaredNorm();
        const Scalar linear = w.dot(dw);
        const Scalar allowed = kMaxPushEnergy * 0.5 * w.squaredNorm();
        Scalar scale = 1;
        if (linear + quadratic > allowed)
            scale = quadratic > 0 ? std::max((-linear + std::sqrt(linear * linear + 4 * quadratic * allowed)) / (2 * quadratic), 0.0)
                                  : 0.0;
        apply(std::min(scale, 1.0) * dw);
        return;
    }
    // r × (w turned by φ) = across·cos φ + along·sin φ = size·sin(φ + ψ), ψ = atan2(across, along).
    const Scalar wanted = std::asin(target / size);
    const Scalar psi = std::atan2(across, along);
    const auto wrap = [](Scalar angle) { return std::remainder(angle, 2 * std::numbers::pi); };
    const Scalar first = wrap(wanted - psi);
    const Scalar second = wrap(std::numbers::pi - wanted - psi);
    const Scalar quarter = std::numbers::pi / 2;
    Scalar turn = std::abs(first) <= std::abs(second) ? first : second;
    if (std::abs(first) < quarter && std::abs(second) < quarter)
        turn = rotate(w, first).dot(push) >= rotate(w, second).dot(push) ? first : second;
    apply(rotate(w, turn) - w);
}

/// The effective mass 1/K (kg) for an impulse along `direction` at rA, rB; 0 when nothing can move.
inline Scalar effectiveMass(const SolverBody& a, const SolverBody& b, const Vec2& rA, const Vec2& rB,
                            const Vec2& direction)
{
    const Scalar rnA = cross(rA, direction);
    const Scalar rnB = cross(rB, direction);
    const Scalar k = a.invMass + b.invMass + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
    return k > 0 ? 1 / k : 0;
}

} // namespace impetus::controller
