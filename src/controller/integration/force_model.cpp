#include "controller/integration/force_model.h"

#include "controller/soft/soft_body_builder.h"
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

using Lanes = Eigen::Array2d;

/// The accelerations of one direction's grid springs on their `a` ends, into fx and fy at each
/// spring's slot (the `b` end feels the opposite): their stiffness alone, since their damping is a
/// pass of its own (soft_damping.h). Positions are per lattice slot:
/// slot pad + c holds cell c, and the slots around the lattice hold zeros, so a spring that is not
/// there (all its values 0) pulls with exactly 0, and so does one whose ends meet (its (dx, dy) is
/// 0 and its length is held at kSoftMinSpringLength, so no branch is needed). Two springs at a
/// time in the two lanes of an Eigen::Array2d, so that the square roots and divisions run packed.
void springField(const model::SoftGrid& grid, const model::SoftSpringField& field, const ForceScratch& in,
                 std::size_t pad, Scalar invMass, Scalar* __restrict fx, Scalar* __restrict fy)
{
    const auto end = static_cast<std::size_t>(field.end);
    const Scalar* __restrict xa = in.x.data() + pad;
    const Scalar* __restrict ya = in.y.data() + pad;
    const auto step = static_cast<std::ptrdiff_t>(field.step);
    const Scalar* __restrict xb = xa + step;
    const Scalar* __restrict yb = ya + step;
    const Scalar* __restrict stiffness = field.stiffness.data();
    const Scalar* __restrict rest = field.restLength.data();
    fx += pad;
    fy += pad;
    // Outside [begin, end) there is no spring: its pull is 0.
    std::fill(fx, fx + field.begin, 0.0);
    std::fill(fy, fy + field.begin, 0.0);
    std::fill(fx + field.end, fx + grid.columns * grid.rows, 0.0);
    std::fill(fy + field.end, fy + grid.columns * grid.rows, 0.0);
    auto c = static_cast<std::size_t>(field.begin);
    for (; c + 1 < end; c += 2) {
        const Lanes dx = Lanes::Map(xb + c) - Lanes::Map(xa + c);
        const Lanes dy = Lanes::Map(yb + c) - Lanes::Map(ya + c);
        const Lanes length = (dx * dx + dy * dy).sqrt().max(Lanes::Constant(constants::kSoftMinSpringLength));
        // T = k·(L − L₀), and the acceleration T/m along (dx, dy)/L.
        const Lanes tension = Lanes::Map(stiffness + c) * (length - Lanes::Map(rest + c));
        const Lanes scale = tension * invMass / length;
        Lanes::Map(fx + c) = scale * dx;
        Lanes::Map(fy + c) = scale * dy;
    }
    for (; c < end; ++c) {
        const Scalar dx = xb[c] - xa[c];
        const Scalar dy = yb[c] - ya[c];
        const Scalar length = std::max(std::sqrt(dx * dx + dy * dy), constants::kSoftMinSpringLength);
        const Scalar tension = stiffness[c] * (length - rest[c]);
        const Scalar scale = tension * invMass / length;
        fx[c] = scale * dx;
        fy[c] = scale * dy;
    }
}

