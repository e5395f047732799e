// The `impetus` command line, run as a user or a teacher's script runs it: the real binary, mostly
// its --screenshot mode.

#include <QColor>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <optional>

namespace {

/// The built `impetus` binary (set by CMake).
const QString kImpetus = QStringLiteral(IMPETUS_APP_PATH);

/// A scene with a red ball 2 m above a fixed blue ground box, no gravity: it stays put.
const char kBallAboveGround[] = R"({
  "format": "impetus-scene",
  "version": 1,
  "world": { "gravity": [0, 0] },
  "bodies": [
    { "name": "ground", "shape": { "type": "box", "width": 4, "height": 0.5 },
      "position": [0, 0], "fixed": true, "color": "#0000ff" },
    { "name": "ball", "shape": { "type": "circle", "radius": 0.4 },
      "position": [0, 2], "color": "#ff0000" }
  ],
  "springs": [],
  "joints": []
}
)";

struct Run {
    int exitCode = -1;
    QString stdErr;
};

Run runImpetus(const QStringList& arguments)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    process.setProcessEnvironment(environment);
    process.start(kImpetus, arguments);
    if (!process.waitForFinished(60000)) {
        process.kill();
        process.waitForFinished();
        return {};
    }
    if (process.exitStatus() != QProcess::NormalExit)
        return {};
    return {process.exitCode(), QString::fromLocal8Bit(process.readAllStandardError())};
}

bool writeFile(const QString& path, const QByteArray& contents)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(contents) == contents.size();
}

/// Mean row of the pixels close to `target`, if any.
std::optional<double> meanRowOf(const QImage& image, const QColor& target)
{
    double sum = 0;
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (qAbs(c.red() - target.red()) < 30 && qAbs(c.green() - target.green()) < 30
                && qAbs(c.blue() - target.blue()) < 30) {
                sum += y;
                ++count;
            }
        }
    }
    if (count == 0)
        return std::nullopt;
    return sum / count;
}

} // namespace

class CommandLineTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void writesPngOfRequestedSize();
    void drawsWithYUp();
    void keepsLoadTimeFraming();
    void usesDefaultSceneWithoutArgument();
    void drawsCollidingBodiesRed();
    void badSceneExitsWithTwo();
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void unwritableOutputExitsWithOne();
    void screenshotOfRunThatBlowsUpExitsWithOne();
    void helpExitsWithZero();

private:
    QString scenePath() const { return m_dir->filePath(QStringLiteral("scene.json")); }
    QString outputPath() const { return m_dir->filePath(QStringLiteral("out.png")); }

    std::optional<QTemporaryDir> m_dir;
};

void CommandLineTest::init()
{
    m_dir.emplace();
    QVERIFY(m_dir->isValid());
    QVERIFY(writeFile(scenePath(), kBallAboveGround));
}

void CommandLineTest::writesPngOfRequestedSize()
{
    const Run run = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--size"),
                                QStringLiteral("320x240"), QStringLiteral("--run-for"), QStringLiteral("0.5"),
                                scenePath()});
    QVERIFY2(run.exitCode == 0, qPrintable(run.stdErr));
    QImage image;
    QVERIFY(image.load(outputPath(), "PNG"));
    QCOMPARE(image.size(), QSize(320, 240));
}

void CommandLineTest::drawsWithYUp()
{
    const Run run = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--size"),
                                QStringLiteral("400x300"), scenePath()});
    QVERIFY2(run.exitCode == 0, qPrintable(run.stdErr));
    QImage image;
    QVERIFY(image.load(outputPath(), "PNG"));
    const std::optional<double> ball = meanRowOf(image, QColor(0xff, 0, 0));
    QVERIFY(ball.has_value());
    // The fixed ground is drawn darker than its colour, so look for the darker blue.
    const std::optional<double> ground = meanRowOf(image, QColor(0x00, 0x00, 0xcc));
    QVERIFY(ground.has_value());
    QVERIFY2(*ball < *ground, qPrintable(QStringLiteral("ball row %1, ground row %2").arg(*ball).arg(*ground)));
}

