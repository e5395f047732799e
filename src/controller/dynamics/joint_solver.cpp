#include "controller/dynamics/joint_solver.h"

#include "controller/dynamics/small_turn.h"
#include "controller/union_find.h"
#include "model/constants.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impetus::controller {

namespace {

/// Smallest share of the step a joint counts a struck body's end velocity for (dimensionless).
/// After an impact at τ·h the end velocity moves the body only for (1 − τ)·h, and the joint's
/// target asks for the velocity that closes its gap in that time: 1/(1 − τ) times the velocity
/// that closes it over the whole step. For an impact late in the step that is unbounded, and the
/// velocity it leaves carries into the next step whole: soak seeds 3, 4, 8, 17, 117, 142, 149,
/// 153, 182, 183, 188 and 193 flung bodies out of the box at up to 1e17 m/s. Counting at least
/// half the step, a joint asks for at most twice that velocity and leaves what remains of the gap
/// to the position passes. (Measured on the soak's 200 scenes: 26 findings with no floor, 22 at
/// 0.1, 20 at 0.25, 16 at 0.5, 15 at 0.75 and 1.) That was while the joints still closed their gap
/// with velocity (solveVelocities says why they no longer do); the floor stays, and keeps a struck
/// body's end velocity, which carries into the next step whole, at least half in its joints' hold.
/// The soak has not been measured without it since.
constexpr Scalar kMinStruckShare = 0.5;

/// K for a point constraint between material points rA, rB (the 2×2 effective-mass matrix), each
/// body's part weighted by how much of its velocity moves it (shareA, shareB; 1 for the position
/// passes).
Eigen::Matrix2d pointK(const SolverBody& a, const SolverBody& b, const Vec2& rA, const Vec2& rB, Scalar shareA = 1,
                       Scalar shareB = 1)
{
    const auto part = [](const SolverBody& body, const Vec2& r, Scalar share) {
        Eigen::Matrix2d k;
        k(0, 0) = body.invMass + body.invInertia * r.y() * r.y();
        k(0, 1) = -body.invInertia * r.x() * r.y();
        k(1, 0) = k(0, 1);
        k(1, 1) = body.invMass + body.invInertia * r.x() * r.x();
        return Eigen::Matrix2d(share * k);
    };
    return part(a, rA, shareA) + part(b, rB, shareB);
}

/// How far a body's point at r moves this step apart from (1 − T)·h times its end velocity: a
/// struck body moves h·(T·v − Σₖ τₖ·Δvₖ) more, with v its velocity after the impacts (v₀ + Σ Δvₖ),
/// and turns likewise (Simulation::finishBodyPosition).
Vec2 impactShift(const SolverBody& body, const Vec2& r, Scalar h)
{
    if (!body.hadImpact)
        return Vec2::Zero();
    const Scalar tau = body.lastImpactTau;
    const Vec2 move = h * (tau * body.velocity - body.impactLateVelocity);
    const Scalar turn = h * (tau * body.angularVelocity - body.impactLateAngularVelocity);
    return move + cross(turn, r);
}

Eigen::Matrix2d safeInverse(const Eigen::Matrix2d& k)
{
    const Scalar det = k.determinant();
    return det != 0 ? Eigen::Matrix2d(k.inverse()) : Eigen::Matrix2d::Zero();
}

/// The largest turn in a step for which a joint's end condition follows its anchor on its arc
/// (JointSolver::prepare), rad: an eighth of a turn, as spinSubsteps allows every pinned body and
/// every other body but a circle (0.1 rad in a world of unlike masses).
constexpr Scalar kMaxArcTurn = std::numbers::pi / 4;

/// How far an anchor at lever arm r, turned by `turn` over a step of h seconds, leaves the tangent
/// along its arc, over h (m/s): (R(turn) − 1 − turn ×)·r / h.
Vec2 arcFor(const Vec2& r, Scalar turn, Scalar h)
{
    return Vec2((rotate(r, turn) - r - cross(turn, r)) / h);
}

/// The same for an anchor on `body` turning at its present spin for `share` of the step; zero past
/// kMaxArcTurn (the body keeps the tangent).
Vec2 arcOf(const SolverBody& body, const Vec2& r, Scalar share, Scalar h)
{
    const Scalar turn = share * h * body.angularVelocity;
    if (!(std::abs(turn) <= kMaxArcTurn) || !(h > 0))
        return Vec2::Zero();
    return arcFor(r, turn, h);
}

/// A rod's arc as its pass takes it now: afresh at the turn `body` (its A) has now where the rod
/// follows its arc and that turn is within kMaxArcTurn, else the one prepare gave it.
template <typename Rod>
Vec2 presentArc(const Rod& rod, const SolverBody& body, Scalar h)
{
    const Scalar turn = rod.shareA * h * body.angularVelocity;
    return rod.followsArc && h > 0 && std::abs(turn) <= kMaxArcTurn ? Vec2(-arcFor(rod.rA, turn, h)) : rod.arc;
}

/// The most (r/k)² (anchor distance r, radius of gyration k) for which a rod to the world follows
/// its anchor's arc afresh in each pass (JointSolver::solveVelocities): an anchor on or in its
/// body. For an anchor far outside a small body (a 5 cm ball on a rod from a point 1 m off its
/// centre, 800) the rod's pull mostly spins the body, each pass's turn overshoots the last, and
/// a pendulum so made was flung apart within 6 s; it keeps the arc of the passes' first turn.
constexpr Scalar kMaxArcFollowRatio = 8;

/// How much faster than its arcs a block's bodies may be set moving by them (JointSolver::
/// buildBlocks): an anchor's arc is a correction of h·ω²·r to its velocity, which moves the
/// bodies of a sound block by about as much. A block that is nearly a mechanism (three pins
/// almost in a line) answers it with speeds thousands of times larger.
constexpr Scalar kMaxArcAmplification = 10;

/// The most pins solved together as one block (JointSolver::PinBlock): a matrix of 2n × 2n. A
/// larger group (a chain of many links, a mesh of pins) goes one pin at a time.
constexpr std::size_t kMaxBlockPins = 8;

/// What an impulse P at lever arm s does to the velocity of the body's point at lever arm r:
/// Δ(v + ω × r) = (1/m)·P + (1/I)·(s × P)·perp(r), as a matrix.
Eigen::Matrix2d pointResponse(const SolverBody& body, const Vec2& r, const Vec2& s)
{
    const Vec2 perpR(-r.y(), r.x());
    const Vec2 perpS(-s.y(), s.x());
    return body.invMass * Eigen::Matrix2d::Identity() + body.invInertia * perpR * perpS.transpose();
}

/// One pin of a block as the block's matrix sees it: its bodies (kWorld for the world), the
/// lever arms its impulses act at, and how much of each body's velocity moves it.
struct PinArms {
    std::uint32_t bodyA;
    std::uint32_t bodyB;
    Vec2 rA;
    Vec2 rB;
    Scalar shareA = 1;
    Scalar shareB = 1;
};

/// The matrix of a block of pins: block (k, l) is what pin l's impulse (+P on its B, −P on its A)
/// does to pin k's relative anchor motion, share_B·(v_B + ω_B × r_B) − share_A·(v_A + ω_A × r_A),
/// summed over the moving bodies the two pins share. Symmetric, as each body has one share.
Eigen::MatrixXd pinBlockMatrix(std::span<const SolverBody> bodies, std::span<const PinArms> pins, std::uint32_t world)
{
    const auto n = static_cast<Eigen::Index>(pins.size());
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    const auto moves = [&](std::uint32_t index) { return index != world && movable(bodies[index]); };
    for (Eigen::Index k = 0; k < n; ++k) {
        const PinArms& pk = pins[static_cast<std::size_t>(k)];
        for (Eigen::Index l = 0; l < n; ++l) {
            const PinArms& pl = pins[static_cast<std::size_t>(l)];
            Eigen::Matrix2d block = Eigen::Matrix2d::Zero();
            const auto add = [&](std::uint32_t bodyK, const Vec2& rK, Scalar signK, Scalar shareK) {
                if (!moves(bodyK))
                    return;
                if (bodyK == pl.bodyA)
                    block -= (signK * shareK) * pointResponse(bodies[bodyK], rK, pl.rA);
                if (bodyK == pl.bodyB)
                    block += (signK * shareK) * pointResponse(bodies[bodyK], rK, pl.rB);
            };
            add(pk.bodyA, pk.rA, -1, pk.shareA);
            add(pk.bodyB, pk.rB, 1, pk.shareB);
            matrix.block<2, 2>(2 * k, 2 * l) = block;
        }
    }
    return matrix;
}

/// A joint's impulse: it holds both bodies, which therefore finish the step as constrained ones.
void applyJointImpulse(SolverBody& a, SolverBody& b, const Vec2& rA, const Vec2& rB, const Vec2& impulse)
{
    applyImpulse(a, b, rA, rB, impulse);
    a.hadContactForce = true;
    b.hadContactForce = true;
}

} // namespace