/// The grid springs' accelerations on every cell of the lattice, into scratch.ax and ay (per
/// cell), from the positions already in the scratch's slots (see springField). Each
/// direction's springs are computed whole first; a cell then adds the springs that start there
/// and subtracts those that end there, so that no spring's result is stored and reloaded at once.
void addGridSpringForces(const model::SoftGrid& grid, ForceScratch& scratch, std::size_t pad, Scalar invMass)
{
    for (std::size_t f = 0; f < grid.springFields.size(); ++f) {
        std::fill_n(scratch.fx[f].begin(), pad, 0.0);
        std::fill_n(scratch.fy[f].begin(), pad, 0.0);
        springField(grid, grid.springFields[f], scratch, pad, invMass, scratch.fx[f].data(), scratch.fy[f].data());
    }
    const auto cells = static_cast<std::size_t>(grid.columns * grid.rows);
    const auto step = [&](std::size_t f) { return static_cast<std::ptrdiff_t>(grid.springFields[f].step); };
    const Scalar* __restrict fx0 = scratch.fx[0].data() + pad;
    const Scalar* __restrict fx1 = scratch.fx[1].data() + pad;
    const Scalar* __restrict fx2 = scratch.fx[2].data() + pad;
    const Scalar* __restrict fx3 = scratch.fx[3].data() + pad;
    const Scalar* __restrict fy0 = scratch.fy[0].data() + pad;
    const Scalar* __restrict fy1 = scratch.fy[1].data() + pad;
    const Scalar* __restrict fy2 = scratch.fy[2].data() + pad;
    const Scalar* __restrict fy3 = scratch.fy[3].data() + pad;
    const Scalar* __restrict ex0 = fx0 - step(0);
    const Scalar* __restrict ex1 = fx1 - step(1);
    const Scalar* __restrict ex2 = fx2 - step(2);
    const Scalar* __restrict ex3 = fx3 - step(3);
    const Scalar* __restrict ey0 = fy0 - step(0);
    const Scalar* __restrict ey1 = fy1 - step(1);
    const Scalar* __restrict ey2 = fy2 - step(2);
    const Scalar* __restrict ey3 = fy3 - step(3);
    Scalar* __restrict ax = scratch.ax.data();
    Scalar* __restrict ay = scratch.ay.data();
    const auto sum = [](const Scalar* f0, const Scalar* e0, const Scalar* f1, const Scalar* e1, const Scalar* f2,
                        const Scalar* e2, const Scalar* f3, const Scalar* e3, std::size_t c) {
        return ((Lanes::Map(f0 + c) - Lanes::Map(e0 + c)) + (Lanes::Map(f1 + c) - Lanes::Map(e1 + c))) +
               ((Lanes::Map(f2 + c) - Lanes::Map(e2 + c)) + (Lanes::Map(f3 + c) - Lanes::Map(e3 + c)));
    };
    std::size_t c = 0;
    for (; c + 1 < cells; c += 2) {
        Lanes::Map(ax + c) = sum(fx0, ex0, fx1, ex1, fx2, ex2, fx3, ex3, c);
        Lanes::Map(ay + c) = sum(fy0, ey0, fy1, ey1, fy2, ey2, fy3, ey3, c);
    }
    for (; c < cells; ++c) {
        ax[c] = ((fx0[c] - ex0[c]) + (fx1[c] - ex1[c])) + ((fx2[c] - ex2[c]) + (fx3[c] - ex3[c]));
        ay[c] = ((fy0[c] - ey0[c]) + (fy1[c] - ey1[c])) + ((fy2[c] - ey2[c]) + (fy3[c] - ey3[c]));
    }
}

