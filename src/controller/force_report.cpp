#include "controller/force_report.h"

#include "controller/collision/colliders.h"
#include "controller/collision/narrow_phase.h"
#include "controller/integration/force_model.h"
#include "controller/simulation.h"
#include "controller/soft/soft_stability.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace impetus::controller {

namespace {

/// How far apart two pieces with a recorded contact may be for the report to still find their
/// normal, m. A recorded contact is within the speculative margin of one step (millimetres); the
/// report looks much farther so that it never misses one, and keeps no points, only the normal.
constexpr Scalar kNormalSearchDistance = 1.0;

/// Which smooth force a probe of the force model keeps on.
enum class SmoothPart : std::uint8_t { Gravity, Springs, Drag };

/// Per body, the force of one smooth part alone: the force model run on a copy of the world with
/// the other parts off. A soft body gets the sum over its ellipses (its own entry has none).
std::vector<Vec2> smoothForces(const model::World& world, const std::vector<model::BodyState>& states, SmoothPart part)
{
    model::World probe;
    probe.settings = world.settings;
    probe.bodies = world.bodies;
    probe.softBodies = world.softBodies;
    probe.settings.gravity = part == SmoothPart::Gravity ? world.settings.gravity : Vec2::Zero();
    probe.settings.drag = part == SmoothPart::Drag ? world.settings.drag : 0;
    if (part == SmoothPart::Springs)
        probe.springs = world.springs;
    std::vector<BodyDerivative> derivatives;
    computeDerivatives(probe, states, derivatives);

    std::vector<Vec2> forces(world.bodies.size(), Vec2::Zero());
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (!body.fixed)
            forces[i] = body.mass * derivatives[i].acceleration;
    }
    // The ellipses follow the bodies in the state list, grid by grid (force_model.h, stateCount).
    std::size_t entry = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        Vec2 sum = Vec2::Zero();
        for (std::size_t e = 0; e < grid.positions.size(); ++e, ++entry)
            sum += grid.ellipseMass * derivatives[entry].acceleration;
        if (!world.body(grid.body).fixed)
            forces[grid.body.index] = sum;
    }
    return forces;
}

/// The time the impulses recorded in the last step acted over, s: one substep of it.
Scalar substepLength(const model::World& world)
{
    const Scalar h = world.settings.timeStep;
    const int substeps = std::max(solverSubsteps(h, constants::kMaxSolverStep), softStability(world).substeps);
    return h / substeps;
}

/// Adds the contact forces of the last step's records to `forces`.
void addContactForces(const model::World& world, Scalar dt, std::vector<BodyForces>& forces)
{
    const auto carries = [](const model::ContactRecord& r) {
        for (std::size_t i = 0; i < r.pointCount; ++i) {
            if (r.normalImpulses[i] != 0 || r.tangentImpulses[i] != 0)
                return true;
        }
        return false;
    };
    if (std::ranges::none_of(world.contacts, carries))
        return;
    ColliderSet colliders;
    colliders.build(world, std::vector<Scalar>(world.bodies.size(), 0));
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> pieceIndex;
    for (std::uint32_t i = 0; i < colliders.pieces().size(); ++i)
        pieceIndex.emplace(std::pair(colliders.pieces()[i].body, colliders.pieces()[i].piece), i);

    for (const model::ContactRecord& record : world.contacts) {
        if (!carries(record))
            continue;
        const auto a = pieceIndex.find({record.bodyA.index, record.pieceA});
        const auto b = pieceIndex.find({record.bodyB.index, record.pieceB});
        if (a == pieceIndex.end() || b == pieceIndex.end())
            continue;
        const Manifold manifold = collide(colliders.shape(a->second), colliders.shape(b->second), kNormalSearchDistance);
        if (manifold.count == 0 || !manifoldIsFinite(manifold))
            continue;
        const Vec2 n = manifold.normal;
        const Vec2 t(n.y(), -n.x());
        Scalar normal = 0;
        Scalar friction = 0;
        for (std::size_t i = 0; i < record.pointCount; ++i) {
            normal += record.normalImpulses[i];
            friction += record.tangentImpulses[i];
        }
        const Vec2 normalForce = (normal / dt) * n;
        const Vec2 frictionForce = (friction / dt) * t;
        if (!world.body(record.bodyA).fixed) {
            forces[record.bodyA.index].contactNormal -= normalForce;
            forces[record.bodyA.index].contactFriction -= frictionForce;
        }
        if (!world.body(record.bodyB).fixed) {
            forces[record.bodyB.index].contactNormal += normalForce;
            forces[record.bodyB.index].contactFriction += frictionForce;
        }
    }
}

/// Adds the joint forces of the last step's impulses to `forces`.
void addJointForces(const model::World& world, Scalar dt, std::vector<BodyForces>& forces)
{
    for (const model::Joint& joint : world.joints) {
        Vec2 impulse = joint.impulse;
        if (joint.type == model::JointType::Rod) {
            // The solver keeps a rod's impulse as a number along the line from A's anchor to B's.
            const Vec2 a = world.body(joint.bodyA).worldPoint(joint.anchorA);
            const Vec2 b = joint.bodyB ? world.body(*joint.bodyB).worldPoint(joint.anchorB) : joint.anchorB;
            const Vec2 d = b - a;
            const Scalar length = d.norm();
            impulse = joint.impulse.x() * (length > 0 ? Vec2(d / length) : Vec2(1, 0));
        }
        const Vec2 force = impulse / dt;
        if (!world.body(joint.bodyA).fixed)
            forces[joint.bodyA.index].joints -= force;
        if (joint.bodyB && !world.body(*joint.bodyB).fixed)
            forces[joint.bodyB->index].joints += force;
    }
}

} // namespace

std::vector<BodyForces> reportForces(const model::World& world)
{
    std::vector<BodyForces> forces(world.bodies.size());
    if (world.bodies.empty())
        return forces;
    std::vector<model::BodyState> states;
    gatherStates(world, states);
    const std::vector<Vec2> gravity = smoothForces(world, states, SmoothPart::Gravity);
    const std::vector<Vec2> springs = smoothForces(world, states, SmoothPart::Springs);
    const std::vector<Vec2> drag = smoothForces(world, states, SmoothPart::Drag);
    for (std::size_t i = 0; i < forces.size(); ++i) {
        forces[i].gravity = gravity[i];
        forces[i].springs = springs[i];
        forces[i].drag = drag[i];
    }
    const Scalar dt = substepLength(world);
    if (dt > 0) {
        addContactForces(world, dt, forces);
        addJointForces(world, dt, forces);
    }
    for (std::size_t i = 0; i < forces.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (!body.fixed && body.mass > 0)
            forces[i].acceleration = forces[i].net() / body.mass;
    }
    return forces;
}

} // namespace impetus::controller
