#include "controller/simulation.h"

#include "controller/collision/narrow_phase.h"
#include "controller/dynamics/prefetch.h"
#include "controller/energy_ledger.h"
#include "controller/large_arrays.h"
#include "controller/soft/soft_body_builder.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <variant>

namespace impetus::controller {

namespace {

/// How many bodies down a chain of touching bodies a large world's strike shares reach
/// (Simulation::addStrikeShares): a blow passes on through a row of touching bodies within one
/// step, and the last of them must find the wall behind it. 8 covers a Newton's cradle of up to
/// nine balls; one body's speed then reaches the bodies within eight links of it, about two
/// hundred in a pile, instead of all of them.
constexpr int kStrikeChainLinks = 8;
/// The farthest a body other than a circle, or a pinned body, turns within one substep
/// (spinSubsteps), rad: an eighth of a turn, as Box2D's b2_maxRotation. Its contacts and pins are
/// built at the substep's start and followed linearly in the turn θ: the normal and the arms are
/// then θ off, and the gap by R·(1 − cos θ) ≈ R·θ²/2 at a point R from the centre.
constexpr Scalar kMaxTurnPerSubstep = 0.25 * std::numbers::pi;
/// The same in a world whose masses lie more than UnlikeMassIslands::kMassRatio apart, rad:
/// there a heavy body can drive a light one against a wall, and the light one's contact rows,
/// linear in its spin, are met by the spin alone (its touching point turns away while its centre
/// goes on into the wall). 11 of the 18 open soak findings of 2026-11-28 were that, at an eighth
/// of a turn a substep (seed 4386: a 54 g ellipse at 148 rad/s, 0.6 rad a substep); at 0.1 rad,
/// which keeps the normal within 6° and the gap within 5 mm on a body of 1 m, all 11 stay in.
/// Worlds of like masses keep the eighth: there it costs the spinner three times its time. In a
/// world without joints, springs or soft grids (every one of the 11 had them) only a heavy body
/// touching a light one drives it, and only such light bodies are held to 0.1 rad.
constexpr Scalar kMaxUnlikeMassTurnPerSubstep = 0.1;
/// The farthest a rod's ends go round each other within one substep (spinSubsteps), rad. A rod's
/// pass solves its end condition with the impulse along the rod's start direction (SHAKE, joint
/// solver), whose energy is off by about (θ/2)² for a turn θ in a substep: for a ball on a rod
/// that stays near 1 % at 0.2 rad, but where the rod's end is off a spinning body's centre the
/// error adds up: a 4.4 t polygon at 51 m/s on a rod to the world gained 2.6 % of its energy a
/// second at 0.2 rad and 0.1 % at 0.1 rad (soak seed 5812).
constexpr Scalar kMaxRodTurnPerSubstep = 0.1;

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// A large world's largest mean travel per substep, as a fraction of each body's bounding radius
/// (crowdSubsteps). The spinner's heap flung by its arm travels 0.4–0.5 of its radius a step of
/// 1/240 s on average, and about 0.14 once it goes round with the arm; the benchmarks' rain of
/// polygons and turning box of circles stay under it (their steps of 1/240 s are not split).
constexpr Scalar kMaxCrowdTravelPerSubstep = 0.25;

/// How many bodies ahead setUpSolverBodies asks for a body's lines.
constexpr std::size_t kBodyPrefetchAhead = 4;

/// The substeps that bring a quantity that grows with the substep to its limit, given its ratio
/// to the limit at one substep: ⌈ratio⌉, at least 1, at most kMaxSolverSubsteps (also for a NaN).
int substepsForRatio(Scalar ratio)
{
    if (!(ratio < constants::kMaxSolverSubsteps))
        return constants::kMaxSolverSubsteps;
    return std::max(1, static_cast<int>(std::ceil(ratio)));
}

} // namespace

Scalar fastestTravel(const model::World& world, Scalar h)
{
    // Every body that moves, a fixed one included: a moving fixed body (the spinner's arm, a
    // turning drum) strikes what it meets, and the margins of a whole step give those bodies
    // 2·h times its speed.
    Scalar fastest = 0;
    for (const model::Body& body : world.bodies) {
        fastest = std::max(fastest, body.state.velocity.norm() +
                                        std::abs(body.state.angularVelocity) * body.geometry.boundingRadius);
    }
    return fastest * h;
}

bool contactsLastTheStep(const model::World& world, Scalar h)
{
    for (const model::Body& body : world.bodies) {
        const Scalar radius = body.geometry.boundingRadius;
        const Scalar travel = h * (body.state.velocity.norm() + std::abs(body.state.angularVelocity) * radius);
        // A moving fixed body strikes whatever it meets at its own speed: only the constant margin.
        Scalar allowed = constants::kReuseContactsMaxTravel;
        if (!body.fixed)
            allowed = std::max(allowed, std::min(constants::kReuseContactsMaxBodyTravel,
                                                 constants::kReuseContactsMaxTravelFraction * radius));
        // Written so that a NaN travel fails.
        if (!(travel <= allowed))
            return false;
    }
    return true;
}

int solverSubsteps(Scalar h, Scalar maxSubstep)
{
    if (!(h > 0) || !(maxSubstep > 0))
        return 1;
    // A relative tolerance far above rounding (1e-16) and far below any step a user would type:
    // h = 1/60 is four substeps of 1/240 s, not five.
    constexpr Scalar kRoundingTolerance = 1e-9;
    return substepsForRatio(h / maxSubstep * (1 - kRoundingTolerance));
}

int dragSubsteps(const model::World& world, Scalar h)
{
    if (!(world.settings.drag > 0) || !(h > 0))
        return 1;
    // The fastest drag rate is the lightest dynamic body's (a soft body's ellipses share its
    // rate: each takes its mass's share of the drag).
    Scalar largestInvMass = 0;
    for (const model::Body& body : world.bodies) {
        if (!body.fixed)
            largestInvMass = std::max(largestInvMass, body.invMass);
    }
    return substepsForRatio(world.settings.drag * largestInvMass * h / constants::kMaxDragRateStep);
}

int spinSubsteps(const model::World& world, Scalar h)
{
    if (!(h > 0))
        return 1;
    // A circle looks the same however far it turns, but any other body's contacts are built at
    // the start of a substep and followed through it linearly in the turn: a box or an ellipse
    // that turns by more than kMaxTurnPerSubstep within one is somewhere else than its contacts
    // say (an ellipse at 2,233 rad/s turned half a turn a substep and passed through a wall, soak
    // seed 131). Such a world is split until no body turns farther than that in a substep, as
    // far as kMaxSolverSubsteps allow. Box2D caps the spin itself at that turn instead; here the
    // body keeps its spin and its kinetic energy. A world of unlike masses is split further
    // (kMaxUnlikeMassTurnPerSubstep).
    Scalar fastest = 0;
    Scalar lightest = std::numeric_limits<Scalar>::infinity();
    Scalar heaviest = 0;
    for (const model::Body& body : world.bodies) {
        if (!body.soft && !std::holds_alternative<model::Circle>(body.shape))
            fastest = std::max(fastest, std::abs(body.state.angularVelocity));
        if (!body.fixed && body.mass > 0) {
            lightest = std::min(lightest, body.mass);
            heaviest = std::max(heaviest, body.mass);
        }
    }
    // A joint's rows are built at the start of a substep too: a rod along its direction then, a
    // pin at its arms then. A pinned body of any shape that turns by more than kMaxTurnPerSubstep
    // within a substep, or a rod whose ends go round each other by more than
    // kMaxRodTurnPerSubstep, is held along a line it has left (a 1.9 kg ellipse at 83 m/s on a
    // rod of 0.3 m to the world, 280 rad/s about its pivot, gained a fifth of the world's energy
    // in one step of 1/240 s: soak seed 3641).
    Scalar fastestRod = 0;
    for (const model::Joint& joint : world.joints) {
        const model::Body& a = world.body(joint.bodyA);
        const model::Body* b = joint.bodyB ? &world.body(*joint.bodyB) : nullptr;
        if (joint.type == model::JointType::Pin) {
            fastest = std::max({fastest, std::abs(a.state.angularVelocity),
                                b ? std::abs(b->state.angularVelocity) : 0.0});
            continue;
        }
        const Vec2 endA = a.worldPoint(joint.anchorA);
        const Vec2 endB = b ? b->worldPoint(joint.anchorB) : joint.anchorB;
        const Vec2 along = endB - endA;
        const Scalar lengthSquared = along.squaredNorm();
        if (!(lengthSquared > 0))
            continue;
        const Vec2 relative = (b ? b->velocityAt(endB) : Vec2::Zero()) - a.velocityAt(endA);
        fastestRod = std::max(fastestRod, std::abs(cross(along, relative)) / lengthSquared);
    }
    const bool unlike = heaviest > UnlikeMassIslands::kMassRatio * lightest;
    // A world whose joints, springs or soft grids can drive a light body into a wall (every
    // finding the finer split fixed had them) is split for its fastest body. Among free bodies
    // only a heavy body touching a light one can drive it: the finer split is for the light bodies
    // of such contacts (as the last step ended), and the rest keep the eighth. (Split for its
    // fastest body, the rain of polygons, whose smallest pieces spin at up to 80 rad/s, took 14
    // substeps of 1/60 s for some steps, six times its median step: issue 12.)
    const bool driven = !world.joints.empty() || !world.springs.empty() || !world.softBodies.empty();
    Scalar turns = fastest * h / (unlike && driven ? kMaxUnlikeMassTurnPerSubstep : kMaxTurnPerSubstep);
    if (unlike && !driven) {
        for (const model::ContactRecord& contact : world.contacts) {
            if (contact.bodyA.index >= world.bodies.size() || contact.bodyB.index >= world.bodies.size())
                continue; // a record of bodies that are gone (the editor renumbers them; kept safe)
            const model::Body& a = world.body(contact.bodyA);
            const model::Body& b = world.body(contact.bodyB);
            if (a.fixed || b.fixed)
                continue;
            const model::Body& light = a.mass < b.mass ? a : b;
            const model::Body& heavy = a.mass < b.mass ? b : a;
            if (heavy.mass > UnlikeMassIslands::kMassRatio * light.mass &&
                !std::holds_alternative<model::Circle>(light.shape))
                turns = std::max(turns, std::abs(light.state.angularVelocity) * h / kMaxUnlikeMassTurnPerSubstep);
        }
    }
    return substepsForRatio(std::max(turns, fastestRod * h / kMaxRodTurnPerSubstep));
}

int crowdSubsteps(const model::World& world, Scalar h)
{
    if (!(h > 0) || world.bodies.size() < constants::kLocalStrikeShareMinBodies)
        return 1;
    Scalar travel = 0;
    std::size_t count = 0;
    for (const model::Body& body : world.bodies) {
        const Scalar radius = body.geometry.boundingRadius;
        if (body.fixed || body.soft || !(radius > 0))
            continue;
        travel += (body.state.velocity.norm() + std::abs(body.state.angularVelocity) * radius) * h / radius;
        ++count;
    }
    return count == 0 ? 1 : substepsForRatio(travel / static_cast<Scalar>(count) / kMaxCrowdTravelPerSubstep);
}

Simulation::Simulation(SolverSettings settings)
    : m_settings(settings)
    , m_euler(makeIntegrator(model::IntegratorKind::Euler))
    , m_semiImplicitEuler(makeIntegrator(model::IntegratorKind::SemiImplicitEuler))
    , m_rk4(makeIntegrator(model::IntegratorKind::Rk4))
    , m_tasks(settings.secondThread ? std::make_unique<TaskPair>() : nullptr)
{
    m_contactSolver.useTasks(m_tasks.get());
    m_contactSolver.setBatchMinConstraints(settings.batchMinConstraints);
    m_contactSolver.setImpactReachBounds(settings.impactReachBounds);
}

void Simulation::setLedger(EnergyLedger* ledger)
{
    m_ledger = ledger;
    m_contactSolver.measureImpactWork(ledger != nullptr);
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

TaskPair* Simulation::bodyTasks(const model::World& world) const
{
    return world.bodies.size() >= constants::kParallelMinBodies ? m_tasks.get() : nullptr;
}

void Simulation::setUpSolverBodies(const model::World& world)
{
    const std::size_t n = world.bodies.size();
    m_bodies.resize(m_startStates.size());
    m_entries.resize(m_startStates.size());
    inHalves(bodyTasks(world), n, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            // A body is seven cache lines, of which this reads most, every substep: a later one's
            // are asked for while this one is copied.
            if (i + kBodyPrefetchAhead < end)
                detail::prefetchObject(world.bodies[i + kBodyPrefetchAhead]);
            const model::Body& body = world.bodies[i];
            m_entries[i] = body.fixed ? Entry::Fixed : Entry::Rigid;
            SolverBody& sb = m_bodies[i];
            sb = SolverBody{};
            sb.position = body.state.position;
            sb.angle = body.state.angle;
            sb.invMass = body.invMass;
            sb.invInertia = body.invInertia;
            // A fixed body's own velocity is what its surface brings to a contact (a belt, a drum).
            sb.velocity = body.state.velocity;
            sb.angularVelocity = body.state.angularVelocity;
            sb.friction = body.material.friction;
            sb.restitution = body.material.restitution;
            if (const auto* circle = std::get_if<model::Circle>(&body.shape))
                sb.round = circle->radius;
        }
    });
    // A soft body's own solver body is its grid's aggregate: only joints act on it (contacts act
    // on the ellipses), and what they do is handed on to the ellipses (shareJointMotion).
    m_softAggregates.resize(world.softBodies.size());
    m_movedBy.resize(world.softBodies.empty() ? 0 : m_bodies.size());
    std::iota(m_movedBy.begin(), m_movedBy.end(), 0U);
    std::size_t next = n;
    for (std::size_t g = 0; g < world.softBodies.size(); ++g) {
        const model::SoftGrid& grid = world.softBodies[g];
        const std::uint32_t owner = grid.body.index;
        m_entries[owner] = Entry::SoftOwner;
        // Its state is already the grid's aggregate (updateSoftOwners, placeSoftGrid); joints
        // also need the grid's present moment of inertia, which takes a pass over the ellipses.
        if (!world.joints.empty()) {
            const SoftAggregate a =
                softAggregate(grid, grid.positions, grid.velocities, world.bodies[owner].state.angle);
            m_bodies[owner].invInertia = a.inertia > 0 ? 1 / a.inertia : 0;
        }
        m_softAggregates[g] = m_bodies[owner];
        const Scalar invMass = 1 / grid.ellipseMass;
        for (std::size_t i = 0; i < grid.size(); ++i, ++next) {
            m_entries[next] = Entry::Ellipse;
            m_movedBy[next] = owner;
            SolverBody& e = m_bodies[next];
            e = SolverBody{};
            e.position = grid.positions[i];
            e.velocity = grid.velocities[i];
            // Ellipses do not spin: they are points of the grid, whose rotation is the springs'.
            e.invMass = invMass;
            e.friction = world.bodies[owner].material.friction;
            e.restitution = world.bodies[owner].material.restitution;
        }
    }
}

