#include "controller/simulation.h"

#include "controller/narrow_phase.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace impetus::controller {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

} // namespace

Simulation::Simulation(SolverSettings settings)
    : m_settings(settings)
    , m_euler(makeIntegrator(model::IntegratorKind::Euler))
    , m_semiImplicitEuler(makeIntegrator(model::IntegratorKind::SemiImplicitEuler))
    , m_rk4(makeIntegrator(model::IntegratorKind::Rk4))
    , m_tasks(settings.secondThread ? std::make_unique<TaskPair>() : nullptr)
{
    m_contactSolver.useTasks(m_tasks.get());
}

Integrator& Simulation::integratorFor(model::IntegratorKind kind)
{
    switch (kind) {
    case model::IntegratorKind::Euler:
        return *m_euler;
    case model::IntegratorKind::SemiImplicitEuler:
        return *m_semiImplicitEuler;
    case model::IntegratorKind::Rk4:
        return *m_rk4;
    }
    return *m_rk4;
}

void Simulation::collide(const model::World& world, Scalar h)
{
    const Clock::time_point broadStart = Clock::now();
    // Each body's speculative margin: how far its surface can move in one step (translation,
    // rotation at its bounding radius, and what its acceleration adds), plus a constant margin so
    // that resting contacts exist before the surfaces touch.
    // A body at rest can also be struck and set moving within the step: one impact hands on at
    // most twice the striker's speed (e ≤ 1), so every dynamic body also gets 2·h times the
    // fastest body's speed, and a struck ball finds the wall just behind it.
    Scalar fastest = 0;
    for (const model::Body& body : world.bodies) {
        if (!body.fixed)
            fastest = std::max(fastest, body.state.velocity.norm() +
                                            std::abs(body.state.angularVelocity) * body.geometry.boundingRadius);
    }
    m_margins.assign(world.bodies.size(), constants::kSpeculativeMargin);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        const model::BodyState& s = body.state;
        const BodyDerivative& d = m_startDerivatives[i];
        m_margins[i] += h * (s.velocity.norm() + std::abs(s.angularVelocity) * body.geometry.boundingRadius) +
                        h * h * (d.acceleration.norm() + std::abs(d.angularAcceleration) * body.geometry.boundingRadius);
        if (!body.fixed)
            m_margins[i] += 2 * h * fastest;
    }
    m_colliders.build(world, m_margins);
    const std::vector<ColliderPiece>& pieces = m_colliders.pieces();
    m_proxies.resize(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i)
        m_proxies[i] = BroadPhaseProxy{m_colliders.boxes()[i], pieces[i].body, world.bodies[pieces[i].body].fixed};
    m_broadPhase.findPairs(m_proxies, m_pairs);
    m_profile.broadMs = millisecondsSince(broadStart);

    const Clock::time_point narrowStart = Clock::now();
    // Each pair's manifold goes to its own slot, so a large world's pairs can be split between
    // two threads and still come out in the broad phase's order.
    m_pairManifolds.resize(m_pairs.size());
    const auto collideRange = [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const ProxyPair& pair = m_pairs[k];
            m_pairManifolds[k] = controller::collide(m_colliders.shape(pair.first), m_colliders.shape(pair.second),
                                                     m_margins[pieces[pair.first].body] +
                                                         m_margins[pieces[pair.second].body]);
        }
    };
    if (m_tasks && m_pairs.size() >= constants::kParallelMinPairs) {
        const std::size_t half = m_pairs.size() / 2;
        m_tasks->run([&](int part) { part == 0 ? collideRange(0, half) : collideRange(half, m_pairs.size()); });
    } else {
        collideRange(0, m_pairs.size());
    }
    m_manifolds.clear();
    for (std::size_t k = 0; k < m_pairs.size(); ++k) {
        if (m_pairManifolds[k].count == 0)
            continue;
        const ColliderPiece& a = pieces[m_pairs[k].first];
        const ColliderPiece& b = pieces[m_pairs[k].second];
        m_manifolds.push_back({a.body, a.piece, b.body, b.piece, m_pairManifolds[k]});
    }
    m_profile.narrowMs = millisecondsSince(narrowStart);
}

void Simulation::integratePositions(model::World& world, Scalar h)
{
    // Two ways to finish a body's step (docs/physics.md, "Contacts"):
    //  - bodies held by contact forces or joints: semi-implicit Euler, x = x₀ + h·v, the
    //    position that matches the constrained velocity (a resting body stays exactly at rest);
    //  - all others keep the integrator's position (RK4 stays exact in free flight), moved by
    //    what their impacts changed after the time of impact.
    // Either way an impact at τ·h moves the body only for the remaining (1 − τ)·h.
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        model::Body& body = world.bodies[i];
        SolverBody& sb = m_bodies[i];
        model::BodyState& s = body.state;
        if (body.fixed) {
            // The integrator moved it with its own velocity; position correction must see that.
            sb.position = s.position;
            sb.angle = s.angle;
            continue;
        }
        const model::BodyState& start = m_startStates[i];
        if (sb.hadContactForce) {
            // Until its first impact the body moved with its start velocity, then with its final
            // one. (Written with the final velocity alone, an impact that a contact force then
            // cancels would still move the body.)
            const Scalar tau = sb.hadImpact ? sb.firstImpactTau : 0.0;
            s.position = start.position + h * (tau * start.velocity + (1 - tau) * sb.velocity);
            s.angle = start.angle + h * (tau * start.angularVelocity + (1 - tau) * sb.angularVelocity);
        } else if (sb.hadImpact) {
            // s holds the integrator's result; sb.velocity − s.velocity is what the impacts added.
            s.position += h * (sb.velocity - s.velocity - sb.impactLateVelocity);
            s.angle += h * (sb.angularVelocity - s.angularVelocity - sb.impactLateAngularVelocity);
        }
        s.velocity = sb.velocity;
        s.angularVelocity = sb.angularVelocity;
        sb.position = s.position;
        sb.angle = s.angle;
    }
}

