#pragma once
/// \file peer_engines.h
/// The same scene in Impetus, Box2D 2.4, Chipmunk and Box2D v3 (box2d_v3_engine.h), behind one
/// small interface, so that the comparison steps each engine the same way and reads back the same
/// poses. No header of a peer engine is included here: Box2D 2.4 and v3 both name theirs
/// <box2d/...>, and each adapter's .cpp alone sees its own.

#include "controller/simulation.h"
#include "model/scalar.h"
#include "model/world.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace impetus::bench {

/// Where a body is at the end of a run: its centre of mass (m) and its angle (rad).
struct Pose {
    Vec2 position = Vec2::Zero();
    Scalar angle = 0;
};

/// Motion a scene needs beyond what its bodies do by themselves: the fixed bodies turn about
/// `pivot` (m) at `angularVelocity` (rad/s, counter-clockwise); 0 means they stay put (or move
/// with the velocity the scene gave them). The peers do it with one kinematic body carrying every
/// fixed shape; Impetus gives its fixed bodies (which move with their own velocity) the
/// rotation's velocity before each step (model::spinFixedBodies).
struct Turning {
    Vec2 pivot = Vec2::Zero();
    Scalar angularVelocity = 0;
};

/// One engine holding one scene.
class Engine {
public:
    virtual ~Engine() = default;
    /// "Impetus", "Box2D 2.4", "Chipmunk" or "Box2D v3".
    virtual std::string name() const = 0;
    /// One fixed step of the time step the engine was built with.
    virtual void step() = 0;
    /// The pose of every body of the model::World the engine was built from, in its order.
    virtual std::vector<Pose> poses() const = 0;
};

/// Impetus itself: a copy of the world stepped by controller::Simulation with the given solver
/// settings, at `timeStep` (s; the world's own world.settings.timeStep for its default). Keeps the
/// sum of every step's profile.
class ImpetusEngine final : public Engine {
public:
    ImpetusEngine(const model::World& world, const Turning& turning, const controller::SolverSettings& settings,
                  Scalar timeStep);
    std::string name() const override { return "Impetus"; }
    void step() override;
    std::vector<Pose> poses() const override;
    /// The sum over all steps so far of controller::Simulation::profile(), ms.
    const controller::StepProfile& profileSum() const { return m_profileSum; }

private:
    model::World m_world;
    Turning m_turning;
    controller::Simulation m_simulation;
    controller::StepProfile m_profileSum;
};

/// The step Box2D 2.4, Chipmunk and Box2D v3 are made for, s: each one's documentation and
/// samples step at 60 Hz (v3 then splits it into substeps itself).
inline constexpr Scalar kPeerRecommendedStep = 1.0 / 60.0;

/// Box2D's velocity and position iterations per step: its documented defaults (b2World::Step).
inline constexpr int kBox2dVelocityIterations = 8;
inline constexpr int kBox2dPositionIterations = 3;

/// Chipmunk's solver iterations per step: its default (cpSpaceSetIterations).
inline constexpr int kChipmunkIterations = 10;

/// Chipmunk's allowed overlap, m. Its default, 0.1, is meant for scenes measured in pixels; in a
/// scene measured in metres it would let boxes sink 10 cm into each other. Box2D's linear slop
/// (b2_linearSlop, 5 mm) is the comparable setting, so Chipmunk gets the same.
inline constexpr Scalar kChipmunkCollisionSlop = 0.005;

/// Box2D 2.4 built from `world`, stepped at `timeStep` (s): bodies at their centres of mass with
/// the same angles, velocities, masses and moments of inertia (Impetus's, set with SetMassData),
/// one fixture per convex piece (shrunk by Box2D's 1 cm polygon skin so that the rounded shape has
/// the same faces, and split into fans of at most 8 vertices, Box2D's limit), friction and
/// restitution per body. A fixed body with a velocity is a kinematic body. Pins are revolute
/// joints, rods rigid distance joints, and the bodies they join still collide (as in Impetus);
/// joints between fixed bodies are left out (jointActs). Sleeping is off. Throws std::invalid_argument for an ellipse (Box2D has none) and for a joint
/// on a wall of the turning container.
std::unique_ptr<Engine> makeBox2dEngine(const model::World& world, const Turning& turning, Scalar timeStep);

/// Chipmunk 7 built from `world` in the same way. Chipmunk multiplies the two shapes' friction
/// (and elasticity) where Box2D takes the geometric mean (and the larger restitution), so each
/// shape gets √μ and √e: the products are then √(μa·μb), Box2D's friction exactly, and the same
/// restitution whenever both bodies share one, as in every benchmark scene. Pins are pivot joints,
/// rods pin joints (Chipmunk's rigid distance). Sleeping stays off (the sleep time threshold is
/// left at its default, infinity). Throws as makeBox2dEngine does.
std::unique_ptr<Engine> makeChipmunkEngine(const model::World& world, const Turning& turning, Scalar timeStep);

/// Lets Chipmunk print its start-up banner now, before any output of ours.
void announceChipmunk();

/// The Box2D library's own version (b2_version). Box2D 2.4.1 still reports 2.4.0 there.
std::string box2dVersion();

/// The Chipmunk library's version, e.g. "7.0.3".
std::string chipmunkVersion();

// ---- What the peers' adapters share ------------------------------------------------------------

/// Maps a point of a body's own frame (centre of mass at the origin) to the frame of the engine
/// body that carries the shape: the identity for a body of its own, or the body's pose relative to
/// the pivot for a wall riding on the turning container.
using ShapePlacement = std::function<Vec2(const Vec2&)>;

/// The placement of a body's shapes on an engine body of its own: the identity.
ShapePlacement ownPlacement();

/// The placement of a fixed body's shapes on a container body whose origin is the pivot (m) and
/// whose angle is 0 at the start.
ShapePlacement containerPlacement(const model::Body& body, const Vec2& pivot);

/// The pose of a wall on the turning container, from the wall's pose at the start and the
/// container's pose now: the start pose about the pivot, turned by the container's angle (rad)
/// and carried to its position (m).
Pose wallPose(const Pose& start, const Vec2& pivot, const Vec2& containerPosition, Scalar containerAngle);

/// Throws std::invalid_argument when `body` is an ellipse, which no peer has.
void rejectEllipse(const model::Body& body);

/// True for a fixed body that moves with a velocity of its own (m/s or rad/s not zero): Impetus
/// moves such a body with that velocity whatever hits it, which is what the peers' kinematic
/// bodies do.
bool isKinematic(const model::Body& body);

/// False for a joint that cannot act: both its bodies are fixed (or it holds a fixed body to the
/// world). The peers are not given such joints (Chipmunk aborts on one: its constraint has no
/// mass to act on); Impetus solves nothing for them either.
bool jointActs(const model::World& world, const model::Joint& joint);

/// A convex piece (counter-clockwise) as convex polygons of at most `limit` vertices: fans from
/// vertex 0 that share an edge with the next. Every subset of a convex polygon's vertices, in
/// order, is convex. Precondition: limit ≥ 3.
std::vector<std::vector<Vec2>> splitIntoFans(const std::vector<Vec2>& piece, std::size_t limit);

} // namespace impetus::bench
