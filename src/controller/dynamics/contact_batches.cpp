#include "controller/dynamics/contact_batches.h"
#include "controller/dynamics/prefetch.h"
#include "controller/dynamics/small_turn.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace impetus::controller {

namespace {

/// The velocities of one side (A or B) of every lane, and its bodies' inverse mass properties.
struct LaneVelocities {
    Lanes x{};
    Lanes y{};
    Lanes angular{};
    Lanes invMass{};
    Lanes invInertia{};
};

// Loading and storing go lane by lane: the bodies lie anywhere in memory. No two lanes of a batch
// share a movable body, so the stores never overwrite one another. (Loading whole 256-bit rows and
// transposing them was tried and was slower.)
[[gnu::always_inline]] inline LaneVelocities load(const std::array<const BatchBody*, kBatchLanes>& bodies)
{
    LaneVelocities v;
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        const BatchBody& body = *bodies[static_cast<std::size_t>(lane)];
        v.x[lane] = body.velocity.x();
        v.y[lane] = body.velocity.y();
        v.angular[lane] = body.angularVelocity;
        v.invMass[lane] = body.invMass;
        v.invInertia[lane] = body.invInertia;
    }
    return v;
}

[[gnu::always_inline]] inline void store(const std::array<BatchBody*, kBatchLanes>& bodies, const LaneVelocities& v)
{
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        BatchBody& body = *bodies[static_cast<std::size_t>(lane)];
        body.velocity = Vec2(v.x[lane], v.y[lane]);
        body.angularVelocity = v.angular[lane];
    }
}

[[gnu::always_inline]] inline Lanes select(const LaneMask& condition, const Lanes& ifTrue, const Lanes& ifFalse)
{
    return condition ? ifTrue : ifFalse;
}

/// The impulse λ along the unit direction (dx, dy), with arms rA × d and rB × d: −λd on A and +λd
/// on B, as applyImpulse does for one contact.
[[gnu::always_inline]] inline void apply(LaneVelocities& a, LaneVelocities& b, const Lanes& impulse, const Lanes& dx,
                                         const Lanes& dy, const Lanes& armA, const Lanes& armB)
{
    const Lanes px = impulse * dx;
    const Lanes py = impulse * dy;
    a.x -= a.invMass * px;
    a.y -= a.invMass * py;
    a.angular -= a.invInertia * (impulse * armA);
    b.x += b.invMass * px;
    b.y += b.invMass * py;
    b.angular += b.invInertia * (impulse * armB);
}

/// The relative velocity of B's point to A's along (dx, dy): (vB − vA)·d + ωB (rB × d) − ωA (rA × d).
[[gnu::always_inline]] inline Lanes relativeAlong(const LaneVelocities& a, const LaneVelocities& b, const Lanes& dx, const Lanes& dy,
                           const Lanes& armA, const Lanes& armB)
{
    return (b.x - a.x) * dx + (b.y - a.y) * dy + b.angular * armB - a.angular * armA;
}

/// The poses of one side of every lane.
struct LanePoses {
    Lanes x{};
    Lanes y{};
    Lanes angle{};
    Lanes cosine{};
    Lanes sine{};
};

[[gnu::always_inline]] inline LanePoses loadPoses(const std::array<std::uint32_t, kBatchLanes>& indices, std::span<const BatchPose> poses)
{
    LanePoses p;
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        const BatchPose& pose = poses[indices[static_cast<std::size_t>(lane)]];
        p.x[lane] = pose.x;
        p.y[lane] = pose.y;
        p.angle[lane] = pose.angle;
        p.cosine[lane] = pose.cosine;
        p.sine[lane] = pose.sine;
    }
    return p;
}

[[gnu::always_inline]] inline void storePoses(const std::array<std::uint32_t, kBatchLanes>& indices, const LanePoses& p,
                       std::span<BatchPose> poses)
{
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        BatchPose& pose = poses[indices[static_cast<std::size_t>(lane)]];
        pose.x = p.x[lane];
        pose.y = p.y[lane];
        pose.angle = p.angle[lane];
        pose.cosine = p.cosine[lane];
        pose.sine = p.sine[lane];
    }
}

