#include "controller/soft/soft_body_shape.h"
#include "controller/soft/soft_body_builder.h"

#include "model/constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <variant>

namespace impetus::controller {

namespace {

/// The shape's outline in the body frame, counter-clockwise, sampled finely enough to bend with
/// the grid.
std::vector<Vec2> restOutline(const model::Body& body, const model::SoftGrid& grid)
{
    std::vector<Vec2> points;
    const auto round = [&](Scalar a, Scalar b) {
        for (int i = 0; i < constants::kSoftRoundOutlinePoints; ++i) {
            const Scalar t = 2 * std::numbers::pi * i / constants::kSoftRoundOutlinePoints;
            points.emplace_back(a * std::cos(t), b * std::sin(t));
        }
    };
    if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
        round(circle->radius, circle->radius);
        return points;
    }
    if (const auto* ellipse = std::get_if<model::Ellipse>(&body.shape)) {
        round(ellipse->radiusX, ellipse->radiusY);
        return points;
    }
    const std::vector<Vec2>& corners = body.geometry.outline;
    const Scalar piece = std::min(grid.cellSize.x(), grid.cellSize.y());
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const Vec2& a = corners[i];
        const Vec2& b = corners[(i + 1) % corners.size()];
        const int parts = std::max(1, static_cast<int>(std::ceil((b - a).norm() / piece)));
        for (int k = 0; k < parts; ++k)
            points.push_back(a + (b - a) * (static_cast<Scalar>(k) / parts));
    }
    return points;
}

/// Signed area of the quadrilateral p0 p1 p2 p3 (shoelace).
Scalar quadArea(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Vec2& p3)
{
    return 0.5 * (cross(p0, p1) + cross(p1, p2) + cross(p2, p3) + cross(p3, p0));
}

/// Calls f(e00, e10, e11, e01) for every lattice cell whose four corners hold ellipses,
/// counter-clockwise from the lower left.
template <class F>
void forEachLatticeCell(const model::SoftGrid& grid, F f)
{
    for (int row = 0; row + 1 < grid.rows; ++row) {
        for (int column = 0; column + 1 < grid.columns; ++column) {
            const std::array<std::int32_t, 4> e{grid.ellipseAt(column, row), grid.ellipseAt(column + 1, row),
                                                grid.ellipseAt(column + 1, row + 1), grid.ellipseAt(column, row + 1)};
            if (std::all_of(e.begin(), e.end(), [](std::int32_t i) { return i >= 0; }))
                f(static_cast<std::size_t>(e[0]), static_cast<std::size_t>(e[1]), static_cast<std::size_t>(e[2]),
                  static_cast<std::size_t>(e[3]));
        }
    }
}

} // namespace

