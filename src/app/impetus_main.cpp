/// \file impetus_main.cpp
/// The desktop app `impetus` (CONTRACT.md section 3).
///
///   impetus                      opens the default example scene, paused, ready to press Play
///   impetus SCENE.json           opens that scene
///   impetus --run [SCENE.json]   opens the scene and starts it running at once (a demonstration
///                                on a projector; tests use it to have a run to autosave)
///   impetus --screenshot OUT.png [--run-for SECONDS] [--size WxH] [SCENE.json]
///                                loads the scene (the default scene when none is given), takes
///                                round(SECONDS / dt) fixed steps headless, renders the canvas
///                                exactly as the window shows it into a WxH PNG (default
///                                1280x720) and exits
///
/// Exit codes, as for impetus-cli: 0 success; 2 bad usage or a bad scene (message on stderr);
/// 1 a failure at run time (the PNG cannot be written, the simulation produced a non-finite
/// number, the embedded default scene cannot be read).
///
/// With --screenshot, a scene that fails to load is reported on stderr, one "FILE: path: reason"
/// line per problem, and the app exits with 2 without rendering: a script reads stderr, and a
/// dialog would hang it. Without --screenshot (a user who double-clicked a file, or typed its
/// name), the window opens on the default scene and lists every problem in the dialog File > Open
/// uses; the problems also go to stderr for a terminal user.
///
/// The window autosaves the open scene (view/autosave.h) and, at start, offers to restore the
/// work of an Impetus that did not quit cleanly.
///
/// The window, the help text and the messages are in the system's language when Impetus has it
/// (German, Spanish; English otherwise), or in the one chosen in View › Language (view/language.h).

#include "view/autosave.h"
#include "view/canvas_view.h"
#include "view/language.h"
#include "view/main_window.h"
#include "view/scene_loading.h"
#include "view/screenshot.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QApplication>
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QImageWriter>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string_view>
#include <utility>

namespace impetus::app {

/// The translation context of the app's own messages, the command line's help and errors
/// (resources/translations/*.ts). Named in full, so that lupdate's context and the one tr() uses
/// at run time are the same string.
class App {
    Q_DECLARE_TR_FUNCTIONS(impetus::app::App)
};

} // namespace impetus::app

