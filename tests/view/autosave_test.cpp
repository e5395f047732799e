// Autosave and recovery (issue 16, item 5): the real `impetus` is killed with SIGKILL in the middle
// of a run, on an X display of Xvfb's own (offscreen where Xvfb is missing), and the next start
// offers its work back. Every autosave goes to a temporary folder:
// the children get their own XDG_DATA_HOME (QStandardPaths::AppDataLocation follows it), the
// in-process windows a folder passed in, so no test touches the user's own.

#include "model/scene_io.h"
#include "view/autosave.h"
#include "view/main_window.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"

#include "test_files.h"
#include "test_settings.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <chrono>
#include <memory>
#include <optional>

using namespace impetus;
using namespace impetus::view;

namespace {

/// The built `impetus` binary (set by CMake).
const QString kImpetus = QStringLiteral(IMPETUS_APP_PATH);

/// A ball that falls freely from 5 m: any autosave taken after the run started shows it lower.
constexpr char kFallingBall[] = R"({
  "format": "impetus-scene",
  "version": 1,
  "bodies": [
    { "name": "ball", "shape": { "type": "circle", "radius": 0.2 }, "position": [0, 5] }
  ]
})";
constexpr double kStartHeight = 5.0;

/// Longest wait for a child to write its autosave, ms: it starts a window and a run first, which
/// takes a few seconds on a loaded machine.
constexpr int kChildTimeoutMs = 60000;

/// A year in which no test runs: an autosave "saved" then is older than any other.
constexpr int kLongAgoYear = 2001;

std::chrono::milliseconds aMinute() { return std::chrono::minutes(1); }

/// Longest wait for Xvfb to open its display, ms.
constexpr int kXvfbStartMs = 10000;

/// The Xvfb that xvfbDisplay() started, if any.
std::unique_ptr<QProcess>& xvfbProcess()
{
    static std::unique_ptr<QProcess> process;
    return process;
}

/// An X server of the test's own (Xvfb, the test command installs it), so that the children run as
/// on a desktop, through the xcb platform; started at the first call, stopped by stopXvfb().
/// Returns the display (":93"), or nothing where Xvfb is missing or does not start: the children
/// then run offscreen.
std::optional<QString> xvfbDisplay()
{
    static std::optional<QString> display;
    static bool tried = false;
    if (tried)
        return display;
    tried = true;
    const QString xvfb = QStandardPaths::findExecutable(QStringLiteral("Xvfb"));
    if (xvfb.isEmpty()) {
        qWarning("Xvfb not found: the killed app runs offscreen");
        return display;
    }
    // A display number no other server holds: its socket does not exist.
    for (int number = 90 + static_cast<int>(QCoreApplication::applicationPid() % 200); number < 1000; ++number) {
        const QString socket = QStringLiteral("/tmp/.X11-unix/X%1").arg(number);
        if (QFileInfo::exists(socket) || QFileInfo::exists(QStringLiteral("/tmp/.X%1-lock").arg(number)))
            continue;
        auto process = std::make_unique<QProcess>();
        process->start(xvfb, {QStringLiteral(":%1").arg(number), QStringLiteral("-screen"), QStringLiteral("0"),
                              QStringLiteral("1280x800x24"), QStringLiteral("-nolisten"), QStringLiteral("tcp")});
        if (!process->waitForStarted())
            break;
        QElapsedTimer clock;
        clock.start();
        while (!QFileInfo::exists(socket) && process->state() == QProcess::Running && clock.elapsed() < kXvfbStartMs)
            QTest::qWait(50);
        if (QFileInfo::exists(socket) && process->state() == QProcess::Running) {
            xvfbProcess() = std::move(process);
            display = QStringLiteral(":%1").arg(number);
            return display;
        }
        process->kill();
        process->waitForFinished();
    }
    qWarning("Xvfb did not start: the killed app runs offscreen");
    return display;
}
/// Stops the Xvfb that xvfbDisplay() started.
void stopXvfb()
{
    if (std::unique_ptr<QProcess>& process = xvfbProcess()) {
        process->terminate();
        if (!process->waitForFinished())
            process->kill();
        process.reset();
    }
}