void Simulation::collide(const model::World& world, Scalar h)
{
    const Clock::time_point broadStart = Clock::now();
    ++m_profile.collisionPasses;
    const std::size_t n = world.bodies.size();
    // Each body's speculative margin: how far its surface can move in one step (translation,
    // rotation at its bounding radius, and what its acceleration adds), plus a constant margin so
    // that resting contacts exist before the surfaces touch.
    // A body at rest can also be struck and set moving within the step: one impact hands on at
    // most twice the striker's speed (e ≤ 1), so a body that a striker can reach gets 2·h times
    // the striker's speed on top, and a struck ball finds the wall just behind it. A small world
    // gives every dynamic body that share of the fastest body; a large one only the share of the
    // fastest body that can reach it (addStrikeShares).
    // One pass over the bodies: each one's margin without the strike share (its surface speed
    // computed once, for both), then the share.
    // A large world does each half of its bodies on its own thread; the fastest speed is the
    // larger of the halves' (a maximum, so the same either way).
    m_margins.resize(n);
    m_strikeSpeeds.resize(n);
    std::array<Scalar, 2> fastestOf{};
    const auto ownMargins = [&](std::size_t begin, std::size_t end) {
        Scalar fastest = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const model::Body& body = world.bodies[i];
            const model::BodyState& s = m_startStates[i];
            const BodyDerivative& d = m_startDerivatives[i];
            const Scalar speed = s.velocity.norm() + std::abs(s.angularVelocity) * body.geometry.boundingRadius;
            // A fixed body moves as it was told whatever strikes it (its own margin covers its
            // travel), but a moving one strikes: the world's share counts it at its fastest
            // point, a large world at its speed where it meets each body (addStrikeShares).
            m_strikeSpeeds[i] = body.fixed ? 0 : speed;
            fastest = std::max(fastest, speed);
            m_margins[i] = constants::kSpeculativeMargin;
            m_margins[i] += h * speed + h * h * (d.acceleration.norm() +
                                                 std::abs(d.angularAcceleration) * body.geometry.boundingRadius);
        }
        return fastest;
    };
    TaskPair* const tasks = bodyTasks(world);
    if (tasks) {
        tasks->run([&](int part) {
            fastestOf[static_cast<std::size_t>(part)] = part == 0 ? ownMargins(0, n / 2) : ownMargins(n / 2, n);
        });
    } else {
        fastestOf[0] = ownMargins(0, n);
    }
    Scalar fastest = std::max(fastestOf[0], fastestOf[1]);
    // A soft body strikes as fast as its fastest ellipse, and its margin is the farthest any of
    // them can move.
    std::size_t next = n;
    for (const model::SoftGrid& grid : world.softBodies) {
        Scalar travel = 0;
        Scalar speed = 0;
        for (std::size_t i = 0; i < grid.size(); ++i, ++next) {
            speed = std::max(speed, m_startStates[next].velocity.norm());
            travel = std::max(travel, h * m_startStates[next].velocity.norm() +
                                          h * h * m_startDerivatives[next].acceleration.norm());
        }
        m_margins[grid.body.index] = constants::kSpeculativeMargin + travel;
        m_strikeSpeeds[grid.body.index] = speed;
        fastest = std::max(fastest, speed);
    }
    const bool local = n >= constants::kLocalStrikeShareMinBodies && 2 * h * fastest > constants::kSpeculativeMargin;
    if (local) {
        // The boxes at the bodies' own margins tell which bodies can reach which; each then grows
        // by its share.
        m_colliders.build(world, m_margins, tasks);
        addStrikeShares(world, h);
    } else {
        inHalves(tasks, n, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                if (m_entries[i] != Entry::Fixed)
                    m_margins[i] += 2 * h * fastest;
            }
        });
        m_colliders.build(world, m_margins, tasks);
    }
    const std::vector<ColliderPiece>& pieces = m_colliders.pieces();
    if (world.softBodies.empty()) {
        m_proxies.resize(pieces.size());
        inHalves(tasks, pieces.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                m_proxies[i] = BroadPhaseProxy{m_colliders.boxes()[i], pieces[i].body,
                                               m_entries[pieces[i].body] == Entry::Fixed};
            }
        });
        m_broadPhase.findPairs(m_proxies, m_pairs);
    } else {
        findPairsWithSoftBodies(world);
    }
    m_profile.broadMs += millisecondsSince(broadStart);

    const Clock::time_point narrowStart = Clock::now();
    // Each pair's manifold goes to its own slot, so a large world's pairs can be split between
    // two threads and still come out in the broad phase's order.
    resizeLarge(m_manifolds, m_pairs.size());
    const auto collideRange = [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const ProxyPair& pair = m_pairs[k];
            const ColliderPiece& a = pieces[pair.first];
            const ColliderPiece& b = pieces[pair.second];
            const Scalar distance = pairDistance(a.body, b.body, h);
            ContactSolver::PairManifold& slot = m_manifolds[k];
            slot.bodyA = a.solver;
            slot.pieceA = a.piece;
            slot.bodyB = b.solver;
            slot.pieceB = b.piece;
            slot.ownerA = a.body;
            slot.ownerB = b.body;
            // Two polygons, the most common pair, go straight to SAT, as collide() would send them.
            const bool polygons = a.kind == ColliderPiece::Kind::Polygon && b.kind == ColliderPiece::Kind::Polygon;
            slot.manifold = polygons ? collidePolygons(m_colliders.polygon(pair.first), m_colliders.polygon(pair.second), distance)
                                     : controller::collide(m_colliders.shape(pair.first), m_colliders.shape(pair.second), distance);
        }
    };
    if (m_tasks && m_pairs.size() >= constants::kParallelMinPairs) {
        const std::size_t half = m_pairs.size() / 2;
        m_tasks->run([&](int part) { part == 0 ? collideRange(0, half) : collideRange(half, m_pairs.size()); });
    } else {
        collideRange(0, m_pairs.size());
    }
    // Pairs without contact keep their (empty) slots: ContactSolver::prepare skips them, and
    // moving the others up would copy most of a pile's manifolds on one thread.
    m_profile.narrowMs += millisecondsSince(narrowStart);
}

