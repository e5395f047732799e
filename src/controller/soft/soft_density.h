#pragma once
/// \file soft_density.h
/// Soft mode's `"auto"` density: the finest grid this machine can step in real time.

#include "model/scalar.h"
#include "model/world.h"

namespace impetus::controller {

/// Wall time, ms, of simulating one display frame (kSoftFrameTime of simulated time) of `world`
/// with every soft body whose density is `"auto"` built at `ellipsesPerSquareMeter`: the fastest
/// of kSoftAutoTrialFrames frames, stepped on a copy (the world is not changed).
double measureSoftFrameCost(const model::World& world, Scalar ellipsesPerSquareMeter);

/// The highest density of kSoftAutoDensities (64 … 1024 per m²) whose frame cost stays within
/// kSoftFrameBudgetFraction of a frame on this machine, measured lowest first and stopping at the
/// first that does not fit; the lowest when none fits. All `"auto"` bodies of the world share the
/// choice, since they share the frame. It depends on the machine and its load, so tests that must
/// be reproducible use fixed densities.
Scalar chooseAutoDensity(const model::World& world);

} // namespace impetus::controller
