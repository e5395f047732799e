#pragma once
/// \file broad_phase.h
/// Candidate pairs from bounding boxes, by sort and sweep.

#include "controller/collision/collision_types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::controller {

/// One convex piece of a body, as the broad phase sees it.
struct BroadPhaseProxy {
    Aabb box; ///< world bounding box, already enlarged by any speculative margin
    std::uint32_t body = 0; ///< index into World::bodies
    bool fixed = false; ///< two fixed proxies are never paired
};

/// A candidate pair: indices into the proxy list, first < second.
struct ProxyPair {
    std::uint32_t first = 0; ///< the lower proxy index
    std::uint32_t second = 0; ///< the higher proxy index
    auto operator<=>(const ProxyPair&) const = default; ///< by first, then second
};

/// Sort-and-sweep broad phase, with a cache of "fat" boxes that makes a step in which little has
/// moved nearly free.
///
/// What is kept between calls: per proxy a fat box (its box enlarged on every side by
/// constants::kBroadPhaseFatFraction of its smaller side), its body and its fixed flag, and the
/// sorted list of fat pairs: the pairs whose fat boxes overlap, under the same rules (never the
/// same body, never two fixed). When a call brings as many proxies as the last recompute, with the
/// same bodies and fixed flags, and every box lies inside its fat box, the fat pairs are reused;
/// otherwise the fat boxes and fat pairs are made afresh from this call's boxes by the sweep.
///
/// Why the output is still exact: a box inside its fat box can overlap another only if their fat
/// boxes overlap, so the fat pairs hold every overlapping pair. The output is the fat pairs, in
/// their (first, second) order, whose own boxes pass Aabb::overlaps: exactly the pairs the sweep
/// would find on the boxes themselves. A box with a NaN is never inside its fat box and overlaps
/// nothing, as without the cache.
class BroadPhase {
public:
    /// Every pair of proxies whose boxes overlap (Aabb::overlaps: touching counts), except pairs of
    /// two fixed proxies and pairs from the same body, sorted by (first, second): a deterministic
    /// order whatever the input's history. A box with a NaN overlaps nothing. Cost: when every box
    /// lies inside its fat box, n plus the number of fat pairs; otherwise about n log n plus the
    /// number of fat overlaps along the sweep axis.
    void findPairs(std::span<const BroadPhaseProxy> proxies, std::vector<ProxyPair>& pairs);

    /// True when the last findPairs call reused the fat pairs of an earlier call (every box was
    /// inside its fat box), false when it swept afresh. For tests and benchmarks: the output is
    /// the same either way.
    bool reusedLastCall() const { return m_reused; }

private:
    /// True when `proxies` are as many as the fat boxes, with the same bodies and fixed flags, and
    /// each box lies inside its fat box. Stops at the first that does not.
    bool fatBoxesHold(std::span<const BroadPhaseProxy> proxies) const;

    /// The sweep: every pair of `proxies` whose boxes overlap, under the rules of findPairs, sorted.
    void sweep(std::span<const BroadPhaseProxy> proxies, std::vector<ProxyPair>& pairs);

    /// A proxy as the sweep reads it, laid out contiguously in sweep order so that the inner loop
    /// walks memory forwards instead of jumping around the proxy list.
    struct SweepEntry {
        Scalar lower = 0; ///< on the sweep axis
        Scalar upper = 0; ///< on the sweep axis
        Scalar otherLower = 0; ///< on the other axis
        Scalar otherUpper = 0; ///< on the other axis
        std::uint32_t index = 0; ///< into the proxy list
        std::uint32_t body = 0;
        bool fixed = false;
    };

    std::vector<BroadPhaseProxy> m_fat; ///< per proxy, its fat box, body and fixed flag
    std::vector<ProxyPair> m_fatPairs; ///< pairs whose fat boxes overlap, sorted by (first, second)
    bool m_reused = false; ///< whether the last call reused m_fatPairs

    std::vector<std::uint32_t> m_order; ///< fat-box indices sorted by box.lower on the sweep axis
    // Scratch, kept so that a step allocates nothing.
    std::vector<SweepEntry> m_entries; ///< per strip, its proxies in sweep order
    std::vector<std::size_t> m_stripStart; ///< where each strip's entries begin
    std::vector<std::size_t> m_cursor; ///< fill positions, for the strips and then the pair sort
    std::vector<std::size_t> m_pairStart; ///< where each first proxy's pairs begin, in the pair sort
    std::vector<std::uint32_t> m_seconds; ///< the pairs' second proxies, in the pair sort
};

} // namespace impetus::controller