namespace {

namespace view = impetus::view;
using impetus::app::App;

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

/// Default screenshot size, px: 720p, a common projector and slide size.
constexpr int kDefaultScreenshotWidth = 1280;
constexpr int kDefaultScreenshotHeight = 720;

/// Largest screenshot side, px. QImage and PNG go further, but a bigger image is a typo, and
/// refusing it beats allocating gigabytes.
constexpr int kMaxScreenshotSide = 16384;

/// Most steps --run-for may ask for: 10⁹ steps (about 48 simulated days at 240 Hz) is already
/// hours of computing, so anything longer is a mistake.
constexpr double kMaxScreenshotSteps = 1e9;


void printError(const QString& message)
{
    std::fputs(qPrintable(QStringLiteral("impetus: ") + message + QLatin1Char('\n')), stderr);
}

void printProblems(const QString& path, const QStringList& problems)
{
    for (const QString& problem : problems)
        std::fputs(qPrintable(path + QStringLiteral(": ") + problem + QLatin1Char('\n')), stderr);
}

/// "WxH" with both sides in 1 … kMaxScreenshotSide.
std::optional<QSize> parseSize(const QString& text)
{
    static const QRegularExpression pattern(QStringLiteral("^(\\d{1,6})[xX](\\d{1,6})$"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch())
        return std::nullopt;
    const int width = match.captured(1).toInt();
    const int height = match.captured(2).toInt();
    if (width < 1 || height < 1 || width > kMaxScreenshotSide || height > kMaxScreenshotSide)
        return std::nullopt;
    return QSize(width, height);
}

int runScreenshot(const QString& output, const QString& runForText, const QString& sizeText,
                  const QString& scenePath)
{
    const std::optional<QSize> size = parseSize(sizeText);
    if (!size) {
        printError(App::tr("--size must be WxH with both sides from 1 to %1 pixels, not “%2”")
                       .arg(kMaxScreenshotSide)
                       .arg(sizeText));
        return kExitUsage;
    }
    bool numberOk = false;
    const double runFor = runForText.toDouble(&numberOk);
    if (!numberOk || !std::isfinite(runFor) || runFor < 0) {
        printError(App::tr("--run-for must be a number of seconds ≥ 0, not “%1”").arg(runForText));
        return kExitUsage;
    }

    const QString path = scenePath.isEmpty() ? QString::fromLatin1(view::kDefaultScenePath) : scenePath;
    impetus::model::SceneLoadResult scene = view::loadScene(path);
    if (!scene.ok()) {
        printProblems(path, view::problemMessages(scene));
        return scenePath.isEmpty() ? kExitFailure : kExitUsage;
    }

    const double steps = std::round(runFor / scene.world->settings.timeStep);
    if (steps > kMaxScreenshotSteps) {
        printError(App::tr("--run-for %1 s is %2 steps, more than the %3 allowed")
                       .arg(runFor)
                       .arg(steps, 0, 'g', 3)
                       .arg(kMaxScreenshotSteps, 0, 'g', 3));
        return kExitUsage;
    }

    view::SimulationRunner runner;
    runner.setWorld(std::move(*scene.world));
    // The runner checks every batch of steps for a state that is not finite and reports it.
    std::optional<std::pair<QString, double>> divergence;
    QObject::connect(&runner, &view::SimulationRunner::diverged,
                     [&divergence](const QString& body, double time) { divergence.emplace(body, time); });
    // The canvas exists before the run, as in the window: it frames the bodies where they were
    // loaded, and a body that flies away leaves the picture instead of shrinking it.
    view::CanvasView canvas(runner);

    // Stepped in chunks of one simulated second: the canvas follows the world once per chunk
    // rather than once per step, and a non-finite state is caught within a second of appearing.
    const double dt = runner.world().settings.timeStep;
    const auto chunk = std::max<std::int64_t>(1, std::llround(1.0 / dt));
    for (auto remaining = static_cast<std::int64_t>(steps); remaining > 0; remaining -= chunk) {
        runner.stepBy(std::min(chunk, remaining));
        if (divergence) {
            printError(App::tr("the simulation produced a non-finite number: body “%1”, by t = %2 s")
                           .arg(divergence->first)
                           .arg(divergence->second));
            return kExitFailure;
        }
    }

    const QImage image = view::renderCanvasImage(canvas, *size);
    QImageWriter writer(output, "png");
    if (!writer.write(image)) {
        printError(App::tr("cannot write %1: %2").arg(output, writer.errorString()));
        return kExitFailure;
    }
    return kExitOk;
}

/// True when the command line asks for something that shows no window: a screenshot or the help
/// text. Looked at before QApplication exists, to choose the platform plugin.
bool needsNoDisplay(int argc, char* argv[])
{
    for (int i = 1; i < argc; ++i) {
        const std::string_view argument(argv[i]);
        if (argument == "--screenshot" || argument.starts_with("--screenshot=") || argument == "-h"
            || argument == "--help" || argument == "-?" || argument == "--help-all")
            return true;
    }
    return false;
}

} // namespace

int main(int argc, char* argv[])
{
    // A screenshot (or --help) never shows a window, so it needs no display: a teacher can run it
    // over ssh or in a batch job. An explicit QT_QPA_PLATFORM is respected.
    if (needsNoDisplay(argc, argv) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("impetus"));
    // QSettings (recent files, the dock layout) live under this name.
    QApplication::setOrganizationName(QStringLiteral("impetus"));
    // The system's language, or the one chosen in View › Language, before any text is made: the
    // help text and the window are built in it. Scene files do not read the locale.
    view::applyLanguage(app, view::chosenLocale());

    QCommandLineParser parser;
    parser.setApplicationDescription(App::tr("Impetus, a 2D physics lab for the classroom."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"), App::tr("Render the canvas to the PNG file FILE and exit."),
        App::tr("FILE"));
    const QCommandLineOption runForOption(
        QStringLiteral("run-for"), App::tr("With --screenshot: simulate SECONDS first (default 0)."),
        App::tr("SECONDS"), QStringLiteral("0"));
    const QCommandLineOption sizeOption(
        QStringLiteral("size"), App::tr("With --screenshot: the image size in pixels (default 1280x720)."),
        App::tr("WxH"), QStringLiteral("%1x%2").arg(kDefaultScreenshotWidth).arg(kDefaultScreenshotHeight));
    const QCommandLineOption runOption(QStringLiteral("run"),
                                       App::tr("Start the simulation as soon as the window opens."));
    parser.addOption(screenshotOption);
    parser.addOption(runOption);
    parser.addOption(runForOption);
    parser.addOption(sizeOption);
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 App::tr("The scene file to open (default: the example scene)."),
                                 QStringLiteral("[SCENE.json]"));

    // parse() rather than process(): process() exits with 1 on a bad option, and the contract
    // says bad usage is 2.
    if (!parser.parse(QCoreApplication::arguments())) {
        printError(parser.errorText());
        return kExitUsage;
    }
    if (parser.isSet(helpOption))
        parser.showHelp(kExitOk);

    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) {
        printError(App::tr("expected at most one scene file, got %1").arg(positional.size()));
        return kExitUsage;
    }
    const QString scenePath = positional.value(0);

    if (parser.isSet(screenshotOption) && parser.isSet(runOption)) {
        printError(App::tr("--run opens a window, --screenshot does not: give one of them"));
        return kExitUsage;
    }
    if (parser.isSet(screenshotOption)) {
        return runScreenshot(parser.value(screenshotOption), parser.value(runForOption),
                             parser.value(sizeOption), scenePath);
    }
    if (parser.isSet(runForOption) || parser.isSet(sizeOption)) {
        printError(App::tr("--run-for and --size need --screenshot"));
        return kExitUsage;
    }

    view::MainWindow window;
    if (scenePath.isEmpty()) {
        const QString path = QString::fromLatin1(view::kDefaultScenePath);
        if (const QStringList problems = window.openScene(path); !problems.isEmpty()) {
            // The embedded default scene failing is a broken build, not the user's input.
            printProblems(path, problems);
            return kExitFailure;
        }
    }
    window.show();
    if (!scenePath.isEmpty())
        printProblems(scenePath, window.openStartupScene(scenePath));
    view::Autosave autosave(window.document(), view::Autosave::defaultFolder(),
                            view::Autosave::intervalFromEnvironment());
    view::offerRecovery(&window, autosave);
    if (parser.isSet(runOption))
        window.playAction()->setChecked(true);
    return QApplication::exec();
}
