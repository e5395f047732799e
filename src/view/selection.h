#pragma once
/// \file selection.h
/// What the user has selected in the editor, by index into the world's vectors. Shared by the
/// canvas tools, the scene document and the attribute pane, so that none of them needs the
/// others' classes.

#include <vector>

namespace impetus::view {

/// Indices into World::bodies, World::springs and World::joints, each sorted ascending and without
/// repeats. Empty everywhere: nothing is selected, and the pane shows the world settings.
struct Selection {
    std::vector<int> bodies;
    std::vector<int> springs;
    std::vector<int> joints;

    bool empty() const { return bodies.empty() && springs.empty() && joints.empty(); }
    bool operator==(const Selection&) const = default;
};

} // namespace impetus::view
