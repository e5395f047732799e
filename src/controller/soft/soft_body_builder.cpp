#include "controller/soft/soft_body_builder.h"

#include "controller/soft/soft_density.h"
#include "model/constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <variant>

namespace impetus::controller {

namespace {

/// The shape's bounding box in the body frame (origin at the centroid): lower and upper corners.
std::pair<Vec2, Vec2> boundsOf(const model::Body& body)
{
    if (const auto* circle = std::get_if<model::Circle>(&body.shape))
        return {Vec2::Constant(-circle->radius), Vec2::Constant(circle->radius)};
    if (const auto* ellipse = std::get_if<model::Ellipse>(&body.shape))
        return {Vec2(-ellipse->radiusX, -ellipse->radiusY), Vec2(ellipse->radiusX, ellipse->radiusY)};
    if (const auto* box = std::get_if<model::Box>(&body.shape))
        return {Vec2(-box->width / 2, -box->height / 2), Vec2(box->width / 2, box->height / 2)};
    Vec2 lower = Vec2::Constant(INFINITY);
    Vec2 upper = Vec2::Constant(-INFINITY);
    for (const Vec2& v : body.geometry.outline) {
        lower = lower.cwiseMin(v);
        upper = upper.cwiseMax(v);
    }
    return {lower, upper};
}

/// Whether body-frame point p lies inside the shape. Polygons by the crossing number, which works
/// for concave ones too.
bool contains(const model::Body& body, const Vec2& p)
{
    if (const auto* circle = std::get_if<model::Circle>(&body.shape))
        return p.squaredNorm() < circle->radius * circle->radius;
    if (const auto* ellipse = std::get_if<model::Ellipse>(&body.shape)) {
        const Scalar x = p.x() / ellipse->radiusX;
        const Scalar y = p.y() / ellipse->radiusY;
        return x * x + y * y < 1;
    }
    if (const auto* box = std::get_if<model::Box>(&body.shape))
        return std::abs(p.x()) < box->width / 2 && std::abs(p.y()) < box->height / 2;
    const std::vector<Vec2>& outline = body.geometry.outline;
    bool inside = false;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const Vec2& a = outline[i];
        const Vec2& b = outline[j];
        if ((a.y() > p.y()) != (b.y() > p.y())) {
            const Scalar x = a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
            if (p.x() < x)
                inside = !inside;
        }
    }
    return inside;
}

/// Largest eigenvalue of the symmetric 2×2 matrix [[xx, xy], [xy, yy]].
Scalar largestEigenvalue(Scalar xx, Scalar xy, Scalar yy)
{
    const Scalar mean = 0.5 * (xx + yy);
    const Scalar half = 0.5 * (xx - yy);
    return mean + std::sqrt(half * half + xy * xy);
}

/// The body's mass, from its grid.
Scalar massOf(const model::SoftGrid& grid) { return grid.ellipseMass * static_cast<Scalar>(grid.size()); }

/// Fills grid.maxSpringRate. The stiffness matrix K of the grid is made of 2×2
/// blocks k·u·uᵀ; by Gershgorin's theorem on blocks, λmax(M⁻¹K) ≤ max over ellipses of
/// 2·λmax(Σ k·u·uᵀ)/m, which is exact for the fastest mode of a uniform square lattice (8k/m).
void computeRates(model::SoftGrid& grid)
{
    struct Block {
        Scalar xx = 0, xy = 0, yy = 0;
    };
    std::vector<Block> stiffness(grid.size());
    for (const model::SoftSpring& s : grid.springs) {
        const Vec2 d = grid.restPositions[s.b] - grid.restPositions[s.a];
        const Vec2 u = d / d.norm();
        for (const std::uint32_t end : {s.a, s.b}) {
            stiffness[end].xx += s.stiffness * u.x() * u.x();
            stiffness[end].xy += s.stiffness * u.x() * u.y();
            stiffness[end].yy += s.stiffness * u.y() * u.y();
        }
    }
    grid.maxSpringRate = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        grid.maxSpringRate = std::max(grid.maxSpringRate, 2 * largestEigenvalue(stiffness[i].xx, stiffness[i].xy,
                                                                                 stiffness[i].yy) / grid.ellipseMass);
    }
    // Shape matching adds its stiffness k_s/m. (The damping does not count: it is a pass of its
    // own, stable at any step, soft_damping.h.)
    grid.maxSpringRate += constants::kSoftShapeMatching * grid.settings.stiffness / massOf(grid);
}

