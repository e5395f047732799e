// UnlikeMassIslands: small jointed islands of very unlike masses, all their joints and contacts
// solved at once after the velocity passes (unlike_masses.h says why).

#include "controller/dynamics/unlike_masses.h"

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"
#include "controller/dynamics/joint_solver.h"
#include "controller/union_find.h"
#include "model/constants.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace impetus::controller {

namespace {

/// The fixed world of a joint row: no mass, at rest.
const SolverBody kWorldBody{};

const SolverBody& bodyAt(std::span<const SolverBody> bodies, std::uint32_t index)
{
    return index == ConstraintRow::kNoBody ? kWorldBody : bodies[index];
}

/// Rounds of the velocity solve: the rod's row is its end condition to first order, which a
/// round may leave a little of.
constexpr int kRounds = 3;

/// How much faster than the island's fastest body before the solve one may leave it, and the
/// slack for an island at rest (m/s, rad/s).
constexpr Scalar kMaxSpeedUp = 2;
constexpr Scalar kSpeedSlack = 1;
constexpr Scalar kSpinSlack = 6;

/// Rounds of the position solve, each at the poses the last left (the rows are linearised).
constexpr int kPositionRounds = 3;

/// The farthest the position solve may move a body, m: an island whose rows contradict each
/// other asks for more, and is left to the passes.
constexpr Scalar kMaxShift = 0.1;

/// A row's velocity error that is left alone, m/s.
constexpr Scalar kTolerance = 1e-9;

/// How much the kinetic energy of an island may grow in its solve, relative: round-off only.
constexpr Scalar kEnergyTolerance = 1e-9;

/// The part of a body in a row: its index, the row's sign on it (−1 for A, +1 for B), its lever arm
/// and its share.
struct RowSide {
    std::uint32_t body;
    Scalar sign;
    const Vec2* r;
    Scalar share;
};

/// What a unit impulse of row j does to row i's value, through the bodies they share: J_i·M⁻¹·G_jᵀ,
/// where J weighs each body's velocity by its share of the step and G applies the impulse whole.
/// Every row takes a body's share from the body (velocityShare), so this is symmetric.
Scalar effect(const ConstraintRow& i, const ConstraintRow& j, std::span<const SolverBody> bodies)
{
    const RowSide sidesI[2] = {{i.bodyA, -1, &i.rA, i.shareA}, {i.bodyB, 1, &i.rB, i.shareB}};
    const RowSide sidesJ[2] = {{j.bodyA, -1, &j.rA, j.shareA}, {j.bodyB, 1, &j.rB, j.shareB}};
    Scalar sum = 0;
    for (const RowSide& p : sidesI) {
        if (p.body == ConstraintRow::kNoBody)
            continue;
        for (const RowSide& q : sidesJ) {
            if (q.body != p.body)
                continue;
            const SolverBody& body = bodies[p.body];
            const Scalar linear = body.invMass * i.direction.dot(j.direction);
            const Scalar angular = body.invInertia * cross(*p.r, i.direction) * cross(*q.r, j.direction);
            sum += p.sign * q.sign * p.share * (linear + angular);
        }
    }
    return sum;
}

/// Moves a contact row's side on a soft body's ellipse onto the grid's aggregate `grid` (`sign`:
/// −1 for side A, +1 for B; `r`, the arm from the ellipse's impulse origin, and `share` are that
/// side's). The arm runs from the aggregate to the contact point, where the other body's arm ends,
/// so that the island's impulses keep the angular momentum; the share is the aggregate's, so that
/// every row on the grid weighs it alike (effect() is then symmetric); and the offset keeps the
/// row's present value: what the ellipse's own velocity adds to the grid's rigid motion there. The
/// grid hands its aggregate's change on to the ellipse at the ellipse's centre
/// (Simulation::shareJointMotion), which the row sees only to within the turn across the ellipse.
void onGrid(ConstraintRow& row, const SolverBody& ellipse, const SolverBody& grid, Vec2& r, Scalar& share, Scalar sign)
{
    r = impulseOrigin(ellipse) + r - grid.position;
    const Scalar gridShare = velocityShare(grid);
    const Vec2 rigid = grid.velocity + cross(grid.angularVelocity, r);
    row.offset += sign * row.direction.dot(Vec2(share * ellipse.velocity - gridShare * rigid));
    share = gridShare;
}

} // namespace