void JointSolver::keepArcsIfSound(const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>& system,
                                  std::span<const std::uint32_t> pins, std::span<const SolverBody> bodies)
{
    // The impulses the block's arcs alone ask for, and the speeds they give its bodies. Three
    // pins almost in a line (a body pinned to the world and to a second one, itself pinned to the
    // world, all three hinges within a milliradian of one line: soak seed 1135) make the block's
    // matrix nearly singular: the bodies may turn about the line's middle hinge, to first order,
    // without opening a pin. The arcs ask for a little motion off the tangents that such a turn
    // alone could give, and the block answered with 600 m/s for a 2 m/s arc. Such a block keeps
    // its anchors on their tangents, as joints between two bodies always do.
    const auto n = static_cast<Eigen::Index>(pins.size());
    Eigen::VectorXd arcs(2 * n);
    Scalar largestArc = 0;
    for (Eigen::Index k = 0; k < n; ++k) {
        const Vec2& arc = m_joints[pins[static_cast<std::size_t>(k)]].arc;
        arcs.segment<2>(2 * k) = arc;
        largestArc = std::max(largestArc, arc.norm());
    }
    if (largestArc == 0)
        return;
    const Eigen::VectorXd impulses = -system.solve(arcs);
    struct Motion {
        std::uint32_t body;
        Vec2 velocity = Vec2::Zero();
        Scalar spin = 0;
        Scalar arm = 0;
    };
    std::vector<Motion> motions;
    const auto add = [&](std::uint32_t body, const Vec2& r, const Vec2& impulse) {
        if (body == kWorld || !movable(bodies[body]))
            return;
        auto it = std::find_if(motions.begin(), motions.end(), [&](const Motion& m) { return m.body == body; });
        if (it == motions.end())
            it = motions.insert(motions.end(), Motion{body});
        it->velocity += bodies[body].invMass * impulse;
        it->spin += bodies[body].invInertia * cross(r, impulse);
        it->arm = std::max(it->arm, r.norm());
    };
    for (Eigen::Index k = 0; k < n; ++k) {
        const Constraint& pin = m_joints[pins[static_cast<std::size_t>(k)]];
        const Vec2 impulse = impulses.segment<2>(2 * k);
        add(pin.bodyA, pin.rA, -impulse);
        add(pin.bodyB, pin.rB, impulse);
    }
    Scalar fastest = 0;
    for (const Motion& m : motions)
        fastest = std::max(fastest, m.velocity.norm() + std::abs(m.spin) * m.arm);
    if (!(fastest <= kMaxArcAmplification * largestArc)) {
        for (const std::uint32_t k : pins)
            m_joints[k].arc = Vec2::Zero();
    }
}

