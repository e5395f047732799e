// PLACEHOLDER: being replaced by the polygon helper (validation, triangulation, decomposition).
#include "model/polygon.h"

#include <algorithm>

namespace impetus::model {

std::vector<PolygonIssue> validatePolygon(std::span<const Vec2>) { return {}; }

Scalar signedArea(std::span<const Vec2> vertices)
{
    Scalar twice = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i)
        twice += cross(vertices[i], vertices[(i + 1) % vertices.size()]);
    return twice / 2;
}

std::vector<Vec2> normalizedCounterClockwise(std::span<const Vec2> vertices)
{
    std::vector<Vec2> out(vertices.begin(), vertices.end());
    if (signedArea(out) < 0)
        std::reverse(out.begin(), out.end());
    return out;
}

bool isConvex(std::span<const Vec2>) { return true; }

std::vector<Triangle> triangulate(std::span<const Vec2>) { return {}; }

std::vector<std::vector<Vec2>> decomposeConvex(std::span<const Vec2> vertices)
{
    return {normalizedCounterClockwise(vertices)};
}

} // namespace impetus::model