/// Turns the poses by δ, keeping their cosine and sine up to date.
[[gnu::always_inline]] inline void turn(LanePoses& p, const Lanes& delta)
{
    p.angle += delta;
    detail::turnSmall(p.cosine, p.sine, delta);
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        if (std::abs(delta[lane]) > detail::kSmallTurn) {
            p.cosine[lane] = std::cos(p.angle[lane]);
            p.sine[lane] = std::sin(p.angle[lane]);
        }
    }
}

} // namespace

// Every helper above is always inlined, so each version of a pass below is one function for one
// target: GCC miscompiles calls from an AVX2 function to a plain one that take vector arguments at
// -O0 (AddressSanitizer caught it reading past a local).

BatchOrder fastestBatchOrder()
{
    // x86-64-v4, the level the side-by-side passes are compiled for.
    static const BatchOrder order = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                                            __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
                                            __builtin_cpu_supports("avx512cd")
                                        ? BatchOrder::InPairs
                                        : BatchOrder::OneByOne;
    return order;
}

const char* batchInstructions()
{
    if (fastestBatchOrder() == BatchOrder::InPairs)
        return "AVX-512";
    return __builtin_cpu_supports("avx2") ? "AVX2" : "SSE2";
}

// Two versions of each pass are compiled: one for processors with AVX2, whose 256-bit registers
// hold a whole batch, and one for any x86-64. The processor picks at load time. Both do the same
// IEEE arithmetic lane by lane (no fused multiply-add), so they give the same bits. The velocity
// and position passes have a third version, for AVX-512, which goes through the batches in pairs.
__attribute__((target_clones("avx2", "default"))) void warmStartBatches(std::span<ContactBatch> batches)
{
    const Lanes zero{};
    for (ContactBatch& c : batches) {
        LaneVelocities a = load(c.bodyA);
        LaneVelocities b = load(c.bodyB);
        const Lanes tx = c.normalY;
        const Lanes ty = -c.normalX;
        for (const BatchPoint& p : c.points) {
            apply(a, b, p.normalImpulse, c.normalX, c.normalY, p.normalArmA, p.normalArmB);
            apply(a, b, p.tangentImpulse, tx, ty, p.tangentArmA, p.tangentArmB);
            c.acted |= (p.normalImpulse != zero) | (p.tangentImpulse != zero);
        }
        store(c.writeA, a);
        store(c.writeB, b);
    }
}

