// Not a test: the integrator ghosts picture of docs/explainers.md, taken from the real window with
// View › Compare Integrators on the mass-on-a-spring example, the ghosts' step at 1/30 s, after a
// few seconds of running. scripts/screenshots runs it under Xvfb.
// Usage: ghost_screenshots OUTPUT_DIRECTORY

#include "screenshot_files.h"
#include "test_settings.h"
#include "view/main_window.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QSlider>
#include <QTest>

#include <cstdio>

using impetus::view::MainWindow;

namespace {

/// The window's size in the picture, px: small enough to read on a page.
constexpr int kWidth = 1200;
constexpr int kHeight = 760;
/// The dock's width, px: room for the readout's columns and the chart.
constexpr int kDockWidth = 470;
/// Steps run before the picture (3.5 s at the scene's 1/240 s), in batches as a run shows them:
/// long enough for explicit Euler's ghost to spiral visibly out, and caught half way round.
constexpr int kBatches = 42;
constexpr int kStepsPerBatch = 20;

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: ghost_screenshots OUTPUT_DIRECTORY\n");
        return 2;
    }
    const impetus::view::test::TemporarySettings settings;
    const QDir directory(QString::fromLocal8Bit(argv[1]));
    MainWindow window;
    if (!window.openScene(QStringLiteral(":/examples/spring.json")).isEmpty())
        return 1;
    if (!impetus::view::test::showWindowAt(window, kWidth, kHeight))
        return 1;
    auto* action = window.findChild<QAction*>(QStringLiteral("compareIntegratorsAction"));
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("integratorGhostsDock"));
    if (action == nullptr || dock == nullptr)
        return 1;
    action->trigger();
    window.resizeDocks({dock}, {kDockWidth}, Qt::Horizontal);
    // The attributes above it take what the readout and the chart leave.
    window.resizeDocks({dock}, {kHeight}, Qt::Vertical);
    auto* slider = dock->findChild<QSlider*>(QStringLiteral("ghostTimeStepSlider"));
    if (slider == nullptr)
        return 1;
    slider->setValue(slider->maximum());
    for (int i = 0; i < kBatches; ++i)
        window.runner().stepBy(kStepsPerBatch);
    QTest::qWait(100);
    return impetus::view::test::saveGrab(window, directory, QStringLiteral("integrator-ghosts.png")) ? 0 : 1;
}
