#pragma once
/// \file test_files.h
/// Scene files written by the view tests.

#include <QByteArray>
#include <QFile>
#include <QString>

namespace impetus::view::test {

/// A scene file with two problems: `bodies[0].shape.width` is negative and `bodies[1].name`
/// repeats the first body's name.
inline constexpr char kSceneWithTwoProblems[] = R"({ "format": "impetus-scene", "version": 1, "bodies": [
    { "name": "a", "shape": { "type": "box", "width": -1, "height": 1 }, "position": [0, 0] },
    { "name": "a", "shape": { "type": "circle", "radius": 1 }, "position": [0, 0] } ] })";

/// Writes `contents` to the file `path`; true when all of it was written.
inline bool writeFile(const QString& path, const QByteArray& contents)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(contents) == contents.size();
}

} // namespace impetus::view::test