/// The lattice directions of the springs (column step, row step), in SoftGrid::springFields order.
constexpr std::array<std::array<int, 2>, 4> kSpringDirections{{{1, 0}, {0, 1}, {1, 1}, {-1, 1}}};

/// Fills grid.springFields from grid.springs.
void buildSpringFields(model::SoftGrid& grid)
{
    const auto cells = static_cast<std::size_t>(grid.columns * grid.rows);
    for (std::size_t f = 0; f < kSpringDirections.size(); ++f) {
        model::SoftSpringField& field = grid.springFields[f];
        field.step = kSpringDirections[f][0] + kSpringDirections[f][1] * grid.columns;
        field.stiffness.assign(cells, 0);
        field.restLength.assign(cells, 0);
        field.begin = static_cast<std::int32_t>(cells);
        field.end = 0;
    }
    for (const model::SoftSpring& s : grid.springs) {
        const int a = grid.ellipseCell[s.a];
        const int b = grid.ellipseCell[s.b];
        const std::array<int, 2> along{b % grid.columns - a % grid.columns, b / grid.columns - a / grid.columns};
        const auto f = static_cast<std::size_t>(
            std::find(kSpringDirections.begin(), kSpringDirections.end(), along) - kSpringDirections.begin());
        model::SoftSpringField& field = grid.springFields[f];
        const auto cell = static_cast<std::size_t>(a);
        field.stiffness[cell] = s.stiffness;
        field.restLength[cell] = s.restLength;
        field.begin = std::min(field.begin, a);
        field.end = std::max(field.end, a + 1);
    }
    for (model::SoftSpringField& field : grid.springFields)
        field.begin = std::min(field.begin, field.end);
}

/// Puts a freshly built grid where `body`'s saved grid state (scene key `soft.state`) says, when
/// there is one with an ellipse for every ellipse of the grid; the body's own state is then the
/// aggregate the file was saved with. Otherwise the grid stays the rigid copy it was built as.
void restoreSoftState(model::SoftGrid& grid, const model::Body& body)
{
    if (!body.softState || body.softState->positions.size() != grid.size() ||
        body.softState->velocities.size() != grid.size())
        return;
    grid.positions = body.softState->positions;
    grid.velocities = body.softState->velocities;
    // The file keeps the frame (the body's angle), not the best fit: the fit is taken afresh, in
    // the half turn nearest the frame.
    grid.fitAngle = body.state.angle;
    grid.fitAngle = softAggregate(grid, grid.positions, grid.velocities, body.state.angle).fitAngle;
    grid.ownerState = body.state;
    grid.rigidCopy = false;
}

/// Whether `grid` still describes `body` (same shape, mass and soft settings).
bool matches(const model::SoftGrid& grid, const model::Body& body)
{
    return body.soft && grid.shape == body.shape && grid.massSpec == body.massSpec && grid.settings == *body.soft;
}

} // namespace

bool isSoftBody(const model::Body& body) { return body.soft.has_value() && !body.fixed; }

Scalar softSpringDamping(const model::SoftSettings& settings, Scalar ellipseMass)
{
    if (settings.dampingMode == model::SoftDampingMode::Coefficient)
        return settings.damping;
    // Two ellipses of mass m joined by one spring vibrate as one mass m/2 on it.
    const Scalar reducedMass = 0.5 * ellipseMass;
    return 2 * settings.dampingRatio * std::sqrt(settings.stiffness * reducedMass);
}

Scalar softShapeMatchingDamping(const model::SoftGrid& grid, const model::Body& body)
{
    return constants::kSoftShapeMatching * grid.springDamping * grid.ellipseMass * body.invMass;
}

Scalar softShapeMatchingStiffness(const model::SoftGrid& grid, const model::Body& body)
{
    return constants::kSoftShapeMatching * grid.settings.stiffness * grid.ellipseMass * body.invMass;
}