void CommandLineTest::keepsLoadTimeFraming()
{
    // Under upward gravity the ball rises away from the ground. As in the window, the picture
    // stays framed on the scene as loaded: the ground does not move, the ball leaves.
    QByteArray falling(kBallAboveGround);
    falling.replace(R"("gravity": [0, 0])", R"("gravity": [0, 9.81])");
    QVERIFY(writeFile(scenePath(), falling));
    const QColor groundColor(0x00, 0x00, 0xcc);
    const QString later = m_dir->filePath(QStringLiteral("later.png"));

    const Run first = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--size"),
                                  QStringLiteral("400x300"), scenePath()});
    QVERIFY2(first.exitCode == 0, qPrintable(first.stdErr));
    const Run second = runImpetus({QStringLiteral("--screenshot"), later, QStringLiteral("--size"),
                                   QStringLiteral("400x300"), QStringLiteral("--run-for"), QStringLiteral("3"),
                                   scenePath()});
    QVERIFY2(second.exitCode == 0, qPrintable(second.stdErr));

    QImage before;
    QImage after;
    QVERIFY(before.load(outputPath(), "PNG"));
    QVERIFY(after.load(later, "PNG"));
    const std::optional<double> groundBefore = meanRowOf(before, groundColor);
    const std::optional<double> groundAfter = meanRowOf(after, groundColor);
    QVERIFY(groundBefore && groundAfter);
    QVERIFY(qAbs(*groundBefore - *groundAfter) < 0.5);
    QVERIFY(meanRowOf(before, QColor(0xff, 0, 0)).has_value());
}

void CommandLineTest::drawsCollidingBodiesRed()
{
    // The ball falls 1.2 m onto the ground and rests there: in the picture after 2 s both bodies
    // are red (contract: fill and outline, whatever their own colour), and neither shows its own
    // colour. Before the fall, both show their own colours and nothing is red.
    QByteArray falling(kBallAboveGround);
    falling.replace(R"("gravity": [0, 0])", R"("gravity": [0, -9.81])");
    QVERIFY(writeFile(scenePath(), falling));
    const QColor red(0xdc, 0x26, 0x26);
    const QColor ownBall(0xff, 0, 0);
    const QColor ownGround(0x00, 0x00, 0xcc);

    const Run before = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--size"),
                                   QStringLiteral("400x300"), scenePath()});
    QVERIFY2(before.exitCode == 0, qPrintable(before.stdErr));
    QImage image;
    QVERIFY(image.load(outputPath(), "PNG"));
    QVERIFY(meanRowOf(image, ownBall).has_value());
    QVERIFY(meanRowOf(image, ownGround).has_value());
    QVERIFY(!meanRowOf(image, red).has_value());

    const Run after = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--size"),
                                  QStringLiteral("400x300"), QStringLiteral("--run-for"), QStringLiteral("2"),
                                  scenePath()});
    QVERIFY2(after.exitCode == 0, qPrintable(after.stdErr));
    QVERIFY(image.load(outputPath(), "PNG"));
    QVERIFY(meanRowOf(image, red).has_value());
    QVERIFY(!meanRowOf(image, ownBall).has_value());
    QVERIFY(!meanRowOf(image, ownGround).has_value());
}

void CommandLineTest::usesDefaultSceneWithoutArgument()
{
    const Run run = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--run-for"),
                                QStringLiteral("1")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.stdErr));
    QImage image;
    QVERIFY(image.load(outputPath(), "PNG"));
    QCOMPARE(image.size(), QSize(1280, 720));
}

