#include "controller/force_model.h"

#include "controller/soft_body_builder.h"
#include "model/constants.h"

namespace impetus::controller {

namespace {

/// The velocity of the material point of a body at `worldPoint`.
Vec2 velocityOf(const model::BodyState& state, const Vec2& worldPoint)
{
    return state.velocity + cross(state.angularVelocity, Vec2(worldPoint - state.position));
}

/// Gravity, drag and the grid springs on every ellipse of every soft grid, as forces in
/// out[...].acceleration (divided by the ellipse mass by the caller).
void addSoftGridForces(const model::World& world, std::span<const model::BodyState> states,
                       std::vector<BodyDerivative>& out)
{
    std::size_t offset = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        const model::Body& body = world.bodies[grid.body.index];
        const Vec2 weight = grid.ellipseMass * world.settings.gravity;
        // Each ellipse's share of the body's drag coefficient: b·m/M.
        const Scalar drag = world.settings.drag * grid.ellipseMass * body.invMass;
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
        const Scalar internal = constants::kSoftInternalDampingRate * grid.ellipseMass;
        // Shape matching: each ellipse is pulled towards its goal, where the best-fit rigid motion
        // of the rest lattice puts it (see softShapeMatchingStiffness).
        const Scalar norm = std::hypot(dot, turn);
        const Scalar c = norm > 0 ? dot / norm : 1;
        const Scalar sn = norm > 0 ? turn / norm : 0;
        const Scalar matching = softShapeMatchingStiffness(grid, body);
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Vec2 rigid = velocity + cross(omega, Vec2(s[i].position - centre));
            const Vec2& r = grid.restPositions[i];
            const Vec2 goal = centre + Vec2(c * r.x() - sn * r.y(), sn * r.x() + c * r.y());
            d[i].velocity = s[i].velocity;
            d[i].acceleration = weight - drag * s[i].velocity - internal * (s[i].velocity - rigid) -
                                matching * (s[i].position - goal);
        }
        // Springs come grouped by their first ellipse (buildSoftGrid): its force is summed in a
        // local and stored once per group, instead of through memory once per spring.
        std::uint32_t current = 0;
        Vec2 onCurrent = Vec2::Zero();
        for (const model::SoftSpring& spring : grid.springs) {
            if (spring.a != current) {
                d[current].acceleration += onCurrent;
                onCurrent.setZero();
                current = spring.a;
            }
            const Vec2 delta = s[spring.b].position - s[spring.a].position;
            const Scalar length = delta.norm();
            if (!(length > 0))
                continue;
            const Vec2 u = delta / length;
            const Scalar lengthRate = u.dot(s[spring.b].velocity - s[spring.a].velocity);
            const Scalar tension = spring.stiffness * (length - spring.restLength) + spring.damping * lengthRate;
            const Vec2 force = tension * u;
            onCurrent += force;
            d[spring.b].acceleration -= force;
        }
        if (!grid.springs.empty())
            d[current].acceleration += onCurrent;
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
/// them: each ellipse gets m·(F/M + (τ/I) × r), added to out[...].acceleration as a force.
void shareOut(const model::World& world, std::size_t g, const SoftAggregate& a, const Vec2& force, Scalar torque,
              std::span<const model::BodyState> states, std::vector<BodyDerivative>& out)
{
    const model::SoftGrid& grid = world.softBodies[g];
    const std::size_t offset = world.bodies.size() + softEllipseOffset(world, g);
    const Scalar share = grid.ellipseMass * world.bodies[grid.body.index].invMass;
    const Scalar alpha = a.inertia > 0 ? torque / a.inertia : 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const Vec2 r = states[offset + i].position - a.position;
        out[offset + i].acceleration += share * force + grid.ellipseMass * cross(alpha, r);
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
    out.assign(states.size(), BodyDerivative{});

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
    std::size_t offset = n;
    for (const model::SoftGrid& grid : world.softBodies) {
        const Scalar invMass = 1 / grid.ellipseMass;
        for (std::size_t i = 0; i < grid.size(); ++i)
            out[offset + i].acceleration *= invMass;
        offset += grid.size();
    }
}

} // namespace impetus::controller
