#pragma once
/// \file example_catalog.h
/// The example scenes embedded in the application, with the titles the Examples menu shows.

#include <QString>

#include <vector>

namespace impetus::view {

/// One example scene: its resource path and its title.
struct ExampleScene {
    QString path; ///< ":/examples/<name>.json"
    QString title; ///< "Newton's cradle"
};

/// The file names of lesson scenes (scenes with a `lesson` block) among the examples start so.
inline constexpr char kLessonPrefix[] = "lesson-";

/// Every scene file under ":/examples/", sorted by file name, the lessons (kLessonPrefix) last.
std::vector<ExampleScene> exampleScenes();

/// The title of the example file called `baseName` (no folder or extension): a translated title
/// for every example shipped in resources/examples ("newtons-cradle" → "Newton's cradle"); for
/// any other name, the name with dashes and underscores as spaces and a capital first letter
/// ("block-on-incline" → "Block on incline"), untranslated.
QString exampleTitle(const QString& baseName);

} // namespace impetus::view