SolverBody& JointSolver::bodyOf(std::span<SolverBody> bodies, std::uint32_t index)
{
    return index == kWorld ? m_world : bodies[index];
}

void JointSolver::startRotations(std::size_t bodyCount)
{
    if (m_rotationStamps.size() != bodyCount || m_rotationStamp == UINT32_MAX) {
        m_rotationStamps.assign(bodyCount, 0);
        m_rotationAngles.resize(bodyCount);
        m_rotations.resize(bodyCount);
        m_rotationStamp = 0;
    }
    ++m_rotationStamp;
}

Vec2 JointSolver::rotated(const Vec2& local, std::span<const SolverBody> bodies, std::uint32_t index)
{
    if (index == kWorld)
        return rotate(local, m_world.angle);
    const Scalar angle = bodies[index].angle;
    Vec2& rotation = m_rotations[index];
    if (m_rotationStamps[index] != m_rotationStamp) {
        m_rotationStamps[index] = m_rotationStamp;
        m_rotationAngles[index] = angle;
        rotation = Vec2(std::cos(angle), std::sin(angle));
    } else {
        detail::turnTo(rotation, m_rotationAngles[index], angle, m_turnRotations);
    }
    const Scalar c = rotation.x();
    const Scalar s = rotation.y();
    return Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
}

