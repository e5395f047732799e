#include "model/shape.h"

namespace impetus::model {

std::string_view shapeTypeName(const Shape& shape)
{
    struct Namer {
        std::string_view operator()(const Circle&) const { return "circle"; }
        std::string_view operator()(const Ellipse&) const { return "ellipse"; }
        std::string_view operator()(const Box&) const { return "box"; }
        std::string_view operator()(const Polygon&) const { return "polygon"; }
    };
    return std::visit(Namer{}, shape);
}

} // namespace impetus::model