Scalar rowValue(const ConstraintRow& row, std::span<const SolverBody> bodies)
{
    const SolverBody& a = bodyAt(bodies, row.bodyA);
    const SolverBody& b = bodyAt(bodies, row.bodyB);
    const Vec2 vA = a.velocity + cross(a.angularVelocity, row.rA);
    const Vec2 vB = b.velocity + cross(b.angularVelocity, row.rB);
    return row.direction.dot(Vec2(row.shareB * vB - row.shareA * vA)) + row.offset;
}

Eigen::VectorXd solveBoundedQuadratic(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                      const std::vector<bool>& bounded)
{
    const Eigen::Index n = b.size();
    Eigen::MatrixXd regular = a;
    const Scalar scale = n > 0 ? a.diagonal().cwiseAbs().maxCoeff() : 0;
    regular.diagonal().array() += 1e-12 * scale + std::numeric_limits<Scalar>::min();
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    // The free set: every unbounded variable, and the bounded ones taken off their bound.
    std::vector<bool> free(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
        free[static_cast<std::size_t>(i)] = !bounded[static_cast<std::size_t>(i)];
    const Scalar tolerance = kTolerance * (1 + b.cwiseAbs().maxCoeff());
    std::vector<Eigen::Index> index;
    // Each exchange lowers the objective; the bound guards against round-off cycling.
    for (int exchange = 0; exchange < 4 * static_cast<int>(n) + 4; ++exchange) {
        // Solve on the free set; step back to the bounds where that would cross one.
        for (int inner = 0; inner <= static_cast<int>(n); ++inner) {
            index.clear();
            for (Eigen::Index i = 0; i < n; ++i) {
                if (free[static_cast<std::size_t>(i)])
                    index.push_back(i);
            }
            Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
            if (!index.empty()) {
                const auto size = static_cast<Eigen::Index>(index.size());
                Eigen::MatrixXd sub(size, size);
                Eigen::VectorXd rhs(size);
                for (Eigen::Index r = 0; r < size; ++r) {
                    rhs(r) = -b(index[static_cast<std::size_t>(r)]);
                    for (Eigen::Index c = 0; c < size; ++c)
                        sub(r, c) = regular(index[static_cast<std::size_t>(r)], index[static_cast<std::size_t>(c)]);
                }
                const Eigen::VectorXd solution = sub.ldlt().solve(rhs);
                for (Eigen::Index r = 0; r < size; ++r)
                    z(index[static_cast<std::size_t>(r)]) = solution(r);
            }
            Scalar step = 1;
            for (Eigen::Index i = 0; i < n; ++i) {
                if (bounded[static_cast<std::size_t>(i)] && free[static_cast<std::size_t>(i)] && z(i) < 0)
                    step = std::min(step, x(i) / (x(i) - z(i)));
            }
            x += step * (z - x);
            if (step >= 1)
                break;
            for (Eigen::Index i = 0; i < n; ++i) {
                if (bounded[static_cast<std::size_t>(i)] && free[static_cast<std::size_t>(i)] && x(i) <= 0) {
                    x(i) = 0;
                    free[static_cast<std::size_t>(i)] = false;
                }
            }
        }
        // A bounded variable at its bound whose raising would lower the objective joins the set.
        const Eigen::VectorXd gradient = regular * x + b;
        Eigen::Index join = -1;
        Scalar steepest = -tolerance;
        for (Eigen::Index i = 0; i < n; ++i) {
            if (!free[static_cast<std::size_t>(i)] && gradient(i) < steepest) {
                steepest = gradient(i);
                join = i;
            }
        }
        if (join < 0)
            break;
        free[static_cast<std::size_t>(join)] = true;
    }
    return x;
}

bool UnlikeMassIslands::moves(std::span<const SolverBody> bodies, std::uint32_t index) const
{
    return index != ConstraintRow::kNoBody && movable(bodies[index]);
}

void UnlikeMassIslands::findIslands(std::span<const SolverBody> bodies, const ContactSolver& contacts)
{
    m_islands.clear();
    m_parent.resize(bodies.size());
    std::iota(m_parent.begin(), m_parent.end(), 0U);
    const auto join = [&](std::uint32_t a, std::uint32_t b) {
        if (moves(bodies, a) && moves(bodies, b))
            m_parent[findRoot(m_parent, a)] = findRoot(m_parent, b);
    };
    m_jointedPairs.clear();
    for (const ConstraintRow& row : m_jointRows) {
        join(row.bodyA, row.bodyB);
        m_jointedPairs.emplace_back(std::min(row.bodyA, row.bodyB), std::max(row.bodyA, row.bodyB));
    }
    std::sort(m_jointedPairs.begin(), m_jointedPairs.end());
    for (const ContactConstraint& c : contacts.constraints())
        join(mover(c.bodyA), mover(c.bodyB));
    // The islands with a joint, and their lightest and heaviest bodies (a soft body's aggregate
    // for the soft body, not its ellipses).
    std::vector<std::uint32_t> roots;
    for (const ConstraintRow& row : m_jointRows) {
        if (moves(bodies, row.bodyA) || moves(bodies, row.bodyB))
            roots.push_back(findRoot(m_parent, moves(bodies, row.bodyA) ? row.bodyA : row.bodyB));
    }
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if (roots.empty())
        return;
    std::vector<Scalar> lightest(roots.size(), std::numeric_limits<Scalar>::infinity());
    std::vector<Scalar> heaviest(roots.size(), 0);
    std::vector<bool> holdsSoft(roots.size(), false);
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        if (!(bodies[i].invMass > 0))
            continue;
        const std::uint32_t root = findRoot(m_parent, mover(i));
        const auto it = std::lower_bound(roots.begin(), roots.end(), root);
        if (it == roots.end() || *it != root)
            continue;
        const auto k = static_cast<std::size_t>(it - roots.begin());
        if (mover(i) != i) {
            holdsSoft[k] = true;
            continue;
        }
        lightest[k] = std::min(lightest[k], 1 / bodies[i].invMass);
        heaviest[k] = std::max(heaviest[k], 1 / bodies[i].invMass);
    }
    m_softIslands.clear();
    for (std::size_t k = 0; k < roots.size(); ++k) {
        if (heaviest[k] > kMassRatio * lightest[k]) {
            m_islands.push_back(roots[k]);
            if (holdsSoft[k])
                m_softIslands.push_back(roots[k]);
        }
    }
}