model::SoftGrid buildSoftGrid(const model::Body& body, model::BodyId id, Scalar ellipsesPerSquareMeter)
{
    model::SoftGrid grid;
    grid.body = id;
    grid.shape = body.shape;
    grid.massSpec = body.massSpec;
    grid.settings = *body.soft;
    grid.ellipsesPerSquareMeter = ellipsesPerSquareMeter;

    const auto [lower, upper] = boundsOf(body);
    const Vec2 size = upper - lower;
    const Scalar perMetre = std::sqrt(ellipsesPerSquareMeter);
    grid.columns = std::max(1, static_cast<int>(std::lround(size.x() * perMetre)));
    grid.rows = std::max(1, static_cast<int>(std::lround(size.y() * perMetre)));
    // At least two cells, along the longer side: one ellipse is a point, with no orientation and
    // no moment of inertia, so a joint or spring anchored off its centre could not turn it (a pin
    // 2 m from such a body's centre tore the two bodies apart: soak seed 2429).
    if (grid.columns == 1 && grid.rows == 1)
        (size.x() >= size.y() ? grid.columns : grid.rows) = 2;
    grid.cellSize = Vec2(size.x() / grid.columns, size.y() / grid.rows);
    grid.latticeOrigin = lower;
    grid.cellEllipse.assign(static_cast<std::size_t>(grid.columns * grid.rows), -1);

    std::vector<Vec2> centres;
    for (int row = 0; row < grid.rows; ++row) {
        for (int column = 0; column < grid.columns; ++column) {
            const Vec2 centre = lower + Vec2((column + 0.5) * grid.cellSize.x(), (row + 0.5) * grid.cellSize.y());
            if (!contains(body, centre))
                continue;
            const int cell = row * grid.columns + column;
            grid.cellEllipse[static_cast<std::size_t>(cell)] = static_cast<std::int32_t>(centres.size());
            grid.ellipseCell.push_back(cell);
            centres.push_back(centre);
        }
    }
    if (centres.empty()) {
        // A shape thinner than a cell everywhere the lattice samples it: one ellipse at the
        // centroid, in the cell that holds it, keeps the body's mass and motion.
        const int column = std::clamp(static_cast<int>(-lower.x() / grid.cellSize.x()), 0, grid.columns - 1);
        const int row = std::clamp(static_cast<int>(-lower.y() / grid.cellSize.y()), 0, grid.rows - 1);
        const int cell = row * grid.columns + column;
        grid.cellEllipse[static_cast<std::size_t>(cell)] = 0;
        grid.ellipseCell.push_back(cell);
        centres.push_back(Vec2::Zero());
    }

    Vec2 sum = Vec2::Zero();
    for (const Vec2& c : centres)
        sum += c;
    grid.restCentre = sum / static_cast<Scalar>(centres.size());
    grid.restPositions.reserve(centres.size());
    for (const Vec2& c : centres)
        grid.restPositions.push_back(c - grid.restCentre);
    grid.ellipseMass = body.mass / static_cast<Scalar>(centres.size());
    grid.springDamping = softSpringDamping(*body.soft, grid.ellipseMass);

    // Right and up neighbours (structural), up-right and up-left (shear): every pair once.
    const model::SoftSettings& soft = *body.soft;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        const int cell = grid.ellipseCell[i];
        const int column = cell % grid.columns;
        const int row = cell / grid.columns;
        for (const auto& [dc, dr] : kSpringDirections) {
            const std::int32_t j = grid.ellipseAt(column + dc, row + dr);
            if (j < 0)
                continue;
            model::SoftSpring spring;
            spring.a = static_cast<std::uint32_t>(i);
            spring.b = static_cast<std::uint32_t>(j);
            spring.restLength = (centres[static_cast<std::size_t>(j)] - centres[i]).norm();
            spring.stiffness = soft.stiffness;
            spring.damping = grid.springDamping;
            spring.diagonal = dc != 0 && dr != 0;
            grid.springs.push_back(spring);
        }
    }
    buildSpringFields(grid);
    computeRates(grid);
    placeSoftGrid(grid, body.state);
    return grid;
}

void placeSoftGrid(model::SoftGrid& grid, const model::BodyState& state)
{
    const Scalar c = std::cos(state.angle);
    const Scalar s = std::sin(state.angle);
    grid.positions.resize(grid.restPositions.size());
    grid.velocities.resize(grid.restPositions.size());
    for (std::size_t i = 0; i < grid.restPositions.size(); ++i) {
        const Vec2& r = grid.restPositions[i];
        const Vec2 arm(c * r.x() - s * r.y(), s * r.x() + c * r.y());
        grid.positions[i] = state.position + arm;
        grid.velocities[i] = state.velocity + cross(state.angularVelocity, arm);
    }
    grid.ownerState = state;
    grid.fitAngle = state.angle;
    grid.rigidCopy = true;
}

