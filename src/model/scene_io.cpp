// PLACEHOLDER: being replaced by the scene I/O helper.
#include "model/scene_io.h"

namespace impetus::model {

SceneLoadResult parseScene(std::string_view)
{
    return SceneLoadResult{std::nullopt, {SceneProblem{"(root)", "scene reading is not built yet"}}};
}

SceneLoadResult loadSceneFile(const std::filesystem::path&) { return parseScene(""); }

std::string serializeScene(const World&) { return "{}\n"; }

std::optional<std::string> saveSceneFile(const std::filesystem::path&, const World&)
{
    return std::string("scene writing is not built yet");
}

} // namespace impetus::model