/// `impetus --run SCENE` with its app data (and settings) under `home`, autosaving every 0.2 s, on
/// the test's X display (xvfbDisplay()), or offscreen where there is none.
std::unique_ptr<QProcess> startApp(const QString& home, const QString& scene)
{
    auto process = std::make_unique<QProcess>();
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    if (const std::optional<QString> display = xvfbDisplay()) {
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
        environment.insert(QStringLiteral("DISPLAY"), *display);
    } else {
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    }
    environment.insert(QStringLiteral("XDG_DATA_HOME"), home + QStringLiteral("/data"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home + QStringLiteral("/config"));
    environment.insert(QStringLiteral("IMPETUS_AUTOSAVE_INTERVAL"), QStringLiteral("0.2"));
    process->setProcessEnvironment(environment);
    process->start(kImpetus, {QStringLiteral("--run"), scene});
    return process;
}

/// Where a child started by startApp() keeps its autosaves: AppDataLocation is
/// $XDG_DATA_HOME/<organisation>/<application>.
QString childAutosaveFolder(const QString& home) { return home + QStringLiteral("/data/impetus/impetus/autosave"); }

/// The autosaved scene of process `pid` in `folder`, once it holds a world whose ball has fallen;
/// nullopt when none appears within kChildTimeoutMs.
std::optional<model::World> waitForRunAutosave(const QString& folder, qint64 pid)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < kChildTimeoutMs) {
        const QStringList files =
            QDir(folder).entryList({QStringLiteral("autosave-%1-*.json").arg(pid)}, QDir::Files);
        for (const QString& name : files) {
            model::SceneLoadResult scene = model::loadSceneFile(QDir(folder).filePath(name).toStdString());
            if (scene.ok() && scene.world->bodies.at(0).state.position.y() < kStartHeight - 0.01)
                return std::move(scene.world);
        }
        QTest::qWait(50);
    }
    return std::nullopt;
}

/// Answers the next modal message box called `objectName` by clicking its button `buttonName`
/// (or its OK button when empty), and records its text.
struct BoxAnswer {
    bool seen = false;
    QString text;
};
void answerBox(QObject* context, BoxAnswer& answer, const QString& objectName, const QString& buttonName)
{
    QTimer::singleShot(0, context, [&answer, context, objectName, buttonName] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box || box->objectName() != objectName) {
            // Not open yet: look again once the event loop has run.
            answerBox(context, answer, objectName, buttonName);
            return;
        }
        answer.seen = true;
        answer.text = box->text() + QLatin1Char('\n') + box->informativeText();
        QAbstractButton* button = buttonName.isEmpty() ? box->button(QMessageBox::Ok)
                                                       : box->findChild<QAbstractButton*>(buttonName);
        QVERIFY(button);
        button->click();
    });
}

} // namespace

class AutosaveTest : public QObject {
    Q_OBJECT

private slots:
    void cleanupTestCase() { stopXvfb(); }
    void killedAppIsOfferedAndRestoredAndALiveOneIsLeftAlone();
    void cleanQuitRemovesTheAutosaveAndAnUnchangedSceneHasNone();
    void discardDeletesTheAutosave();
    void unreadableAutosaveIsKeptAsideWithAMessage();
    void intervalComesFromTheEnvironment();

private:
    test::TemporarySettings m_settings;
};