Scalar Simulation::approachSpeed(const model::World& world, std::uint32_t first, std::uint32_t second) const
{
    const model::BodyState& a = m_startStates[first];
    const model::BodyState& b = m_startStates[second];
    return (a.velocity - b.velocity).norm() + std::abs(a.angularVelocity) * world.bodies[first].geometry.boundingRadius +
           std::abs(b.angularVelocity) * world.bodies[second].geometry.boundingRadius;
}

Scalar Simulation::pairDistance(std::uint32_t first, std::uint32_t second, Scalar h) const
{
    const Scalar margins = m_margins[first] + m_margins[second];
    if (m_entries[first] == Entry::SoftOwner || m_entries[second] == Entry::SoftOwner)
        return margins;
    // Each margin took h times its body's own speed, |v| + |ω|·r, for its travel; what brings the
    // two surfaces together is the speed of one relative to the other, at most |v_A − v_B| plus
    // both spins' share (approachSpeed), never more than the sum. The spins' shares are in both
    // and cancel: the pair gives back h·(|v_A| + |v_B| − |v_A − v_B|) ≥ 0. Bodies flying together
    // (a heap thrown by the spinner's arm at 100 m/s) then keep contacts with the neighbours they
    // can meet, not with every body within 2·h·100 m/s. Everything else the margins hold (the
    // constant margin, the acceleration's share, the strike shares) stays.
    const Vec2& a = m_startStates[first].velocity;
    const Vec2& b = m_startStates[second].velocity;
    return margins - h * std::max<Scalar>(0, a.norm() + b.norm() - (a - b).norm());
}

