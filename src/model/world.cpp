#include "model/world.h"

namespace impetus::model {

std::string_view integratorName(IntegratorKind kind)
{
    switch (kind) {
    case IntegratorKind::Euler:
        return "euler";
    case IntegratorKind::SemiImplicitEuler:
        return "semi-implicit-euler";
    case IntegratorKind::Rk4:
        return "rk4";
    }
    return "rk4";
}

std::optional<IntegratorKind> integratorFromName(std::string_view name)
{
    for (const IntegratorKind kind :
         {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4}) {
        if (integratorName(kind) == name)
            return kind;
    }
    return std::nullopt;
}

std::optional<BodyId> World::findBody(std::string_view name) const
{
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].name == name)
            return BodyId{static_cast<std::uint32_t>(i)};
    }
    return std::nullopt;
}

const SoftGrid* World::softGrid(BodyId id) const
{
    for (const SoftGrid& grid : softBodies) {
        if (grid.body == id)
            return &grid;
    }
    return nullptr;
}

} // namespace impetus::model