void UnlikeMassIslands::gatherRows(std::uint32_t root, std::span<const SolverBody> bodies,
                                   const std::vector<ConstraintRow>& jointRows, const ContactSolver& contacts, Scalar h,
                                   bool positions)
{
    m_rows.clear();
    const auto inIsland = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint32_t body = moves(bodies, a) ? a : b;
        return moves(bodies, body) && findRoot(m_parent, body) == root;
    };
    for (const ConstraintRow& row : jointRows) {
        if (inIsland(row.bodyA, row.bodyB))
            m_rows.push_back(row);
    }
    for (const ContactConstraint& c : contacts.constraints()) {
        const std::uint32_t moverA = mover(c.bodyA);
        const std::uint32_t moverB = mover(c.bodyB);
        if (moverA == moverB || !inIsland(moverA, moverB) ||
            std::binary_search(m_jointedPairs.begin(), m_jointedPairs.end(),
                               std::pair(std::min(moverA, moverB), std::max(moverA, moverB))))
            continue;
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = bodies[c.bodyB];
        for (int p = 0; p < c.pointCount; ++p) {
            const ContactConstraintPoint& point = c.points[static_cast<std::size_t>(p)];
            ConstraintRow row;
            row.bodyA = moverA;
            row.bodyB = moverB;
            row.contact = true;
            if (positions) {
                // Out of the overlap past the slop, as the position passes aim (an island with a
                // soft body has no position solve: see solvePositions).
                const detail::ContactGeometry look =
                    detail::contactGeometry(c, point, a, b, Vec2(std::cos(a.angle), std::sin(a.angle)),
                                            Vec2(std::cos(b.angle), std::sin(b.angle)));
                row.direction = look.normal;
                row.rA = look.rA;
                row.rB = look.rB;
                row.offset = look.separation + constants::kLinearSlop;
            } else {
                row.direction = c.normal;
                row.rA = point.rA;
                row.rB = point.rB;
                row.shareA = velocityShare(a);
                row.shareB = velocityShare(b);
                row.offset = h > 0 ? std::max(point.closingGap, 0.0) / h : 0;
                if (c.bodyA != moverA)
                    onGrid(row, a, bodies[moverA], row.rA, row.shareA, -1);
                if (c.bodyB != moverB)
                    onGrid(row, b, bodies[moverB], row.rB, row.shareB, 1);
            }
            m_rows.push_back(row);
        }
    }
}

