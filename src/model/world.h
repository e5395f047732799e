#pragma once
/// \file world.h
/// Everything a scene holds: settings, bodies, springs and joints. A plain value: copy it with `=`
/// to reset, undo or compare runs.

#include "model/body.h"
#include "model/constants.h"
#include "model/joint.h"
#include "model/lesson.h"
#include "model/scalar.h"
#include "model/soft_grid.h"
#include "model/spring.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace impetus::model {

/// The three integrators of scene key `world.integrator`.
enum class IntegratorKind {
    Euler, ///< "euler": explicit (forward) Euler, first order
    SemiImplicitEuler, ///< "semi-implicit-euler": symplectic Euler, first order, bounded energy
    Rk4, ///< "rk4": classical fourth-order Runge–Kutta
};

/// The scene-file name of an integrator ("euler", "semi-implicit-euler", "rk4").
std::string_view integratorName(IntegratorKind kind);

/// Parses a scene-file integrator name; nullopt when unknown.
std::optional<IntegratorKind> integratorFromName(std::string_view name);

/// World settings (scene key `world`).
struct WorldSettings {
    Vec2 gravity = Vec2(0, -constants::kStandardGravity); ///< m/s²
    IntegratorKind integrator = IntegratorKind::Rk4; ///< the integrator of the smooth forces
    Scalar timeStep = constants::kDefaultTimeStep; ///< the fixed step h, s (1/240 s)
    Scalar drag = 0; ///< Stokes coefficient b in F = −b·v on every dynamic body, N·s/m
    bool operator==(const WorldSettings&) const = default; ///< memberwise equality
};

/// Two convex pieces that were in contact, or close enough for a speculative contact, at the end
/// of the last step. Remembered so that the next step can warm-start its solver with these
/// impulses and tell a contact that begins from one that goes on.
/// One cache line each: a large world writes and reads thousands of them every step.
struct alignas(64) ContactRecord {
    BodyId bodyA; ///< bodyA.index < bodyB.index
    std::uint32_t pieceA = 0; ///< convex piece of body A (0 for round shapes)
    BodyId bodyB; ///< the other body
    std::uint32_t pieceB = 0; ///< convex piece of body B (0 for round shapes)
    std::uint8_t pointCount = 0; ///< 1 or 2
    bool touching = false; ///< really touching (not only speculative)
    std::array<std::uint32_t, 2> featureIds{}; ///< which features touched, per point
    std::array<Scalar, 2> normalImpulses{}; ///< accumulated normal impulse per point, N·s
    std::array<Scalar, 2> tangentImpulses{}; ///< accumulated friction impulse per point, N·s
    bool operator==(const ContactRecord&) const = default; ///< memberwise equality
};
static_assert(sizeof(ContactRecord) == 64);

/// A whole scene and its simulated time.
struct World {
    WorldSettings settings; ///< gravity, integrator, time step, drag
    std::vector<Body> bodies; ///< in scene order; BodyId indexes them
    std::vector<Spring> springs; ///< in scene order
    std::vector<Joint> joints; ///< in scene order
    /// The scene's lesson (scene key `lesson`), if it is an exercise: what students may change and
    /// the questions. The engine ignores it.
    std::optional<Lesson> lesson;
    Scalar time = 0; ///< simulated time since the scene was loaded, s
    std::int64_t stepCount = 0; ///< fixed steps taken since the scene was loaded
    std::int64_t collisionCount = 0; ///< contact-begin events since the scene was loaded
    /// Contacts at the end of the last step, sorted by (bodyA, pieceA, bodyB, pieceB).
    std::vector<ContactRecord> contacts;
    /// The grids of the soft bodies, sorted by body index: runtime state, not part of the scene
    /// file. Built and kept up to date by controller::prepareSoftBodies (Simulation::step calls it).
    std::vector<SoftGrid> softBodies;

    bool operator==(const World&) const = default; ///< memberwise equality

    /// The id of the body called `name`, if any.
    std::optional<BodyId> findBody(std::string_view name) const;

    /// The body with id `id`. Precondition: id.index < bodies.size().
    Body& body(BodyId id) { return bodies[id.index]; }
    const Body& body(BodyId id) const { return bodies[id.index]; } ///< see the overload above

    /// The grid of soft body `id`, or nullptr when it has none (rigid, or not prepared yet).
    const SoftGrid* softGrid(BodyId id) const;
};

} // namespace impetus::model
