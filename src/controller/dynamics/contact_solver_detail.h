#pragma once
/// \file contact_solver_detail.h
/// What the contact solver's phases (contact_prepare, contact_impacts, contact_velocities,
/// contact_positions, contact_order) share inside the engine. Not for use outside
/// controller/dynamics.

#include "controller/dynamics/contact_solver.h"
#include "controller/transform.h"
#include "model/constants.h"

#include <Eigen/Core>

#include <algorithm>
#include <optional>
#include <span>

namespace impetus::controller::detail {

/// The 2×2 block solve is used only when K's condition number stays below this: two contact
/// points that (nearly) coincide make K singular, and then the points are solved one at a time.
inline constexpr Scalar kMaxBlockConditionNumber = 1000.0;

/// The impact pass looks again at the contacts of the two bodies of each impact; it stops when it
/// has looked at this many contacts per contact of the step (or kMinImpactVisits, for small
/// worlds), and what still approaches is left to the velocity passes, as at the per-point cap.
/// A count of impacts alone did not bound the work: in a packed pile struck at 100 m/s (Box2D
/// v3's spinner, whose 6076 bodies start overlapping) a fast body has dozens of speculative
/// contacts, and 258,000 impacts looked at 10⁸ of them: 4 s, then over a minute, a step.
/// The spinner meets this budget in every substep; a look there costs about what a contact of one
/// velocity pass does (27 and 21 ns, most looks ruled out by bounds, staysOpen in
/// contact_impacts.cpp), so the budget is the work of some sixteen velocity passes.
inline constexpr std::size_t kMaxImpactVisitsPerContact = 16;
/// The floor of that budget: a Newton's cradle or a struck stack of a few bodies, whose impacts
/// each pass the blow on, never meets it (a cradle of 5 balls looks at about 20 contacts).
inline constexpr std::size_t kMinImpactVisits = 4096;

/// The most impacts one contact between a pinched body and a fixed one takes in a step; what
/// still approaches there is left to the velocity and position passes. A body is pinched when two
/// fixed bodies, one of them moving, have struck it in the step: caught between them as they
/// close, it has no rigid answer once the gap is smaller than the body, and before that the rigid
/// answer squirts it out of the wedge at about u / tan α, u the closing speed and α the wedge's
/// half-angle, with ever more impacts as the gap closes. Box2D v3's spinner has such a wedge: its
/// arm's tip passes within 0.2 m of the ring, and through it at the bottom. Struck back and forth
/// between the two, one body left the arm at 568 m/s (α ≈ 8°) spinning at 2,400 rad/s after 40
/// impacts in one step; its speculative margins then gave that step 800,000 contacts, 30 times
/// the median step's work. A body between a fixed body and a moving dynamic one (a light ball
/// knocked against a wall by a heavy one) is not pinched: the dynamic one gives way, and the ball
/// rattles between the two with as many impacts as it takes.
inline constexpr std::uint8_t kMaxFixedImpactsPerContact = 2;

/// A touching pair whose masses differ by this factor or more makes its light body a prop where a
/// fixed body holds it (ContactSolver::findProps). A pass of sequential impulses between a wall,
/// a light body and a body R times as heavy takes about 1/(1 + R) of the heavy body's approach;
/// at R = 10 the eight passes of a step leave it nearly half (0.91⁸ = 0.47), at R = 100 over nine
/// tenths, and a tonne on a 0.3 kg block sank through the block and the floor (R = 3,300). Below
/// it the warm start carries the load from step to step as in any stack. It was 100 until a soft
/// ball's 14 kg ellipses pressed a 0.3 kg ellipse through a wall (R = 42, soak seed 3433).
inline constexpr Scalar kPropMassRatio = 10.0;
/// How squarely a fixed body must push a prop against the heavy body's push to hold it: the cosine
/// of the widest angle between the two, 45°.
inline constexpr Scalar kPropMinOpposition = 0.70710678118654752;

/// One position pass's look at point p of c (non-linear Gauss–Seidel): the surface points'
/// separation along the normal, which turns with A, at the bodies' poses, given each one's
/// (cos, sin); and, when it is deeper than the slop, the lever arms and the position impulse that
/// corrects it (zero impulse otherwise).
struct PositionCorrection {
    Scalar separation = 0; ///< m
    Vec2 rA = Vec2::Zero();
    Vec2 rB = Vec2::Zero();
    Vec2 impulse = Vec2::Zero(); ///< m·kg, +P on B and −P on A
};
/// Where point p of c is at the bodies' poses (each one's (cos, sin)): the normal, which turns
/// with A, the surface points' separation along it, and the lever arms of the point half-way
/// between them.
struct ContactGeometry {
    Vec2 normal = Vec2::Zero();
    Scalar separation = 0; ///< m
    Vec2 rA = Vec2::Zero();
    Vec2 rB = Vec2::Zero();
};
inline ContactGeometry contactGeometry(const ContactConstraint& c, const ContactConstraintPoint& p, const SolverBody& a,
                                       const SolverBody& b, const Vec2& rotationA, const Vec2& rotationB)
{
    const Transform frameA{a.position, rotationA.x(), rotationA.y()};
    const Transform frameB{b.position, rotationB.x(), rotationB.y()};
    ContactGeometry out;
    out.normal = frameA.rotate(c.localNormalA);
    const Vec2 pointA = frameA.apply(p.localAnchorA);
    const Vec2 pointB = frameB.apply(p.localAnchorB);
    out.separation = (pointB - pointA).dot(out.normal);
    const Vec2 mid = 0.5 * (pointA + pointB);
    out.rA = mid - a.position;
    out.rB = mid - b.position;
    return out;
}

inline PositionCorrection positionCorrection(const ContactConstraint& c, const ContactConstraintPoint& p,
                                             const SolverBody& a, const SolverBody& b, const Vec2& rotationA,
                                             const Vec2& rotationB)
{
    PositionCorrection out;
    const ContactGeometry look = contactGeometry(c, p, a, b, rotationA, rotationB);
    out.separation = look.separation;
    const Scalar correction = std::clamp(constants::kPositionCorrectionFactor * (out.separation + constants::kLinearSlop),
                                         -constants::kMaxPositionCorrection, 0.0);
    if (correction == 0)
        return out;
    out.rA = look.rA;
    out.rB = look.rB;
    out.impulse = (-correction * effectiveMass(a, b, out.rA, out.rB, look.normal)) * look.normal;
    return out;
}

/// The tangent of a contact: the normal turned clockwise, so (n, t) is a right-handed pair.
inline Vec2 tangentOf(const Vec2& n) { return Vec2(n.y(), -n.x()); }

/// The fastest approach among c's points that is an impact this step, m/s (< 0); 0 when none is
/// (contact_impacts.cpp). Within the impact pass, `impacts` is the solver whose impacts have
/// already struck some bodies: a struck body's contacts then close from the gap left at its last
/// impact (nullptr before any impact: from the step's start). (A plain number, not an optional:
/// an optional came back through the stack, its flag written as a byte and read as a word, and
/// the read waited on the write in every call of the refresh and the build.)
Scalar fastestApproach(const ContactConstraint& c, std::span<const SolverBody> bodies, Scalar h,
                       const ContactSolver* impacts = nullptr);

/// The effective-mass matrix K of a contact's normal impulses, 1/kg: for two points the 2×2 matrix
/// of the block solve; for one, K₁₁ = 1/(its normal mass) and the rest 0.
Eigen::Matrix2d normalK(const ContactConstraint& c, const SolverBody& a, const SolverBody& b);

} // namespace impetus::controller::detail
