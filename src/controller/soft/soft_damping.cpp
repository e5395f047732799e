#include "controller/soft/soft_damping.h"

#include "controller/soft/soft_body_builder.h"
#include "model/constants.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

namespace {

/// Σ ½m|v|² over the grid's ellipses, J.
Scalar kineticEnergy(const model::SoftGrid& grid)
{
    Scalar sum = 0;
    for (const Vec2& v : grid.velocities)
        sum += v.squaredNorm();
    return 0.5 * grid.ellipseMass * sum;
}

/// y = (M + h·C)·x / m, the implicit Euler system of the grid springs' dampers (equal masses m),
/// with the springs' axes and weights h·c/m in `scratch`.
void applyDampingSystem(const model::SoftGrid& grid, const SoftDampingScratch& scratch, const std::vector<Vec2>& x,
                        std::vector<Vec2>& y)
{
    std::copy(x.begin(), x.end(), y.begin());
    for (std::size_t j = 0; j < grid.springs.size(); ++j) {
        const model::SoftSpring& s = grid.springs[j];
        const Vec2& u = scratch.axis[j];
        const Vec2 pull = scratch.weight[j] * u.dot(x[s.b] - x[s.a]) * u;
        y[s.a] -= pull;
        y[s.b] += pull;
    }
}

/// The grid springs' dampers by implicit Euler over h: solves (M + h·C)·v' = M·v for the grid's
/// velocities by conjugate gradients, starting from v.
void dampSprings(model::SoftGrid& grid, Scalar h, SoftDampingScratch& scratch)
{
    const std::size_t springs = grid.springs.size();
    const std::size_t count = grid.size();
    scratch.axis.resize(springs);
    scratch.weight.resize(springs);
    bool any = false;
    for (std::size_t j = 0; j < springs; ++j) {
        const model::SoftSpring& s = grid.springs[j];
        const Vec2 d = grid.positions[s.b] - grid.positions[s.a];
        const Scalar length = d.norm();
        // Ends on one point have no line to damp along (the force model's spring pulls with 0).
        const bool line = length > constants::kSoftMinSpringLength;
        scratch.axis[j] = line ? Vec2(d / length) : Vec2::Zero();
        scratch.weight[j] = line ? h * s.damping / grid.ellipseMass : 0.0;
        any = any || scratch.weight[j] > 0;
    }
    if (!any)
        return;
    std::vector<Vec2>& v = grid.velocities;
    std::vector<Vec2>& r = scratch.residual;
    std::vector<Vec2>& p = scratch.direction;
    std::vector<Vec2>& q = scratch.product;
    r.resize(count);
    p.resize(count);
    q.resize(count);
    // The right-hand side is the velocities themselves: r = v − A·v.
    const auto dot = [count](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
        Scalar sum = 0;
        for (std::size_t i = 0; i < count; ++i)
            sum += a[i].dot(b[i]);
        return sum;
    };
    const Scalar target = constants::kSoftDampingSolveTolerance * constants::kSoftDampingSolveTolerance * dot(v, v);
    applyDampingSystem(grid, scratch, v, q);
    for (std::size_t i = 0; i < count; ++i) {
        r[i] = v[i] - q[i];
        p[i] = r[i];
    }
    Scalar rr = dot(r, r);
    for (int iteration = 0; iteration < constants::kSoftDampingSolveIterations && rr > target; ++iteration) {
        applyDampingSystem(grid, scratch, p, q);
        const Scalar pq = dot(p, q);
        if (!(pq > 0))
            break;
        const Scalar alpha = rr / pq;
        for (std::size_t i = 0; i < count; ++i) {
            v[i] += alpha * p[i];
            r[i] -= alpha * q[i];
        }
        const Scalar next = dot(r, r);
        const Scalar beta = next / rr;
        rr = next;
        for (std::size_t i = 0; i < count; ++i)
            p[i] = r[i] + beta * p[i];
    }
}

/// Internal damping and shape matching's damping: every ellipse's velocity relative to the grid's
/// rigid motion decays at their summed rate for `h` seconds.
void dampTowardsRigidMotion(model::SoftGrid& grid, const model::Body& body, Scalar h)
{
    const std::size_t count = grid.size();
    Vec2 centre = Vec2::Zero();
    Vec2 velocity = Vec2::Zero();
    for (std::size_t i = 0; i < count; ++i) {
        centre += grid.positions[i];
        velocity += grid.velocities[i];
    }
    const auto n = static_cast<Scalar>(count);
    centre /= n;
    velocity /= n;
    // ω = L/I about the centre of mass, equal masses cancelling.
    Scalar spin = 0;
    Scalar spread = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec2 p = grid.positions[i] - centre;
        spin += cross(p, Vec2(grid.velocities[i] - velocity));
        spread += p.squaredNorm();
    }
    const Scalar omega = spread > 0 ? spin / spread : 0;
    const Scalar rate = constants::kSoftInternalDampingRate + softShapeMatchingDamping(grid, body) / grid.ellipseMass;
    const Scalar kept = std::exp(-rate * h);
    // Σ(v − v_rigid) = 0 and Σ p × (v − v_rigid) = 0 by the choice of v_c and ω: scaling what is
    // left over changes neither momentum nor angular momentum.
    for (std::size_t i = 0; i < count; ++i) {
        const Vec2 rigid = velocity + cross(omega, Vec2(grid.positions[i] - centre));
        grid.velocities[i] = rigid + kept * (grid.velocities[i] - rigid);
    }
}

} // namespace

Scalar dampSoftGrid(model::SoftGrid& grid, const model::Body& body, Scalar h, SoftDampingScratch& scratch)
{
    if (grid.size() == 0 || !(h > 0))
        return 0;
    const Scalar before = kineticEnergy(grid);
    dampSprings(grid, h, scratch);
    dampTowardsRigidMotion(grid, body, h);
    return before - kineticEnergy(grid);
}

Scalar dampSoftGrids(model::World& world, Scalar h, SoftDampingScratch& scratch)
{
    Scalar taken = 0;
    for (model::SoftGrid& grid : world.softBodies)
        taken += dampSoftGrid(grid, world.bodies[grid.body.index], h, scratch);
    return taken;
}

} // namespace impetus::controller