void Simulation::step(model::World& world)
{
    const Clock::time_point stepStart = Clock::now();
    const Scalar h = world.settings.timeStep;
    const std::size_t n = world.bodies.size();

    // Phase 0: the start of the step, as the solvers see it.
    m_startStates.resize(n);
    m_bodies.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const model::Body& body = world.bodies[i];
        m_startStates[i] = body.state;
        SolverBody& sb = m_bodies[i];
        sb = SolverBody{};
        sb.position = body.state.position;
        sb.angle = body.state.angle;
        sb.invMass = body.invMass;
        sb.invInertia = body.invInertia;
        // A fixed body's own velocity is what its surface brings to a contact (a belt, a drum).
        sb.velocity = body.state.velocity;
        sb.angularVelocity = body.state.angularVelocity;
    }
    computeDerivatives(world, m_startStates, m_startDerivatives);

    // Phase 1: collision detection at the start-of-step poses, with speculative margins.
    collide(world, h);

    // Phase 2: impacts, on the velocities from before this step's forces.
    const Clock::time_point solveStart = Clock::now();
    m_contactSolver.prepare(world, m_manifolds, m_bodies, m_startDerivatives);
    m_contactSolver.partition(m_bodies);
    m_jointSolver.prepare(world, m_bodies);
    m_profile.prepareMs = millisecondsSince(solveStart);
    const Clock::time_point impactsStart = Clock::now();
    m_profile.impacts = m_contactSolver.solveImpacts(m_bodies, h);
    m_profile.contacts = static_cast<int>(m_contactSolver.constraints().size());
    m_profile.impactsMs = millisecondsSince(impactsStart);
    double solveMs = millisecondsSince(solveStart);

    // Phase 3: smooth forces (gravity, springs, drag) integrated over the whole world state.
    const Clock::time_point integrateStart = Clock::now();
    integratorFor(world.settings.integrator).integrate(world, h);
    m_profile.integrateMs = millisecondsSince(integrateStart);

    // Phase 4: contact forces and joints, on the integrated velocities plus the impacts' change.
    const Clock::time_point velocityStart = Clock::now();
    for (std::size_t i = 0; i < n; ++i) {
        if (world.bodies[i].fixed)
            continue;
        SolverBody& sb = m_bodies[i];
        sb.velocity += world.bodies[i].state.velocity - m_startStates[i].velocity;
        sb.angularVelocity += world.bodies[i].state.angularVelocity - m_startStates[i].angularVelocity;
    }
    m_jointSolver.warmStart(m_bodies);
    m_contactSolver.warmStart(m_bodies, h);
    for (int i = 0; i < m_settings.velocityIterations; ++i) {
        m_jointSolver.solveVelocities(m_bodies, h);
        m_contactSolver.solveVelocities(m_bodies);
    }
    m_contactSolver.finishVelocities(m_bodies);
    m_profile.velocityMs = millisecondsSince(velocityStart);
    const Clock::time_point positionStart = Clock::now();

    // Phase 5: positions, then position correction (moves bodies, never touches velocities).
    integratePositions(world, h);
    for (int i = 0; i < m_settings.positionIterations; ++i) {
        const bool jointsOk = m_jointSolver.solvePositions(m_bodies);
        const bool contactsOk = m_contactSolver.solvePositions(m_bodies);
        if (jointsOk && contactsOk)
            break;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (world.bodies[i].fixed)
            continue;
        world.bodies[i].state.position = m_bodies[i].position;
        world.bodies[i].state.angle = m_bodies[i].angle;
    }
    m_profile.positionMs = millisecondsSince(positionStart);
    solveMs += millisecondsSince(velocityStart);
    m_profile.solveMs = solveMs;

    // Phase 6: the clock, then what the contacts mean (colliding flags, events, warm start).
    world.time += h;
    ++world.stepCount;
    const Clock::time_point eventsStart = Clock::now();
    // The last step's records move aside and their buffer takes this step's: two buffers take
    // turns, so a large world's records are not allocated afresh every step.
    m_previousContacts.swap(world.contacts);
    m_events = updateCollisionState(world, m_contactSolver, m_bodies, m_previousContacts);
    m_profile.eventsMs = millisecondsSince(eventsStart);
    m_jointSolver.storeImpulses(world);
    for (model::Joint& joint : world.joints) {
        // Keep a pin between two bodies at the hinge's current place, so that saving mid-run writes
        // a scene that loads to this state. A pin to the world keeps its fixed pivot.
        if (joint.type == model::JointType::Pin && joint.bodyB)
            joint.worldAnchor = world.body(joint.bodyA).worldPoint(joint.anchorA);
    }

    m_profile.totalMs = millisecondsSince(stepStart);
}

} // namespace impetus::controller