void Simulation::addStrikeShares(const model::World& world, Scalar h)
{
    // One proxy per body that can strike or be struck: the box around its pieces' boxes, each
    // already enlarged by the body's own margin. Two bodies whose proxies overlap can meet within
    // the step. Fixed bodies at rest neither strike nor are set moving, so they are left out; a
    // moving fixed body (the spinner's arm, a turning box's walls) strikes but is never set
    // moving (the broad phase never pairs two fixed proxies).
    const std::vector<ColliderPiece>& pieces = m_colliders.pieces();
    const std::vector<Aabb>& boxes = m_colliders.boxes();
    m_reachProxies.clear();
    for (std::size_t i = 0; i < pieces.size();) {
        const std::uint32_t body = pieces[i].body;
        Aabb box = boxes[i];
        for (++i; i < pieces.size() && pieces[i].body == body; ++i)
            box = Aabb::merged(box, boxes[i]);
        const model::BodyState& s = m_startStates[body];
        const bool fixed = world.bodies[body].fixed;
        if (!fixed || !s.velocity.isZero() || s.angularVelocity != 0)
            m_reachProxies.push_back(BroadPhaseProxy{box, body, fixed});
    }
    m_reachPhase.findPairs(m_reachProxies, m_reachPairs);

    // Each body's reach speed: the fastest a striker that can reach it approaches it, counting
    // blows passed on. An impact changes a body's velocity by at most twice the speed at which
    // its striker approaches (e ≤ 1), so its margin takes 2·h times that speed on top of its own
    // travel. The speed is the striker's relative to the body, not its speed in the world's
    // frame: bodies flying together at 100 m/s (the spinner's heap thrown by its arm) strike each
    // other no harder than at rest, and taking their speeds in the world's frame gave each of
    // them a margin of 2·h·100 m/s, 40 contacts a body. A blow passes on down a chain of touching
    // bodies within the step (Newton's cradle: the last ball leaves at the first one's speed), so
    // the speeds are handed on along the pairs, kStrikeChainLinks times: a chain of that many
    // bodies is covered as the world's share covered it, while a pile does not hand one body's
    // speed to all of its thousands. Handed on without doubling: equal bodies pass a blow on at
    // the striker's speed, and a blow that doubles at every link needs ever lighter bodies down
    // the chain.
    const std::size_t n = world.bodies.size();
    // A bound on how fast a point of `first` approaches a point of `second`: the difference of
    // their velocities plus each one's spin at its bounding radius. A soft body's ellipses move
    // each their own way, so a pair with one counts both bodies' fastest speeds in full.
    const auto soft = [&](std::uint32_t body) { return m_entries[body] == Entry::SoftOwner; };
    const auto approachBound = [&](std::uint32_t first, std::uint32_t second) {
        if (soft(first) || soft(second))
            return m_strikeSpeeds[first] + m_strikeSpeeds[second];
        return approachSpeed(world, first, second);
    };
    m_reachSpeeds.assign(n, 0);
    for (const ProxyPair& pair : m_reachPairs) {
        const BroadPhaseProxy& first = m_reachProxies[pair.first];
        const BroadPhaseProxy& second = m_reachProxies[pair.second];
        if (!first.fixed && !second.fixed) {
            const Scalar speed = approachBound(first.body, second.body);
            m_reachSpeeds[first.body] = std::max(m_reachSpeeds[first.body], speed);
            m_reachSpeeds[second.body] = std::max(m_reachSpeeds[second.body], speed);
            continue;
        }
        // A moving fixed body strikes at its velocity where it meets the other: taken at the
        // centre of the other's box, plus its spin times the half-diagonal of that box for the
        // box's other points (not its whole length: the spinner's 40 m arm turns slowly near its
        // centre), relative to the other body.
        const BroadPhaseProxy& wall = first.fixed ? first : second;
        const BroadPhaseProxy& struck = first.fixed ? second : first;
        const model::BodyState& w = m_startStates[wall.body];
        const model::BodyState& b = m_startStates[struck.body];
        const Vec2 centre = 0.5 * (struck.box.lower + struck.box.upper);
        const Scalar halfDiagonal = 0.5 * (struck.box.upper - struck.box.lower).norm();
        const Vec2 wallVelocity = w.velocity + cross(w.angularVelocity, Vec2(centre - w.position));
        const Scalar own = soft(struck.body)
                               ? m_strikeSpeeds[struck.body] + b.velocity.norm()
                               : std::abs(b.angularVelocity) * world.bodies[struck.body].geometry.boundingRadius;
        const Scalar speed = (wallVelocity - b.velocity).norm() + std::abs(w.angularVelocity) * halfDiagonal + own;
        m_reachSpeeds[struck.body] = std::max(m_reachSpeeds[struck.body], speed);
    }
    // Jacobi rounds, from the last round's speeds, so that the result does not depend on the
    // pairs' order.
    for (int link = 0; link < kStrikeChainLinks; ++link) {
        m_handedSpeeds = m_reachSpeeds;
        for (const ProxyPair& pair : m_reachPairs) {
            const BroadPhaseProxy& first = m_reachProxies[pair.first];
            const BroadPhaseProxy& second = m_reachProxies[pair.second];
            if (first.fixed || second.fixed)
                continue;
            m_handedSpeeds[second.body] = std::max(m_handedSpeeds[second.body], m_reachSpeeds[first.body]);
            m_handedSpeeds[first.body] = std::max(m_handedSpeeds[first.body], m_reachSpeeds[second.body]);
        }
        m_reachSpeeds.swap(m_handedSpeeds);
    }
    m_strikeShares.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!world.bodies[i].fixed)
            m_strikeShares[i] = 2 * h * m_reachSpeeds[i];
        m_margins[i] += m_strikeShares[i];
    }
    m_colliders.enlargeBoxes(m_strikeShares);
}

