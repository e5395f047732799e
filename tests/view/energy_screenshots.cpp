// Not a test: the energy ledger picture of docs/explainers.md, taken from the real window
// with View › Energy Ledger open on the default example after a few seconds of running.
// scripts/screenshots runs it under Xvfb. Usage: energy_screenshots OUTPUT_DIRECTORY

#include "screenshot_files.h"
#include "test_settings.h"
#include "view/main_window.h"
#include "view/simulation_runner.h"

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QTest>

#include <cstdio>

using impetus::view::MainWindow;

namespace {

/// The window's size in the picture, px: small enough to read on a page.
constexpr int kWidth = 1100;
constexpr int kHeight = 760;
/// Steps run before the picture (6 s at the default step), in batches as a run shows them.
constexpr int kBatches = 72;
constexpr int kStepsPerBatch = 20;

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: energy_screenshots OUTPUT_DIRECTORY\n");
        return 2;
    }
    const impetus::view::test::TemporarySettings settings;
    const QDir directory(QString::fromLocal8Bit(argv[1]));
    MainWindow window;
    if (!window.openScene(QStringLiteral(":/examples/default.json")).isEmpty())
        return 1;
    if (!impetus::view::test::showWindowAt(window, kWidth, kHeight))
        return 1;
    window.showEnergyLedger();
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("energyLedgerDock"));
    if (dock == nullptr)
        return 1;
    window.resizeDocks({dock}, {kHeight / 2}, Qt::Vertical);
    for (int i = 0; i < kBatches; ++i)
        window.runner().stepBy(kStepsPerBatch);
    QTest::qWait(100);
    return impetus::view::test::saveGrab(window, directory, QStringLiteral("energy-ledger.png")) ? 0 : 1;
}