void JointSolver::prepare(const model::World& world, std::span<const SolverBody> bodies, Scalar h)
{
    m_joints.clear();
    m_world = SolverBody{};
    m_turnRotations = false; // until beginPositions() says
    // The bodies do not move while the constraints are built: each body's cosine and sine once,
    // the bits of rotate().
    startRotations(bodies.size());
    for (const model::Joint& joint : world.joints) {
        Constraint c;
        c.type = joint.type;
        c.bodyA = joint.bodyA.index;
        c.bodyB = joint.bodyB ? joint.bodyB->index : kWorld;
        c.localA = joint.anchorA;
        c.localB = joint.anchorB;
        c.length = joint.length;
        c.impulse = joint.impulse;
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = c.bodyB == kWorld ? m_world : bodies[c.bodyB];
        c.rA = rotated(c.localA, bodies, c.bodyA);
        c.rB = rotated(c.localB, bodies, c.bodyB);
        const Vec2 offset = b.position + c.rB - a.position - c.rA;
        // Impulses act from where each body is when they act: at the start, or after a struck
        // body's last impact (SolverBody::impulseOrigin).
        const Vec2& originA = impulseOrigin(a);
        const Vec2& originB = impulseOrigin(b);
        // A struck body's end velocity moves it only after its last impact, and its motion
        // before counts apart (review point of issue 16: the target ignored it).
        c.shareA = velocityShare(a);
        c.shareB = velocityShare(b);
        c.separation = offset + impactShift(b, c.rB, h) - impactShift(a, c.rA, h);
        c.heldLength = c.separation.norm();
        if (c.type == model::JointType::Pin) {
            if (c.bodyB != kWorld) {
                const Vec2 common = 0.5 * (originA + c.rA + originB + c.rB);
                c.rA = common - originA;
                c.rB = common - originB;
            }
            c.pinMass = safeInverse(pointK(a, b, c.rA, c.rB, c.shareA, c.shareB));
        } else {
            // Along the line between the anchors as the impulses see them, which keeps the
            // angular momentum exactly.
            const Vec2 d = originB + c.rB - originA - c.rA;
            const Scalar distance = d.norm();
            // A rod squeezed to a point has no direction this instant; push along x until it
            // opens up again.
            c.axis = distance > 0 ? Vec2(d / distance) : Vec2(1, 0);
            const Scalar rnA = cross(c.rA, c.axis);
            const Scalar rnB = cross(c.rB, c.axis);
            const Scalar k = c.shareA * (a.invMass + a.invInertia * rnA * rnA) +
                             c.shareB * (b.invMass + b.invInertia * rnB * rnB);
            c.rodMass = k > 0 ? 1 / k : 0;
        }
        // An anchor at lever arm r on a body turning at ω moves by h·v + (R(h·ω) − 1)·r in the
        // step, on its arc, not by h·(v + ω × r) along the tangent. A joint to the world takes
        // the arc with the turn the body has when the passes begin: the difference, a constant
        // of the step, joins the anchor's velocity, and the passes stay projections. On the
        // tangent the body drifted out of its joint every step, which the position passes took
        // back while the velocity kept its tangent: a bar hinged to the world by a pin lost 0.4 %
        // of its swing energy a second, whatever the step. Between two bodies the arcs are not
        // taken: there they fed soak seed 145 (a pin and a rod between a 3 t circle and a 2 t
        // ellipse, its energy 100 times its start in 1.4 s), and with each pass's own turn (a
        // Newton step) seed 23. A body turning more than kMaxArcTurn in the step (a circle on a
        // rod, whose own spin spinSubsteps leaves alone) keeps the tangent. A rod to the world
        // takes its arc afresh in each pass, with the turn the pass finds (solveVelocities).
        if (c.bodyB == kWorld) {
            c.arc = -arcOf(a, c.rA, c.shareA, h);
            // (r/k)², k the body's radius of gyration: how much more the rod's pull at r turns the
            // body than it moves it. An anchor on or in a body has at most about 4 (a box's
            // corner 3, a disc's rim 2); one far outside a small body, hundreds. A soft body's
            // turn between passes is its grid's, fitted afresh to ellipses that the contacts
            // move, not the rod's doing: it keeps the first turn's arc (a soft box on a rod to
            // the world, following its grid's turn, was flung out of the box: soak seed 8426).
            const Scalar turnOverMove = a.invMass > 0 ? a.invInertia * c.rA.squaredNorm() / a.invMass : 0;
            c.followsArc = c.type == model::JointType::Rod && !c.arc.isZero() &&
                           turnOverMove <= kMaxArcFollowRatio && !world.bodies[c.bodyA].soft;
        }
        m_joints.push_back(c);
    }
    buildBlocks(bodies);
}

