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
    std::vector<std::uint32_t> m_order; ///< proxy indices sorted by box.lower on the sweep axis
};

} // namespace impetus::controller