namespace {

/// `turn` less the whole half turns nearest it: between −π/2 and π/2.
Scalar nearestHalfTurn(Scalar turn) { return turn - std::numbers::pi * std::round(turn / std::numbers::pi); }

} // namespace

SoftAggregate softAggregate(const model::SoftGrid& grid, std::span<const Vec2> positions,
                            std::span<const Vec2> velocities, const SoftReference& reference)
{
    // Every ellipse has the same mass, so means are mass-weighted means.
    SoftAggregate a;
    const auto count = static_cast<Scalar>(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        a.position += positions[i];
        a.velocity += velocities[i];
    }
    a.position /= count;
    a.velocity /= count;
    const bool moved = !reference.positions.empty() && reference.positions.data() != positions.data() &&
                       reference.positions.size() == positions.size();
    Vec2 centreThen = a.position;
    if (moved) {
        centreThen = Vec2::Zero();
        for (const Vec2& p : reference.positions)
            centreThen += p;
        centreThen /= count;
    }

    Scalar dot = 0;
    Scalar crossSum = 0;
    Scalar dotThen = 0;
    Scalar crossThen = 0;
    Scalar dotTurn = 0;
    Scalar crossTurn = 0;
    Scalar spin = 0;
    Scalar inertia = 0;
    Scalar restSpread = 0;
    Scalar spreadThen = 0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Vec2 p = positions[i] - a.position;
        const Vec2& r = grid.restPositions[i];
        dot += r.dot(p);
        crossSum += cross(r, p);
        spin += cross(p, Vec2(velocities[i] - a.velocity));
        inertia += p.squaredNorm();
        restSpread += r.squaredNorm();
        if (moved) {
            const Vec2 then = reference.positions[i] - centreThen;
            dotThen += r.dot(then);
            crossThen += cross(r, then);
            spreadThen += then.squaredNorm();
            dotTurn += then.dot(p);
            crossTurn += cross(then, p);
        }
    }
    if (!moved) {
        dotThen = dot;
        crossThen = crossSum;
        spreadThen = inertia;
    }
    a.angularVelocity = inertia > 0 ? spin / inertia : 0;
    a.inertia = grid.ellipseMass * inertia;
    // A grid of one ellipse has no rest lattice to fit: it keeps the angle it had, so that a
    // joint's anchor on it stays where it was (taken as 0, atan2(0, 0), it swung a pin's anchor
    // on such a body round its centre and the joint tore the bodies apart: soak seeds 2429 and
    // 3419; the builder now makes two cells at least, but a sliver of a shape can still hold
    // one). Its ellipse cannot spin, so its inertia is 0 and it never turns.
    const Scalar fit = std::hypot(dot, crossSum);
    if (fit == 0 || !(restSpread > 0)) {
        a.angle = reference.angle;
        a.fitAngle = reference.fitAngle;
        a.bestFit = reference.fitAngle;
        return a;
    }
    a.bestFit = std::atan2(crossSum, dot);
    // The best fit of a grid whose ellipses pass through one another (two ellipses struck into
    // each other, a lattice turned inside out) flips by half a turn within a step: the fit
    // shrinks to nothing and comes back the other way round. A frame that followed it swung a
    // joint's anchor metres from the grid to the far side of it, and the joint tore the bodies
    // apart (soak seed 1014); one that followed a torn grid's fit by a share turned against the
    // grid's own spin, and the pin that held it there pumped energy in (4961). So a turn is taken
    // in the half turn nearest the reference (a two-ellipse grid turned by half a turn is the same
    // grid), and a grid crushed then or now turns its frame as its ellipses turn about their
    // centre, which its angular momentum is (the turn of the fit for the rest).
    const Scalar quality = std::min(fit / std::max(restSpread, std::sqrt(restSpread * inertia)),
                                    std::hypot(dotThen, crossThen) / std::max(restSpread, std::sqrt(restSpread * spreadThen)));
    const Scalar share = std::min<Scalar>(1, quality / constants::kSoftFullFitQuality);
    // (A grid spinning faster than a quarter turn a substep is counted short by half a turn: a
    // free soft wheel above 377 rad/s at 1/240 s. Counting its fit's turn from its ellipses' own
    // turn instead made soak seed 7857 fail, a light soft polygon whipped round by a pin.)
    const Scalar fitTurn = nearestHalfTurn(a.bestFit - reference.fitAngle);
    a.fitAngle = reference.fitAngle + fitTurn;
    const Scalar ownTurn = dotTurn == 0 && crossTurn == 0 ? 0 : nearestHalfTurn(std::atan2(crossTurn, dotTurn));
    a.angle = reference.angle + share * fitTurn + (1 - share) * ownTurn;
    return a;
}