void JointSolver::buildBlocks(std::span<const SolverBody> bodies)
{
    m_blocks.clear();
    std::size_t pins = 0;
    for (const Constraint& c : m_joints)
        pins += c.type == model::JointType::Pin ? 1 : 0;
    if (pins < 2)
        return;
    // The pins' moving bodies, joined into sets by the pins: the world and fixed bodies join
    // nothing, as they do not move whatever the impulses.
    const auto moves = [&](std::uint32_t index) { return index != kWorld && movable(bodies[index]); };
    std::vector<std::uint32_t> parent(bodies.size());
    for (std::uint32_t i = 0; i < parent.size(); ++i)
        parent[i] = i;
    for (const Constraint& c : m_joints) {
        if (c.type == model::JointType::Pin && moves(c.bodyA) && moves(c.bodyB))
            parent[findRoot(parent, c.bodyA)] = findRoot(parent, c.bodyB);
    }
    // The pins of each set, in list order.
    std::vector<std::int64_t> element(m_joints.size(), -1);
    for (std::size_t k = 0; k < m_joints.size(); ++k) {
        const Constraint& c = m_joints[k];
        if (c.type == model::JointType::Pin && (moves(c.bodyA) || moves(c.bodyB)))
            element[k] = moves(c.bodyA) ? c.bodyA : c.bodyB;
    }
    std::vector<std::vector<std::uint32_t>> groups = groupBySet(parent, element);
    for (std::vector<std::uint32_t>& group : groups) {
        if (group.size() < 2 || group.size() > kMaxBlockPins)
            continue;
        std::vector<PinArms> arms;
        for (const std::uint32_t k : group) {
            const Constraint& c = m_joints[k];
            arms.push_back({c.bodyA, c.bodyB, c.rA, c.rB, c.shareA, c.shareB});
        }
        const Eigen::MatrixXd matrix = pinBlockMatrix(bodies, arms, kWorld);
        PinBlock pinBlock;
        pinBlock.system.compute(matrix);
        keepArcsIfSound(pinBlock.system, group, bodies);
        pinBlock.velocity.resize(static_cast<Eigen::Index>(2 * group.size()));
        for (const std::uint32_t k : group)
            m_joints[k].block = static_cast<std::int32_t>(m_blocks.size());
        pinBlock.pins = std::move(group);
        m_blocks.push_back(std::move(pinBlock));
    }
}

void JointSolver::warmStart(std::span<SolverBody> bodies)
{
    for (const Constraint& c : m_joints) {
        SolverBody& a = bodyOf(bodies, c.bodyA);
        SolverBody& b = bodyOf(bodies, c.bodyB);
        const Vec2 impulse = c.type == model::JointType::Pin ? c.impulse : Vec2(c.impulse.x() * c.axis);
        applyJointImpulse(a, b, c.rA, c.rB, impulse);
    }
}

