// Takes the screenshots of docs/images/: the whole window, as a user sees it, in projector mode, in
// German and Spanish, with a lesson, and the pictures of the user guide (doc_screenshots_guide.cpp).
// Run by scripts/screenshots (under Xvfb, or on Qt's offscreen platform); not a test.
//
//   doc_screenshots OUTPUT_DIR

#include "doc_screenshots_guide.h"
#include "test_settings.h"
#include "view/language.h"
#include "view/main_window.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QLineEdit>
#include <QPushButton>
#include <QApplication>
#include <QDir>
#include <QPixmap>
#include <QTest>

#include <cstdio>

namespace view = impetus::view;

namespace {

/// Window size of the shots, px: a common projector resolution.
constexpr int kShotWidth = 1280;
constexpr int kShotHeight = 720;

/// One picture: the window in `language` ("" for English), projector mode or not, showing the
/// example `example` after `steps` fixed steps, with the body `selected` selected (−1: none).
struct Shot {
    const char* file;
    const char* language;
    bool projector;
    const char* example;
    int steps;
    int selected;
};

bool take(const Shot& shot, const QString& folder)
{
    view::setLanguageSetting(QString::fromLatin1(shot.language));
    view::applyLanguage(*QCoreApplication::instance(), view::chosenLocale());
    view::MainWindow window;
    if (!window.openScene(QStringLiteral(":/examples/%1.json").arg(QLatin1String(shot.example))).isEmpty())
        return false;
    window.resize(kShotWidth, kShotHeight);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    if (shot.projector)
        window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
    // Projector mode goes full screen; the shot keeps the projector's size either way.
    window.setWindowState(Qt::WindowNoState);
    window.resize(kShotWidth, kShotHeight);
    window.runner().stepBy(shot.steps);
    if (shot.selected >= 0)
        window.document().setSelection(view::Selection{{shot.selected}, {}, {}});
    QTest::qWait(200);
    const bool saved = window.grab().save(QDir(folder).filePath(QLatin1String(shot.file)), "png");
    if (shot.projector)
        window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
    return saved;
}

/// The incline lesson as a student sees it: the lesson panel beside the canvas, the first
/// question answered and checked, and the block selected so the pane shows its locks.
bool takeLesson(const QString& folder)
{
    view::setLanguageSetting(QString());
    view::applyLanguage(*QCoreApplication::instance(), view::chosenLocale());
    view::MainWindow window;
    if (!window.openScene(QStringLiteral(":/examples/lesson-incline-friction.json")).isEmpty())
        return false;
    window.resize(kShotWidth, kShotHeight);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    auto* answer = window.findChild<QLineEdit*>(QStringLiteral("lessonAnswer0"));
    auto* check = window.findChild<QPushButton*>(QStringLiteral("lessonCheck0"));
    if (!answer || !check)
        return false;
    QTest::keyClicks(answer, QStringLiteral("30"));
    QTest::mouseClick(check, Qt::LeftButton);
    window.document().setSelection(view::Selection{{2}, {}, {}});
    QTest::qWait(200);
    return window.grab().save(QDir(folder).filePath(QStringLiteral("lesson-incline.png")), "png");
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    if (argc != 2) {
        std::fputs("usage: doc_screenshots OUTPUT_DIR\n", stderr);
        return 2;
    }
    // The user's own settings are neither read nor changed.
    const view::test::TemporarySettings settings;
    const QString folder = QString::fromLocal8Bit(argv[1]);
    if (!QDir().mkpath(folder)) {
        std::fprintf(stderr, "doc_screenshots: cannot make the folder %s\n", argv[1]);
        return 1;
    }
    const Shot shots[] = {
        {"projector-mode.png", "", true, "default", 1104, -1},
        {"window-collision.png", "", false, "default", 1105, -1},
        {"window-german.png", "de", false, "incline", 240, 3},
        {"window-spanish.png", "es", false, "pendulum", 120, -1},
    };
    for (const Shot& shot : shots) {
        if (!take(shot, folder)) {
            std::fprintf(stderr, "doc_screenshots: could not take %s\n", shot.file);
            return 1;
        }
        std::printf("%s\n", qPrintable(QDir(folder).filePath(QLatin1String(shot.file))));
    }
    if (!takeLesson(folder)) {
        std::fputs("doc_screenshots: could not take lesson-incline.png\n", stderr);
        return 1;
    }
    std::printf("%s\n", qPrintable(QDir(folder).filePath(QStringLiteral("lesson-incline.png"))));
    // The guide is in English, whatever the machine's language.
    view::setLanguageSetting(QStringLiteral("en"));
    view::applyLanguage(*QCoreApplication::instance(), view::chosenLocale());
    if (!view::screenshots::takeGuidePictures(folder)) {
        std::fputs("doc_screenshots: could not take a picture of the user guide\n", stderr);
        return 1;
    }
    return 0;
}
