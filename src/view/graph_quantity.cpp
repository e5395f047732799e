#include "view/graph_quantity.h"

#include <QCoreApplication>

namespace impetus::view {

namespace {

/// tr() for this file's free functions.
QString tr(const char* text) { return QCoreApplication::translate("GraphQuantity", text); }

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
    switch (quantity) {
    case GraphQuantity::Time: return tr("t (s)");
    case GraphQuantity::X: return tr("x (m)");
    case GraphQuantity::Y: return tr("y (m)");
    case GraphQuantity::Angle: return tr("angle (rad)");
    case GraphQuantity::Vx: return tr("vx (m/s)");
    case GraphQuantity::Vy: return tr("vy (m/s)");
    case GraphQuantity::Speed: return tr("speed (m/s)");
    case GraphQuantity::AngularVelocity: return tr("ω (rad/s)");
    case GraphQuantity::Px: return tr("px (kg·m/s)");
    case GraphQuantity::Py: return tr("py (kg·m/s)");
    case GraphQuantity::Kinetic: return tr("kinetic energy (J)");
    case GraphQuantity::Potential: return tr("potential energy (J)");
    case GraphQuantity::Energy: return tr("kinetic + potential (J)");
    case GraphQuantity::Collisions: return tr("collisions");
    case GraphQuantity::WorldKinetic: return tr("world kinetic energy (J)");
    case GraphQuantity::WorldPotential: return tr("world potential energy (J)");
    case GraphQuantity::WorldElastic: return tr("world elastic energy (J)");
    case GraphQuantity::WorldTotal: return tr("world total energy (J)");
    case GraphQuantity::WorldPx: return tr("world px (kg·m/s)");
    case GraphQuantity::WorldPy: return tr("world py (kg·m/s)");
    case GraphQuantity::WorldAngularMomentum: return tr("world angular momentum (kg·m²/s)");
    case GraphQuantity::WorldCollisions: return tr("world collisions");
    }
    return {};
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
