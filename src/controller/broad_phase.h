#pragma once
/// \file broad_phase.h
/// Candidate pairs from bounding boxes, by sort and sweep.

#include "controller/collision_types.h"

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
    std::uint32_t first = 0;
    std::uint32_t second = 0;
    auto operator<=>(const ProxyPair&) const = default;
};

/// Sort-and-sweep broad phase. Keeps its scratch buffers between calls, and its sort order, so
/// that from one step to the next (when little has moved) the sort is nearly free.
class BroadPhase {
public:
    /// Every pair of proxies whose boxes overlap, except pairs of two fixed proxies and pairs from
    /// the same body, sorted by (first, second): a deterministic order whatever the input's
    /// history. Cost about n log n plus the number of overlaps along the sweep axis.
    void findPairs(std::span<const BroadPhaseProxy> proxies, std::vector<ProxyPair>& pairs);

private:
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

    std::vector<std::uint32_t> m_order; ///< proxy indices sorted by box.lower on the sweep axis
    // Scratch, kept so that a step allocates nothing.
    std::vector<SweepEntry> m_entries; ///< per strip, its proxies in sweep order
    std::vector<std::size_t> m_stripStart; ///< where each strip's entries begin
    std::vector<std::size_t> m_cursor; ///< fill positions, for the strips and then the pair sort
    std::vector<std::size_t> m_pairStart; ///< where each first proxy's pairs begin, in the pair sort
    std::vector<std::uint32_t> m_seconds; ///< the pairs' second proxies, in the pair sort
};

} // namespace impetus::controller
