#pragma once
/// \file doc_screenshots_guide.h
/// The pictures of docs/user-guide.md that show the app at work (drawing, the attribute pane, the
/// run controls and timeline, the instruments, the Examples menu, soft bodies, the lesson editor),
/// taken by doc_screenshots from the real window driven with keys and clicks.

#include <QString>

namespace impetus::view::screenshots {

/// Takes every picture of the guide into `folder`, printing each path; false (with a message on
/// stderr) at the first that cannot be taken.
bool takeGuidePictures(const QString& folder);

} // namespace impetus::view::screenshots