void JointSolver::solveVelocities(std::span<SolverBody> bodies, Scalar h)
{
    // Each joint asks for the velocity that puts its anchors where the joint wants them at the
    // END of the step (x = x₀ + h·v), not merely for a velocity along the joint's current
    // tangent. The impulse acts along the constraint's direction at the start of the step, and
    // the iterations solve the non-linear end condition. This is the SHAKE scheme: symplectic, so
    // a pendulum's energy stays bounded over any number of swings, where projecting velocities
    // on the start tangent alone loses about 1 % of the swing per second at 240 Hz.
    //
    // What the joints want at the end is the error they had when their impulses begin to act
    // (`separation`): a pin's anchors as far apart, a rod as long. They do not close an error
    // with velocity. An error of d closed in one step asks for d/h more speed, and that speed
    // stays when the step ends: a pin whose anchors a fast turn had left 1.5 m apart asked for
    // 360 m/s at 1/240 s, and the soak's jointed scenes gained energy without bound or left the
    // box (seeds 18, 27, 49, 51, 61, 66, 69, 87, 111, 121, 195). The position passes remove the
    // error instead; they move bodies and give them no speed.
    const auto relativeVelocity = [&](const Constraint& c) {
        const SolverBody& a = bodyOf(bodies, c.bodyA);
        const SolverBody& b = bodyOf(bodies, c.bodyB);
        return Vec2(c.shareB * Vec2(b.velocity + cross(b.angularVelocity, c.rB)) -
                    c.shareA * Vec2(a.velocity + cross(a.angularVelocity, c.rA)) + c.arc);
    };
    for (std::size_t index = 0; index < m_joints.size(); ++index) {
        Constraint& c = m_joints[index];
        SolverBody& a = bodyOf(bodies, c.bodyA);
        SolverBody& b = bodyOf(bodies, c.bodyB);
        if (c.block >= 0) {
            // A block is solved at its first pin, all its pins at once: the impulses that bring
            // every anchor pair of the block together (the least ones, should the pins ask for the
            // same thing twice).
            PinBlock& block = m_blocks[static_cast<std::size_t>(c.block)];
            if (block.pins.front() != index)
                continue;
            for (std::size_t k = 0; k < block.pins.size(); ++k)
                block.velocity.segment<2>(2 * static_cast<Eigen::Index>(k)) = relativeVelocity(m_joints[block.pins[k]]);
            const Eigen::VectorXd impulses = -block.system.solve(block.velocity);
            for (std::size_t k = 0; k < block.pins.size(); ++k) {
                Constraint& pin = m_joints[block.pins[k]];
                const Vec2 impulse = impulses.segment<2>(2 * static_cast<Eigen::Index>(k));
                pin.impulse += impulse;
                applyJointImpulse(bodyOf(bodies, pin.bodyA), bodyOf(bodies, pin.bodyB), pin.rA, pin.rB, impulse);
            }
            continue;
        }
        // A rod to the world follows its anchor on the arc of the turn the body has now, not the
        // one it had when the passes began: the rod's impulse turns the body (its anchor off the
        // centre), and on the first turn's arc the end condition aimed where the anchor would
        // not be. A box on a rod from its corner, swinging under gravity, lost 6.5 % of its
        // energy in a minute at 1/240 s; a 106 kg ellipse at 77 m/s on a rod of 2.8 cm whose ends
        // went round each other faster than the substeps could follow gained 8 % a second (soak
        // seed 5292). Only for an anchor on or in its body (prepare, kMaxArcFollowRatio); a turn
        // past kMaxArcTurn keeps the arc it had. Between two bodies the arcs are not taken
        // (prepare says why).
        if (c.followsArc)
            c.arc = presentArc(c, a, h);
        const Vec2 dv = relativeVelocity(c);
        if (c.type == model::JointType::Pin) {
            // The anchors move together: h·dv = 0.
            const Vec2 impulse = -(c.pinMass * dv);
            c.impulse += impulse;
            applyJointImpulse(a, b, c.rA, c.rB, impulse);
        } else {
            const Vec2 predicted = c.separation + h * dv;
            const Scalar error = predicted.norm() - c.heldLength;
            Scalar lambda = -c.rodMass * error / h;
            // The pass moves the predicted separation along the rod's start direction, by
            // −error. That brings its length nearer the one held only while
            // 2·(predicted · axis) > error. Past that (a body that moves farther in a step than the
            // rod is long, its anchor predicted a quarter turn or more round), pulling makes the
            // rod longer and every pass asks for more: the passes sent a 17 g ball on a 0.34 m
            // rod (soak seed 144) and a 0.5 kg box on a 0.44 m one (seed 191) off at thousands
            // of m/s in one step. Such a pass holds the relative velocity along the rod at zero
            // instead, the end condition to first order: a projection, which never adds kinetic
            // energy.
            if (!(2 * predicted.dot(c.axis) > error))
                lambda = -c.rodMass * c.axis.dot(dv);
            c.impulse.x() += lambda;
            applyJointImpulse(a, b, c.rA, c.rB, lambda * c.axis);
        }
    }
}

Scalar velocityShare(const SolverBody& body)
{
    return body.hadImpact ? std::max(kMinStruckShare, 1 - body.lastImpactTau) : 1;
}