std::vector<Vec2> softOutline(const model::World& world, const model::SoftGrid& grid)
{
    const model::Body& body = world.bodies[grid.body.index];
    const Vec2 centre = body.state.position;
    // The best-fit rigid motion (not the frame, which a grid crushed once may have left turned
    // away from its ellipses).
    const Scalar angle = softAggregate(grid, grid.positions, grid.velocities, body.state.angle).bestFit;
    // How far each ellipse is from where the best-fit rigid motion would put it.
    std::vector<Vec2> displacement(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i)
        displacement[i] = grid.positions[i] - (centre + rotate(grid.restPositions[i], angle));

    std::vector<Vec2> outline;
    for (const Vec2& local : restOutline(body, grid)) {
        // Lattice coordinates, with ellipse centres on whole numbers.
        const Scalar u = (local.x() - grid.latticeOrigin.x()) / grid.cellSize.x() - 0.5;
        const Scalar v = (local.y() - grid.latticeOrigin.y()) / grid.cellSize.y() - 0.5;
        // The lattice square around the point, kept inside the lattice so that a point beyond the
        // outermost centres (a box's edge) is extrapolated linearly from the last square.
        const int column = std::clamp(static_cast<int>(std::floor(u)), 0, std::max(0, grid.columns - 2));
        const int row = std::clamp(static_cast<int>(std::floor(v)), 0, std::max(0, grid.rows - 2));
        const std::array<std::array<int, 2>, 4> corners{{{0, 0}, {1, 0}, {0, 1}, {1, 1}}};
        std::array<std::int32_t, 4> nodes{};
        bool complete = grid.columns > 1 && grid.rows > 1;
        for (std::size_t k = 0; k < 4; ++k) {
            nodes[k] = grid.ellipseAt(column + corners[k][0], row + corners[k][1]);
            complete = complete && nodes[k] >= 0;
        }
        // With a corner missing (outside a curved or concave shape) the weights of the others
        // are renormalised inside the square instead.
        const Scalar fu = complete ? u - column : std::clamp(u - column, 0.0, 1.0);
        const Scalar fv = complete ? v - row : std::clamp(v - row, 0.0, 1.0);
        Vec2 moved = Vec2::Zero();
        Scalar weight = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            if (nodes[k] < 0)
                continue;
            const Scalar w = (corners[k][0] != 0 ? fu : 1 - fu) * (corners[k][1] != 0 ? fv : 1 - fv);
            moved += w * displacement[static_cast<std::size_t>(nodes[k])];
            weight += w;
        }
        if (!complete && weight > 0) {
            moved /= weight;
        } else if (!complete) {
            // No ellipse around this point (a spike thinner than a cell): follow the nearest one.
            const Vec2 rest = local - grid.restCentre;
            std::size_t nearest = 0;
            for (std::size_t i = 1; i < grid.size(); ++i) {
                if ((grid.restPositions[i] - rest).squaredNorm() < (grid.restPositions[nearest] - rest).squaredNorm())
                    nearest = i;
            }
            moved = displacement[nearest];
        }
        outline.push_back(centre + rotate(Vec2(local - grid.restCentre), angle) + moved);
    }
    return outline;
}

std::vector<SoftEllipseView> softEllipses(const model::World& /*world*/, const model::SoftGrid& grid)
{
    // Along the lattice's axes as the ellipses lie now (an ellipse turned by half a turn is the
    // same ellipse).
    const Scalar angle = grid.fitAngle;
    const Vec2 semi = grid.semiAxes();
    std::vector<SoftEllipseView> ellipses;
    ellipses.reserve(grid.size());
    for (const Vec2& p : grid.positions)
        ellipses.push_back({p, semi.x(), semi.y(), angle});
    return ellipses;
}

std::vector<SoftSpringView> softSprings(const model::SoftGrid& grid)
{
    std::vector<SoftSpringView> springs;
    springs.reserve(grid.springs.size());
    for (const model::SoftSpring& s : grid.springs) {
        const Vec2& a = grid.positions[s.a];
        const Vec2& b = grid.positions[s.b];
        springs.push_back({a, b, (b - a).norm() / s.restLength - 1, s.diagonal});
    }
    return springs;
}

Scalar softLatticeArea(const model::SoftGrid& grid)
{
    Scalar area = 0;
    forEachLatticeCell(grid, [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
        area += quadArea(grid.positions[a], grid.positions[b], grid.positions[c], grid.positions[d]);
    });
    return area;
}

Scalar softRestLatticeArea(const model::SoftGrid& grid)
{
    Scalar area = 0;
    forEachLatticeCell(grid, [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
        area += quadArea(grid.restPositions[a], grid.restPositions[b], grid.restPositions[c], grid.restPositions[d]);
    });
    return area;
}

int invertedSoftCells(const model::SoftGrid& grid)
{
    int inverted = 0;
    forEachLatticeCell(grid, [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
        const std::array<Vec2, 4> p{grid.positions[a], grid.positions[b], grid.positions[c], grid.positions[d]};
        bool turnedOver = false;
        for (std::size_t k = 0; k < 4; ++k) {
            const Vec2& previous = p[(k + 3) % 4];
            const Vec2& next = p[(k + 1) % 4];
            turnedOver = turnedOver || cross(Vec2(next - p[k]), Vec2(previous - p[k])) <= 0;
        }
        inverted += turnedOver ? 1 : 0;
    });
    return inverted;
}

} // namespace impetus::controller
