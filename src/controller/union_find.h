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

/// Groups items by the set of `parent` each belongs to: element[i] is the forest element item i
/// stands for, or −1 for an item in no set. The groups come in the order of their first item,
/// each with its items in order.
std::vector<std::vector<std::uint32_t>> groupBySet(std::vector<std::uint32_t>& parent,
                                                   const std::vector<std::int64_t>& element);

} // namespace impetus::controller