namespace {

/// One velocity pass over N batches of one colour, step by step side by side: they share no
/// movable body, so their N chains of dependent arithmetic are independent, and the processor
/// runs one while another waits for a result. Each lane does exactly its own arithmetic, whatever
/// N is.
template <std::size_t N> [[gnu::always_inline]] inline void solveTogether(ContactBatch* const* batches)
{
    const Lanes zero{};
    LaneVelocities a[N];
    LaneVelocities b[N];
    Lanes tx[N];
    Lanes ty[N];
    for (std::size_t k = 0; k < N; ++k) {
        a[k] = load(batches[k]->bodyA);
        b[k] = load(batches[k]->bodyB);
        // The tangent is the normal turned clockwise, as for a lone contact.
        tx[k] = batches[k]->normalY;
        ty[k] = -batches[k]->normalX;
    }

    // Friction first, limited by the normal impulse of the last pass.
    for (std::size_t i = 0; i < 2; ++i) {
        for (std::size_t k = 0; k < N; ++k) {
            ContactBatch& c = *batches[k];
            BatchPoint& p = c.points[i];
            const Lanes vt = relativeAlong(a[k], b[k], tx[k], ty[k], p.tangentArmA, p.tangentArmB);
            const Lanes limit = c.friction * p.normalImpulse;
            const Lanes wanted = p.tangentImpulse - vt * p.tangentMass;
            const Lanes clamped = select(wanted < -limit, -limit, select(limit < wanted, limit, wanted));
            const Lanes delta = clamped - p.tangentImpulse;
            p.tangentImpulse = clamped;
            c.acted |= delta != zero;
            apply(a[k], b[k], delta, tx[k], ty[k], p.tangentArmA, p.tangentArmB);
        }
    }

    // Normal. Where the 2×2 block solve applies, the total impulse x solves x ≥ 0,
    // w = b + K·x ≥ 0, xᵢwᵢ = 0, where b is the velocity (plus the allowed approach s⁺/h)
    // without this contact's accumulated impulse: the lane tries the active sets in order
    // (both points, the first, the second, none) and keeps the first that holds. Elsewhere (one
    // point, or two so close together that K is nearly singular) each point is solved on its
    // own, one after the other, as ContactSolver does for one contact; a missing second point
    // has no mass, so its impulse stays 0.
    Lanes old2[N];
    Lanes block2[N];
    for (std::size_t k = 0; k < N; ++k) {
        ContactBatch& c = *batches[k];
        BatchPoint& p1 = c.points[0];
        BatchPoint& p2 = c.points[1];
        // K from the masses and arms, in the order ContactSolver builds it for one contact.
        const Lanes mass = a[k].invMass + b[k].invMass;
        const Lanes k11 = mass + a[k].invInertia * p1.normalArmA * p1.normalArmA +
                          b[k].invInertia * p1.normalArmB * p1.normalArmB;
        const Lanes k22 = mass + a[k].invInertia * p2.normalArmA * p2.normalArmA +
                          b[k].invInertia * p2.normalArmB * p2.normalArmB;
        const Lanes k12 = mass + a[k].invInertia * p1.normalArmA * p2.normalArmA +
                          b[k].invInertia * p1.normalArmB * p2.normalArmB;
        const Lanes inverseDeterminant = 1 / (k11 * k22 - k12 * k12);
        const Lanes old1 = p1.normalImpulse;
        old2[k] = p2.normalImpulse;
        const Lanes vn1 = relativeAlong(a[k], b[k], c.normalX, c.normalY, p1.normalArmA, p1.normalArmB) + p1.gapSpeed;
        const Lanes b1 = vn1 - (k11 * old1 + k12 * old2[k]);
        const Lanes b2 = relativeAlong(a[k], b[k], c.normalX, c.normalY, p2.normalArmA, p2.normalArmB) +
                         p2.gapSpeed - (k12 * old1 + k22 * old2[k]);
        // x = −K⁻¹b, K⁻¹ = [k22 −k12; −k12 k11] / det. Only lanes with blockSolve use it;
        // elsewhere det may be 0 and the values are never selected.
        const Lanes both1 = -((k22 * b1 - k12 * b2) * inverseDeterminant);
        const Lanes both2 = -((k11 * b2 - k12 * b1) * inverseDeterminant);
        const LaneMask useBoth = (both1 >= zero) & (both2 >= zero);
        const Lanes firstAlone = -b1 * p1.normalMass;
        const LaneMask useFirst = (firstAlone >= zero) & (k12 * firstAlone + b2 >= zero);
        const Lanes secondAlone = -b2 * p2.normalMass;
        const LaneMask useSecond = (secondAlone >= zero) & (k12 * secondAlone + b1 >= zero);
        const Lanes block1 = select(useBoth, both1, select(useFirst, firstAlone, zero));
        block2[k] = select(useBoth, both2, select(useFirst, zero, select(useSecond, secondAlone, zero)));

        const Lanes alone1 = old1 - vn1 * p1.normalMass;
        const Lanes x1 = select(c.blockSolve, block1, select(alone1 < zero, zero, alone1));
        const Lanes delta1 = x1 - old1;
        p1.normalImpulse = x1;
        c.acted |= delta1 != zero;
        apply(a[k], b[k], delta1, c.normalX, c.normalY, p1.normalArmA, p1.normalArmB);
    }
    for (std::size_t k = 0; k < N; ++k) {
        ContactBatch& c = *batches[k];
        BatchPoint& p2 = c.points[1];
        // The second point alone sees the first point's impulse.
        const Lanes vn2 = relativeAlong(a[k], b[k], c.normalX, c.normalY, p2.normalArmA, p2.normalArmB) + p2.gapSpeed;
        const Lanes alone2 = old2[k] - vn2 * p2.normalMass;
        const Lanes x2 = select(c.blockSolve, block2[k], select(alone2 < zero, zero, alone2));
        const Lanes delta2 = x2 - old2[k];
        p2.normalImpulse = x2;
        c.acted |= delta2 != zero;
        apply(a[k], b[k], delta2, c.normalX, c.normalY, p2.normalArmA, p2.normalArmB);
    }
    for (std::size_t k = 0; k < N; ++k) {
        store(batches[k]->writeA, a[k]);
        store(batches[k]->writeB, b[k]);
    }
}

} // namespace

