#include "view/example_catalog.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace impetus::view {

namespace {

QString translate(const char* text) { return QCoreApplication::translate("impetus::view::Examples", text); }

} // namespace

std::vector<ExampleScene> exampleScenes()
{
    std::vector<ExampleScene> scenes;
    const QDir folder(QStringLiteral(":/examples"));
    for (const QString& file : folder.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        scenes.push_back({folder.filePath(file), exampleTitle(QFileInfo(file).completeBaseName())});
    return scenes;
}

QString exampleTitle(const QString& baseName)
{
    // Names whose title is not just the file name with spaces: an apostrophe, a scenario.
    struct Known {
        const char* name;
        const char* title;
    };
    static constexpr Known kKnown[] = {
        {"default", QT_TRANSLATE_NOOP("impetus::view::Examples", "Default scene")},
        {"asteroids", QT_TRANSLATE_NOOP("impetus::view::Examples", "Spaceship and asteroids")},
        {"spaceship-asteroids", QT_TRANSLATE_NOOP("impetus::view::Examples", "Spaceship and asteroids")},
        {"newtons-cradle", QT_TRANSLATE_NOOP("impetus::view::Examples", "Newton's cradle")},
        {"newton-cradle", QT_TRANSLATE_NOOP("impetus::view::Examples", "Newton's cradle")},
    };
    for (const Known& known : kKnown) {
        if (baseName == QLatin1String(known.name))
            return translate(known.title);
    }
    QString title = baseName;
    title.replace(QLatin1Char('-'), QLatin1Char(' ')).replace(QLatin1Char('_'), QLatin1Char(' '));
    if (!title.isEmpty())
        title[0] = title[0].toUpper();
    return title;
}

} // namespace impetus::view
