// Box2D v3 built from a model::World. This is the one file that includes v3's headers (from the
// peer's include directory, see bench/CMakeLists.txt); it includes none of Box2D 2.4's.
//
// v3's C types share their names with Box2D 2.4's C++ classes (b2Vec2, b2BodyDef, b2Profile,
// ...), which peer_engines.cpp uses. Two different classes of one name in one program are harmless
// only while no symbol of external linkage is made from them, so this file keeps its helpers in an
// anonymous namespace and instantiates no template over such a type (no std::vector<b2Vec2>:
// std::vector<b2BodyId> is fine, 2.4 has no b2BodyId).

#include "box2d_v3_engine.h"

#include <box2d/box2d.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#ifndef IMPETUS_BOX2D_V3_AVX2
#error "bench/CMakeLists.txt defines IMPETUS_BOX2D_V3_AVX2 as v3's BOX2D_AVX2 option (0 or 1)"
#endif

namespace impetus::bench {

namespace {

b2Vec2 toV3(const Vec2& v) { return b2Vec2{static_cast<float>(v.x()), static_cast<float>(v.y())}; }

/// The rotation by `angle` (rad), from the double-precision cosine and sine. v3's b2MakeRot uses
/// its own polynomial approximation, which would turn the start poses by up to its error.
b2Rot rotationOf(Scalar angle)
{
    return b2Rot{static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

/// The angle of a rotation, rad, with the library's atan2 rather than v3's approximate b2Atan2.
Scalar angleOf(b2Rot q) { return std::atan2(static_cast<Scalar>(q.s), static_cast<Scalar>(q.c)); }

/// Creates the shapes of `body` on `target`, placed by `place`: a circle, or one polygon per
/// convex piece (fans of at most B2_MAX_POLYGON_VERTICES). The body's mass is set apart, so the
/// shapes do not update it.
void addShapes(b2BodyId target, const model::Body& body, const ShapePlacement& place)
{
    b2ShapeDef def = b2DefaultShapeDef();
    def.density = static_cast<float>(body.density());
    def.material.friction = static_cast<float>(body.material.friction);
    def.material.restitution = static_cast<float>(body.material.restitution);
    def.updateBodyMass = false;
    if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
        const b2Circle shape{toV3(place(Vec2::Zero())), static_cast<float>(circle->radius)};
        b2CreateCircleShape(target, &def, &shape);
        return;
    }
    for (const auto& piece : body.geometry.convexPieces) {
        for (const auto& polygon : splitIntoFans(piece, B2_MAX_POLYGON_VERTICES)) {
            b2Vec2 points[B2_MAX_POLYGON_VERTICES];
            for (std::size_t i = 0; i < polygon.size(); ++i)
                points[i] = toV3(place(polygon[i]));
            const b2Hull hull = b2ComputeHull(points, static_cast<int>(polygon.size()));
            // v3 takes a polygon only as a hull, which drops points closer than its linear slop
            // (5 mm) or on a straight edge; an empty hull means none was left to take.
            if (hull.count == 0)
                throw std::invalid_argument("body \"" + body.name + "\" has a piece Box2D v3 cannot take as a hull");
            const b2Polygon shape = b2MakePolygon(&hull, 0.0f);
            b2CreatePolygonShape(target, &def, &shape);
        }
    }
}

void addProfile(Box2dV3Profile& sum, const b2Profile& p)
{
    sum.step += p.step;
    sum.pairs += p.pairs;
    sum.collide += p.collide;
    sum.solve += p.solve;
    sum.solverSetup += p.solverSetup;
    sum.constraints += p.constraints;
    sum.prepareConstraints += p.prepareConstraints;
    sum.integrateVelocities += p.integrateVelocities;
    sum.warmStart += p.warmStart;
    sum.solveImpulses += p.solveImpulses;
    sum.integratePositions += p.integratePositions;
    sum.relaxImpulses += p.relaxImpulses;
    sum.applyRestitution += p.applyRestitution;
    sum.storeImpulses += p.storeImpulses;
    sum.transforms += p.transforms;
    sum.refit += p.refit;
    sum.bullets += p.bullets;
}

} // namespace

struct Box2dV3Engine::State {
    b2WorldId world = b2_nullWorldId;
    float timeStep = 0; ///< s
    int substeps = 1;
    Vec2 pivot = Vec2::Zero();
    bool hasContainer = false;
    b2BodyId container = b2_nullBodyId; ///< the turning container, when the scene turns
    bool hasGround = false;
    b2BodyId ground = b2_nullBodyId; ///< what joints to the world hold on to, once there is one
    std::vector<b2BodyId> bodies; ///< per Impetus body; meaningless for a wall on the container
    std::vector<bool> onContainer; ///< per Impetus body
    std::vector<Pose> start; ///< per Impetus body, for the walls

    /// The engine body of Impetus body `id`; a joint on a wall of the container is refused.
    b2BodyId jointBody(model::BodyId id) const
    {
        if (onContainer[id.index])
            throw std::invalid_argument("a joint on a wall of the turning container is not supported");
        return bodies[id.index];
    }

