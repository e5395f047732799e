#pragma once
/// \file lesson_io.h
/// Reading and writing a scene's `lesson` block (docs/scene-format.md, "Lessons"). Scene I/O
/// (scene_io.cpp) calls these; a program reads and writes lessons through parseScene() and
/// serializeScene(), which keep World::lesson.

#include "model/lesson.h"
#include "model/scene_io.h"
#include "model/world.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace impetus::model {

/// Reads the value of the scene key `lesson`, found at JSON path `path`, for a scene whose bodies
/// are `world.bodies` (bodies are named by `name`). Appends one problem per fault to `problems`
/// (unknown keys, wrong types, unknown or repeated bodies and attributes, an empty title or
/// prompt, a non-finite answer, a tolerance that is not > 0) and returns nullopt then.
std::optional<Lesson> readLesson(const nlohmann::json& value, const std::string& path, const World& world,
                                 std::vector<SceneProblem>& problems);

/// The lesson as the scene's `lesson` value, every key written. Bodies are written by their name
/// in `world`; an entry for a body `world` does not have is left out.
nlohmann::ordered_json lessonJson(const Lesson& lesson, const World& world);

} // namespace impetus::model
