#include "controller/force_model.h"

#include "controller/soft_body_builder.h"
#include "model/constants.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

namespace {

/// The velocity of the material point of a body at `worldPoint`.
Vec2 velocityOf(const model::BodyState& state, const Vec2& worldPoint)
{
    return state.velocity + cross(state.angularVelocity, Vec2(worldPoint - state.position));
}

/// The grid springs' accelerations on the ellipses of one grid (states s, derivatives d), every
/// ellipse of mass 1/invMass. Two springs at a time in the two lanes of an Eigen::Array2d, so that
/// the square roots and divisions run packed; the sums then go to the ends one by one.
void addGridSpringForces(const model::SoftGrid& grid, const model::BodyState* s, BodyDerivative* d, Scalar invMass)
{
    using Lanes = Eigen::Array2d;
    const std::vector<model::SoftSpring>& springs = grid.springs;
    const std::size_t count = springs.size();
    // Springs come grouped by their first ellipse (buildSoftGrid): its acceleration is summed in
    // locals and stored once per group, instead of through memory once per spring.
    std::uint32_t current = count == 0 ? 0 : springs.front().a;
    Scalar sumX = 0;
    Scalar sumY = 0;
    // Component by component: a Vec2 built from two computed scalars goes through the stack
    // and stalls the load that reads it back.
    const auto apply = [&](const model::SoftSpring& spring, Scalar ax, Scalar ay) {
        if (spring.a != current) {
            d[current].acceleration.x() += sumX;
            d[current].acceleration.y() += sumY;
            sumX = 0;
            sumY = 0;
            current = spring.a;
        }
        sumX += ax;
        sumY += ay;
        d[spring.b].acceleration.x() -= ax;
        d[spring.b].acceleration.y() -= ay;
    };
    std::size_t k = 0;
    for (; k + 1 < count; k += 2) {
        const model::SoftSpring& p = springs[k];
        const model::SoftSpring& q = springs[k + 1];
        const model::BodyState& pa = s[p.a];
        const model::BodyState& pb = s[p.b];
        const model::BodyState& qa = s[q.a];
        const model::BodyState& qb = s[q.b];
        const Lanes dx(pb.position.x() - pa.position.x(), qb.position.x() - qa.position.x());
        const Lanes dy(pb.position.y() - pa.position.y(), qb.position.y() - qa.position.y());
        const Lanes dvx(pb.velocity.x() - pa.velocity.x(), qb.velocity.x() - qa.velocity.x());
        const Lanes dvy(pb.velocity.y() - pa.velocity.y(), qb.velocity.y() - qa.velocity.y());
        const Lanes length = (dx * dx + dy * dy).sqrt();
        const Lanes invLength = length.inverse();
        // T = k·(L − L₀) + c·dL/dt, and the acceleration T/m along (dx, dy)/L. Two ends on one
        // point have no line to pull along: no force (the select drops the NaN of 0·∞).
        const Lanes tension = Lanes(p.stiffness, q.stiffness) * (length - Lanes(p.restLength, q.restLength)) +
                              Lanes(p.damping, q.damping) * (invLength * (dx * dvx + dy * dvy));
        const Lanes scale = (length > 0).select(tension * invMass * invLength, Lanes::Zero());
        apply(p, scale(0) * dx(0), scale(0) * dy(0));
        apply(q, scale(1) * dx(1), scale(1) * dy(1));
    }
    for (; k < count; ++k) {
        const model::SoftSpring& p = springs[k];
        const Vec2 delta = s[p.b].position - s[p.a].position;
        const Scalar length = delta.norm();
        if (!(length > 0))
            continue;
        const Scalar lengthRate = delta.dot(s[p.b].velocity - s[p.a].velocity) / length;
        const Scalar tension = p.stiffness * (length - p.restLength) + p.damping * lengthRate;
        const Scalar scale = tension * invMass / length;
        apply(p, scale * delta.x(), scale * delta.y());
    }
    if (count > 0) {
        d[current].acceleration.x() += sumX;
        d[current].acceleration.y() += sumY;
    }
}

/// Gravity, drag, internal damping, shape matching and the grid springs on every ellipse of every
/// soft grid: writes every field of their entries in `out`, with the accelerations (every ellipse
/// of a grid has the same mass, so forces are divided by it up front).
void addSoftGridForces(const model::World& world, std::span<const model::BodyState> states,
                       std::vector<BodyDerivative>& out)
{
    std::size_t offset = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        const model::Body& body = world.bodies[grid.body.index];
        const Scalar invMass = 1 / grid.ellipseMass;
        const Vec2 gravity = world.settings.gravity;
        // Each ellipse's share of the body's drag coefficient, b·m/M, over its mass m.
        const Scalar drag = world.settings.drag * body.invMass;
        const model::BodyState* s = states.data() + offset;
        BodyDerivative* d = out.data() + offset;
        // The grid's rigid motion (centre of mass, its velocity, and the angular velocity of the
        // ellipses about it) for the internal damping, which acts on what is left over.
        Vec2 centre = Vec2::Zero();
        Vec2 velocity = Vec2::Zero();
        for (std::size_t i = 0; i < grid.size(); ++i) {
            centre += s[i].position;
            velocity += s[i].velocity;
        }
        centre /= static_cast<Scalar>(grid.size());
        velocity /= static_cast<Scalar>(grid.size());
        Scalar spin = 0;
        Scalar spread = 0;
        Scalar dot = 0;
        Scalar turn = 0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Vec2 r = s[i].position - centre;
            spin += cross(r, Vec2(s[i].velocity - velocity));
            spread += r.squaredNorm();
            dot += grid.restPositions[i].dot(r);
            turn += cross(grid.restPositions[i], r);
        }
        const Scalar omega = spread > 0 ? spin / spread : 0;
        const Scalar internal = constants::kSoftInternalDampingRate;
        // Shape matching: each ellipse is pulled towards its goal, where the best-fit rigid motion
        // of the rest lattice puts it (see softShapeMatchingStiffness).
        const Scalar norm = std::hypot(dot, turn);
        const Scalar c = norm > 0 ? dot / norm : 1;
        const Scalar sn = norm > 0 ? turn / norm : 0;
        const Scalar matching = softShapeMatchingStiffness(grid, body) * invMass;
        // Shape matching is damped in the same proportion as the grid springs (c/k), so the
        // body's own damping setting governs how much of a landing it gives back.
        const Scalar matchingDamping = softShapeMatchingDamping(grid, body) * invMass;
        // Written with scalars: see addGridSpringForces.
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Scalar px = s[i].position.x() - centre.x();
            const Scalar py = s[i].position.y() - centre.y();
            const Scalar vx = s[i].velocity.x();
            const Scalar vy = s[i].velocity.y();
            const Vec2& r = grid.restPositions[i];
            // v − v_rigid, with v_rigid = v_c + ω × p; and x − g, with g = c + R·r.
            const Scalar relativeX = vx - (velocity.x() - omega * py);
            const Scalar relativeY = vy - (velocity.y() + omega * px);
            const Scalar offX = px - (c * r.x() - sn * r.y());
            const Scalar offY = py - (sn * r.x() + c * r.y());
            d[i].velocity = s[i].velocity;
            d[i].angularVelocity = 0;
            d[i].acceleration.x() =
                gravity.x() - drag * vx - (internal + matchingDamping) * relativeX - matching * offX;
            d[i].acceleration.y() =
                gravity.y() - drag * vy - (internal + matchingDamping) * relativeY - matching * offY;
            d[i].angularAcceleration = 0;
        }
        addGridSpringForces(grid, s, d, invMass);
        offset += grid.size();
    }
}

