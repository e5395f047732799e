#include "peer_engines.h"

#include "model/example_scenes.h"

#include <box2d/box2d.h>
#include <chipmunk.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <variant>

namespace impetus::bench {

namespace {

// ---- Box2D -----------------------------------------------------------------------------------

b2Vec2 toBox2d(const Vec2& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }

/// The piece moved inwards by Box2D's polygon skin. Box2D 2.4 rounds every polygon by
/// b2_polygonRadius (1 cm) and collides the rounded shape, so an unshrunk 1 m box would act as a
/// 1.02 m one: boxes built exactly touching would start 2 cm deep in each other and the pyramid
/// would be pushed apart. Each vertex moves along its two edges' normals n₁, n₂ by the miter
/// v − r·(n₁ + n₂)/(1 + n₁·n₂), which moves every edge inwards by exactly r; the rounded result
/// then has Impetus's faces (its corners are rounded by 1 cm).
std::vector<Vec2> shrunkBySkin(const std::vector<Vec2>& piece)
{
    const Scalar r = b2_polygonRadius;
    const std::size_t n = piece.size();
    const auto outwardNormal = [&](std::size_t i) {
        const Vec2 edge = piece[(i + 1) % n] - piece[i];
        return Vec2(Vec2(edge.y(), -edge.x()).normalized());
    };
    std::vector<Vec2> shrunk;
    shrunk.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 before = outwardNormal((i + n - 1) % n);
        const Vec2 after = outwardNormal(i);
        shrunk.push_back(piece[i] - r * (before + after) / (1 + before.dot(after)));
    }
    return shrunk;
}

class Box2dEngine final : public Engine {
public:
    Box2dEngine(const model::World& world, const Turning& turning, Scalar timeStep)
        : m_world(std::make_unique<b2World>(toBox2d(world.settings.gravity)))
        , m_timeStep(static_cast<float>(timeStep))
        , m_pivot(turning.pivot)
    {
        // Sleeping off everywhere: a body at rest still costs its full share of every step, in
        // every engine, so that the figures compare the work of simulating, not of skipping it.
        m_world->SetAllowSleeping(false);
        if (turning.angularVelocity != 0) {
            b2BodyDef def;
            def.type = b2_kinematicBody;
            def.position = toBox2d(turning.pivot);
            def.angularVelocity = static_cast<float>(turning.angularVelocity);
            def.allowSleep = false;
            m_container = m_world->CreateBody(&def);
        }
        for (const model::Body& body : world.bodies) {
            rejectEllipse(body);
            m_start.push_back(Pose{body.state.position, body.state.angle});
            if (body.fixed && m_container != nullptr) {
                addFixtures(m_container, body, containerPlacement(body, turning.pivot));
                m_bodies.push_back(nullptr);
                continue;
            }
            b2BodyDef def;
            def.type = !body.fixed ? b2_dynamicBody : isKinematic(body) ? b2_kinematicBody : b2_staticBody;
            def.position = toBox2d(body.state.position);
            def.angle = static_cast<float>(body.state.angle);
            def.linearVelocity = toBox2d(body.state.velocity);
            def.angularVelocity = static_cast<float>(body.state.angularVelocity);
            def.allowSleep = false;
            b2Body* created = m_world->CreateBody(&def);
            addFixtures(created, body, ownPlacement());
            if (!body.fixed) {
                // Impetus's own mass and moment, not Box2D's float recomputation from the density.
                b2MassData mass;
                mass.mass = static_cast<float>(body.mass);
                mass.center = b2Vec2(0, 0);
                mass.I = static_cast<float>(body.inertia);
                created->SetMassData(&mass);
            }
            m_bodies.push_back(created);
        }
        for (const model::Joint& joint : world.joints) {
            if (jointActs(world, joint))
                addJoint(joint);
        }
    }

    std::string name() const override { return "Box2D 2.4"; }

    void step() override { m_world->Step(m_timeStep, kBox2dVelocityIterations, kBox2dPositionIterations); }

    std::vector<Pose> poses() const override
    {
        std::vector<Pose> result;
        result.reserve(m_bodies.size());
        for (std::size_t i = 0; i < m_bodies.size(); ++i) {
            if (const b2Body* body = m_bodies[i]) {
                const b2Vec2 p = body->GetPosition();
                result.push_back(Pose{Vec2(p.x, p.y), body->GetAngle()});
            } else {
                const b2Vec2 p = m_container->GetPosition();
                result.push_back(wallPose(m_start[i], m_pivot, Vec2(p.x, p.y), m_container->GetAngle()));
            }
        }
        return result;
    }

private:
    /// The engine body of Impetus body `id`; a joint on a wall of the container is refused.
    b2Body* jointBody(model::BodyId id) const
    {
        if (m_bodies[id.index] == nullptr)
            throw std::invalid_argument("a joint on a wall of the turning container is not supported");
        return m_bodies[id.index];
    }