void JointSolver::appendRows(std::span<const SolverBody> bodies, Scalar h, std::vector<ConstraintRow>& rows) const
{
    for (const Constraint& c : m_joints) {
        ConstraintRow row;
        row.bodyA = c.bodyA;
        row.bodyB = c.bodyB == kWorld ? ConstraintRow::kNoBody : c.bodyB;
        row.rA = c.rA;
        row.rB = c.rB;
        row.shareA = c.shareA;
        row.shareB = c.shareB;
        if (c.type == model::JointType::Pin) {
            for (int axis = 0; axis < 2; ++axis) {
                row.direction = axis == 0 ? Vec2(1, 0) : Vec2(0, 1);
                row.offset = c.arc[axis];
                rows.push_back(row);
            }
            continue;
        }
        // The rod's pass drives the end condition's error over h to zero (solveVelocities), or
        // where that condition has turned over, the velocity along the rod.
        row.direction = c.axis;
        row.offset = 0;
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = c.bodyB == kWorld ? m_world : bodies[c.bodyB];
        // A rod that follows its arc takes it at the body's present turn, as its pass would.
        const Vec2 arc = presentArc(c, a, h);
        const Vec2 dv = c.shareB * Vec2(b.velocity + cross(b.angularVelocity, c.rB)) -
                        c.shareA * Vec2(a.velocity + cross(a.angularVelocity, c.rA)) + arc;
        const Vec2 predicted = c.separation + h * dv;
        const Scalar error = predicted.norm() - c.heldLength;
        const Scalar wanted = 2 * predicted.dot(c.axis) > error && h > 0 ? error / h : c.axis.dot(dv);
        row.offset = wanted - c.axis.dot(dv - arc);
        rows.push_back(row);
    }
}

void JointSolver::appendPositionRows(std::span<const SolverBody> bodies, std::vector<ConstraintRow>& rows) const
{
    for (const Constraint& c : m_joints) {
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = c.bodyB == kWorld ? m_world : bodies[c.bodyB];
        ConstraintRow row;
        row.bodyA = c.bodyA;
        row.bodyB = c.bodyB == kWorld ? ConstraintRow::kNoBody : c.bodyB;
        row.rA = rotate(c.localA, a.angle);
        row.rB = rotate(c.localB, b.angle);
        const Vec2 d = b.position + row.rB - a.position - row.rA;
        if (c.type == model::JointType::Pin) {
            for (int axis = 0; axis < 2; ++axis) {
                row.direction = axis == 0 ? Vec2(1, 0) : Vec2(0, 1);
                row.offset = d[axis];
                rows.push_back(row);
            }
            continue;
        }
        const Scalar distance = d.norm();
        if (!(distance > 0))
            continue;
        row.direction = d / distance;
        row.offset = distance - c.length;
        rows.push_back(row);
    }
}

void JointSolver::beginPositions(std::size_t bodyCount, bool turnRotations)
{
    m_turnRotations = turnRotations;
    // The bodies have moved since prepare(): their cosines and sines afresh at first use, then
    // turned with them through the passes.
    startRotations(bodyCount);
    for (Constraint& c : m_joints)
        c.push = Vec2::Zero();
}

void JointSolver::measurePushes(std::span<const SolverBody> bodies)
{
    m_changes.clear();
    for (const Constraint& c : m_joints) {
        if (c.bodyB == kWorld || c.push.isZero())
            continue;
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = bodies[c.bodyB];
        if (a.invMass > 0 && b.invMass > 0)
            m_changes.push_back(cross(c.push, Vec2(b.velocity - a.velocity)));
        else
            m_changes.push_back(0);
    }
}

void JointSolver::takeBackPushes(std::span<SolverBody> bodies) const
{
    std::size_t next = 0;
    for (const Constraint& c : m_joints) {
        if (c.bodyB == kWorld || c.push.isZero())
            continue;
        const Scalar change = m_changes[next++];
        if (change != 0)
            restoreAngularMomentum(bodies[c.bodyA], bodies[c.bodyB], change, c.push);
    }
}

