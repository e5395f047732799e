#pragma once
/// \file peer_engines.h
/// The same scene in Impetus, Box2D and Chipmunk, behind one small interface, so that the
/// comparison steps each engine the same way and reads back the same poses.

#include "controller/simulation.h"
#include "model/scalar.h"
#include "model/world.h"

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
/// `pivot` (m) at `angularVelocity` (rad/s, counter-clockwise); 0 means they stay put. Box2D and
/// Chipmunk do it with one kinematic body carrying every fixed shape; Impetus gives its fixed
/// bodies (which move with their own velocity) the rotation's velocity before each step
/// (model::spinFixedBodies).
struct Turning {
    Vec2 pivot = Vec2::Zero();
    Scalar angularVelocity = 0;
};

/// One engine holding one scene.
class Engine {
public:
    virtual ~Engine() = default;
    /// "Impetus", "Box2D" or "Chipmunk".
    virtual std::string name() const = 0;
    /// One fixed step of the scene's time step.
    virtual void step() = 0;
    /// The pose of every body of the model::World the engine was built from, in its order.
    virtual std::vector<Pose> poses() const = 0;
};

/// Impetus itself: a copy of the world stepped by controller::Simulation with the given solver
/// settings. Keeps the sum of every step's profile.
class ImpetusEngine final : public Engine {
public:
    ImpetusEngine(const model::World& world, const Turning& turning, const controller::SolverSettings& settings);
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

/// Box2D's velocity and position iterations per step: its documented defaults (b2World::Step).
inline constexpr int kBox2dVelocityIterations = 8;
inline constexpr int kBox2dPositionIterations = 3;

/// Chipmunk's solver iterations per step: its default (cpSpaceSetIterations).
inline constexpr int kChipmunkIterations = 10;

/// Chipmunk's allowed overlap, m. Its default, 0.1, is meant for scenes measured in pixels; in a
/// scene measured in metres it would let boxes sink 10 cm into each other. Box2D's linear slop
/// (b2_linearSlop, 5 mm) is the comparable setting, so Chipmunk gets the same.
inline constexpr Scalar kChipmunkCollisionSlop = 0.005;

/// Box2D 2.4 built from `world`: bodies at their centres of mass with the same angles,
/// velocities, masses and moments of inertia (Impetus's, set with SetMassData), one fixture per
/// convex piece (shrunk by Box2D's 1 cm polygon skin so that the rounded shape has the same
/// faces, and split into fans of at most 8 vertices, Box2D's limit), friction and restitution per
/// body. Sleeping is off. Throws std::invalid_argument for an ellipse (Box2D has none).
std::unique_ptr<Engine> makeBox2dEngine(const model::World& world, const Turning& turning);

/// Chipmunk 7 built from `world` in the same way. Chipmunk multiplies the two shapes' friction
/// (and elasticity) where Box2D takes the geometric mean (and the larger restitution), so each
/// shape gets √μ and √e: the products are then √(μa·μb), Box2D's friction exactly, and the same
/// restitution whenever both bodies share one, as in every benchmark scene. Sleeping stays off
/// (the sleep time threshold is left at its default, infinity). Throws for an ellipse.
std::unique_ptr<Engine> makeChipmunkEngine(const model::World& world, const Turning& turning);

/// Lets Chipmunk print its start-up banner now, before any output of ours.
void announceChipmunk();

/// The Box2D library's own version (b2_version). Box2D 2.4.1 still reports 2.4.0 there.
std::string box2dVersion();

/// The Chipmunk library's version, e.g. "7.0.3".
std::string chipmunkVersion();

} // namespace impetus::bench