    /// A pin as a revolute joint, a rod as a distance joint held at its length (no spring). A
    /// joint to the world holds on to a static body at the origin, whose frame is the world's.
    void addJoint(const model::Joint& joint)
    {
        b2Body* a = jointBody(joint.bodyA);
        b2Body* b = nullptr;
        if (joint.bodyB) {
            b = jointBody(*joint.bodyB);
        } else {
            if (m_ground == nullptr) {
                b2BodyDef def;
                m_ground = m_world->CreateBody(&def);
            }
            b = m_ground;
        }
        if (joint.type == model::JointType::Pin) {
            b2RevoluteJointDef def;
            def.bodyA = a;
            def.bodyB = b;
            def.localAnchorA = toBox2d(joint.anchorA);
            def.localAnchorB = toBox2d(joint.anchorB);
            def.referenceAngle = b->GetAngle() - a->GetAngle();
            def.collideConnected = true;
            m_world->CreateJoint(&def);
            return;
        }
        b2DistanceJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.localAnchorA = toBox2d(joint.anchorA);
        def.localAnchorB = toBox2d(joint.anchorB);
        def.length = static_cast<float>(joint.length);
        def.minLength = def.length;
        def.maxLength = def.length;
        def.stiffness = 0; // rigid
        def.damping = 0;
        def.collideConnected = true;
        m_world->CreateJoint(&def);
    }

    void addFixtures(b2Body* target, const model::Body& body, const ShapePlacement& place)
    {
        b2FixtureDef def;
        def.density = static_cast<float>(body.density());
        def.friction = static_cast<float>(body.material.friction);
        def.restitution = static_cast<float>(body.material.restitution);
        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            b2CircleShape shape;
            shape.m_p = toBox2d(place(Vec2::Zero()));
            shape.m_radius = static_cast<float>(circle->radius);
            def.shape = &shape;
            target->CreateFixture(&def);
            return;
        }
        for (const auto& piece : body.geometry.convexPieces) {
            for (const auto& polygon : splitIntoFans(shrunkBySkin(piece), b2_maxPolygonVertices)) {
                std::vector<b2Vec2> points;
                for (const Vec2& v : polygon)
                    points.push_back(toBox2d(place(v)));
                b2PolygonShape shape;
                shape.Set(points.data(), static_cast<int32>(points.size()));
                def.shape = &shape;
                target->CreateFixture(&def);
            }
        }
    }

    std::unique_ptr<b2World> m_world;
    float m_timeStep;
    Vec2 m_pivot;
    b2Body* m_container = nullptr; ///< the turning container, when the scene turns
    b2Body* m_ground = nullptr; ///< what joints to the world hold on to, once there is one
    std::vector<b2Body*> m_bodies; ///< per Impetus body; null for a wall on the container
    std::vector<Pose> m_start; ///< per Impetus body, for the walls
};

// ---- Chipmunk --------------------------------------------------------------------------------

cpVect toChipmunk(const Vec2& v) { return cpv(v.x(), v.y()); }

class ChipmunkEngine final : public Engine {
public:
    ChipmunkEngine(const model::World& world, const Turning& turning, Scalar timeStep)
        : m_space(cpSpaceNew())
        , m_timeStep(timeStep)
        , m_pivot(turning.pivot)
    {
        cpSpaceSetGravity(m_space, toChipmunk(world.settings.gravity));
        cpSpaceSetIterations(m_space, kChipmunkIterations);
        cpSpaceSetCollisionSlop(m_space, kChipmunkCollisionSlop);
        // The sleep time threshold stays at its default, infinity: sleeping off, as in Box2D.
        if (turning.angularVelocity != 0) {
            m_container = addBody(cpBodyNewKinematic());
            cpBodySetPosition(m_container, toChipmunk(turning.pivot));
            cpBodySetAngularVelocity(m_container, turning.angularVelocity);
        }
        for (const model::Body& body : world.bodies) {
            rejectEllipse(body);
            m_start.push_back(Pose{body.state.position, body.state.angle});
            if (body.fixed && m_container != nullptr) {
                addShapes(m_container, body, containerPlacement(body, turning.pivot));
                m_bodies.push_back(nullptr);
                continue;
            }
            cpBody* created = addBody(!body.fixed           ? cpBodyNew(body.mass, body.inertia)
                                      : isKinematic(body) ? cpBodyNewKinematic()
                                                          : cpBodyNewStatic());
            // Pose first: a static body's shapes are indexed where the body is when they are added.
            cpBodySetPosition(created, toChipmunk(body.state.position));
            cpBodySetAngle(created, body.state.angle);
            if (!body.fixed || isKinematic(body)) {
                cpBodySetVelocity(created, toChipmunk(body.state.velocity));
                cpBodySetAngularVelocity(created, body.state.angularVelocity);
            }
            addShapes(created, body, ownPlacement());
            m_bodies.push_back(created);
        }
        for (const model::Joint& joint : world.joints) {
            if (jointActs(world, joint))
                addJoint(joint);
        }
    }