// The passes run one batch at a time, or on processors with AVX-512 two at a time (colour() lays
// every colour out in whole pairs): their 32 vector registers hold two batches' state, where
// AVX2's 16 would spill it to memory. Each version gives the same bits.
__attribute__((target_clones("avx2", "default"))) void solveBatchesOneByOne(std::span<ContactBatch> batches)
{
    for (ContactBatch& c : batches) {
        ContactBatch* const one[1] = {&c};
        solveTogether<1>(one);
    }
}

__attribute__((target("arch=x86-64-v4,prefer-vector-width=256"))) void solveBatchesInPairs(std::span<ContactBatch> batches)
{
    assert(batches.size() % kBatchPair == 0);
    for (std::size_t first = 0; first < batches.size(); first += kBatchPair) {
        ContactBatch* const pair[kBatchPair] = {&batches[first], &batches[first + 1]};
        solveTogether<kBatchPair>(pair);
    }
}

void solveBatches(std::span<ContactBatch> batches, BatchOrder order)
{
    order == BatchOrder::InPairs ? solveBatchesInPairs(batches) : solveBatchesOneByOne(batches);
}

namespace {

/// The poses of one side of each of N batches.
template <std::size_t N, std::size_t... K>
[[gnu::always_inline]] inline std::array<LanePoses, N>
loadEach(PositionBatch* const* batches, const std::array<std::uint32_t, kBatchLanes> PositionBatch::*side,
         std::span<const BatchPose> poses, std::index_sequence<K...>)
{
    return {loadPoses(batches[K]->*side, poses)...};
}

/// One position pass over N batches of one colour side by side (see solveTogether), keeping each
/// lane's deepest separation in `deepest`.
template <std::size_t N>
[[gnu::always_inline]] inline void correctTogether(PositionBatch* const* batches, std::span<BatchPose> poses,
                                                   Lanes& deepest)
{
    const Lanes zero{};
    const Lanes half = zero + 0.5;
    const Lanes slop = zero + constants::kLinearSlop;
    const Lanes factor = zero + constants::kPositionCorrectionFactor;
    const Lanes maxCorrection = zero + constants::kMaxPositionCorrection;
    // Initialised from the loads, not zeroed first: GCC clears such arrays with 512-bit stores,
    // even at prefer-vector-width=256, and the AVX-512 passes keep to 256-bit instructions (512-bit
    // ones lower the clock of some processors).
    std::array<LanePoses, N> a = loadEach<N>(batches, &PositionBatch::readA, poses, std::make_index_sequence<N>{});
    std::array<LanePoses, N> b = loadEach<N>(batches, &PositionBatch::readB, poses, std::make_index_sequence<N>{});
    for (std::size_t i = 0; i < 2; ++i) {
        for (std::size_t k = 0; k < N; ++k) {
            PositionBatch& c = *batches[k];
            // The two surface points and the normal, which turns with A, where the bodies are now.
            const Lanes nx = a[k].cosine * c.localNormalX - a[k].sine * c.localNormalY;
            const Lanes ny = a[k].sine * c.localNormalX + a[k].cosine * c.localNormalY;
            const Lanes pointAX = a[k].x + (a[k].cosine * c.anchors[i].ax - a[k].sine * c.anchors[i].ay);
            const Lanes pointAY = a[k].y + (a[k].sine * c.anchors[i].ax + a[k].cosine * c.anchors[i].ay);
            const Lanes pointBX = b[k].x + (b[k].cosine * c.anchors[i].bx - b[k].sine * c.anchors[i].by);
            const Lanes pointBY = b[k].y + (b[k].sine * c.anchors[i].bx + b[k].cosine * c.anchors[i].by);
            const Lanes separation = (pointBX - pointAX) * nx + (pointBY - pointAY) * ny;
            const LaneMask active = i == 0 ? (zero == zero) : c.secondPoint;
            deepest = select(active & (separation < deepest), separation, deepest);

            const Lanes wanted = factor * (separation + slop);
            const Lanes clamped = select(wanted < -maxCorrection, -maxCorrection, select(zero < wanted, zero, wanted));
            const Lanes correction = select(active, clamped, zero);
            const Lanes armAX = half * (pointAX + pointBX) - a[k].x;
            const Lanes armAY = half * (pointAY + pointBY) - a[k].y;
            const Lanes armBX = half * (pointAX + pointBX) - b[k].x;
            const Lanes armBY = half * (pointAY + pointBY) - b[k].y;
            const Lanes armA = armAX * ny - armAY * nx;
            const Lanes armB = armBX * ny - armBY * nx;
            const Lanes kk = c.invMassA + c.invMassB + c.invInertiaA * armA * armA + c.invInertiaB * armB * armB;
            // Only where there is something to correct and a body that can move: padding lanes
            // (K = 0) never divide by zero, and a correction of 0 never meets an infinite mass.
            const LaneMask corrects = (kk > zero) & (correction != zero);
            const Lanes mass = select(corrects, 1 / select(corrects, kk, zero + 1), zero);
            const Lanes impulse = -correction * mass;
            const Lanes px = impulse * nx;
            const Lanes py = impulse * ny;
            c.pushX += px;
            c.pushY += py;
            a[k].x -= c.invMassA * px;
            a[k].y -= c.invMassA * py;
            b[k].x += c.invMassB * px;
            b[k].y += c.invMassB * py;
            turn(a[k], -(c.invInertiaA * (impulse * armA)));
            turn(b[k], c.invInertiaB * (impulse * armB));
        }
    }
    for (std::size_t k = 0; k < N; ++k) {
        storePoses(batches[k]->writeA, a[k], poses);
        storePoses(batches[k]->writeB, b[k], poses);
    }
}

} // namespace

