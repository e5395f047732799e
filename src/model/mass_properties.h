#pragma once
/// \file mass_properties.h
/// Area, centroid and polar second moment of area of every shape, per unit areal density.

#include "model/scalar.h"
#include "model/shape.h"

#include <span>

namespace impetus::model {

/// Geometric properties of a shape of unit areal density (1 kg/m²).
/// A body of density ρ has mass m = ρ·area and moment of inertia about its centroid I = ρ·polarMoment.
struct AreaProperties {
    Scalar area = 0; ///< m²
    Vec2 centroid = Vec2::Zero(); ///< m, in the shape's own (user) frame
    Scalar polarMoment = 0; ///< ∫|r − centroid|² dA, m⁴ (moment of inertia per unit density)
};

/// Properties of a polygon (either winding; the area is returned positive) by decomposition into
/// the triangles (r, pᵢ, pᵢ₊₁) fanned from the first vertex r. With dᵢ = pᵢ − r, the signed areas
/// Aᵢ = ½ dᵢ×dᵢ₊₁ sum to the area, the centroid is r + Σ Aᵢ(dᵢ+dᵢ₊₁)/3 / A, and each triangle's
/// moment about r, Aᵢ(dᵢ·dᵢ + dᵢ·dᵢ₊₁ + dᵢ₊₁·dᵢ₊₁)/6, sums to J_r. The parallel-axis theorem shifts
/// it to the centroid: J = J_r − A|c − r|². Precondition: validatePolygon(vertices) is empty.
AreaProperties polygonAreaProperties(std::span<const Vec2> vertices);

/// Properties of any shape: circle J = πr⁴/2 (I = ½mr²), ellipse J = πab(a²+b²)/4
/// (I = m(a²+b²)/4), box J = wh(w²+h²)/12 (I = m(w²+h²)/12), polygon as above.
AreaProperties areaProperties(const Shape& shape);

} // namespace impetus::model
