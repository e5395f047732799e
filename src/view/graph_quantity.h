#pragma once
/// \file graph_quantity.h
/// The quantities a graph can plot, with their names, units and CSV columns.

#include "controller/body_readout.h"
#include "view/step_sample.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace impetus::view {

/// What a graph plots on an axis: time, a quantity of its body, or a total of the world.
enum class GraphQuantity : std::uint8_t {
    Time, ///< t, s
    X, ///< centre of mass x, m
    Y, ///< centre of mass y, m
    Angle, ///< rad
    Vx, ///< m/s
    Vy, ///< m/s
    Speed, ///< |v|, m/s
    AngularVelocity, ///< ω, rad/s
    Px, ///< m·vx, kg·m/s
    Py, ///< m·vy, kg·m/s
    Kinetic, ///< the body's ½mv² + ½Iω², J
    Potential, ///< the body's −m·(g · x), J
    Energy, ///< the body's kinetic + potential, J
    Collisions, ///< the body's contact-begin events
    WorldKinetic, ///< J
    WorldPotential, ///< J
    WorldElastic, ///< J
    WorldTotal, ///< J
    WorldPx, ///< kg·m/s
    WorldPy, ///< kg·m/s
    WorldAngularMomentum, ///< about the origin, kg·m²/s
    WorldCollisions, ///< contact-begin events since the scene was loaded
};

/// Every quantity, in menu order.
const std::vector<GraphQuantity>& graphQuantities();

/// True for the world's totals (the body does not matter).
bool isWorldQuantity(GraphQuantity quantity);

/// The name with its unit, as the axis and the menus show it: "vy (m/s)".
QString quantityLabel(GraphQuantity quantity);

/// The CSV column: impetus-cli's name where it has the quantity ("time", "x", "vy",
/// "angularVelocity"), the summary's otherwise ("kinetic", "px", "collisions"; the world's totals
/// prefixed "world").
QString csvColumn(GraphQuantity quantity);

/// One step as a graph keeps it: its body's readout and the world's totals.
struct GraphRecord {
    std::int64_t step = 0; ///< World::stepCount
    double time = 0; ///< s
    controller::BodyReadout body;
    WorldTotals totals;
};

/// The value of `quantity` in `record`, in the unit of quantityLabel().
double valueOf(GraphQuantity quantity, const GraphRecord& record);

} // namespace impetus::view
