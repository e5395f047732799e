#include "view/example_catalog.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <algorithm>

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
    // The lessons come after the plain examples, together, so the menu reads as two lists.
    std::stable_partition(scenes.begin(), scenes.end(), [](const ExampleScene& scene) {
        return !QFileInfo(scene.path).completeBaseName().startsWith(QLatin1String(kLessonPrefix));
    });
    return scenes;
}

QString exampleTitle(const QString& baseName)
{
    // Every example in resources/examples, so that each title goes through tr(). A file missing
    // here still gets a title from its name, but one that no translation reaches
    // (tests/view/editor_test.cpp checks that none is missing).
    struct Known {
        const char* name;
        const char* title;
    };
    static constexpr Known kKnown[] = {
        {"billiards", QT_TRANSLATE_NOOP("impetus::view::Examples", "Billiards break")},
        {"box-stack", QT_TRANSLATE_NOOP("impetus::view::Examples", "Box stack and overhang")},
        {"default", QT_TRANSLATE_NOOP("impetus::view::Examples", "Default scene")},
        {"incline", QT_TRANSLATE_NOOP("impetus::view::Examples", "Block on an incline")},
        {"lesson-cart-crash", QT_TRANSLATE_NOOP("impetus::view::Examples", "Lesson: momentum in a cart crash")},
        {"lesson-incline-friction", QT_TRANSLATE_NOOP("impetus::view::Examples", "Lesson: friction on an incline")},
        {"lesson-pendulum-length", QT_TRANSLATE_NOOP("impetus::view::Examples", "Lesson: pendulum period and length")},
        {"lesson-pendulum-tuning", QT_TRANSLATE_NOOP("impetus::view::Examples", "Lesson: tuning a pendulum")},
        {"lesson-spring-period", QT_TRANSLATE_NOOP("impetus::view::Examples", "Lesson: spring period and stiffness")},
        {"newtons-cradle", QT_TRANSLATE_NOOP("impetus::view::Examples", "Newton's cradle")},
        {"pendulum", QT_TRANSLATE_NOOP("impetus::view::Examples", "Pendulum")},
        {"projectile", QT_TRANSLATE_NOOP("impetus::view::Examples", "Projectile over the ground")},
        {"pyramid", QT_TRANSLATE_NOOP("impetus::view::Examples", "Pyramid")},
        {"soft-bodies", QT_TRANSLATE_NOOP("impetus::view::Examples", "Soft bodies: rigid and soft side by side")},
        {"spaceship-asteroids", QT_TRANSLATE_NOOP("impetus::view::Examples", "Spaceship and asteroids")},
        {"spring", QT_TRANSLATE_NOOP("impetus::view::Examples", "Mass on a spring")},
        {"spring-chain", QT_TRANSLATE_NOOP("impetus::view::Examples", "Chain of springs")},
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
