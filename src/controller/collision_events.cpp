#include "controller/collision_events.h"

#include "model/constants.h"

#include <algorithm>
#include <utility>

namespace impetus::controller {

namespace {

using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

/// A contact touches when a point is within the touch distance, or when any impulse acted on it
/// this step (a speculative contact that stopped a fast body a hair before the surface touched).
bool isTouching(const ContactConstraint& c)
{
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
        if (p.separation <= constants::kTouchDistance || p.normalImpulse > 0 || p.impactImpulse > 0)
            return true;
    }
    return false;
}

} // namespace

void updateCollisionState(model::World& world, const ContactSolver& contacts, std::span<const SolverBody> bodies,
                          const std::vector<model::ContactRecord>& previous, CollisionScratch& scratch,
                          std::vector<CollisionEvent>& events)
{
    // Body pairs that touched at the end of the last step. Records are sorted by pieces, which is
    // body-pair order unless a concave body has several pieces: sort only then.
    std::vector<BodyPair>& before = scratch.touchedBefore;
    before.clear();
    for (const model::ContactRecord& r : previous) {
        if (r.touching)
            before.emplace_back(r.bodyA.index, r.bodyB.index);
    }
    if (!std::is_sorted(before.begin(), before.end()))
        std::sort(before.begin(), before.end());
    before.erase(std::unique(before.begin(), before.end()), before.end());

    for (model::Body& body : world.bodies)
        body.colliding = false;

    const std::vector<ContactConstraint>& constraints = contacts.constraints();
    std::vector<model::ContactRecord>& records = world.contacts;
    records.clear();
    records.reserve(constraints.size());
    const std::size_t firstEvent = events.size();
    // Constraints come in the same order as `before` (again, up to concave bodies): a cursor finds
    // most pairs, and a binary search the rest.
    std::size_t cursor = 0;
    // Constraints come in broad-phase order, by ownerA first, so the events already opened for
    // body A are the last ones. Should that order ever not hold, every event is searched.
    bool ownersInOrder = true;
    std::uint32_t lastOwnerA = 0;
    for (const ContactConstraint& c : constraints) {
        ownersInOrder = ownersInOrder && c.ownerA >= lastOwnerA;
        lastOwnerA = c.ownerA;
        model::ContactRecord& r = records.emplace_back();
        r.bodyA = model::BodyId{c.ownerA};
        r.pieceA = c.pieceA;
        r.bodyB = model::BodyId{c.ownerB};
        r.pieceB = c.pieceB;
        r.pointCount = static_cast<std::uint8_t>(c.pointCount);
        for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i) {
            r.featureIds[i] = c.points[i].id;
            r.normalImpulses[i] = c.points[i].normalImpulse;
            r.tangentImpulses[i] = c.points[i].tangentImpulse;
        }
        r.touching = isTouching(c);
        if (!r.touching)
            continue;
        world.bodies[c.ownerA].colliding = true;
        world.bodies[c.ownerB].colliding = true;

        const BodyPair pair(c.ownerA, c.ownerB);
        while (cursor < before.size() && before[cursor] < pair)
            ++cursor;
        const bool touchedBefore = (cursor < before.size() && before[cursor] == pair) ||
                                   std::binary_search(before.begin(), before.begin() + static_cast<std::ptrdiff_t>(cursor), pair);
        if (touchedBefore)
            continue;
        // A pair of bodies may touch through several pieces (a soft body through many ellipses):
        // the first touching one opens the event and the others add their impulse to it.
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = bodies[c.bodyB];
        const ContactConstraintPoint& p = c.points[0];
        Scalar impulse = 0;
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& q = c.points[static_cast<std::size_t>(i)];
            impulse += q.normalImpulse + q.impactImpulse;
        }
        CollisionEvent* open = nullptr;
        for (std::size_t k = events.size(); k > firstEvent; --k) {
            CollisionEvent& e = events[k - 1];
            if (e.bodyA.index == c.ownerA && e.bodyB.index == c.ownerB) {
                open = &e;
                break;
            }
            if (ownersInOrder && e.bodyA.index != c.ownerA)
                break;
        }
        if (open) {
            open->normalImpulse += impulse;
            continue;
        }
        CollisionEvent e;
        e.time = world.time;
        e.bodyA = model::BodyId{c.ownerA};
        e.bodyB = model::BodyId{c.ownerB};
        e.point = p.point;
        e.normal = c.normal;
        e.normalImpulse = impulse;
        e.normalSpeedBefore = p.impacted ? p.approachVelocity : p.startNormalVelocity;
        const Vec2 rA = e.point - a.position;
        const Vec2 rB = e.point - b.position;
        e.normalSpeedAfter =
            (b.velocity + cross(b.angularVelocity, rB) - a.velocity - cross(a.angularVelocity, rA)).dot(c.normal);
        events.push_back(e);
    }

    for (std::size_t k = firstEvent; k < events.size(); ++k) {
        ++world.bodies[events[k].bodyA.index].collisionCount;
        ++world.bodies[events[k].bodyB.index].collisionCount;
        ++world.collisionCount;
    }
}

} // namespace impetus::controller
