#pragma once
/// \file step_sample.h
/// What the instruments record after every fixed step of a run: the trails' centres, the graphed
/// bodies' readouts and the world's totals. Taken on the step worker's thread, after each step,
/// so that a graph has every step even when the canvas shows only one state a frame.

#include "controller/body_readout.h"
#include "controller/diagnostics.h"
#include "controller/energy_ledger.h"
#include "model/world.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace impetus::view {

/// What to record after each step. An empty request records nothing (and costs nothing).
struct SampleRequest {
    bool centres = false; ///< every body's centre of mass and angle (trails, traced points)
    std::vector<std::uint32_t> bodies; ///< the bodies whose readout is recorded (graphs), by index
    bool totals = false; ///< the world's energies, momentum and collision count (graphs)
    /// The energy ledger's lines (the ledger chart): the steps are booked by cause while it is set.
    bool ledger = false;
    bool empty() const { return !centres && bodies.empty() && !totals && !ledger; }
    bool operator==(const SampleRequest&) const = default;
};

/// The world's totals after a step.
struct WorldTotals {
    controller::Energy energy; ///< J
    Vec2 momentum = Vec2::Zero(); ///< Σ m·v of the dynamic bodies, kg·m/s
    Scalar angularMomentum = 0; ///< about the origin, kg·m²/s
    std::int64_t collisions = 0; ///< contact-begin events since the scene was loaded
};

/// One body's readout in a step's record.
struct BodySample {
    std::uint32_t body = 0; ///< index into World::bodies
    controller::BodyReadout readout;
};

/// One step's record.
struct StepSample {
    std::int64_t step = 0; ///< World::stepCount after the step
    double time = 0; ///< World::time after the step, s
    std::vector<Vec2> centres; ///< per body (request.centres), m; empty otherwise
    /// Per body with the centres, rad: with them, where any point fixed on a body is (traced points).
    std::vector<double> angles;
    /// Per requested body that exists, in the request's order.
    std::vector<BodySample> bodies;
    WorldTotals totals; ///< meaningful with request.totals
    /// With request.ledger: the ledger after the step (its time is when it started, s).
    std::optional<controller::LedgerSample> ledger;
};

/// The record of `world` as `request` asks for it.
StepSample takeSample(const model::World& world, const SampleRequest& request);

} // namespace impetus::view