void CommandLineTest::badSceneExitsWithTwo()
{
    const QString badScene = m_dir->filePath(QStringLiteral("bad.json"));
    QVERIFY(writeFile(badScene, R"({ "format": "impetus-scene", "version": 1, "bodies": 3 })"));
    const Run run = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--size"),
                                QStringLiteral("320x240"), badScene});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.stdErr.contains(badScene));
    QVERIFY(!QFile::exists(outputPath()));

    const Run missing = runImpetus({QStringLiteral("--screenshot"), outputPath(),
                                    m_dir->filePath(QStringLiteral("missing.json"))});
    QCOMPARE(missing.exitCode, 2);
    QVERIFY(!QFile::exists(outputPath()));
}

void CommandLineTest::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    const QString out = QStringLiteral("OUT");
    QTest::newRow("size-not-wxh") << QStringList{QStringLiteral("--screenshot"), out, QStringLiteral("--size"),
                                                 QStringLiteral("big")};
    QTest::newRow("size-zero") << QStringList{QStringLiteral("--screenshot"), out, QStringLiteral("--size"),
                                              QStringLiteral("0x240")};
    QTest::newRow("run-for-negative") << QStringList{QStringLiteral("--screenshot"), out,
                                                     QStringLiteral("--run-for"), QStringLiteral("-1")};
    QTest::newRow("run-for-nan") << QStringList{QStringLiteral("--screenshot"), out, QStringLiteral("--run-for"),
                                                QStringLiteral("nan")};
    QTest::newRow("unknown-option") << QStringList{QStringLiteral("--screenshot"), out,
                                                   QStringLiteral("--frobnicate")};
    QTest::newRow("two-scenes") << QStringList{QStringLiteral("--screenshot"), out, QStringLiteral("a.json"),
                                               QStringLiteral("b.json")};
    QTest::newRow("size-without-screenshot") << QStringList{QStringLiteral("--size"), QStringLiteral("320x240")};
}

void CommandLineTest::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    arguments.replaceInStrings(QStringLiteral("OUT"), outputPath());
    const Run run = runImpetus(arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(!run.stdErr.isEmpty());
    QVERIFY(!QFile::exists(outputPath()));
}

void CommandLineTest::unwritableOutputExitsWithOne()
{
    const QString unwritable = m_dir->filePath(QStringLiteral("no-such-folder/out.png"));
    const Run run = runImpetus({QStringLiteral("--screenshot"), unwritable, QStringLiteral("--size"),
                                QStringLiteral("320x240"), scenePath()});
    QCOMPARE(run.exitCode, 1);
    QVERIFY(!run.stdErr.isEmpty());
}

void CommandLineTest::screenshotOfRunThatBlowsUpExitsWithOne()
{
    // A spring far too stiff for the step: the state stops being a number, the contract's exit 1
    // naming the body and the time, and no picture of it.
    QVERIFY(writeFile(scenePath(), R"({ "format": "impetus-scene", "version": 1,
        "world": { "gravity": [0, 0], "integrator": "euler", "timeStep": 0.1 },
        "bodies": [ { "name": "bob", "shape": { "type": "circle", "radius": 0.05 }, "position": [1, 0], "mass": 0.001 } ],
        "springs": [ { "bodyA": "bob", "anchorA": [0, 0], "bodyB": null, "anchorB": [0, 0],
                       "stiffness": 1000000, "restLength": 0 } ] })"));
    const Run run = runImpetus({QStringLiteral("--screenshot"), outputPath(), QStringLiteral("--run-for"),
                                QStringLiteral("500"), scenePath()});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.stdErr.contains(QStringLiteral("non-finite")) && run.stdErr.contains(QStringLiteral("“bob”"))
                 && run.stdErr.contains(QStringLiteral("t = ")),
             qPrintable(run.stdErr));
    QVERIFY(!QFile::exists(outputPath()));
}

void CommandLineTest::helpExitsWithZero()
{
    const Run run = runImpetus({QStringLiteral("--help")});
    QCOMPARE(run.exitCode, 0);
}

QTEST_MAIN(CommandLineTest)
#include "command_line_test.moc"