void AutosaveTest::killedAppIsOfferedAndRestoredAndALiveOneIsLeftAlone()
{
    QTemporaryDir home;
    QVERIFY(home.isValid());
    const QString scenePath = QDir(home.path()).filePath(QStringLiteral("falling ball.json"));
    QVERIFY(test::writeFile(scenePath, kFallingBall));
    const QString folder = childAutosaveFolder(home.path());
    // Where Xvfb is installed (the test command installs it), the children run on its display; a
    // machine whose Xvfb cannot start runs them offscreen, with a warning, rather than fail here.
    if (const std::optional<QString> display = xvfbDisplay())
        qInfo("the children run on Xvfb's display %s", qPrintable(*display));
    else
        qInfo("the children run offscreen");

    // Two Impetus at once on one folder: each autosaves its own run, and the second, starting
    // while the first is alive, does not take the first's autosave for an orphan (it would then
    // sit in a modal question and never autosave).
    std::unique_ptr<QProcess> killed = startApp(home.path(), scenePath);
    QVERIFY(killed->waitForStarted());
    const qint64 killedPid = killed->processId(); // QProcess forgets it once the process is gone
    const std::optional<model::World> lost = waitForRunAutosave(folder, killedPid);
    QVERIFY2(lost, qPrintable(QString::fromLocal8Bit(killed->readAllStandardError())));
    std::unique_ptr<QProcess> alive = startApp(home.path(), scenePath);
    QVERIFY(alive->waitForStarted());
    QVERIFY2(waitForRunAutosave(folder, alive->processId()),
             qPrintable(QString::fromLocal8Bit(alive->readAllStandardError())));

    // SIGKILL: no destructor, no close event, the lock stays behind.
    killed->kill();
    QVERIFY(killed->waitForFinished());
    QCOMPARE(killed->exitStatus(), QProcess::CrashExit);
    // The last autosave before the kill is what can be restored.
    const std::optional<model::World> last = waitForRunAutosave(folder, killedPid);
    QVERIFY(last);
    QVERIFY(last->bodies[0].state.position.y() <= lost->bodies[0].state.position.y());

    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Autosave autosave(window.document(), folder, aMinute());
    QDateTime savedAt;
    {
        // Only the dead one is an orphan: the live one's lock is held.
        const std::vector<OrphanedAutosave> orphans = autosave.findOrphans();
        QCOMPARE(orphans.size(), std::size_t{1});
        QVERIFY(QFileInfo(orphans[0].scenePath).fileName().startsWith(QStringLiteral("autosave-%1-").arg(killedPid)));
        QVERIFY(orphans[0].problems.isEmpty());
        QCOMPARE(orphans[0].originalFile, QFileInfo(scenePath).absoluteFilePath());
        savedAt = orphans[0].savedAt;
        QVERIFY(qAbs(savedAt.secsTo(QDateTime::currentDateTimeUtc())) < kChildTimeoutMs / 1000);
        for (const OrphanedAutosave& orphan : orphans)
            orphan.lock->unlock(); // offered below, by offerRecovery's own search
    }

    BoxAnswer answer;
    answerBox(this, answer, QStringLiteral("recoverAutosaveBox"), QStringLiteral("restoreAutosaveButton"));
    QVERIFY(offerRecovery(&window, autosave));
    QVERIFY(answer.seen);
    // The question names the scene's file and when the work was saved.
    QVERIFY2(answer.text.contains(QStringLiteral("falling ball.json")), qPrintable(answer.text));
    const QString when = QLocale().toString(savedAt.toLocalTime(), QLocale::LongFormat);
    QVERIFY2(answer.text.contains(when), qPrintable(answer.text + QStringLiteral(" / ") + when));

    // The run's state is back, the document is modified and still belongs to the original file.
    const model::World& restored = window.document().world();
    QCOMPARE(restored.bodies.at(0).state.position.y(), last->bodies[0].state.position.y());
    QCOMPARE(restored.bodies.at(0).state.velocity.y(), last->bodies[0].state.velocity.y());
    QVERIFY(window.document().isModified());
    QVERIFY(window.document().hasUnsavedEdits());
    QCOMPARE(window.document().filePath(), QFileInfo(scenePath).absoluteFilePath());
    QVERIFY(window.windowTitle().startsWith(QStringLiteral("falling ball[*]")));
    // The orphan is gone; the work is autosaved again under this process.
    QVERIFY(autosave.findOrphans().empty());
    QVERIFY(QFileInfo::exists(autosave.scenePath()));

    // Save writes where the user expects: the original file, now with the ball where it fell.
    QVERIFY(window.save());
    model::SceneLoadResult saved = model::loadSceneFile(scenePath.toStdString());
    QVERIFY(saved.ok());
    QCOMPARE(saved.world->bodies[0].state.position.y(), last->bodies[0].state.position.y());
    QVERIFY(!window.document().isModified());

    alive->kill();
    QVERIFY(alive->waitForFinished());
}

void AutosaveTest::cleanQuitRemovesTheAutosaveAndAnUnchangedSceneHasNone()
{
    QTemporaryDir folder;
    SceneDocument document;
    QString written;
    {
        Autosave autosave(document, folder.path(), aMinute());
        written = autosave.scenePath();
        QVERIFY(autosave.saveNow());
        QVERIFY(!QFileInfo::exists(written)); // nothing to lose yet

        model::WorldSettings settings = document.world().settings;
        settings.drag = 0.5;
        document.setWorldSettings(settings, QStringLiteral("Change drag"));
        QVERIFY(autosave.saveNow());
        QVERIFY(QFileInfo::exists(written));
        QVERIFY(QFileInfo::exists(autosave.infoPath()));
        model::SceneLoadResult scene = model::loadSceneFile(written.toStdString());
        QVERIFY(scene.ok());
        QCOMPARE(scene.world->settings.drag, 0.5);

        // Saved (or undone to the file): the autosave goes.
        document.undoStack()->undo();
        QVERIFY(autosave.saveNow());
        QVERIFY(!QFileInfo::exists(written));
        document.undoStack()->redo();

        // A run start autosaves at once.
        QVERIFY(autosave.saveNow());
        QFile::remove(written);
        document.runner().play();
        QVERIFY(QFileInfo::exists(written));
        document.runner().pause();
    }
    QVERIFY(!QFileInfo::exists(written));
    QVERIFY(QDir(folder.path()).entryList(QDir::Files).isEmpty());
}

