#pragma once
/// \file screenshot_files.h
/// What the programs that take the pictures of docs/images/ share (not tests): showing the real
/// window at the pictures' size, and writing a grab of a widget into the output folder.

#include "view/main_window.h"

#include <QDir>
#include <QString>
#include <QTest>
#include <QWidget>

#include <cstdio>

namespace impetus::view::test {

/// Writes a grab of `widget` to `name` in `directory`, and prints the path (or why it could not).
inline bool saveGrab(QWidget& widget, const QDir& directory, const QString& name)
{
    const QString path = directory.filePath(name);
    if (!widget.grab().save(path)) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
        return false;
    }
    std::printf("%s\n", qPrintable(path));
    return true;
}

/// Shows `window` at width × height px, active, and waits until it is on screen.
inline bool showWindowAt(MainWindow& window, int width, int height)
{
    window.resize(width, height);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowExposed(&window);
}

} // namespace impetus::view::test
