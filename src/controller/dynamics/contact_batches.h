#pragma once
/// \file contact_batches.h
/// The velocity passes of a large world, several contacts at a time. The contacts are coloured so
/// that no two of one colour share a movable body; a batch holds kBatchLanes contacts of one
/// colour side by side (structure of arrays), and one sequence of vector instructions solves all
/// of them at once. Each lane does exactly the arithmetic a lone contact would, so the result does
/// not depend on the vector width the processor offers. See docs/physics.md, "Batches".

#include "model/constants.h"
#include "model/scalar.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace impetus::controller {

/// Contacts per batch: four doubles fill one 256-bit register.
inline constexpr int kBatchLanes = 4;

/// Batches the passes may solve side by side (BatchOrder::InPairs): each colour fills a whole
/// number of such pairs, so that two neighbouring batches never share a movable body.
inline constexpr std::size_t kBatchPair = 2;

/// kBatchLanes doubles, one per contact of a batch (GCC vector extension). The alignment is spelled
/// out: GCC otherwise reports 16 bytes for an alias of a vector type, so containers would not
/// align it, yet still uses aligned 256-bit loads on it.
using Lanes = Scalar __attribute__((vector_size(kBatchLanes * sizeof(Scalar)), aligned(kBatchLanes * sizeof(Scalar))));
/// A per-lane truth value: all bits set (−1) for true, 0 for false.
using LaneMask = std::int64_t
    __attribute__((vector_size(kBatchLanes * sizeof(std::int64_t)), aligned(kBatchLanes * sizeof(std::int64_t))));

/// A body as the batched velocity passes see it: its velocity and inverse mass properties, one
/// cache line each. The passes work on copies of the solver bodies laid out by half (see
/// ContactSolver): each thread's bodies lie together in memory, apart from the other thread's.
struct alignas(64) BatchBody {
    Vec2 velocity = Vec2::Zero(); ///< m/s
    Scalar angularVelocity = 0; ///< rad/s
    Scalar invMass = 0; ///< 1/kg
    Scalar invInertia = 0; ///< 1/(kg·m²)
    /// A contact force acted on the body in this substep's passes (set by
    /// ContactSolver::finishVelocities, handed on as SolverBody::hadContactForce). Not read by
    /// the passes.
    bool contactForce = false;
};

/// One contact point of every lane. The arms are the lever arms' cross products with the
/// contact's normal and tangent, r × n and r × t (m), which is all the angular terms need.
struct BatchPoint {
    Lanes normalArmA{}; ///< rA × n, m
    Lanes normalArmB{}; ///< rB × n, m
    Lanes tangentArmA{}; ///< rA × t, m
    Lanes tangentArmB{}; ///< rB × t, m
    Lanes normalMass{}; ///< 1/K along the normal, kg
    Lanes tangentMass{}; ///< 1/K along the tangent, kg
    Lanes normalImpulse{}; ///< accumulated, N·s (warm-started)
    Lanes tangentImpulse{}; ///< accumulated, N·s
    Lanes gapSpeed{}; ///< max(separation, 0)/h, m/s
};

/// kBatchLanes contacts of one colour. Every lane has two points: a one-point contact's second
/// point has no arms, no mass and a gap so large it can never become active, and a lane with no
/// contact (padding at the end of a colour) is such a contact between two bodies that cannot move.
struct ContactBatch {
    static_assert(alignof(Lanes) == sizeof(Lanes));
    // Kept small, as the passes stream through every batch eight times a step: the bodies' inverse
    // masses are read from the bodies, in the cache line that holds their velocities, and the 2×2
    // effective-mass matrix K and its inverse are computed from them and the arms.
    Lanes normalX{}; ///< unit normal from A to B
    Lanes normalY{};
    Lanes friction{}; ///< mixed μ
    LaneMask blockSolve{}; ///< both points may be solved together (K well conditioned)
    LaneMask acted{}; ///< an impulse acted on this lane's bodies this step
    std::array<BatchPoint, 2> points{};
    /// The bodies each lane reads its velocities from.
    std::array<const BatchBody*, kBatchLanes> bodyA{};
    std::array<const BatchBody*, kBatchLanes> bodyB{};
    /// Where each lane writes them back: the same body, or for a fixed body (whose velocity an
    /// impulse never changes) a scratch body, so that batches on two threads never write to one
    /// shared ground.
    std::array<BatchBody*, kBatchLanes> writeA{};
    std::array<BatchBody*, kBatchLanes> writeB{};
};