/// How many batches ahead the one-by-one position pass asks for a batch's lines: its first reads
/// of a batch waited on memory (the velocity passes, whose batches are read in the same order,
/// were no faster with it).
constexpr std::size_t kPositionPrefetchAhead = 2;

// The passes keep each lane's deepest separation in memory, and the dispatcher below takes their
// smallest: a vector result handed back from an AVX-512 function let GCC place a 256-bit
// instruction after the function's closing vzeroupper, and the plain SSE code after it ran up to
// 2.7 times slower for the rest of the step.
__attribute__((target_clones("avx2", "default"))) void solvePositionBatchesOneByOne(std::span<PositionBatch> batches,
                                                                                   std::span<BatchPose> poses,
                                                                                   Lanes& deepest)
{
    for (std::size_t i = 0; i < batches.size(); ++i) {
        if (i + kPositionPrefetchAhead < batches.size())
            detail::prefetchObject(batches[i + kPositionPrefetchAhead]);
        PositionBatch* const one[1] = {&batches[i]};
        correctTogether<1>(one, poses, deepest);
    }
}

// Each lane keeps the smallest separation it meets, so the order in which the pairs' two batches
// are met does not matter.
__attribute__((target("arch=x86-64-v4,prefer-vector-width=256"))) void
solvePositionBatchesInPairs(std::span<PositionBatch> batches, std::span<BatchPose> poses, Lanes& deepest)
{
    assert(batches.size() % kBatchPair == 0);
    for (std::size_t first = 0; first < batches.size(); first += kBatchPair) {
        // The next pair's lines are asked for ahead: a pair's first reads of its batches waited on
        // memory for half the pass's time in the 20 × 20 pyramids, whose batches far outgrow the
        // cache (1.9 → 1.1 ms per step; the velocity passes are slower with it, and go without).
        if (first + 2 * kBatchPair <= batches.size())
            detail::prefetchLines(&batches[first + kBatchPair], kBatchPair * sizeof(PositionBatch));
        PositionBatch* const pair[kBatchPair] = {&batches[first], &batches[first + 1]};
        correctTogether<kBatchPair>(pair, poses, deepest);
    }
}

Scalar solvePositionBatches(std::span<PositionBatch> batches, std::span<BatchPose> poses, BatchOrder order)
{
    Lanes deepest{};
    order == BatchOrder::InPairs ? solvePositionBatchesInPairs(batches, poses, deepest)
                                 : solvePositionBatchesOneByOne(batches, poses, deepest);
    Scalar result = 0;
    for (int lane = 0; lane < kBatchLanes; ++lane)
        result = std::min(result, deepest[lane]);
    return result;
}

} // namespace impetus::controller
