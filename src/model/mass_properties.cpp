#include "model/mass_properties.h"

#include <numbers>

namespace impetus::model {

AreaProperties polygonAreaProperties(std::span<const Vec2> vertices)
{
    // Fan of triangles (r, pᵢ, pᵢ₊₁) from a reference point r. Each has signed area ½ dᵢ×dᵢ₊₁
    // (dᵢ = pᵢ − r), centroid r + (dᵢ+dᵢ₊₁)/3 and polar moment about r Aᵢ/6 · (dᵢ·dᵢ + dᵢ·dᵢ₊₁ +
    // dᵢ₊₁·dᵢ₊₁). Triangles on the far side of r have negative area and subtract, which is why any
    // simple polygon works.
    // r is the first vertex, not the origin: the parallel-axis shift J = J_r − A·|c − r|² then
    // subtracts numbers of the shape's own size. About the origin, a shape 1 km away would lose
    // ~9 of its 16 digits to cancellation.
    const std::size_t n = vertices.size();
    const Vec2 reference = n > 0 ? vertices[0] : Vec2::Zero();
    Scalar twiceArea = 0;
    Vec2 firstMoment = Vec2::Zero(); // Σ 2Aᵢ·(dᵢ+dᵢ₊₁)
    Scalar moment = 0; // Σ 2Aᵢ·(dᵢ·dᵢ + dᵢ·dᵢ₊₁ + dᵢ₊₁·dᵢ₊₁)
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p = vertices[i] - reference;
        const Vec2 q = vertices[(i + 1) % n] - reference;
        const Scalar c = cross(p, q);
        twiceArea += c;
        firstMoment += c * (p + q);
        moment += c * (p.dot(p) + p.dot(q) + q.dot(q));
    }
    AreaProperties props;
    const Scalar signedA = twiceArea / 2;
    const Vec2 centroidFromReference = firstMoment / (3 * twiceArea);
    props.centroid = reference + centroidFromReference;
    // Orientation flips the sign of every term alike; divide it out to get positive quantities.
    const Scalar sign = signedA < 0 ? -1.0 : 1.0;
    props.area = sign * signedA;
    const Scalar momentAboutReference = sign * moment / 12;
    // Parallel-axis theorem: J_c = J_r − A·|c − r|².
    props.polarMoment = momentAboutReference - props.area * centroidFromReference.squaredNorm();
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
