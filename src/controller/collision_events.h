#pragma once
/// \file collision_events.h
/// What the contacts of a step mean to a student: which bodies are colliding (drawn red), which
/// contacts began (counted), and a log of each new collision.

#include "controller/dynamics/contact_solver.h"
#include "controller/task_pair.h"
#include "model/world.h"

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace impetus::controller {

/// A contact between two bodies that began in this step: they were not touching at the end of
/// the last step and are now.
struct CollisionEvent {
    Scalar time = 0; ///< simulated time at the end of the step, s
    model::BodyId bodyA; ///< bodyA.index < bodyB.index
    model::BodyId bodyB; ///< the other body
    Vec2 point = Vec2::Zero(); ///< a contact point (the first of the first touching pair of pieces), m
    Vec2 normal = Vec2::Zero(); ///< unit, from A to B
    Scalar normalImpulse = 0; ///< total normal impulse between the two bodies this step, N·s
    Scalar normalSpeedBefore = 0; ///< relative normal velocity before (< 0: approaching), m/s
    Scalar normalSpeedAfter = 0; ///< relative normal velocity after the step (> 0: separating), m/s
};

/// Buffers updateCollisionState reuses from call to call, so that a large world's step allocates
/// nothing. Holds no state that matters between calls.
struct CollisionScratch {
    /// Body pairs (A < B) that touched at the end of the last step, sorted.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> touchedBefore;
    /// Per body: 1 when it touches another at the end of this step.
    std::vector<std::uint8_t> colliding;
    /// The events each half of the records found, in record order.
    std::array<std::vector<CollisionEvent>, 2> found;
};

/// Sets each body's `colliding` flag from this step's contact records and counts contact-begin
/// events (per pair of bodies, whatever the number of pieces or points) into the bodies' and the
/// world's collision counts. world.contacts must already hold this step's records, one per
/// constraint of `contacts` in the same order (ContactSolver::swapRecords). `bodies` hold the
/// velocities after the solve. `previous` are the last step's records.
/// Appends the events of the step, in pair order, to `events`. With `tasks`, a large world's
/// flags are written from two threads (the same results).
void updateCollisionState(model::World& world, const ContactSolver& contacts, std::span<const SolverBody> bodies,
                          const std::vector<model::ContactRecord>& previous, CollisionScratch& scratch,
                          std::vector<CollisionEvent>& events, TaskPair* tasks = nullptr);

} // namespace impetus::controller
