#pragma once
/// \file scene_loading.h
/// Loading scenes from files or from the application's embedded resources.

#include "model/scene_io.h"

#include <QString>
#include <QStringList>

namespace impetus::view {

/// Resource path of the default example scene, the one `impetus` opens with no argument.
inline constexpr char kDefaultScenePath[] = ":/examples/default.json";

/// Loads a scene from `path`: a file on disk (through model::loadSceneFile, so its messages match
/// impetus-cli's) or a Qt resource path starting with ':'.
model::SceneLoadResult loadScene(const QString& path);

/// The problems of a failed load, one "path: reason" line each.
QStringList problemMessages(const model::SceneLoadResult& result);

/// The name a scene is shown under: the file's name without its folder and extension
/// ("default" for ":/examples/default.json").
QString sceneDisplayName(const QString& path);

} // namespace impetus::view
