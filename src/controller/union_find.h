#pragma once
/// \file union_find.h
/// A union–find forest over indices, for grouping bodies that constraints or springs join.

#include <cstdint>
#include <vector>

namespace impetus::controller {

/// Root of x's set in the forest `parent` (parent[i] == i at a root), halving the path on the way.
inline std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

} // namespace impetus::controller
