#include "controller/collision_events.h"

#include "model/constants.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <utility>

namespace impetus::controller {

namespace {

using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

} // namespace

void updateCollisionState(model::World& world, const ContactSolver& contacts, std::span<const SolverBody> bodies,
                          const std::vector<model::ContactRecord>& previous, CollisionScratch& scratch,
                          std::vector<CollisionEvent>& events, TaskPair* tasks)
{
    const std::vector<ContactConstraint>& constraints = contacts.constraints();
    const std::vector<model::ContactRecord>& records = world.contacts;
    const bool split = tasks && constraints.size() >= constants::kParallelMinConstraints;

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

    // Which bodies touch, gathered in a byte per body and written to the (large) Body records in
    // one pass at the end, rather than clearing every body's flag and then setting it again. Both
    // halves of a split walk may mark one body: the bytes are set with relaxed atomic stores.
    std::vector<std::uint8_t>& colliding = scratch.colliding;
    colliding.assign(world.bodies.size(), 0);

    // Walks records [begin, end), marking the touching bodies and appending the contacts that
    // began to `out`. Returns whether the records came by body A in order: only then are a body
    // pair's records all next to each other in body A's run, which the search for an open event
    // relies on to stop early, and which lets two halves that split between runs walk apart.
    const auto walk = [&](std::size_t begin, std::size_t end, std::vector<CollisionEvent>& out) {
        out.clear();
        if (begin == end)
            return true;
        // Records come in the same order as `before` (again, up to concave bodies): a cursor finds
        // most pairs, and a binary search the rest.
        const auto pairOf = [](const model::ContactRecord& r) { return BodyPair(r.bodyA.index, r.bodyB.index); };
        auto cursor = static_cast<std::size_t>(std::lower_bound(before.begin(), before.end(), pairOf(records[begin])) -
                                               before.begin());
        bool ownersInOrder = true;
        std::uint32_t lastOwnerA = records[begin].bodyA.index;
        for (std::size_t k = begin; k < end; ++k) {
            const model::ContactRecord& r = records[k];
            ownersInOrder = ownersInOrder && r.bodyA.index >= lastOwnerA;
            lastOwnerA = r.bodyA.index;
            if (!r.touching)
                continue;
            std::atomic_ref<std::uint8_t>(colliding[r.bodyA.index]).store(1, std::memory_order_relaxed);
            std::atomic_ref<std::uint8_t>(colliding[r.bodyB.index]).store(1, std::memory_order_relaxed);

            const BodyPair pair = pairOf(r);
            while (cursor < before.size() && before[cursor] < pair)
                ++cursor;
            const bool touchedBefore =
                (cursor < before.size() && before[cursor] == pair) ||
                std::binary_search(before.begin(), before.begin() + static_cast<std::ptrdiff_t>(cursor), pair);
            if (touchedBefore)
                continue;
            // A pair of bodies may touch through several pieces (a soft body through many ellipses):
            // the first touching one opens the event and the others add their impulse to it.
            const ContactConstraint& c = constraints[k];
            Scalar impulse = 0;
            for (std::size_t i = 0; i < r.pointCount; ++i)
                impulse += r.normalImpulses[i] + c.points[i].impactImpulse;
            CollisionEvent* open = nullptr;
            for (std::size_t e = out.size(); e > 0; --e) {
                CollisionEvent& event = out[e - 1];
                if (event.bodyA.index == c.ownerA && event.bodyB.index == c.ownerB) {
                    open = &event;
                    break;
                }
                if (ownersInOrder && event.bodyA.index != c.ownerA)
                    break;
            }
            if (open) {
                open->normalImpulse += impulse;
                continue;
            }
            const SolverBody& a = bodies[c.bodyA];
            const SolverBody& b = bodies[c.bodyB];
            const ContactConstraintPoint& p = c.points[0];
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
            out.push_back(e);
        }
        return ownersInOrder;
    };

    // A large world walks in two halves, cut where body A changes, so that no body pair's records
    // are in both. Should the records not come by body A after all, the walk is done again whole.
    std::array<std::vector<CollisionEvent>, 2>& found = scratch.found;
    const std::size_t count = records.size();
    bool walked = false;
    if (split) {
        std::size_t middle = count / 2;
        while (middle > 0 && middle < count && records[middle].bodyA == records[middle - 1].bodyA)
            ++middle;
        std::array<bool, 2> inOrder{};
        tasks->run([&](int part) {
            inOrder[static_cast<std::size_t>(part)] = part == 0 ? walk(0, middle, found[0]) : walk(middle, count, found[1]);
        });
        walked = inOrder[0] && inOrder[1] &&
                 (middle == 0 || middle == count || records[middle - 1].bodyA.index <= records[middle].bodyA.index);
    }
    if (!walked) {
        walk(0, count, found[0]);
        found[1].clear();
    }
    const std::size_t firstEvent = events.size();
    for (const std::vector<CollisionEvent>& half : found)
        events.insert(events.end(), half.begin(), half.end());

    inHalves(split ? tasks : nullptr, world.bodies.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            world.bodies[i].colliding = colliding[i] != 0;
    });
    for (std::size_t k = firstEvent; k < events.size(); ++k) {
        ++world.bodies[events[k].bodyA.index].collisionCount;
        ++world.bodies[events[k].bodyB.index].collisionCount;
        ++world.collisionCount;
    }
}

} // namespace impetus::controller