void Simulation::findPairsWithSoftBodies(const model::World& world)
{
    // Two levels. The broad phase sees each soft body as one box around its ellipses (so it never
    // sweeps past the thousands of neighbouring ellipses of one body, which never collide), next
    // to every rigid piece. Then, for each pair of boxes that involves a soft body, the ellipses
    // whose boxes reach into the other's box are paired with it (or with each other's).
    const std::vector<ColliderPiece>& pieces = m_colliders.pieces();
    const std::vector<Aabb>& boxes = m_colliders.boxes();
    m_proxies.clear();
    m_proxyPieces.clear();
    for (std::uint32_t i = 0; i < pieces.size();) {
        const std::uint32_t body = pieces[i].body;
        std::uint32_t end = i + 1;
        Aabb box = boxes[i];
        if (world.softGrid(model::BodyId{body})) {
            for (; end < pieces.size() && pieces[end].body == body; ++end)
                box = Aabb::merged(box, boxes[end]);
        }
        m_proxies.push_back(BroadPhaseProxy{box, body, world.bodies[body].fixed});
        m_proxyPieces.push_back({i, end});
        i = end;
    }
    m_broadPhase.findPairs(m_proxies, m_coarsePairs);

    m_pairs.clear();
    std::vector<std::uint32_t>& nearA = m_nearA;
    std::vector<std::uint32_t>& nearB = m_nearB;
    for (const ProxyPair& coarse : m_coarsePairs) {
        const auto [firstA, endA] = m_proxyPieces[coarse.first];
        const auto [firstB, endB] = m_proxyPieces[coarse.second];
        if (endA - firstA == 1 && endB - firstB == 1) {
            m_pairs.push_back({firstA, firstB});
            continue;
        }
        // The pieces of each side that reach into the other side's box, then every pair of them
        // whose boxes overlap.
        nearA.clear();
        nearB.clear();
        for (std::uint32_t a = firstA; a < endA; ++a) {
            if (boxes[a].overlaps(m_proxies[coarse.second].box))
                nearA.push_back(a);
        }
        for (std::uint32_t b = firstB; b < endB; ++b) {
            if (boxes[b].overlaps(m_proxies[coarse.first].box))
                nearB.push_back(b);
        }
        for (const std::uint32_t a : nearA) {
            for (const std::uint32_t b : nearB) {
                if (boxes[a].overlaps(boxes[b]))
                    m_pairs.push_back({a, b});
            }
        }
    }
    // The broad phase's order, (first, second), whatever order the coarse pairs came in.
    std::sort(m_pairs.begin(), m_pairs.end());
}

void Simulation::integratePositions(const model::World& world, Scalar h)
{
    // Two ways to finish a body's step (docs/physics.md, "Contacts"):
    //  - bodies held by contact forces or joints: semi-implicit Euler, x = x₀ + h·v, the
    //    position that matches the constrained velocity (a resting body stays exactly at rest);
    //  - all others keep the integrator's position (RK4 stays exact in free flight), moved by
    //    what their impacts changed after the time of impact.
    // Either way an impact at τ·h moves the body only for the remaining (1 − τ)·h. Soft grids'
    // ellipses are finished the same way; a soft body's own entry follows its grid afterwards.
    inHalves(bodyTasks(world), m_endStates.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            finishBodyPosition(i, h);
    });
}