void UnlikeMassIslands::buildSystem(std::span<const SolverBody> bodies)
{
    const auto n = static_cast<Eigen::Index>(m_rows.size());
    m_system.resize(n, n);
    for (Eigen::Index r = 0; r < n; ++r) {
        for (Eigen::Index c = 0; c <= r; ++c)
            m_system(r, c) = m_system(c, r) =
                effect(m_rows[static_cast<std::size_t>(r)], m_rows[static_cast<std::size_t>(c)], bodies);
    }
}

void UnlikeMassIslands::solveVelocities(std::span<SolverBody> bodies, const JointSolver& joints,
                                        const ContactSolver& contacts, Scalar h,
                                        std::span<const std::uint32_t> movedBy)
{
    m_solvedVelocities = 0;
    m_solvedBodies.clear();
    m_islands.clear();
    m_movedBy = movedBy;
    if (joints.empty())
        return;
    // Most jointed worlds (a chain, a mesh of equal links) have no masses ten times apart at all:
    // one look at the masses, and nothing more.
    Scalar lightestInverse = 0;
    Scalar heaviestInverse = std::numeric_limits<Scalar>::infinity();
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        // A soft body by its aggregate, not by its ellipses.
        if (bodies[i].invMass > 0 && mover(i) == i) {
            lightestInverse = std::max(lightestInverse, bodies[i].invMass);
            heaviestInverse = std::min(heaviestInverse, bodies[i].invMass);
        }
    }
    if (!(lightestInverse > kMassRatio * heaviestInverse))
        return;
    m_jointRows.clear();
    joints.appendRows(bodies, h, m_jointRows);
    findIslands(bodies, contacts);
    std::size_t kept = 0;
    for (const std::uint32_t root : m_islands) {
        gatherRows(root, bodies, m_jointRows, contacts, h, false);
        if (m_rows.size() > kMaxRows)
            continue;
        m_islands[kept++] = root;
        const auto n = static_cast<Eigen::Index>(m_rows.size());
        std::vector<bool> bounded(m_rows.size());
        for (std::size_t r = 0; r < m_rows.size(); ++r)
            bounded[r] = m_rows[r].contact;
        buildSystem(bodies);
        // The island's bodies as they leave the passes, to go back to should the solve not take
        // kinetic energy out (rows that contradict each other have no exact answer, and the
        // least-squares one may be of any size).
        m_saved.clear();
        Scalar kineticBefore = 0;
        for (const ConstraintRow& row : m_rows) {
            for (const std::uint32_t index : {row.bodyA, row.bodyB}) {
                if (moves(bodies, index) && std::none_of(m_saved.begin(), m_saved.end(),
                                                         [&](const SavedBody& saved) { return saved.index == index; })) {
                    const SolverBody& body = bodies[index];
                    m_saved.push_back({index, body.velocity, body.angularVelocity, body.position, body.angle});
                    kineticBefore += kineticEnergyOf(body);
                }
            }
        }
        Eigen::VectorXd total = Eigen::VectorXd::Zero(n);
        for (int round = 0; round < kRounds; ++round) {
            Eigen::VectorXd values(n);
            bool violated = false;
            for (Eigen::Index r = 0; r < n; ++r) {
                const ConstraintRow& row = m_rows[static_cast<std::size_t>(r)];
                values(r) = rowValue(row, bodies);
                violated = violated || (row.contact ? values(r) < -kTolerance : std::abs(values(r)) > kTolerance);
            }
            if (!violated)
                break;
            const Eigen::VectorXd impulses = solveBoundedQuadratic(m_system, values, bounded);
            for (Eigen::Index r = 0; r < n; ++r) {
                const ConstraintRow& row = m_rows[static_cast<std::size_t>(r)];
                SolverBody scratch;
                SolverBody& a = row.bodyA == ConstraintRow::kNoBody ? scratch : bodies[row.bodyA];
                SolverBody& b = row.bodyB == ConstraintRow::kNoBody ? scratch : bodies[row.bodyB];
                applyImpulse(a, b, row.rA, row.rB, impulses(r) * row.direction);
            }
            total += impulses;
        }
        if (total.isZero())
            continue;
        Scalar kineticAfter = 0;
        Scalar fastest = 0;
        Scalar fastestSpin = 0;
        for (const SavedBody& saved : m_saved) {
            kineticAfter += kineticEnergyOf(bodies[saved.index]);
            fastest = std::max(fastest, saved.velocity.norm());
            fastestSpin = std::max(fastestSpin, std::abs(saved.angularVelocity));
        }
        // A body sent off faster than twice the island's fastest (as an elastic blow at most
        // would) is the rows' first order speaking, not the bodies: a light body between a wall
        // and a heavy one that the solve would turn about its contact, hundreds of rad/s, and
        // which a step's turn through a whole radian takes through the wall (soak seed 66).
        bool tame = true;
        for (const SavedBody& saved : m_saved) {
            const SolverBody& body = bodies[saved.index];
            tame = tame && body.velocity.norm() <= kMaxSpeedUp * fastest + kSpeedSlack &&
                   std::abs(body.angularVelocity) <= kMaxSpeedUp * fastestSpin + kSpinSlack;
        }
        if (!(kineticAfter <= kineticBefore * (1 + kEnergyTolerance)) || !tame) {
            for (const SavedBody& saved : m_saved) {
                bodies[saved.index].velocity = saved.velocity;
                bodies[saved.index].angularVelocity = saved.angularVelocity;
            }
            continue;
        }
        // Not kept for the joints' warm start: handed to the passes of the next step, an
        // impulse that stopped a tonne through a light body is one they cannot take back (soak
        // seed 183's heavy circle, stopped on a light polygon, then pushed off it faster each step).
        for (const SavedBody& saved : m_saved) {
            bodies[saved.index].hadContactForce = true;
            m_solvedBodies.push_back(saved.index);
        }
        ++m_solvedVelocities;
    }
    m_islands.resize(kept);
    std::sort(m_solvedBodies.begin(), m_solvedBodies.end());
}

