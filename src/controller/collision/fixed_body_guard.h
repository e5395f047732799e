#pragma once
/// \file fixed_body_guard.h
/// The last line of continuous collision: no centre of a moving body passes into a fixed body.

#include "controller/collision/broad_phase.h"
#include "controller/transform.h"
#include "model/body.h"
#include "model/world.h"

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::controller {

/// A body the guard put back: its centre, or one of its soft body's ellipses, had entered a fixed body.
struct KeptOut {
    std::uint32_t body = 0; ///< the body put back (World::bodies index; a soft body for its ellipse)
    std::uint32_t fixedBody = 0; ///< the fixed body it had entered (World::bodies index)
    bool operator==(const KeptOut&) const = default; ///< memberwise equality
};

/// Keeps the centre of every dynamic body, and of every soft body's ellipse, out of the fixed
/// bodies (docs/physics.md, "The fixed-body guard").
///
/// The contact solve keeps bodies out of walls by itself: speculative contacts, impacts and the
/// position passes. What it cannot always do is hold a light body that a joint to a far heavier
/// one drives into a wall, spinning it up within a step beyond what the step's contacts, built at
/// its start, follow (soak seeds 2087, 4062 and others: a 3 kg ellipse on a rod to a chain of
/// 82 kg and 4.9 t at 78 m/s went through a wall 2 m thick in two steps). Box2D v3 keeps such
/// bodies in with continuous collision against static shapes, and, where a shape starts a step
/// overlapping one already, with a sweep of its centroid alone. This is that sweep: after each
/// substep, a centre whose path from the substep's start to its end enters a fixed body's piece
/// (seen in that body's own frame, so that a moving fixed body counts too) is put back where the
/// path enters, and the body's turn is cut at the same fraction of the substep. Its velocity
/// stays: the next substep's contacts, with the body half in the wall, stop it there, and the
/// position passes push it out.
///
/// A centre that starts the substep inside a fixed piece is left alone (a body drawn into the
/// ground), and so is every path that meets no fixed piece: in every scene the solve holds, the
/// guard does nothing. It moves bodies only, so it adds no kinetic energy; the height or a
/// spring's stretch it changes the energy ledger books under position correction. A path with a
/// number that is not finite is skipped, and so is a fixed body whose pose has one.
class FixedBodyGuard {
public:
    /// Puts back each entry of `end` whose centre's path from `start` enters a fixed body's piece.
    /// `start` and `end` are the world's state lists (force_model.h, stateCount: the bodies, then
    /// the soft grids' ellipses) at the start and the end of a substep; fixed bodies' entries give
    /// their poses at both. Returns how many entries it put back.
    int keepOut(const model::World& world, std::span<const model::BodyState> start, std::span<model::BodyState> end);

    /// The bodies the last keepOut put back, each with the fixed body it had entered, once per pair,
    /// in the order of the state list.
    const std::vector<KeptOut>& keptOut() const { return m_keptOut; }

private:
    std::vector<BroadPhaseProxy> m_proxies; ///< the fixed bodies' boxes, then the paths' boxes
    std::vector<BroadPhaseProxy> m_paths; ///< the paths' boxes, gathered beside the fixed bodies'
    std::vector<ProxyPair> m_pairs;
    /// Per fixed body (its proxy's index), its poses at the substep's start and end.
    struct FixedPose {
        Transform start;
        Transform end;
    };
    std::vector<FixedPose> m_fixedPoses;
    /// An entry whose path enters a fixed body: the earliest such entry of its path.
    struct Hit {
        std::uint32_t entry = 0; ///< in the state list
        std::uint32_t fixed = 0; ///< the fixed body's proxy (m_proxies, m_fixedPoses)
        Scalar fraction = 0; ///< of the way from the substep's start to its end
        Vec2 from = Vec2::Zero(); ///< the path's start, in the fixed body's frame at the start
        Vec2 to = Vec2::Zero(); ///< the path's end, in the fixed body's frame at the end
    };
    std::vector<Hit> m_hits;
    std::vector<KeptOut> m_keptOut;
    BroadPhase m_broadPhase; ///< its own cache, apart from the contacts' broad phase
};

namespace detail {

/// Where the segment from `from` to `to` (in the body frame of `body`) first enters the body's
/// shape, as a fraction of the way in (0, 1]; a negative number when it starts inside, or meets
/// the shape nowhere on the way.
Scalar pathEntry(const model::Body& body, const Vec2& from, const Vec2& to);

} // namespace detail

} // namespace impetus::controller