/// The states of the bodies with each soft body's entry replaced by its grid's aggregate, for the
/// scene springs attached to soft bodies.
std::vector<model::BodyState> aggregateStates(const model::World& world, std::span<const model::BodyState> states,
                                              std::vector<SoftAggregate>& aggregates)
{
    std::vector<model::BodyState> bodies(states.begin(), states.begin() + static_cast<std::ptrdiff_t>(world.bodies.size()));
    aggregates.clear();
    std::size_t offset = world.bodies.size();
    std::vector<Vec2> positions;
    std::vector<Vec2> velocities;
    for (const model::SoftGrid& grid : world.softBodies) {
        positions.clear();
        velocities.clear();
        for (std::size_t i = 0; i < grid.size(); ++i) {
            positions.push_back(states[offset + i].position);
            velocities.push_back(states[offset + i].velocity);
        }
        const SoftAggregate a =
            softAggregate(grid, positions, velocities, world.bodies[grid.body.index].state.angle);
        aggregates.push_back(a);
        bodies[grid.body.index] = model::BodyState{a.position, a.angle, a.velocity, a.angularVelocity};
        offset += grid.size();
    }
    return bodies;
}

/// Shares out a force F and torque τ on soft grid g over its ellipses as a rigid body would take
/// them: each ellipse's acceleration gets F/M + (τ/I) × r.
void shareOut(const model::World& world, std::size_t g, const SoftAggregate& a, const Vec2& force, Scalar torque,
              std::span<const model::BodyState> states, std::vector<BodyDerivative>& out)
{
    const model::SoftGrid& grid = world.softBodies[g];
    const std::size_t offset = world.bodies.size() + softEllipseOffset(world, g);
    const Vec2 linear = world.bodies[grid.body.index].invMass * force;
    const Scalar alpha = a.inertia > 0 ? torque / a.inertia : 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const Vec2 r = states[offset + i].position - a.position;
        out[offset + i].acceleration += linear + cross(alpha, r);
    }
}

} // namespace

std::size_t stateCount(const model::World& world)
{
    std::size_t count = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies)
        count += grid.size();
    return count;
}

void gatherStates(const model::World& world, std::vector<model::BodyState>& out)
{
    out.clear();
    out.reserve(stateCount(world));
    for (const model::Body& body : world.bodies)
        out.push_back(body.state);
    for (const model::SoftGrid& grid : world.softBodies) {
        for (std::size_t i = 0; i < grid.size(); ++i)
            out.push_back(model::BodyState{grid.positions[i], 0, grid.velocities[i], 0});
    }
}

