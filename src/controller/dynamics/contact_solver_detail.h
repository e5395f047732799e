#pragma once
/// \file contact_solver_detail.h
/// What the contact solver's phases (contact_prepare, contact_impacts, contact_velocities,
/// contact_positions, contact_order) share inside the engine. Not for use outside
/// controller/dynamics.

#include "controller/dynamics/contact_solver.h"

#include <Eigen/Core>

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
/// 16 visits per contact is about the work of two velocity iterations.
inline constexpr std::size_t kMaxImpactVisitsPerContact = 16;
/// The floor of that budget: a Newton's cradle or a struck stack of a few bodies, whose impacts
/// each pass the blow on, never meets it (a cradle of 5 balls looks at about 20 contacts).
inline constexpr std::size_t kMinImpactVisits = 4096;

/// The tangent of a contact: the normal turned clockwise, so (n, t) is a right-handed pair.
inline Vec2 tangentOf(const Vec2& n) { return Vec2(n.y(), -n.x()); }

/// The fastest approach among c's points that is an impact this step, m/s (< 0); nothing when
/// none is (contact_impacts.cpp). Within the impact pass, `impacts` is the solver whose impacts
/// have already struck some bodies: a struck body's contacts then close from the gap left at its
/// last impact (nullptr before any impact: from the step's start).
std::optional<Scalar> fastestApproach(const ContactConstraint& c, std::span<const SolverBody> bodies, Scalar h,
                                      const ContactSolver* impacts = nullptr);

/// The effective-mass matrix K of a contact's normal impulses, 1/kg: for two points the 2×2 matrix
/// of the block solve; for one, K₁₁ = 1/(its normal mass) and the rest 0.
Eigen::Matrix2d normalK(const ContactConstraint& c, const SolverBody& a, const SolverBody& b);

} // namespace impetus::controller::detail
