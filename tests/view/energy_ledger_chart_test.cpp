// View › Energy Ledger on the real window, offscreen: the chart gets a row per step from the
// engine's ledger while it is open (and the steps are not booked once it is closed), its top edge
// is the starting energy, and the bands show in a grab.

#include "test_settings.h"
#include "view/energy_ledger_chart.h"
#include "view/main_window.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QChartView>
#include <QDockWidget>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTest>

using impetus::view::EnergyLedgerChart;
using impetus::view::MainWindow;

class EnergyLedgerChartTest : public QObject {
    Q_OBJECT

private slots:
    void viewMenuOpensTheChartWhichFillsAsTheSceneRuns();

private:
    impetus::view::test::TemporarySettings m_settings;
};

void EnergyLedgerChartTest::viewMenuOpensTheChartWhichFillsAsTheSceneRuns()
{
    MainWindow window;
    QVERIFY(window.openScene(QStringLiteral(":/examples/default.json")).isEmpty());
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(!window.runner().sampleRequest().ledger);

    // The View menu holds it, as a user finds it.
    QAction* action = nullptr;
    for (QAction* menu : window.menuBar()->actions()) {
        if (menu->menu() != nullptr) {
            for (QAction* item : menu->menu()->actions()) {
                if (item->objectName() == QStringLiteral("energyLedgerAction"))
                    action = item;
            }
        }
    }
    QVERIFY(action);
    action->trigger();
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("energyLedgerDock"));
    QVERIFY(dock);
    auto* chart = dock->findChild<EnergyLedgerChart*>();
    QVERIFY(chart);
    QVERIFY(window.runner().sampleRequest().ledger);

    // Two seconds in batches, as a run shows them: a row per step.
    for (int i = 0; i < 24; ++i)
        window.runner().stepBy(20);
    QCOMPARE(chart->pointCount(), std::size_t{480});

    // "Start E₀ J = now E J + losses L J (off by ε J)": the ledger closes.
    const QRegularExpression pattern(QStringLiteral("Start (\\S+) J = now (\\S+) J \\+ losses (\\S+) J \\(off by (\\S+) J\\)"));
    const QRegularExpressionMatch match = pattern.match(chart->readout());
    QVERIFY2(match.hasMatch(), qPrintable(chart->readout()));
    const double start = QLocale().toDouble(match.captured(1));
    const double gap = QLocale().toDouble(match.captured(4));
    QVERIFY(start > 0);
    QVERIFY2(gap < 1e-9 * start, qPrintable(chart->readout()));

    // The bands are drawn: the kinetic band's blue is in the grab of the chart.
    auto* view = chart->findChild<QChartView*>();
    QVERIFY(view);
    const QImage image = view->grab().toImage();
    int bluish = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.blue() > 200 && c.red() < 90 && c.green() > 80 && c.green() < 140)
                ++bluish;
        }
    }
    QVERIFY2(bluish > 500, qPrintable(QString::number(bluish)));

    // Closed, it is gone, and the steps are no longer booked.
    dock->close();
    QTRY_VERIFY(!window.runner().sampleRequest().ledger);
}

QTEST_MAIN(EnergyLedgerChartTest)
#include "energy_ledger_chart_test.moc"