void scatterStates(model::World& world, std::span<const model::BodyState> states)
{
    std::size_t k = 0;
    for (model::Body& body : world.bodies)
        body.state = states[k++];
    for (model::SoftGrid& grid : world.softBodies) {
        for (std::size_t i = 0; i < grid.size(); ++i, ++k) {
            grid.positions[i] = states[k].position;
            grid.velocities[i] = states[k].velocity;
        }
    }
}

std::pair<Vec2, Vec2> springEnds(const model::Spring& spring, std::span<const model::BodyState> states)
{
    const model::BodyState& a = states[spring.bodyA.index];
    const Vec2 endA = a.position + rotate(spring.anchorA, a.angle);
    if (!spring.bodyB)
        return {endA, spring.anchorB};
    const model::BodyState& b = states[spring.bodyB->index];
    return {endA, b.position + rotate(spring.anchorB, b.angle)};
}

void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out)
{
    const std::size_t n = world.bodies.size();
    // The bodies' entries start from zero; the ellipses' are written whole by addSoftGridForces.
    out.resize(states.size());
    std::fill(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n), BodyDerivative{});

    // Accumulate forces and torques in `acceleration` and `angularAcceleration` first, then divide
    // by mass and inertia once at the end.
    const Vec2 gravity = world.settings.gravity;
    const Scalar drag = world.settings.drag;
    for (std::size_t i = 0; i < n; ++i) {
        const model::Body& body = world.bodies[i];
        const model::BodyState& s = states[i];
        // Every body moves with its velocity; a fixed body's never changes (no force acts on it).
        out[i].velocity = s.velocity;
        out[i].angularVelocity = s.angularVelocity;
        if (!body.fixed)
            out[i].acceleration = body.mass * gravity - drag * s.velocity;
    }
    // A soft body's own entry stands still: its grid carries its motion.
    for (const model::SoftGrid& grid : world.softBodies)
        out[grid.body.index] = BodyDerivative{};
    addSoftGridForces(world, states, out);

    // Scene springs see a soft body as its grid's aggregate.
    std::vector<SoftAggregate> aggregates;
    std::vector<model::BodyState> softAware;
    std::span<const model::BodyState> bodyStates = states.first(n);
    if (!world.softBodies.empty() && !world.springs.empty()) {
        softAware = aggregateStates(world, states, aggregates);
        bodyStates = softAware;
    }
    const auto softIndex = [&](std::uint32_t body) -> std::ptrdiff_t {
        for (std::size_t g = 0; g < world.softBodies.size(); ++g) {
            if (world.softBodies[g].body.index == body)
                return static_cast<std::ptrdiff_t>(g);
        }
        return -1;
    };

    for (const model::Spring& spring : world.springs) {
        const auto [endA, endB] = springEnds(spring, bodyStates);
        const Vec2 d = endB - endA;
        const Scalar length = d.norm();
        // With both ends on one point the direction is undefined; the force is then zero for a
        // zero rest length, and we choose zero for any other (the spring has no line to push along).
        if (!(length > 0))
            continue;
        const Vec2 u = d / length;

        const model::Body& bodyA = world.bodies[spring.bodyA.index];
        const Vec2 velA = velocityOf(bodyStates[spring.bodyA.index], endA);
        Vec2 velB = Vec2::Zero();
        if (spring.bodyB)
            velB = velocityOf(bodyStates[spring.bodyB->index], endB);
        const Scalar lengthRate = u.dot(velB - velA);
        const Scalar tension =
            spring.stiffness * (length - spring.restLength) + spring.damping * lengthRate;
        const Vec2 forceOnA = tension * u;

        if (!bodyA.fixed) {
            const Scalar torque = cross(Vec2(endA - bodyStates[spring.bodyA.index].position), forceOnA);
            if (const std::ptrdiff_t g = world.softBodies.empty() ? -1 : softIndex(spring.bodyA.index); g >= 0) {
                shareOut(world, static_cast<std::size_t>(g), aggregates[static_cast<std::size_t>(g)], forceOnA,
                         torque, states, out);
            } else {
                BodyDerivative& da = out[spring.bodyA.index];
                da.acceleration += forceOnA;
                da.angularAcceleration += torque;
            }
        }
        if (spring.bodyB && !world.bodies[spring.bodyB->index].fixed) {
            const Scalar torque = cross(Vec2(endB - bodyStates[spring.bodyB->index].position), forceOnA);
            if (const std::ptrdiff_t g = world.softBodies.empty() ? -1 : softIndex(spring.bodyB->index); g >= 0) {
                shareOut(world, static_cast<std::size_t>(g), aggregates[static_cast<std::size_t>(g)], -forceOnA,
                         -torque, states, out);
            } else {
                BodyDerivative& db = out[spring.bodyB->index];
                db.acceleration -= forceOnA;
                db.angularAcceleration -= torque;
            }
        }
    }

    for (std::size_t i = 0; i < n; ++i) {
        const model::Body& body = world.bodies[i];
        out[i].acceleration *= body.invMass;
        out[i].angularAcceleration *= body.invInertia;
    }
}

} // namespace impetus::controller