bool JointSolver::solvePositions(std::span<SolverBody> bodies)
{
    Scalar worst = 0;
    for (std::size_t index = 0; index < m_joints.size(); ++index) {
        Constraint& c = m_joints[index];
        if (c.block >= 0) {
            if (m_blocks[static_cast<std::size_t>(c.block)].pins.front() == index)
                worst = std::max(worst, solveBlockPositions(m_blocks[static_cast<std::size_t>(c.block)], bodies));
            continue;
        }
        SolverBody& a = bodyOf(bodies, c.bodyA);
        SolverBody& b = bodyOf(bodies, c.bodyB);
        const Vec2 rA = rotated(c.localA, bodies, c.bodyA);
        const Vec2 rB = rotated(c.localB, bodies, c.bodyB);
        const Vec2 d = b.position + rB - a.position - rA;
        if (c.type == model::JointType::Pin) {
            worst = std::max(worst, d.norm());
            Vec2 error = d;
            const Scalar size = error.norm();
            if (size > constants::kMaxPositionCorrection)
                error *= constants::kMaxPositionCorrection / size;
            const Vec2 impulse = -(safeInverse(pointK(a, b, rA, rB)) * error);
            applyPositionImpulse(a, b, rA, rB, impulse);
            c.push += impulse;
        } else {
            const Scalar distance = d.norm();
            if (!(distance > 0))
                continue;
            const Vec2 u = d / distance;
            const Scalar error = std::clamp(distance - c.length, -constants::kMaxPositionCorrection,
                                            constants::kMaxPositionCorrection);
            worst = std::max(worst, std::abs(distance - c.length));
            const Scalar rnA = cross(rA, u);
            const Scalar rnB = cross(rB, u);
            const Scalar k = a.invMass + b.invMass + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
            if (k > 0) {
                const Vec2 impulse = (-error / k) * u;
                applyPositionImpulse(a, b, rA, rB, impulse);
                c.push += impulse;
            }
        }
    }
    return worst <= constants::kLinearSlop;
}

Scalar JointSolver::solveBlockPositions(const PinBlock& block, std::span<SolverBody> bodies)
{
    // The pins' errors and lever arms where the bodies are now, and the impulses that remove
    // every error at once to first order, as one pin's pass does for itself. A block whose worst
    // error is over kMaxPositionCorrection takes that much of it (every pin's in proportion).
    const auto n = static_cast<Eigen::Index>(block.pins.size());
    std::vector<PinArms> arms;
    arms.reserve(block.pins.size());
    Eigen::VectorXd error(2 * n);
    Scalar worst = 0;
    for (Eigen::Index k = 0; k < n; ++k) {
        const Constraint& c = m_joints[block.pins[static_cast<std::size_t>(k)]];
        const SolverBody& a = bodyOf(bodies, c.bodyA);
        const SolverBody& b = bodyOf(bodies, c.bodyB);
        const Vec2 rA = rotated(c.localA, bodies, c.bodyA);
        const Vec2 rB = rotated(c.localB, bodies, c.bodyB);
        const Vec2 d = b.position + rB - a.position - rA;
        error.segment<2>(2 * k) = d;
        worst = std::max(worst, d.norm());
        arms.push_back({c.bodyA, c.bodyB, rA, rB});
    }
    if (worst > constants::kMaxPositionCorrection)
        error *= constants::kMaxPositionCorrection / worst;
    const Eigen::VectorXd impulses =
        -Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(pinBlockMatrix(bodies, arms, kWorld)).solve(error);
    for (Eigen::Index k = 0; k < n; ++k) {
        Constraint& c = m_joints[block.pins[static_cast<std::size_t>(k)]];
        const PinArms& arm = arms[static_cast<std::size_t>(k)];
        const Vec2 impulse = impulses.segment<2>(2 * k);
        applyPositionImpulse(bodyOf(bodies, c.bodyA), bodyOf(bodies, c.bodyB), arm.rA, arm.rB, impulse);
        c.push += impulse;
    }
    return worst;
}

void JointSolver::forgetImpulses(std::span<const std::uint32_t> bodies)
{
    if (bodies.empty())
        return;
    for (Constraint& joint : m_joints) {
        if (std::binary_search(bodies.begin(), bodies.end(), joint.bodyA) ||
            std::binary_search(bodies.begin(), bodies.end(), joint.bodyB))
            joint.impulse = Vec2::Zero();
    }
}

void JointSolver::storeImpulses(model::World& world) const
{
    for (std::size_t i = 0; i < m_joints.size(); ++i)
        world.joints[i].impulse = m_joints[i].impulse;
}

} // namespace impetus::controller
