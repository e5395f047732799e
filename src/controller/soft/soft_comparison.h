#pragma once
/// \file soft_comparison.h
/// Seed S1's accuracy question made visible: the same scene with one body rigid and soft, and how
/// far apart the two centre-of-mass paths drift over time.

#include "model/body.h"
#include "model/scalar.h"
#include "model/world.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace impetus::controller {

/// The two centres of mass at one sample time.
struct RigidSoftSample {
    Scalar time = 0; ///< s
    Vec2 rigid = Vec2::Zero(); ///< centre of mass in the rigid run, m
    Vec2 soft = Vec2::Zero(); ///< centre of mass in the soft run, m
    Scalar distance = 0; ///< |soft − rigid|, m
};

/// The deviation of the soft run from the rigid one.
struct RigidSoftComparison {
    std::vector<RigidSoftSample> samples; ///< at t = 0 and every sampleEvery steps
    Scalar rmsDistance = 0; ///< root mean square of the samples' distances, m
    Scalar maxDistance = 0; ///< largest sample distance, m
    Scalar maxDistanceTime = 0; ///< when it happened, s
    Scalar ellipsesPerSquareMeter = 0; ///< density of the soft run's grid, 1/m²
    std::size_t ellipses = 0; ///< ellipses in the soft run's grid
};

/// Runs `world` twice for `steps` steps, once with `body` rigid (its `soft` removed) and once soft
/// (its own `soft` settings, or the defaults when it has none, or `softSettings` when given), and
/// compares the body's centre-of-mass paths every `sampleEvery` steps (≥ 1). The other bodies
/// keep their own mode in both runs. Precondition: body.index < world.bodies.size().
RigidSoftComparison compareRigidSoft(const model::World& world, model::BodyId body, std::int64_t steps,
                                     std::int64_t sampleEvery,
                                     std::optional<model::SoftSettings> softSettings = std::nullopt);

} // namespace impetus::controller