/// Gravity, drag, shape matching and the grid springs' stiffness on every ellipse of every soft
/// grid (their damping, and the internal damping, are a pass of their own, soft_damping.h): writes every field of their entries in `out`, with the accelerations (every ellipse
/// of a grid has the same mass, so forces are divided by it up front). The grid's coordinates are
/// copied into `scratch`, one array per component laid out on the lattice, for the springs.
void addSoftGridForces(const model::World& world, std::span<const model::BodyState> states,
                       std::vector<BodyDerivative>& out, ForceScratch& scratch)
{
    std::size_t offset = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        const model::Body& body = world.bodies[grid.body.index];
        const std::size_t count = grid.size();
        const auto cells = static_cast<std::size_t>(grid.columns * grid.rows);
        // Slots before and after the lattice, so that every spring's far end and every cell's
        // nearest spring start lie inside the arrays.
        const auto pad = static_cast<std::size_t>(grid.columns + 1);
        const std::size_t slots = cells + 2 * pad;
        const Scalar invMass = 1 / grid.ellipseMass;
        const Vec2 gravity = world.settings.gravity;
        // Each ellipse's share of the body's drag coefficient, b·m/M, over its mass m.
        const Scalar drag = world.settings.drag * body.invMass;
        const model::BodyState* s = states.data() + offset;
        BodyDerivative* d = out.data() + offset;
        scratch.resize(slots);
        Scalar* __restrict x = scratch.x.data();
        Scalar* __restrict y = scratch.y.data();
        // Zeros around the lattice and in its empty cells; a full lattice (a box) needs them only
        // around it.
        for (Scalar* v : {x, y}) {
            if (count == cells) {
                std::fill_n(v, pad, 0.0);
                std::fill_n(v + pad + cells, pad, 0.0);
            } else {
                std::fill_n(v, slots, 0.0);
            }
        }
        // The grid's centre of mass, for shape matching. Sums of the even and the odd ellipses
        // apart, so that two additions are under way at a time.
        Vec2 centreEven = Vec2::Zero();
        Vec2 centreOdd = Vec2::Zero();
        const std::int32_t* __restrict cellOf = grid.ellipseCell.data();
        const auto place = [&](std::size_t i) {
            const std::size_t slot = pad + static_cast<std::size_t>(cellOf[i]);
            x[slot] = s[i].position.x();
            y[slot] = s[i].position.y();
        };
        std::size_t i = 0;
        for (; i + 1 < count; i += 2) {
            place(i);
            place(i + 1);
            centreEven += s[i].position;
            centreOdd += s[i + 1].position;
        }
        if (i < count) {
            place(i);
            centreEven += s[i].position;
        }
        const auto n = static_cast<Scalar>(count);
        const Vec2 centre = (centreEven + centreOdd) / n;
        // Σ r · p and Σ r × p, with p = x − c and r the rest position, again even and odd apart.
        Vec2 sumsEven = Vec2::Zero();
        Vec2 sumsOdd = Vec2::Zero();
        const auto sums = [&](std::size_t k) {
            const Vec2 p = s[k].position - centre;
            const Vec2& r = grid.restPositions[k];
            return Vec2(r.dot(p), cross(r, p));
        };
        for (i = 0; i + 1 < count; i += 2) {
            sumsEven += sums(i);
            sumsOdd += sums(i + 1);
        }
        if (i < count)
            sumsEven += sums(i);
        const Vec2 total = sumsEven + sumsOdd;
        // Shape matching: each ellipse is pulled towards its goal, where the best-fit rigid motion
        // of the rest lattice puts it (see softShapeMatchingStiffness).
        const Scalar norm = std::hypot(total.x(), total.y());
        const Scalar c = norm > 0 ? total.x() / norm : 1;
        const Scalar sn = norm > 0 ? total.y() / norm : 0;
        const Scalar matching = softShapeMatchingStiffness(grid, body) * invMass;

        addGridSpringForces(grid, scratch, pad, invMass);
        const Scalar* __restrict ax = scratch.ax.data();
        const Scalar* __restrict ay = scratch.ay.data();
        // Component by component: a Vec2 built from two computed scalars goes through the stack
        // and stalls the load that reads it back.
        for (i = 0; i < count; ++i) {
            const Scalar px = s[i].position.x() - centre.x();
            const Scalar py = s[i].position.y() - centre.y();
            const Scalar vxi = s[i].velocity.x();
            const Scalar vyi = s[i].velocity.y();
            const Vec2& r = grid.restPositions[i];
            const auto cell = static_cast<std::size_t>(cellOf[i]);
            // x − g, with g = c + R·r.
            const Scalar offX = px - (c * r.x() - sn * r.y());
            const Scalar offY = py - (sn * r.x() + c * r.y());
            d[i].velocity = s[i].velocity;
            d[i].angularVelocity = 0;
            d[i].acceleration.x() = gravity.x() - drag * vxi - matching * offX + ax[cell];
            d[i].acceleration.y() = gravity.y() - drag * vyi - matching * offY + ay[cell];
            d[i].angularAcceleration = 0;
        }
        offset += count;
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
        SoftAggregate a = softAggregate(grid, positions, velocities, world.bodies[grid.body.index].state.angle);
        // The smooth forces turn a grid crushed until its ellipses nearly meet as if it kept a share
        // of its rest lattice's inertia (constants::kSoftMinInertiaFraction), with its angular
        // momentum: the angular velocity at which its springs' ends move, and the turn their torque
        // gives it, stay bounded. (The joints see its own inertia: what they hand on to the
        // ellipses as a rigid motion must be the momentum they computed.)
        Scalar rest = 0;
        for (const Vec2& r : grid.restPositions)
            rest += r.squaredNorm();
        const Scalar least = constants::kSoftMinInertiaFraction * grid.ellipseMass * rest;
        if (a.inertia < least) {
            a.angularVelocity *= a.inertia / least;
            a.inertia = least;
        }
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

void gatherStates(const model::World& world, std::vector<model::BodyState>& out, TaskPair* tasks)
{
    out.resize(stateCount(world));
    inHalves(tasks, world.bodies.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            out[i] = world.bodies[i].state;
    });
    std::size_t k = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        for (std::size_t i = 0; i < grid.size(); ++i)
            out[k++] = model::BodyState{grid.positions[i], 0, grid.velocities[i], 0};
    }
}

void scatterStates(model::World& world, std::span<const model::BodyState> states, TaskPair* tasks)
{
    inHalves(tasks, world.bodies.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            world.bodies[i].state = states[i];
    });
    std::size_t k = world.bodies.size();
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

void ForceScratch::resize(std::size_t slots)
{
    // Only ever grows, so a run of evaluations allocates on its first one alone.
    if (x.size() >= slots)
        return;
    for (std::vector<Scalar>* v : {&x, &y, &ax, &ay})
        v->resize(slots);
    for (std::size_t f = 0; f < fx.size(); ++f) {
        fx[f].resize(slots);
        fy[f].resize(slots);
    }
}

void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out)
{
    ForceScratch scratch;
    computeDerivatives(world, states, out, scratch);
}

void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out, ForceScratch& scratch)
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
    addSoftGridForces(world, states, out, scratch);

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
