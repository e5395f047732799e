#pragma once
/// \file box2d_v3_engine.h
/// Box2D v3.2 as a peer of the engine comparison, built from the same model::World as the others
/// (peer_engines.h). Only box2d_v3_engine.cpp sees v3's headers: they are <box2d/...> like
/// Box2D 2.4's, and v3's C types share names with 2.4's C++ classes (b2Vec2, b2BodyDef, ...).

#include "peer_engines.h"

#include "model/scalar.h"
#include "model/world.h"

#include <memory>
#include <string>
#include <vector>

namespace impetus::bench {

/// v3's substeps per step at its recommended settings: its samples and its own benchmark step
/// 1/60 s in 4 substeps (b2World_Step's subStepCount).
inline constexpr int kBox2dV3Substeps = 4;

/// v3's own timing of the phases of its steps (b2Profile, read with b2World_GetProfile after each
/// step), summed over the steps, ms. Indented names are parts of the one above.
struct Box2dV3Profile {
    double step = 0; ///< the whole b2World_Step
    double pairs = 0; ///< broad phase: new pairs, contacts begun
    double collide = 0; ///< narrow phase: contact manifolds
    double solve = 0; ///< the solver and what follows it, of which:
    double solverSetup = 0; ///<   awake bodies, colours and constraint blocks laid out
    double constraints = 0; ///<   the substepped solver stages, of which:
    double prepareConstraints = 0; ///<     contact and joint constraints built
    double integrateVelocities = 0; ///<     forces integrated, per substep
    double warmStart = 0; ///<     last step's impulses applied, per substep
    double solveImpulses = 0; ///<     the soft-step velocity iteration, per substep
    double integratePositions = 0; ///<     positions from velocities, per substep
    double relaxImpulses = 0; ///<     the relax iteration (no bias), per substep
    double applyRestitution = 0; ///<     restitution, once a step
    double storeImpulses = 0; ///<     impulses kept for the next step
    double transforms = 0; ///<   bodies finalised: transforms, bounding boxes, islands
    double refit = 0; ///<   broad-phase trees refitted to the moved boxes
    double bullets = 0; ///<   continuous collision of fast bodies
};

/// Box2D v3 built from `world`, stepped at `timeStep` (s) in `substeps` substeps, on one thread
/// (workerCount 1) with sleeping off. Bodies at their centres of mass with the same angles,
/// velocities, masses and moments of inertia (Impetus's, b2Body_SetMassData); one shape per
/// convex piece, with radius 0 (v3 collides sharp polygons, so no skin to take off as for 2.4),
/// split into fans of at most 8 vertices; friction and restitution per body (v3 mixes them as
/// 2.4 does). A fixed body with a velocity is a kinematic body; the turning container is one
/// kinematic body. Pins are revolute joints, rods rigid distance joints, and the bodies they join
/// still collide (as in Impetus); joints between fixed bodies are left out (jointActs). Everything else, continuous collision included, is at v3's
/// defaults. Throws std::invalid_argument for an ellipse, for a polygon v3 cannot take as a hull
/// and for a joint on a wall of the turning container.
class Box2dV3Engine final : public Engine {
public:
    Box2dV3Engine(const model::World& world, const Turning& turning, Scalar timeStep, int substeps);
    ~Box2dV3Engine() override;
    Box2dV3Engine(const Box2dV3Engine&) = delete;
    Box2dV3Engine& operator=(const Box2dV3Engine&) = delete;

    std::string name() const override { return "Box2D v3"; }
    void step() override;
    std::vector<Pose> poses() const override;
    /// The sum over all steps so far of v3's b2Profile, ms.
    const Box2dV3Profile& profileSum() const { return m_profileSum; }

private:
    /// v3's world and body ids, behind a pointer so that this header needs none of v3's.
    struct State;
    std::unique_ptr<State> m_state;
    Box2dV3Profile m_profileSum;
};

/// The version v3 reports (b2GetVersion), e.g. "3.2.0".
std::string box2dV3Version();

/// The vector instructions v3 was built for: "AVX2" or "SSE2" (its BOX2D_AVX2 option).
std::string box2dV3Instructions();

} // namespace impetus::bench