    ~ChipmunkEngine() override
    {
        // cpSpaceFree leaves the bodies, shapes and constraints that were added to it to their owner.
        cpSpaceFree(m_space);
        for (cpConstraint* constraint : m_constraints)
            cpConstraintFree(constraint);
        for (cpShape* shape : m_shapes)
            cpShapeFree(shape);
        for (cpBody* body : m_ownedBodies)
            cpBodyFree(body);
    }

    ChipmunkEngine(const ChipmunkEngine&) = delete;
    ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;

    std::string name() const override { return "Chipmunk"; }

    void step() override { cpSpaceStep(m_space, m_timeStep); }

    std::vector<Pose> poses() const override
    {
        std::vector<Pose> result;
        result.reserve(m_bodies.size());
        for (std::size_t i = 0; i < m_bodies.size(); ++i) {
            if (const cpBody* body = m_bodies[i]) {
                const cpVect p = cpBodyGetPosition(body);
                result.push_back(Pose{Vec2(p.x, p.y), cpBodyGetAngle(body)});
            } else {
                const cpVect p = cpBodyGetPosition(m_container);
                result.push_back(wallPose(m_start[i], m_pivot, Vec2(p.x, p.y), cpBodyGetAngle(m_container)));
            }
        }
        return result;
    }

private:
    cpBody* addBody(cpBody* body)
    {
        m_ownedBodies.push_back(body);
        return cpSpaceAddBody(m_space, body);
    }

    /// The engine body of Impetus body `id`; a joint on a wall of the container is refused.
    cpBody* jointBody(model::BodyId id) const
    {
        if (m_bodies[id.index] == nullptr)
            throw std::invalid_argument("a joint on a wall of the turning container is not supported");
        return m_bodies[id.index];
    }

    /// A pin as a pivot joint, a rod as a pin joint (Chipmunk's rigid distance) set to the rod's
    /// length. A joint to the world holds on to the space's static body, whose frame is the
    /// world's. Constraints let their bodies collide by default, as Impetus does.
    void addJoint(const model::Joint& joint)
    {
        cpBody* a = jointBody(joint.bodyA);
        cpBody* b = joint.bodyB ? jointBody(*joint.bodyB) : cpSpaceGetStaticBody(m_space);
        const cpVect anchorA = toChipmunk(joint.anchorA);
        const cpVect anchorB = toChipmunk(joint.anchorB);
        cpConstraint* constraint = nullptr;
        if (joint.type == model::JointType::Pin) {
            constraint = cpPivotJointNew2(a, b, anchorA, anchorB);
        } else {
            constraint = cpPinJointNew(a, b, anchorA, anchorB);
            cpPinJointSetDist(constraint, joint.length);
        }
        m_constraints.push_back(cpSpaceAddConstraint(m_space, constraint));
    }

    void addShapes(cpBody* target, const model::Body& body, const ShapePlacement& place)
    {
        // Friction and elasticity multiply in Chipmunk: √μ per shape gives μ for two alike.
        const cpFloat friction = std::sqrt(body.material.friction);
        const cpFloat elasticity = std::sqrt(body.material.restitution);
        std::vector<cpShape*> created;
        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            created.push_back(cpCircleShapeNew(target, circle->radius, toChipmunk(place(Vec2::Zero()))));
        } else {
            for (const auto& piece : body.geometry.convexPieces) {
                std::vector<cpVect> vertices;
                for (const Vec2& v : piece)
                    vertices.push_back(toChipmunk(place(v)));
                created.push_back(cpPolyShapeNew(target, static_cast<int>(vertices.size()), vertices.data(),
                                                 cpTransformIdentity, 0.0));
            }
        }
        for (cpShape* shape : created) {
            cpShapeSetFriction(shape, friction);
            cpShapeSetElasticity(shape, elasticity);
            m_shapes.push_back(cpSpaceAddShape(m_space, shape));
        }
    }

    cpSpace* m_space;
    cpFloat m_timeStep;
    Vec2 m_pivot;
    cpBody* m_container = nullptr; ///< the turning container, when the scene turns
    std::vector<cpBody*> m_bodies; ///< per Impetus body; null for a wall on the container
    std::vector<Pose> m_start; ///< per Impetus body, for the walls
    std::vector<cpBody*> m_ownedBodies;
    std::vector<cpShape*> m_shapes;
    std::vector<cpConstraint*> m_constraints;
};

} // namespace