/// A body's pose as the batched position passes see it, with the cosine and sine of its angle kept
/// up to date as it turns. One cache line each.
struct alignas(64) BatchPose {
    Scalar x = 0; ///< centre of mass, m
    Scalar y = 0;
    Scalar angle = 0; ///< rad
    Scalar cosine = 1; ///< cos(angle)
    Scalar sine = 0; ///< sin(angle)
};

/// The same kBatchLanes contacts as a ContactBatch, as the position passes see them: the normal and
/// each point's two surface points in the bodies' own frames.
struct PositionBatch {
    Lanes localNormalX{}; ///< the normal in A's frame
    Lanes localNormalY{};
    Lanes invMassA{}; ///< 1/kg
    Lanes invInertiaA{}; ///< 1/(kg·m²)
    Lanes invMassB{};
    Lanes invInertiaB{};
    /// Each contact point's two surface points, in their bodies' frames.
    struct Anchors {
        Lanes ax{}; ///< A's surface point, A's frame, m
        Lanes ay{};
        Lanes bx{}; ///< B's surface point, B's frame, m
        Lanes by{};
    };
    std::array<Anchors, 2> anchors{};
    LaneMask secondPoint{}; ///< the lane's contact has a second point
    /// The linear position impulse the passes of this substep have applied, summed over its
    /// points, m·kg: what ContactSolver::measurePushes reads. Cleared by packLane and by
    /// ContactSolver::beginPositions where they will be measured (elsewhere they run on unread).
    Lanes pushX{};
    Lanes pushY{};
    /// Each lane's bodies, as indices into the poses; a fixed body writes to a scratch pose.
    std::array<std::uint32_t, kBatchLanes> readA{};
    std::array<std::uint32_t, kBatchLanes> readB{};
    std::array<std::uint32_t, kBatchLanes> writeA{};
    std::array<std::uint32_t, kBatchLanes> writeB{};
};

/// How the passes go through a colour's batches: one at a time, or two side by side, which a
/// processor with AVX-512 (32 vector registers, room for two batches' state) runs faster as their
/// two chains of dependent arithmetic overlap. Both give the same bits.
enum class BatchOrder { OneByOne, InPairs };

/// InPairs on a processor with AVX-512, else OneByOne. InPairs runs only where this gives it.
BatchOrder fastestBatchOrder();

/// The instructions the batch passes run with on this processor: "AVX-512" (two batches side by
/// side), "AVX2" or "SSE2", all with the same bits.
const char* batchInstructions();

/// Applies every lane's accumulated impulses to its bodies (warm starting).
void warmStartBatches(std::span<ContactBatch> batches);

/// One sequential-impulse pass over the batches in order: per lane, Coulomb friction at each
/// point (|jt| ≤ μ·jn of the last pass), then the normal impulses, as ContactSolver does for one
/// contact: two points together by enumerating the complementarity problem's active sets where
/// the block solve applies, else one point after the other. InPairs takes the batches two at a
/// time, which must then be a whole number of pairs, no pair sharing a movable body (each colour
/// laid out in whole pairs, as ContactSolver does).
void solveBatches(std::span<ContactBatch> batches, BatchOrder order = fastestBatchOrder());

/// One non-linear Gauss–Seidel pass over the batches in order, as ContactSolver::solvePositions
/// does for one contact: each point's separation is pushed towards −slop by moving the two bodies
/// along the normal, in proportion to their inverse masses. Returns the deepest separation seen
/// (≤ 0), m. InPairs asks of the batches what it asks in solveBatches.
Scalar solvePositionBatches(std::span<PositionBatch> batches, std::span<BatchPose> poses,
                            BatchOrder order = fastestBatchOrder());

} // namespace impetus::controller