void UnlikeMassIslands::solvePositions(std::span<SolverBody> bodies, const JointSolver& joints,
                                       const ContactSolver& contacts, std::span<const std::uint32_t> movedBy)
{
    m_pushes.clear();
    m_movedBy = movedBy;
    if (m_islands.empty())
        return;
    m_jointRows.clear();
    joints.appendPositionRows(bodies, m_jointRows);
    for (const std::uint32_t root : m_islands) {
        // A soft body's ellipses are taken out of their overlaps one by one by the position
        // passes, which may bend its grid; moved as one rigid body to clear one wall, a grid
        // squeezed into a corner went through the other (soak seed 2932).
        if (std::binary_search(m_softIslands.begin(), m_softIslands.end(), root))
            continue;
        const std::size_t firstPush = m_pushes.size();
        m_saved.clear();
        bool acted = false;
        for (int round = 0; round < kPositionRounds; ++round) {
            if (round > 0) {
                m_jointRows.clear();
                joints.appendPositionRows(bodies, m_jointRows);
            }
            gatherRows(root, bodies, m_jointRows, contacts, 0, true);
            const auto n = static_cast<Eigen::Index>(m_rows.size());
            Eigen::VectorXd values(n);
            std::vector<bool> bounded(m_rows.size());
            // The first round acts only where the passes left a joint open or a contact deeper than
            // the slop; later ones finish what it began.
            const Scalar tolerance = round == 0 ? constants::kLinearSlop : 0.1 * constants::kLinearSlop;
            bool violated = false;
            for (Eigen::Index r = 0; r < n; ++r) {
                const ConstraintRow& row = m_rows[static_cast<std::size_t>(r)];
                values(r) = row.offset;
                bounded[static_cast<std::size_t>(r)] = row.contact;
                violated = violated || (row.contact ? values(r) < -tolerance : std::abs(values(r)) > tolerance);
            }
            if (!violated)
                break;
            if (m_saved.empty()) {
                for (const ConstraintRow& row : m_rows) {
                    for (const std::uint32_t index : {row.bodyA, row.bodyB}) {
                        if (moves(bodies, index) &&
                            std::none_of(m_saved.begin(), m_saved.end(),
                                         [&](const SavedBody& saved) { return saved.index == index; })) {
                            const SolverBody& body = bodies[index];
                            m_saved.push_back({index, body.velocity, body.angularVelocity, body.position, body.angle});
                        }
                    }
                }
            }
            buildSystem(bodies);
            const Eigen::VectorXd impulses = solveBoundedQuadratic(m_system, values, bounded);
            for (Eigen::Index r = 0; r < n; ++r) {
                const ConstraintRow& row = m_rows[static_cast<std::size_t>(r)];
                if (impulses(r) == 0)
                    continue;
                SolverBody scratch;
                SolverBody& a = row.bodyA == ConstraintRow::kNoBody ? scratch : bodies[row.bodyA];
                SolverBody& b = row.bodyB == ConstraintRow::kNoBody ? scratch : bodies[row.bodyB];
                const Vec2 push = impulses(r) * row.direction;
                applyPositionImpulse(a, b, row.rA, row.rB, push);
                if (moves(bodies, row.bodyA) && moves(bodies, row.bodyB))
                    m_pushes.push_back({row.bodyA, row.bodyB, push});
            }
            acted = true;
        }
        if (!acted)
            continue;
        bool sound = true;
        for (const SavedBody& saved : m_saved) {
            const SolverBody& body = bodies[saved.index];
            sound = sound && (body.position - saved.position).norm() <= kMaxShift && std::isfinite(body.angle);
        }
        if (!sound) {
            for (const SavedBody& saved : m_saved) {
                bodies[saved.index].position = saved.position;
                bodies[saved.index].angle = saved.angle;
            }
            m_pushes.resize(firstPush);
        }
    }
}

void UnlikeMassIslands::measurePushes(std::span<const SolverBody> bodies)
{
    for (Push& push : m_pushes) {
        const SolverBody& a = bodies[push.bodyA];
        const SolverBody& b = bodies[push.bodyB];
        push.change = a.invMass > 0 && b.invMass > 0 ? cross(push.push, Vec2(b.velocity - a.velocity)) : 0;
    }
}

void UnlikeMassIslands::takeBackPushes(std::span<SolverBody> bodies) const
{
    for (const Push& push : m_pushes) {
        if (push.change != 0)
            restoreAngularMomentum(bodies[push.bodyA], bodies[push.bodyB], push.change, push.push);
    }
}

} // namespace impetus::controller
