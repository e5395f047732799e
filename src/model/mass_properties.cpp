#include "model/mass_properties.h"

#include <numbers>

namespace impetus::model {

AreaProperties polygonAreaProperties(std::span<const Vec2> vertices)
{
    // Fan of triangles (origin, pᵢ, pᵢ₊₁). Each has signed area ½ pᵢ×pᵢ₊₁, centroid (pᵢ+pᵢ₊₁)/3 and
    // polar moment about the origin Aᵢ/6 · (pᵢ·pᵢ + pᵢ·pᵢ₊₁ + pᵢ₊₁·pᵢ₊₁). Triangles on the far side
    // of the origin have negative area and subtract, which is why any simple polygon works.
    Scalar twiceArea = 0;
    Vec2 firstMoment = Vec2::Zero(); // Σ 2Aᵢ·(pᵢ+pᵢ₊₁)
    Scalar moment = 0; // Σ 2Aᵢ·(pᵢ·pᵢ + pᵢ·pᵢ₊₁ + pᵢ₊₁·pᵢ₊₁)
    const std::size_t n = vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& p = vertices[i];
        const Vec2& q = vertices[(i + 1) % n];
        const Scalar c = cross(p, q);
        twiceArea += c;
        firstMoment += c * (p + q);
        moment += c * (p.dot(p) + p.dot(q) + q.dot(q));
    }
    AreaProperties props;
    const Scalar signedA = twiceArea / 2;
    props.centroid = firstMoment / (3 * twiceArea);
    // Orientation flips the sign of every term alike; divide it out to get positive quantities.
    const Scalar sign = signedA < 0 ? -1.0 : 1.0;
    props.area = sign * signedA;
    const Scalar momentAboutOrigin = sign * moment / 12;
    // Parallel-axis theorem: J_c = J_0 − A·|c|².
    props.polarMoment = momentAboutOrigin - props.area * props.centroid.squaredNorm();
    return props;
}

AreaProperties areaProperties(const Shape& shape)
{
    constexpr Scalar pi = std::numbers::pi_v<Scalar>;
    AreaProperties props;
    if (const auto* circle = std::get_if<Circle>(&shape)) {
        const Scalar r = circle->radius;
        props.area = pi * r * r;
        props.polarMoment = props.area * r * r / 2;
    } else if (const auto* ellipse = std::get_if<Ellipse>(&shape)) {
        const Scalar a = ellipse->radiusX;
        const Scalar b = ellipse->radiusY;
        props.area = pi * a * b;
        props.polarMoment = props.area * (a * a + b * b) / 4;
    } else if (const auto* box = std::get_if<Box>(&shape)) {
        const Scalar w = box->width;
        const Scalar h = box->height;
        props.area = w * h;
        props.polarMoment = props.area * (w * w + h * h) / 12;
    } else if (const auto* polygon = std::get_if<Polygon>(&shape)) {
        props = polygonAreaProperties(polygon->vertices);
    }
    return props;
}

} // namespace impetus::model
