#include "model/body.h"

#include "model/mass_properties.h"
#include "model/polygon.h"

#include <algorithm>

namespace impetus::model {

namespace {

/// Sets outline and convex pieces from user-frame vertices, shifted so the centroid is the origin.
void setPolygonGeometry(BodyGeometry& geometry, std::span<const Vec2> userVertices)
{
    const Vec2 offset = geometry.centroidOffset;
    geometry.outline = normalizedCounterClockwise(userVertices);
    for (Vec2& v : geometry.outline)
        v -= offset;
    geometry.convexPieces = decomposeConvex(userVertices);
    for (auto& piece : geometry.convexPieces) {
        for (Vec2& v : piece)
            v -= offset;
    }
    for (const auto& piece : geometry.convexPieces) {
        std::vector<Vec2> normals;
        normals.reserve(piece.size());
        for (std::size_t i = 0; i < piece.size(); ++i) {
            const Vec2 edge = piece[(i + 1) % piece.size()] - piece[i];
            // Counter-clockwise winding puts the outside on the right of each edge.
            normals.push_back(Vec2(edge.y(), -edge.x()).normalized());
        }
        geometry.pieceNormals.push_back(std::move(normals));
    }
    for (const Vec2& v : geometry.outline)
        geometry.boundingRadius = std::max(geometry.boundingRadius, v.norm());
}

} // namespace

void Body::updateDerived()
{
    const AreaProperties props = areaProperties(shape);
    area = props.area;
    const Scalar rho = density();
    // Keep the user's number exactly: a mass given in kg stays that mass, not ρ·A rounded back.
    mass = massSpec.mode == MassMode::Mass ? massSpec.value : rho * area;
    inertia = rho * props.polarMoment;
    invMass = fixed ? 0.0 : 1.0 / mass;
    invInertia = fixed ? 0.0 : 1.0 / inertia;

    geometry = BodyGeometry{};
    geometry.centroidOffset = props.centroid;
    if (const auto* circle = std::get_if<Circle>(&shape)) {
        geometry.boundingRadius = circle->radius;
    } else if (const auto* ellipse = std::get_if<Ellipse>(&shape)) {
        geometry.boundingRadius = std::max(ellipse->radiusX, ellipse->radiusY);
    } else if (const auto* box = std::get_if<Box>(&shape)) {
        const Scalar hx = box->width / 2;
        const Scalar hy = box->height / 2;
        const std::vector<Vec2> corners = {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)};
        setPolygonGeometry(geometry, corners);
    } else if (const auto* polygon = std::get_if<Polygon>(&shape)) {
        setPolygonGeometry(geometry, polygon->vertices);
    }
}

Scalar Body::density() const
{
    return massSpec.mode == MassMode::Density ? massSpec.value : massSpec.value / area;
}

Vec2 Body::worldPoint(const Vec2& local) const { return state.position + rotate(local, state.angle); }

Vec2 Body::velocityAt(const Vec2& world) const
{
    return state.velocity + cross(state.angularVelocity, Vec2(world - state.position));
}

} // namespace impetus::model
