#include "view/graph_quantity.h"

#include <QCoreApplication>

namespace impetus::view {

namespace {

/// The untranslated label of `quantity`, marked for lupdate (context "GraphQuantity"; a tr() of
/// this file's own would not be found by it).
const char* labelText(GraphQuantity quantity)
{
    switch (quantity) {
    case GraphQuantity::Time:
        return QT_TRANSLATE_NOOP("GraphQuantity", "t (s)");
    case GraphQuantity::X:
        return QT_TRANSLATE_NOOP("GraphQuantity", "x (m)");
    case GraphQuantity::Y:
        return QT_TRANSLATE_NOOP("GraphQuantity", "y (m)");
    case GraphQuantity::Angle:
        return QT_TRANSLATE_NOOP("GraphQuantity", "angle (rad)");
    case GraphQuantity::Vx:
        return QT_TRANSLATE_NOOP("GraphQuantity", "vx (m/s)");
    case GraphQuantity::Vy:
        return QT_TRANSLATE_NOOP("GraphQuantity", "vy (m/s)");
    case GraphQuantity::Speed:
        return QT_TRANSLATE_NOOP("GraphQuantity", "speed (m/s)");
    case GraphQuantity::AngularVelocity:
        return QT_TRANSLATE_NOOP("GraphQuantity", "ω (rad/s)");
    case GraphQuantity::Px:
        return QT_TRANSLATE_NOOP("GraphQuantity", "px (kg·m/s)");
    case GraphQuantity::Py:
        return QT_TRANSLATE_NOOP("GraphQuantity", "py (kg·m/s)");
    case GraphQuantity::Kinetic:
        return QT_TRANSLATE_NOOP("GraphQuantity", "kinetic energy (J)");
    case GraphQuantity::Potential:
        return QT_TRANSLATE_NOOP("GraphQuantity", "potential energy (J)");
    case GraphQuantity::Energy:
        return QT_TRANSLATE_NOOP("GraphQuantity", "kinetic + potential (J)");
    case GraphQuantity::Collisions:
        return QT_TRANSLATE_NOOP("GraphQuantity", "collisions");
    case GraphQuantity::WorldKinetic:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world kinetic energy (J)");
    case GraphQuantity::WorldPotential:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world potential energy (J)");
    case GraphQuantity::WorldElastic:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world elastic energy (J)");
    case GraphQuantity::WorldTotal:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world total energy (J)");
    case GraphQuantity::WorldPx:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world px (kg·m/s)");
    case GraphQuantity::WorldPy:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world py (kg·m/s)");
    case GraphQuantity::WorldAngularMomentum:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world angular momentum (kg·m²/s)");
    case GraphQuantity::WorldCollisions:
        return QT_TRANSLATE_NOOP("GraphQuantity", "world collisions");
    }
    return "";
}

} // namespace

const std::vector<GraphQuantity>& graphQuantities()
{
    static const std::vector<GraphQuantity> all = {
        GraphQuantity::Time,         GraphQuantity::X,
        GraphQuantity::Y,            GraphQuantity::Angle,
        GraphQuantity::Vx,           GraphQuantity::Vy,
        GraphQuantity::Speed,        GraphQuantity::AngularVelocity,
        GraphQuantity::Px,           GraphQuantity::Py,
        GraphQuantity::Kinetic,      GraphQuantity::Potential,
        GraphQuantity::Energy,       GraphQuantity::Collisions,
        GraphQuantity::WorldKinetic, GraphQuantity::WorldPotential,
        GraphQuantity::WorldElastic, GraphQuantity::WorldTotal,
        GraphQuantity::WorldPx,      GraphQuantity::WorldPy,
        GraphQuantity::WorldAngularMomentum, GraphQuantity::WorldCollisions,
    };
    return all;
}

bool isWorldQuantity(GraphQuantity quantity) { return quantity >= GraphQuantity::WorldKinetic; }

QString quantityLabel(GraphQuantity quantity)
{
    return QCoreApplication::translate("GraphQuantity", labelText(quantity));
}

QString csvColumn(GraphQuantity quantity)
{
    switch (quantity) {
    case GraphQuantity::Time: return QStringLiteral("time");
    case GraphQuantity::X: return QStringLiteral("x");
    case GraphQuantity::Y: return QStringLiteral("y");
    case GraphQuantity::Angle: return QStringLiteral("angle");
    case GraphQuantity::Vx: return QStringLiteral("vx");
    case GraphQuantity::Vy: return QStringLiteral("vy");
    case GraphQuantity::Speed: return QStringLiteral("speed");
    case GraphQuantity::AngularVelocity: return QStringLiteral("angularVelocity");
    case GraphQuantity::Px: return QStringLiteral("px");
    case GraphQuantity::Py: return QStringLiteral("py");
    case GraphQuantity::Kinetic: return QStringLiteral("kinetic");
    case GraphQuantity::Potential: return QStringLiteral("potential");
    case GraphQuantity::Energy: return QStringLiteral("energy");
    case GraphQuantity::Collisions: return QStringLiteral("collisions");
    case GraphQuantity::WorldKinetic: return QStringLiteral("worldKinetic");
    case GraphQuantity::WorldPotential: return QStringLiteral("worldPotential");
    case GraphQuantity::WorldElastic: return QStringLiteral("worldElastic");
    case GraphQuantity::WorldTotal: return QStringLiteral("worldTotal");
    case GraphQuantity::WorldPx: return QStringLiteral("worldPx");
    case GraphQuantity::WorldPy: return QStringLiteral("worldPy");
    case GraphQuantity::WorldAngularMomentum: return QStringLiteral("worldAngularMomentum");
    case GraphQuantity::WorldCollisions: return QStringLiteral("worldCollisions");
    }
    return {};
}

double valueOf(GraphQuantity quantity, const GraphRecord& r)
{
    switch (quantity) {
    case GraphQuantity::Time: return r.time;
    case GraphQuantity::X: return r.body.position.x();
    case GraphQuantity::Y: return r.body.position.y();
    case GraphQuantity::Angle: return r.body.angle;
    case GraphQuantity::Vx: return r.body.velocity.x();
    case GraphQuantity::Vy: return r.body.velocity.y();
    case GraphQuantity::Speed: return r.body.speed;
    case GraphQuantity::AngularVelocity: return r.body.angularVelocity;
    case GraphQuantity::Px: return r.body.momentum.x();
    case GraphQuantity::Py: return r.body.momentum.y();
    case GraphQuantity::Kinetic: return r.body.kinetic;
    case GraphQuantity::Potential: return r.body.potential;
    case GraphQuantity::Energy: return r.body.kinetic + r.body.potential;
    case GraphQuantity::Collisions: return static_cast<double>(r.body.collisions);
    case GraphQuantity::WorldKinetic: return r.totals.energy.kinetic;
    case GraphQuantity::WorldPotential: return r.totals.energy.potential;
    case GraphQuantity::WorldElastic: return r.totals.energy.elastic;
    case GraphQuantity::WorldTotal: return r.totals.energy.total();
    case GraphQuantity::WorldPx: return r.totals.momentum.x();
    case GraphQuantity::WorldPy: return r.totals.momentum.y();
    case GraphQuantity::WorldAngularMomentum: return r.totals.angularMomentum;
    case GraphQuantity::WorldCollisions: return static_cast<double>(r.totals.collisions);
    }
    return 0;
}

} // namespace impetus::view
