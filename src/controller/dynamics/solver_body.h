#pragma once
/// \file solver_body.h
/// A body as the contact and joint solvers see it, and the impulse arithmetic they share.

#include "model/scalar.h"

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
};

/// The velocity of B's material point at rB relative to A's at rA, m/s.
inline Vec2 relativeVelocity(const SolverBody& a, const SolverBody& b, const Vec2& rA, const Vec2& rB)
{
    return b.velocity + cross(b.angularVelocity, rB) - a.velocity - cross(a.angularVelocity, rA);
}

/// A body that can move (a fixed body has zero inverse mass and inertia).
inline bool movable(const SolverBody& body) { return body.invMass > 0 || body.invInertia > 0; }

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