void AutosaveTest::discardDeletesTheAutosave()
{
    QTemporaryDir folder;
    // An orphan as a killed process leaves it: scene and description, no live lock.
    const QString scene = QDir(folder.path()).filePath(QStringLiteral("autosave-1-1.json"));
    QVERIFY(test::writeFile(scene, kFallingBall));
    QVERIFY(test::writeFile(QDir(folder.path()).filePath(QStringLiteral("autosave-1-1.info")),
                            R"({"file": "", "name": "untitled", "savedAt": "2001-02-03T04:05:06.000Z"})"));

    MainWindow window;
    window.setScene(model::World{}, QStringLiteral("empty"));
    Autosave autosave(window.document(), folder.path(), aMinute());
    BoxAnswer answer;
    answerBox(this, answer, QStringLiteral("recoverAutosaveBox"), QStringLiteral("discardAutosaveButton"));
    QVERIFY(!offerRecovery(&window, autosave));
    QVERIFY(answer.seen);
    QVERIFY2(answer.text.contains(QStringLiteral("untitled")), qPrintable(answer.text));
    QVERIFY2(answer.text.contains(QString::number(kLongAgoYear)), qPrintable(answer.text));
    QVERIFY(!QFileInfo::exists(scene));
    QVERIFY(window.document().world().bodies.empty());
    QVERIFY(!window.document().isModified());
}

void AutosaveTest::unreadableAutosaveIsKeptAsideWithAMessage()
{
    QTemporaryDir folder;
    const QString scene = QDir(folder.path()).filePath(QStringLiteral("autosave-2-2.json"));
    QVERIFY(test::writeFile(scene, "{ \"format\": \"impetus-scene\", \"version\": 1, \"bodies\": [ {"));
    QVERIFY(test::writeFile(QDir(folder.path()).filePath(QStringLiteral("autosave-2-2.info")), "not json"));

    MainWindow window;
    window.setScene(model::World{}, QStringLiteral("empty"));
    Autosave autosave(window.document(), folder.path(), aMinute());
    BoxAnswer answer;
    answerBox(this, answer, QStringLiteral("unreadableAutosaveBox"), QString());
    QVERIFY(!offerRecovery(&window, autosave));
    QVERIFY(answer.seen);
    // The message names the problem and where the file was kept.
    QVERIFY2(answer.text.contains(QStringLiteral("invalid JSON")) || answer.text.contains(QStringLiteral("autosave-2-2")),
             qPrintable(answer.text));
    QVERIFY2(answer.text.contains(QStringLiteral("unreadable")), qPrintable(answer.text));
    QVERIFY(!QFileInfo::exists(scene));
    QVERIFY(QFileInfo::exists(QDir(folder.path()).filePath(QStringLiteral("unreadable/autosave-2-2.json"))));
    QVERIFY(autosave.findOrphans().empty()); // never offered again
    QVERIFY(window.document().world().bodies.empty());
}

void AutosaveTest::intervalComesFromTheEnvironment()
{
    qputenv("IMPETUS_AUTOSAVE_INTERVAL", "0.5");
    QCOMPARE(Autosave::intervalFromEnvironment(), std::chrono::milliseconds(500));
    qputenv("IMPETUS_AUTOSAVE_INTERVAL", "soon");
    QCOMPARE(Autosave::intervalFromEnvironment(), aMinute());
    qputenv("IMPETUS_AUTOSAVE_INTERVAL", "-1");
    QCOMPARE(Autosave::intervalFromEnvironment(), aMinute());
    qunsetenv("IMPETUS_AUTOSAVE_INTERVAL");
    QCOMPARE(Autosave::intervalFromEnvironment(), aMinute());
}

QTEST_MAIN(AutosaveTest)
#include "autosave_test.moc"
