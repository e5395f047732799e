#include "controller/union_find.h"

namespace impetus::controller {

std::vector<std::vector<std::uint32_t>> groupBySet(std::vector<std::uint32_t>& parent,
                                                   const std::vector<std::int64_t>& element)
{
    std::vector<std::int32_t> groupOf(parent.size(), -1);
    std::vector<std::vector<std::uint32_t>> groups;
    for (std::size_t i = 0; i < element.size(); ++i) {
        if (element[i] < 0)
            continue;
        std::int32_t& group = groupOf[findRoot(parent, static_cast<std::uint32_t>(element[i]))];
        if (group < 0) {
            group = static_cast<std::int32_t>(groups.size());
            groups.emplace_back();
        }
        groups[static_cast<std::size_t>(group)].push_back(static_cast<std::uint32_t>(i));
    }
    return groups;
}

} // namespace impetus::controller