    /// A pin as a revolute joint, a rod as a rigid distance joint (no spring) at the rod's length.
    /// A joint to the world holds on to a static body at the origin, whose frame is the world's.
    /// Joint stiffness and damping stay at v3's defaults.
    void addJoint(const model::Joint& joint)
    {
        const b2BodyId a = jointBody(joint.bodyA);
        b2BodyId b = b2_nullBodyId;
        if (joint.bodyB) {
            b = jointBody(*joint.bodyB);
        } else {
            if (!hasGround) {
                const b2BodyDef def = b2DefaultBodyDef();
                ground = b2CreateBody(world, &def);
                hasGround = true;
            }
            b = ground;
        }
        if (joint.type == model::JointType::Pin) {
            b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
            def.base.bodyIdA = a;
            def.base.bodyIdB = b;
            def.base.localFrameA.p = toV3(joint.anchorA);
            def.base.localFrameB.p = toV3(joint.anchorB);
            def.base.collideConnected = true;
            b2CreateRevoluteJoint(world, &def);
            return;
        }
        b2DistanceJointDef def = b2DefaultDistanceJointDef();
        def.base.bodyIdA = a;
        def.base.bodyIdB = b;
        def.base.localFrameA.p = toV3(joint.anchorA);
        def.base.localFrameB.p = toV3(joint.anchorB);
        def.base.collideConnected = true;
        def.length = static_cast<float>(joint.length);
        def.enableSpring = false; // rigid
        b2CreateDistanceJoint(world, &def);
    }
};

Box2dV3Engine::Box2dV3Engine(const model::World& world, const Turning& turning, Scalar timeStep, int substeps)
    : m_state(std::make_unique<State>())
{
    State& s = *m_state;
    s.timeStep = static_cast<float>(timeStep);
    s.substeps = substeps;
    s.pivot = turning.pivot;

    b2WorldDef worldDef = b2DefaultWorldDef();
    worldDef.gravity = toV3(world.settings.gravity);
    // Sleeping off and one thread, as every engine here: a body at rest still costs its full
    // share of every step, and no engine gets a second core.
    worldDef.enableSleep = false;
    worldDef.workerCount = 1;
    s.world = b2CreateWorld(&worldDef);

    if (turning.angularVelocity != 0) {
        b2BodyDef def = b2DefaultBodyDef();
        def.type = b2_kinematicBody;
        def.position = toV3(turning.pivot);
        def.angularVelocity = static_cast<float>(turning.angularVelocity);
        def.enableSleep = false;
        s.container = b2CreateBody(s.world, &def);
        s.hasContainer = true;
    }
    s.bodies.reserve(world.bodies.size());
    for (const model::Body& body : world.bodies) {
        rejectEllipse(body);
        s.start.push_back(Pose{body.state.position, body.state.angle});
        if (body.fixed && s.hasContainer) {
            addShapes(s.container, body, containerPlacement(body, turning.pivot));
            s.bodies.push_back(s.container);
            s.onContainer.push_back(true);
            continue;
        }
        b2BodyDef def = b2DefaultBodyDef();
        def.type = !body.fixed ? b2_dynamicBody : isKinematic(body) ? b2_kinematicBody : b2_staticBody;
        def.position = toV3(body.state.position);
        def.rotation = rotationOf(body.state.angle);
        def.linearVelocity = toV3(body.state.velocity);
        def.angularVelocity = static_cast<float>(body.state.angularVelocity);
        def.enableSleep = false;
        const b2BodyId created = b2CreateBody(s.world, &def);
        addShapes(created, body, ownPlacement());
        if (!body.fixed) {
            // Impetus's own mass and moment about the centre of mass, which is the body's origin.
            b2MassData mass;
            mass.mass = static_cast<float>(body.mass);
            mass.center = b2Vec2{0.0f, 0.0f};
            mass.rotationalInertia = static_cast<float>(body.inertia);
            b2Body_SetMassData(created, mass);
        }
        s.bodies.push_back(created);
        s.onContainer.push_back(false);
    }
    for (const model::Joint& joint : world.joints) {
        if (jointActs(world, joint))
            s.addJoint(joint);
    }
}

Box2dV3Engine::~Box2dV3Engine() { b2DestroyWorld(m_state->world); }

void Box2dV3Engine::step()
{
    b2World_Step(m_state->world, m_state->timeStep, m_state->substeps);
    addProfile(m_profileSum, b2World_GetProfile(m_state->world));
}

std::vector<Pose> Box2dV3Engine::poses() const
{
    const State& s = *m_state;
    std::vector<Pose> result;
    result.reserve(s.bodies.size());
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const b2Vec2 p = b2Body_GetPosition(s.bodies[i]);
        const Vec2 position(p.x, p.y);
        const Scalar angle = angleOf(b2Body_GetRotation(s.bodies[i]));
        result.push_back(s.onContainer[i] ? wallPose(s.start[i], s.pivot, position, angle) : Pose{position, angle});
    }
    return result;
}

std::string box2dV3Version()
{
    const b2Version v = b2GetVersion();
    return std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.revision);
}

std::string box2dV3Instructions() { return IMPETUS_BOX2D_V3_AVX2 ? "AVX2" : "SSE2"; }

} // namespace impetus::bench