void Simulation::finishBodyPosition(std::size_t i, Scalar h)
{
    SolverBody& sb = m_bodies[i];
    model::BodyState& s = m_endStates[i];
    if (m_entries[i] == Entry::Fixed) {
        // The integrator moved it with its own velocity; position correction must see that.
        sb.position = s.position;
        sb.angle = s.angle;
        return;
    }
    if (m_entries[i] == Entry::SoftOwner)
        return;
    const model::BodyState& start = m_startStates[i];
    if (sb.hadContactForce) {
        // Each impact changes the velocity at its own time τₖ·h, and the contact forces and
        // joints after the last one, at T·h (they answer the impacts: written with the final
        // velocity alone, an impact that a contact force then cancels would still move the body):
        //   x = x₀ + h·v₀ + h·Σₖ (1 − τₖ)·Δvₖ + h·(1 − T)·Δv_contacts
        //     = x₀ + h·(T·v₀ + (1 − T)·v) + h·(T·Σₖ Δvₖ − Σₖ τₖ·Δvₖ).
        // The contact impulses took their lever arms from where the body is at T·h
        // (SolverBody::impulseOrigin), which keeps the angular momentum (docs/physics.md,
        // "Conservation"). A body without impacts has T = 0: x = x₀ + h·v.
        const Scalar tau = sb.hadImpact ? sb.lastImpactTau : 0.0;
        s.position = start.position + h * (tau * start.velocity + (1 - tau) * sb.velocity) +
                     h * (tau * sb.impactVelocity - sb.impactLateVelocity);
        s.angle = start.angle + h * (tau * start.angularVelocity + (1 - tau) * sb.angularVelocity) +
                  h * (tau * sb.impactAngularVelocity - sb.impactLateAngularVelocity);
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

void Simulation::syncSoftAggregates(const model::World& world)
{
    std::size_t next = world.bodies.size();
    for (std::size_t g = 0; g < world.softBodies.size(); ++g) {
        const model::SoftGrid& grid = world.softBodies[g];
        m_scratchPositions.resize(grid.size());
        m_scratchVelocities.resize(grid.size());
        for (std::size_t i = 0; i < grid.size(); ++i, ++next) {
            m_scratchPositions[i] = m_bodies[next].position;
            m_scratchVelocities[i] = m_bodies[next].velocity;
        }
        const SoftAggregate a = softAggregate(grid, m_scratchPositions, m_scratchVelocities,
                                              world.bodies[grid.body.index].state.angle);
        SolverBody& owner = m_bodies[grid.body.index];
        owner.position = a.position;
        owner.angle = a.angle;
        owner.velocity = a.velocity;
        owner.angularVelocity = a.angularVelocity;
        m_softAggregates[g] = owner;
    }
}

void Simulation::shareJointMotion(const model::World& world, bool positions)
{
    std::size_t next = world.bodies.size();
    for (std::size_t g = 0; g < world.softBodies.size(); ++g) {
        const model::SoftGrid& grid = world.softBodies[g];
        SolverBody& owner = m_bodies[grid.body.index];
        const SolverBody& before = m_softAggregates[g];
        const auto first = static_cast<std::ptrdiff_t>(next);
        next += grid.size();
        if (positions) {
            const Vec2 shift = owner.position - before.position;
            const Scalar turn = owner.angle - before.angle;
            if (shift.isZero() && turn == 0)
                continue;
            for (auto i = static_cast<std::size_t>(first); i < next; ++i) {
                SolverBody& e = m_bodies[i];
                e.position = owner.position + rotate(Vec2(e.position - before.position), turn);
            }
        } else {
            const Vec2 dv = owner.velocity - before.velocity;
            const Scalar dw = owner.angularVelocity - before.angularVelocity;
            if (dv.isZero() && dw == 0)
                continue;
            for (auto i = static_cast<std::size_t>(first); i < next; ++i) {
                SolverBody& e = m_bodies[i];
                e.velocity += dv + cross(dw, Vec2(e.position - before.position));
                e.hadContactForce = true;
            }
        }
    }
}

Scalar Simulation::saveVelocities()
{
    m_savedVelocities.resize(m_bodies.size());
    Scalar kinetic = 0;
    for (std::size_t i = 0; i < m_bodies.size(); ++i) {
        const SolverBody& b = m_bodies[i];
        m_savedVelocities[i] = {b.velocity, b.angularVelocity};
        kinetic += kineticEnergyOf(b);
    }
    return kinetic;
}

Scalar Simulation::kineticEnergyOfBodies() const
{
    Scalar kinetic = 0;
    for (const SolverBody& b : m_bodies)
        kinetic += kineticEnergyOf(b);
    return kinetic;
}

void Simulation::holdContactEnergy(Scalar kineticBefore, Scalar h)
{
    const Scalar limit = kineticBefore * (1 + constants::kContactEnergyGrowthTolerance);
    if (kineticEnergyOfBodies() <= limit)
        return;
    // Warm starting put in more than the passes took out again: more passes first, as the passes
    // converge towards contact forces that do no positive work.
    for (int round = 0; round < constants::kMaxExtraVelocityRounds; ++round) {
        for (int i = 0; i < m_settings.velocityIterations; ++i)
            m_contactSolver.solveVelocities(m_bodies);
        m_contactSolver.finishVelocities(m_bodies);
        if (kineticEnergyOfBodies() <= limit)
            return;
    }
    // Then from no impulse at all: each pass from there only lowers the kinetic energy.
    for (std::size_t i = 0; i < m_bodies.size(); ++i) {
        m_bodies[i].velocity = m_savedVelocities[i].velocity;
        m_bodies[i].angularVelocity = m_savedVelocities[i].angularVelocity;
    }
    m_contactSolver.forgetImpulses();
    m_contactSolver.warmStart(m_bodies, h, false);
    for (int i = 0; i < m_settings.velocityIterations; ++i)
        m_contactSolver.solveVelocities(m_bodies);
    m_contactSolver.finishVelocities(m_bodies);
}

void Simulation::startAndCollide(const model::World& world, Scalar h)
{
    // Phase 0: the start of the step, as the solvers see it.
    gatherStates(world, m_startStates, bodyTasks(world));
    setUpSolverBodies(world);
    computeDerivatives(world, m_startStates, m_startDerivatives, m_forceScratch);

    // Phase 1: collision detection at the start-of-step poses, with speculative margins.
    collide(world, h);
}

int Simulation::substepsFor(model::World& world, bool& collided)
{
    collided = false;
    const Scalar h = world.settings.timeStep;
    // What the contacts and joints need: substeps of at most the solver's step, in which no body
    // but a circle turns by more than an eighth of a turn, or 0.1 rad where masses are unlike
    // (spinSubsteps), and a large world's bodies travel a quarter of their size on average at most
    // (crowdSubsteps). A world in free flight keeps the user's step, however fast its bodies move.
    const int split = std::max({solverSubsteps(h, m_settings.maxSubstep), spinSubsteps(world, h), crowdSubsteps(world, h)});
    // What the integrators need to stay stable, contacts or not.
    const int stable = std::max(m_stability.substeps, dragSubsteps(world, h));
    // Joints always need the split, and so does a world that ended its last step with contacts
    // (a pile, a resting box): it is split without first looking for this step's contacts, which
    // would cost a collision pass that the substeps then do again.
    if (split == 1 || !world.joints.empty() || !world.softBodies.empty() || !world.contacts.empty())
        return std::max(stable, split);
    // Whether this step has contacts: found with the whole step's margins, which cover everything
    // that can touch within it. A world in free flight (a projectile, an oscillator) is then
    // integrated over the step the user chose, so that a lesson on integrators sees their error
    // at that step; a world with contacts is split, and finds its contacts again per substep.
    startAndCollide(world, h);
    collided = true;
    const bool contacts = std::any_of(m_manifolds.begin(), m_manifolds.end(),
                                      [](const ContactSolver::PairManifold& pm) { return pm.manifold.count > 0; });
    return std::max(stable, contacts ? split : 1);
}

void Simulation::substep(model::World& world, Scalar h, Scalar step, Scalar endTime, Contacts contacts,
                         bool handOver)
{
    const std::size_t total = stateCount(world);
    if (m_ledger)
        m_ledger->beginSubstep(world);
    // The soft grids' damping, as a pass of its own before anything reads the velocities: stable
    // at any step, so that a strongly damped grid is never unstable (soft_damping.h). A world
    // with soft bodies always finds its contacts here (substepsFor never collides for it), after
    // the pass.
    if (!world.softBodies.empty()) {
        const Scalar damped = dampSoftGrids(world, h, m_dampingScratch);
        if (m_ledger)
            m_ledger->afterSoftDamping(damped);
    }

    // Phases 0 and 1: the start of the step and its collisions (startAndCollide). A later substep
    // of a step that found its contacts for the whole step only takes the start states afresh.
    const bool reuse = contacts == Contacts::Reuse;
    if (contacts == Contacts::Find || contacts == Contacts::FindForStep) {
        startAndCollide(world, contacts == Contacts::FindForStep ? step : h);
    } else if (reuse) {
        gatherStates(world, m_startStates, bodyTasks(world));
        setUpSolverBodies(world);
        computeDerivatives(world, m_startStates, m_startDerivatives, m_forceScratch);
    }

    // Phase 2: impacts, on the velocities from before this step's forces.
    const Clock::time_point solveStart = Clock::now();
    if (reuse)
        m_contactSolver.refresh(m_bodies, m_startDerivatives, h);
    else
        m_contactSolver.prepare(world, m_manifolds, m_bodies, m_startDerivatives, h);
    m_profile.prepareMs += millisecondsSince(solveStart);
    const Clock::time_point impactsStart = Clock::now();
    if (m_ledger)
        m_ledger->beforeImpacts(m_bodies);
    m_profile.impacts += m_contactSolver.solveImpacts(m_bodies, h);
    m_profile.impactVisits += m_contactSolver.impactVisits();
    m_profile.impactLooks += m_contactSolver.impactLooks();
    m_profile.impactsMs += millisecondsSince(impactsStart);
    // After the impacts: a struck body's joint impulses act from where it is after its last one.
    // (Timed as preparation, which it is: it was counted with the impacts, and the joint grid's
    // phase line showed 7 ms a step of "impacts" that had none.)
    const Clock::time_point jointsStart = Clock::now();
    m_jointSolver.prepare(world, m_bodies, h);
    m_profile.prepareMs += millisecondsSince(jointsStart);
    if (m_ledger)
        m_ledger->afterImpacts(m_bodies, m_contactSolver.impactNormalWork(), m_contactSolver.impactFrictionWork());
    m_profile.contacts += static_cast<int>(m_contactSolver.constraints().size());
    m_profile.batchLanes += static_cast<int>(m_contactSolver.batchLaneCount());
    double solveMs = millisecondsSince(solveStart);

    // Phase 3: smooth forces (gravity, springs, drag) integrated over the whole world state.
    const Clock::time_point integrateStart = Clock::now();
    integratorFor(world.settings.integrator).step(world, m_startStates, m_startDerivatives, h, m_endStates);
    if (m_ledger)
        m_ledger->afterIntegration(world, m_startStates, m_endStates, h);
    m_profile.integrateMs += millisecondsSince(integrateStart);

    // Phase 4: contact forces and joints, on the integrated velocities plus the impacts' change.
    const Clock::time_point velocityStart = Clock::now();
    inHalves(bodyTasks(world), total, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            if (m_entries[i] == Entry::Fixed || m_entries[i] == Entry::SoftOwner)
                continue;
            SolverBody& sb = m_bodies[i];
            sb.velocity += m_endStates[i].velocity - m_startStates[i].velocity;
            sb.angularVelocity += m_endStates[i].angularVelocity - m_startStates[i].angularVelocity;
        }
    });
    // Joints on soft bodies act on each grid's aggregate, contacts on its ellipses: each joint
    // pass starts from the aggregate of where the contacts have left the ellipses, and hands what
    // it did on to them before the contacts' next pass, so that the two see each other as joints
    // and contacts on a rigid body do. (Handed on once at the end, the joints kept pulling at a
    // resting body that the contacts had already stopped.)
    const bool softJoints = !world.softBodies.empty() && !m_jointSolver.empty();
    const auto onSoftAggregates = [&](auto&& jointWork, bool positions = false) {
        if (softJoints)
            syncSoftAggregates(world);
        jointWork();
        if (softJoints)
            shareJointMotion(world, positions);
    };
    if (m_ledger)
        m_ledger->beforeVelocities(m_bodies, m_contactSolver.constraints());
    // Without joints (whose passes move energy between bodies) the contact forces may only take
    // kinetic energy out; the guard below holds them to it. Only without gravity, as for the
    // angular momentum below: in a stack at rest the passes start from the tiny speed gravity gave
    // each body over the step, and stopping it takes the warm start, which a cold restart loses
    // (the base-20 pyramid fell).
    const bool guardEnergy = m_jointSolver.empty() && world.settings.gravity.isZero();
    const Scalar kineticBefore = guardEnergy ? saveVelocities() : 0;
    onSoftAggregates([&] { m_jointSolver.warmStart(m_bodies); });
    m_contactSolver.warmStart(m_bodies, h, !m_jointSolver.empty());
    for (int i = 0; i < m_settings.velocityIterations; ++i) {
        onSoftAggregates([&] { m_jointSolver.solveVelocities(m_bodies, h); });
        m_contactSolver.solveVelocities(m_bodies);
    }
    // The records only where something reads them before the next substep's passes: the
    // substep that hands them on, and the ledger.
    m_contactSolver.finishVelocities(m_bodies, handOver || m_ledger != nullptr);
    if (guardEnergy)
        holdContactEnergy(kineticBefore, h);
    // Small jointed islands of very unlike masses, which the passes cannot settle, solved whole;
    // a soft body in one takes part as its grid's aggregate, as in the joint passes.
    onSoftAggregates([&] { m_unlikeMasses.solveVelocities(m_bodies, m_jointSolver, m_contactSolver, h, m_movedBy); });
    m_profile.unlikeMassIslands += m_unlikeMasses.solvedVelocityIslands();
    m_jointSolver.forgetImpulses(m_unlikeMasses.solvedBodies());
    // A light body held by a fixed one against a far heavier one props it up (a pebble under a
    // tonne): the passes cannot stop the heavy body through it, this does.
    m_contactSolver.findProps(m_bodies);
    m_contactSolver.solvePropVelocities(m_bodies, h);
    if (m_ledger)
        m_ledger->afterVelocities(m_bodies, m_contactSolver.constraints(), m_contactSolver.records());
    m_profile.velocityMs += millisecondsSince(velocityStart);
    const Clock::time_point positionStart = Clock::now();

    // Phase 5: positions, then position correction (moves bodies, never touches velocities).
    integratePositions(world, h);
    if (m_ledger)
        m_ledger->beforeCorrection(world, m_endStates);
    m_contactSolver.beginPositions(world.settings.gravity.isZero()); // when the pushes are taken back, below
    // A soft body's aggregate is fitted afresh to its ellipses between the joint passes: its
    // rotation is taken afresh too (and two soak findings with soft bodies, chaotic scenes, took
    // the other side of their bound with the carried rotations' last bits: 1489 and 3477).
    m_jointSolver.beginPositions(m_bodies.size(), world.softBodies.empty());
    for (int i = 0; i < m_settings.positionIterations; ++i) {
        if (m_ledger)
            m_ledger->beforeJointCorrection(world, m_bodies);
        // As in the velocity passes: the joints move a soft body's aggregate from where the
        // contacts have left its ellipses, and the ellipses follow before the contacts' pass.
        // (Handed on once after all passes, the joints' moves came after the contacts' last
        // word and pushed ellipses into a wall: soak seed 111.)
        bool jointsOk = false;
        onSoftAggregates([&] { jointsOk = m_jointSolver.solvePositions(m_bodies); }, true);
        if (m_ledger)
            m_ledger->afterJointCorrection(world, m_bodies);
        const bool contactsOk = m_contactSolver.solvePositions(m_bodies, i == 0 || !m_jointSolver.empty());
        if (jointsOk && contactsOk)
            break;
    }
    m_unlikeMasses.solvePositions(m_bodies, m_jointSolver, m_contactSolver, m_movedBy);
    m_contactSolver.solvePropPositions(m_bodies);
    // Moving bodies while their velocities stay changes the angular momentum; each pushed pair
    // takes it back by turning its relative velocity (docs/physics.md, "Conservation"). Only
    // without gravity, whose torque changes the angular momentum about any fixed point anyway:
    // turning the relative velocity of two boxes side by side in a settling stack would make them
    // approach, and a stack under gravity keeps the exact motion it had.
    if (world.settings.gravity.isZero()) {
        // A joint's take-back turns a soft body's aggregate velocity, which its ellipses must
        // follow as they follow the velocity passes; kept on the aggregate alone it was lost, and
        // only the rigid partner's half turned: soak seed 189 gained energy every step.
        onSoftAggregates([&] {
            m_contactSolver.measurePushes(m_bodies);
            m_jointSolver.measurePushes(m_bodies);
            m_unlikeMasses.measurePushes(m_bodies);
            m_contactSolver.takeBackPushes(m_bodies);
            m_jointSolver.takeBackPushes(m_bodies);
            m_unlikeMasses.takeBackPushes(m_bodies);
        });
        // What is left is the smooth forces' timing (a spring's pull taken by each end from its
        // own last impact): each island nothing outside touches keeps its angular momentum.
        if (IslandSpin::applies(world))
            m_islandSpin.keep(world, m_startStates, m_bodies, m_contactSolver.constraints());
    }
    inHalves(bodyTasks(world), total, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            if (m_entries[i] == Entry::Fixed || m_entries[i] == Entry::SoftOwner)
                continue;
            m_endStates[i].position = m_bodies[i].position;
            m_endStates[i].angle = m_bodies[i].angle;
            m_endStates[i].velocity = m_bodies[i].velocity; // takeBackPushes may turn it
            m_endStates[i].angularVelocity = m_bodies[i].angularVelocity; // and IslandSpin spin it
        }
    });
    // What the solve could not hold: no centre passes into a fixed body (fixed_body_guard.h).
    m_profile.guardedCentres += m_fixedBodyGuard.keepOut(world, m_startStates, m_endStates);
    for (const KeptOut& kept : m_fixedBodyGuard.keptOut()) {
        if (std::find(m_keptOut.begin(), m_keptOut.end(), kept) == m_keptOut.end())
            m_keptOut.push_back(kept);
    }
    m_profile.positionMs += millisecondsSince(positionStart);
    scatterStates(world, m_endStates, bodyTasks(world));
    updateSoftOwners(world, m_startStates);
    if (m_ledger)
        m_ledger->endSubstep(world);
    solveMs += millisecondsSince(velocityStart);
    m_profile.solveMs += solveMs;

    // Phase 6: the clock, then what the contacts mean (colliding flags, events, warm start). The
    // substeps that reuse one step's contacts keep them in the solver until the step's end: the
    // next substep refreshes them, and a contact that began in any of them is told once.
    world.time = endTime;
    m_jointSolver.storeImpulses(world);
    if (!handOver)
        return;
    const Clock::time_point eventsStart = Clock::now();
    // The last step's records move aside, and the solver's records of this step take their place
    // (ContactSolver::finishVelocities wrote them): three buffers take turns, so a large world's
    // records are not allocated afresh every step.
    m_previousContacts.swap(world.contacts);
    m_contactSolver.swapRecords(world.contacts);
    updateCollisionState(world, m_contactSolver, m_bodies, m_previousContacts, m_collisionScratch, m_events, m_tasks.get());
    m_profile.eventsMs += millisecondsSince(eventsStart);
}