SoftAggregate softAggregate(const model::SoftGrid& grid, std::span<const Vec2> positions,
                            std::span<const Vec2> velocities, Scalar referenceAngle)
{
    return softAggregate(grid, positions, velocities, SoftReference{grid.positions, referenceAngle, grid.fitAngle});
}

void prepareSoftBodies(model::World& world)
{
    // The common case, every step: each soft body has a matching grid at its recorded state.
    bool current = true;
    std::size_t g = 0;
    for (std::uint32_t i = 0; i < world.bodies.size() && current; ++i) {
        const model::Body& body = world.bodies[i];
        if (!isSoftBody(body))
            continue;
        current = g < world.softBodies.size() && world.softBodies[g].body.index == i && !body.softState &&
                  matches(world.softBodies[g], body) && world.softBodies[g].ownerState == body.state;
        ++g;
    }
    if (current && g == world.softBodies.size())
        return;

    std::optional<Scalar> autoChoice;
    for (const model::SoftGrid& grid : world.softBodies) {
        if (grid.settings.autoDensity)
            autoChoice = grid.ellipsesPerSquareMeter;
    }
    bool needsAuto = false;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (!isSoftBody(body) || !body.soft->autoDensity)
            continue;
        const model::SoftGrid* grid = world.softGrid(model::BodyId{i});
        needsAuto = needsAuto || !grid || !matches(*grid, body);
    }
    if (needsAuto && !autoChoice)
        autoChoice = chooseAutoDensity(world);

    std::vector<model::SoftGrid> previous = std::move(world.softBodies);
    // A body read with a saved grid state gets a grid built afresh for it, whatever it had.
    std::erase_if(previous, [&](const model::SoftGrid& grid) {
        return grid.body.index < world.bodies.size() && world.bodies[grid.body.index].softState.has_value();
    });
    world.softBodies.clear();
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (!isSoftBody(body))
            continue;
        const auto old = std::find_if(previous.begin(), previous.end(),
                                      [&](const model::SoftGrid& grid) { return grid.body.index == i; });
        if (old != previous.end() && matches(*old, body)) {
            world.softBodies.push_back(std::move(*old));
            if (!(world.softBodies.back().ownerState == body.state))
                placeSoftGrid(world.softBodies.back(), body.state);
            continue;
        }
        const Scalar density = body.soft->autoDensity ? *autoChoice : body.soft->ellipsesPerSquareMeter;
        world.softBodies.push_back(buildSoftGrid(body, model::BodyId{i}, density));
        restoreSoftState(world.softBodies.back(), body);
    }
    // A saved grid state applies once, to the grid first built for it.
    for (model::Body& body : world.bodies)
        body.softState.reset();
}

void updateSoftOwners(model::World& world, std::span<const model::BodyState> previous)
{
    std::vector<Vec2> then;
    std::size_t offset = world.bodies.size();
    for (model::SoftGrid& grid : world.softBodies) {
        model::Body& body = world.bodies[grid.body.index];
        then.clear();
        Scalar angleThen = body.state.angle;
        if (previous.size() >= offset + grid.size()) {
            for (std::size_t i = 0; i < grid.size(); ++i)
                then.push_back(previous[offset + i].position);
            angleThen = previous[grid.body.index].angle;
        }
        offset += grid.size();
        const SoftAggregate a =
            softAggregate(grid, grid.positions, grid.velocities, SoftReference{then, angleThen, grid.fitAngle});
        body.state.position = a.position;
        body.state.angle = a.angle;
        grid.fitAngle = a.fitAngle;
        body.state.velocity = a.velocity;
        body.state.angularVelocity = a.angularVelocity;
        grid.ownerState = body.state;
        grid.rigidCopy = false;
    }
}

std::size_t softEllipseOffset(const model::World& world, std::size_t g)
{
    std::size_t offset = 0;
    for (std::size_t k = 0; k < g; ++k)
        offset += world.softBodies[k].size();
    return offset;
}

} // namespace impetus::controller