// ---- Impetus ---------------------------------------------------------------------------------

ImpetusEngine::ImpetusEngine(const model::World& world, const Turning& turning,
                             const controller::SolverSettings& settings, Scalar timeStep)
    : m_world(world)
    , m_turning(turning)
    , m_simulation(settings)
{
    m_world.settings.timeStep = timeStep;
}

void ImpetusEngine::step()
{
    if (m_turning.angularVelocity != 0)
        model::spinFixedBodies(m_world, m_turning.pivot, m_turning.angularVelocity);
    m_simulation.step(m_world);
    const controller::StepProfile& last = m_simulation.profile();
    m_profileSum.broadMs += last.broadMs;
    m_profileSum.narrowMs += last.narrowMs;
    m_profileSum.integrateMs += last.integrateMs;
    m_profileSum.solveMs += last.solveMs;
    m_profileSum.prepareMs += last.prepareMs;
    m_profileSum.impactsMs += last.impactsMs;
    m_profileSum.velocityMs += last.velocityMs;
    m_profileSum.positionMs += last.positionMs;
    m_profileSum.eventsMs += last.eventsMs;
    m_profileSum.totalMs += last.totalMs;
    m_profileSum.contacts += last.contacts;
    m_profileSum.batchLanes += last.batchLanes;
    m_profileSum.impacts += last.impacts;
    m_profileSum.substeps += last.substeps;
    m_profileSum.collisionPasses += last.collisionPasses;
}

std::vector<Pose> ImpetusEngine::poses() const
{
    std::vector<Pose> result;
    result.reserve(m_world.bodies.size());
    for (const model::Body& body : m_world.bodies)
        result.push_back(Pose{body.state.position, body.state.angle});
    return result;
}

void announceChipmunk()
{
    // Chipmunk prints a banner on stdout when the first space is made (and a warning that this
    // build has its debug checks on); making that happen first keeps it out of the tables.
    cpSpaceFree(cpSpaceNew());
}

std::unique_ptr<Engine> makeBox2dEngine(const model::World& world, const Turning& turning, Scalar timeStep)
{
    return std::make_unique<Box2dEngine>(world, turning, timeStep);
}

std::unique_ptr<Engine> makeChipmunkEngine(const model::World& world, const Turning& turning, Scalar timeStep)
{
    return std::make_unique<ChipmunkEngine>(world, turning, timeStep);
}

std::string box2dVersion()
{
    return std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
           std::to_string(b2_version.revision);
}

std::string chipmunkVersion() { return cpVersionString; }

// ---- What the adapters share ------------------------------------------------------------------

ShapePlacement ownPlacement()
{
    return [](const Vec2& p) { return p; };
}

ShapePlacement containerPlacement(const model::Body& body, const Vec2& pivot)
{
    const Vec2 position = body.state.position;
    const Scalar angle = body.state.angle;
    return [position, angle, pivot](const Vec2& p) { return Vec2(position + rotate(p, angle) - pivot); };
}

Pose wallPose(const Pose& start, const Vec2& pivot, const Vec2& containerPosition, Scalar containerAngle)
{
    return Pose{containerPosition + rotate(Vec2(start.position - pivot), containerAngle), start.angle + containerAngle};
}

void rejectEllipse(const model::Body& body)
{
    if (std::holds_alternative<model::Ellipse>(body.shape))
        throw std::invalid_argument("body \"" + body.name + "\" is an ellipse, which the peer engines do not have");
}

bool jointActs(const model::World& world, const model::Joint& joint)
{
    return !world.body(joint.bodyA).fixed || (joint.bodyB && !world.body(*joint.bodyB).fixed);
}

bool isKinematic(const model::Body& body)
{
    return body.fixed && (body.state.velocity != Vec2::Zero() || body.state.angularVelocity != 0);
}

std::vector<std::vector<Vec2>> splitIntoFans(const std::vector<Vec2>& piece, std::size_t limit)
{
    if (piece.size() <= limit)
        return {piece};
    std::vector<std::vector<Vec2>> fans;
    for (std::size_t k = 1; k + 1 < piece.size(); k += limit - 2) {
        std::vector<Vec2>& fan = fans.emplace_back();
        fan.push_back(piece.front());
        for (std::size_t j = k; j < piece.size() && j <= k + limit - 2; ++j)
            fan.push_back(piece[j]);
    }
    return fans;
}

} // namespace impetus::bench
