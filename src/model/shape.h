#pragma once
/// \file shape.h
/// The four shapes a body can have, as the user defines them (scene-file `shape`).

#include "model/scalar.h"

#include <string_view>
#include <variant>
#include <vector>

namespace impetus::model {

/// A disc of radius `radius` (m), centred on the body's centre of mass.
struct Circle {
    Scalar radius = 0.5; ///< m, > 0
    bool operator==(const Circle&) const = default; ///< memberwise equality
};

/// An ellipse with semi-axes `radiusX` and `radiusY` (m) along the body's x and y axes.
struct Ellipse {
    Scalar radiusX = 0.5; ///< semi-axis along body x, m, > 0
    Scalar radiusY = 0.25; ///< semi-axis along body y, m, > 0
    bool operator==(const Ellipse&) const = default; ///< memberwise equality
};

/// An axis-aligned (in the body frame) rectangle of `width` × `height` (m), centred on the body.
struct Box {
    Scalar width = 1.0; ///< m, > 0
    Scalar height = 1.0; ///< m, > 0
    bool operator==(const Box&) const = default; ///< memberwise equality
};

/// A simple polygon, convex or concave, winding either way. `vertices` are kept exactly as the
/// user gave them (so a scene round-trips bit for bit); the engine re-centres them on their
/// centroid when it builds the body's geometry (see BodyGeometry).
struct Polygon {
    std::vector<Vec2> vertices; ///< m, in the body's own frame
    bool operator==(const Polygon&) const = default; ///< memberwise equality
};

/// One of the four shapes.
using Shape = std::variant<Circle, Ellipse, Box, Polygon>;

/// The scene-file name of a shape's type: "circle", "ellipse", "box" or "polygon".
std::string_view shapeTypeName(const Shape& shape);

} // namespace impetus::model
