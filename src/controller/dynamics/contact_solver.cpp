// ContactSolver's shared pieces: the material mix, the bodies' rotations, and running its groups
// on one thread or two. The phases are in contact_prepare, contact_impacts, contact_velocities and
// contact_positions; the order in contact_order.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"
#include "controller/dynamics/small_turn.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace impetus::controller {

namespace detail {

/// The effective-mass matrix K of a contact's normal impulses, 1/kg: for two points the 2×2 matrix
/// of the block solve; for one, K₁₁ = 1/(its normal mass) and the rest 0.
Eigen::Matrix2d normalK(const ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
    Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
    const ContactConstraintPoint& p1 = c.points[0];
    if (c.pointCount != 2) {
        k(0, 0) = p1.normalMass > 0 ? 1 / p1.normalMass : 0;
        return k;
    }
    const ContactConstraintPoint& p2 = c.points[1];
    const Scalar rn1A = cross(p1.rA, c.normal);
    const Scalar rn1B = cross(p1.rB, c.normal);
    const Scalar rn2A = cross(p2.rA, c.normal);
    const Scalar rn2B = cross(p2.rB, c.normal);
    const Scalar m = a.invMass + b.invMass;
    const Scalar k11 = m + a.invInertia * rn1A * rn1A + b.invInertia * rn1B * rn1B;
    const Scalar k22 = m + a.invInertia * rn2A * rn2A + b.invInertia * rn2B * rn2B;
    const Scalar k12 = m + a.invInertia * rn1A * rn2A + b.invInertia * rn1B * rn2B;
    k << k11, k12, k12, k22;
    return k;
}

} // namespace detail

Scalar mixRestitution(Scalar a, Scalar b) { return std::max(a, b); }

// Equal materials, the common case, skip the square root: √(μ·μ) rounds back to exactly μ anyway.
Scalar mixFriction(Scalar a, Scalar b) { return a == b ? a : std::sqrt(a * b); }

void ContactSolver::computeRotations(std::span<const SolverBody> bodies, bool split)
{
    m_rotations.resize(bodies.size());
    m_rotationAngles.resize(bodies.size());
    inHalves(split ? m_tasks : nullptr, bodies.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            m_rotations[i] = Vec2(std::cos(bodies[i].angle), std::sin(bodies[i].angle));
            m_rotationAngles[i] = bodies[i].angle;
        }
    });
}

void ContactSolver::turnRotations(std::span<const SolverBody> bodies, bool split)
{
    assert(m_rotations.size() == bodies.size() && m_rotationAngles.size() == bodies.size());
    // Between the substeps of a step a body turns by ω·h: a few thousandths of a radian in a
    // pile, where std::cos and std::sin of every body's angle cost as much as a position pass.
    inHalves(split ? m_tasks : nullptr, bodies.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            detail::turnTo(m_rotations[i], m_rotationAngles[i], bodies[i].angle); // nothing at rest
    });
}

void ContactSolver::runGroups(const std::function<void(int)>& solve)
{
    if (m_split && m_tasks) {
        m_tasks->run(solve);
    } else {
        solve(0);
        solve(1);
    }
    solve(2);
}

void ContactSolver::forEachGroupIndex(const std::function<void(std::span<const std::uint32_t>, int)>& solve)
{
    runGroups([&](int g) { solve(m_groups[static_cast<std::size_t>(g)], g); });
}

void ContactSolver::forEachGroup(const std::function<void(std::span<VelocityConstraint>, int)>& solve)
{
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        solve(std::span<VelocityConstraint>(m_velocityConstraints).subspan(m_groupStart[ug],
                                                                           m_groupStart[ug + 1] - m_groupStart[ug]),
              g);
    });
}

} // namespace impetus::controller