void Simulation::step(model::World& world)
{
    const Clock::time_point stepStart = Clock::now();
    prepareSoftBodies(world);
    m_stability = softStability(world);
    m_profile = StepProfile{};
    m_events.clear();
    m_keptOut.clear();

    const Scalar h = world.settings.timeStep;
    bool collided = false;
    const int substeps = substepsFor(world, collided);
    m_profile.substeps = substeps;
    const Scalar startTime = world.time;
    // A split step of a rigid world at rest or nearly (a pile, a stack) finds its contacts once,
    // with margins for the whole step, and its later substeps refresh them (ContactSolver::refresh):
    // one collision pass and one build a step, as Box2D v3 does. Where bodies move fast the whole
    // step's margins would make many more speculative contacts than they save
    // (contactsLastTheStep), and a soft body's ellipses move too far against each
    // other within a step: those steps find their contacts again every substep.
    const bool reuse = substeps > 1 && world.softBodies.empty() && contactsLastTheStep(world, h);
    for (int k = 1; k <= substeps; ++k) {
        // The last substep lands exactly on t + h, whatever the rounding of h/substeps.
        const Scalar endTime = k == substeps ? startTime + h : startTime + k * (h / substeps);
        Contacts contacts = reuse ? (k == 1 ? Contacts::FindForStep : Contacts::Reuse) : Contacts::Find;
        // substepsFor's collision pass used the whole step's margins: what a single substep or
        // the first of a reusing step needs.
        if (k == 1 && collided && (reuse || substeps == 1))
            contacts = Contacts::Found;
        substep(world, h / substeps, h, endTime, contacts, !reuse || k == substeps);
    }
    ++world.stepCount;
    for (model::Joint& joint : world.joints) {
        // Keep a pin between two bodies at the hinge's current place, so that saving mid-run writes
        // a scene that loads to this state. A pin to the world keeps its fixed pivot.
        if (joint.type == model::JointType::Pin && joint.bodyB)
            joint.worldAnchor = world.body(joint.bodyA).worldPoint(joint.anchorA);
    }

    m_profile.totalMs = millisecondsSince(stepStart);
}

} // namespace impetus::controller
