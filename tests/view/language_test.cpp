// The language of the window: German and Spanish translations built into the program, chosen from
// the system or from View › Language, numbers in the locale's format, scene files always with a
// decimal point. Driven as a user would: the menus are read, a value is typed into the pane.

#include "model/scene_io.h"
#include "test_graphs.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/collision_inspector.h"
#include "view/language.h"
#include "view/graph_panel.h"
#include "view/graph_quantity.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/sat_explainer.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/tools/measure_tools.h"
#include "view/tools/probe_tool.h"

#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QFile>
#include <QHash>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>

#include <cmath>
#include <initializer_list>
#include <variant>

using impetus::view::MainWindow;
namespace model = impetus::model;
namespace test = impetus::view::test;
namespace view = impetus::view;

namespace {

/// The titles of the menu bar's menus, in order.
QStringList menuTitles(MainWindow& window)
{
    QStringList titles;
    for (const QAction* action : window.menuBar()->actions())
        titles << action->text();
    return titles;
}

/// The texts of the entries of the menu whose title is `title`, sub-menus included.
QStringList menuEntries(MainWindow& window, const QString& title)
{
    QStringList entries;
    for (const QAction* action : window.menuBar()->actions())
        if (action->text() == title && action->menu())
            for (const QAction* entry : action->menu()->actions())
                if (!entry->isSeparator())
                    entries << entry->text();
    return entries;
}

/// The letter after the single `&` of `text` (its keyboard mnemonic), lower-cased; null when none.
QChar mnemonic(const QString& text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        if (text[i + 1] != QLatin1Char('&'))
            return text[i + 1].toLower();
        ++i; // "&&" is a literal ampersand, not a mnemonic.
    }
    return {};
}

/// "menu: letter shared by A and B" for each mnemonic two entries of `actions` share.
QStringList mnemonicClashes(const QString& menu, const QList<QAction*>& actions)
{
    QStringList clashes;
    QHash<QChar, QString> owner;
    for (const QAction* action : actions) {
        if (action->isSeparator() || !action->isVisible())
            continue;
        const QChar letter = mnemonic(action->text());
        if (letter.isNull())
            continue;
        if (owner.contains(letter))
            clashes << QStringLiteral("%1: %2 shared by %3 and %4").arg(menu, letter, owner[letter], action->text());
        else
            owner.insert(letter, action->text());
    }
    return clashes;
}

/// The status bar label whose accessible name is `name`, or nullptr.
QLabel* statusLabel(MainWindow& window, const QString& name)
{
    for (QLabel* label : window.statusBar()->findChildren<QLabel*>())
        if (label->accessibleName() == name)
            return label;
    return nullptr;
}

/// Shows `window` at 1200 × 750 px and waits until it is active.
bool showLarge(MainWindow& window)
{
    window.resize(1200, 750);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

/// Chooses `code` as a user would have in View › Language before this start, then starts the app's
/// language as impetus_main does. True when a translation was installed.
bool startIn(const QString& code)
{
    view::setLanguageSetting(code);
    return view::applyLanguage(*QCoreApplication::instance(), view::chosenLocale());
}

/// A world with one ball of radius 0.5 m at (1.5, 2).
model::World ballWorld()
{
    model::World world;
    world.bodies.push_back(test::makeBody("ball", model::Circle{0.5}, impetus::Vec2(1.5, 2)));
    return world;
}

/// True when `text` has a number with a decimal point in it ("0.500"), which a German window
/// should not show.
bool hasDecimalPoint(const QString& text)
{
    static const QRegularExpression point(QStringLiteral("[0-9]\\.[0-9]"));
    return point.match(text).hasMatch();
}

/// Selects everything in `edit`, types `text` and presses Enter, as a user would.
void typeAndEnter(QLineEdit* edit, const QString& text)
{
    edit->setFocus();
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Delete);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

} // namespace

class LanguageTest : public QObject {
    Q_OBJECT

private slots:
    void cleanup();
    void germanWindowHasGermanMenus();
    void spanishWindowHasSpanishMenus();
    void newerMenusSpeakTheLanguage();
    void graphQuantitiesSpeakTheLanguage();
    void menuLettersAreUniqueInEachMenu();
    void englishNeedsNoTranslation();
    void numbersFollowTheLocaleButSceneFilesDoNot();
    void readoutsFollowTheLocale();
    void explainersFollowTheLocale();
    void languageMenuKeepsTheChoiceForTheNextStart();
    void unknownLanguageSettingMeansTheSystemLanguage();

private:
    test::TemporarySettings m_settings;
};

void LanguageTest::cleanup()
{
    // Back to the untranslated C locale, so that each test starts from the same place.
    view::setLanguageSetting(QString());
    view::applyLanguage(*QCoreApplication::instance(), QLocale::c());
}

void LanguageTest::germanWindowHasGermanMenus()
{
    QVERIFY(startIn(QStringLiteral("de")));
    MainWindow window;

    const QStringList titles = menuTitles(window);
    for (const char* title : {"&Datei", "&Bearbeiten", "&Ansicht", "&Werkzeuge", "&Simulation", "Beisp&iele"})
        QVERIFY2(titles.contains(QString::fromUtf8(title)), qPrintable(titles.join(QLatin1Char('|'))));
    QVERIFY(!titles.contains(QStringLiteral("&File")));

    const QStringList file = menuEntries(window, QStringLiteral("&Datei"));
    QVERIFY2(file.contains(QStringLiteral("Ö&ffnen…")) && file.contains(QStringLiteral("&Speichern")),
             qPrintable(file.join(QLatin1Char('|'))));
    const QStringList viewEntries = menuEntries(window, QStringLiteral("&Ansicht"));
    QVERIFY2(viewEntries.contains(QStringLiteral("&Projektormodus")) && viewEntries.contains(QStringLiteral("&Sprache")),
             qPrintable(viewEntries.join(QLatin1Char('|'))));
    QVERIFY(menuEntries(window, QStringLiteral("Beisp&iele")).contains(QStringLiteral("Pendel")));
    QCOMPARE(window.playAction()->text(), QStringLiteral("Start"));
    QCOMPARE(window.resetAction()->text(), QStringLiteral("Zurücksetzen"));
}

void LanguageTest::spanishWindowHasSpanishMenus()
{
    QVERIFY(startIn(QStringLiteral("es")));
    MainWindow window;

    const QStringList titles = menuTitles(window);
    for (const char* title : {"&Archivo", "&Editar", "&Ver", "&Herramientas", "&Simulación", "E&jemplos"})
        QVERIFY2(titles.contains(QString::fromUtf8(title)), qPrintable(titles.join(QLatin1Char('|'))));
    QCOMPARE(window.stepAction()->text(), QStringLiteral("Paso"));
    QVERIFY(menuEntries(window, QStringLiteral("E&jemplos")).contains(QStringLiteral("Péndulo")));
}

void LanguageTest::newerMenusSpeakTheLanguage()
{
    // Explain (SAT explainer, collision inspector) and View's energy ledger and integrator ghosts
    // came after the first translations; a user reads them in the window's language too.
    struct Expected {
        const char* code;
        const char* view;
        const char* explain;
        std::initializer_list<const char*> explainEntries;
        std::initializer_list<const char*> viewEntries;
    };
    const Expected languages[] = {
        {"de", "&Ansicht", "&Erklären", {"&Trennende Achsen", "&Stoßinspektor"},
         {"Energie&bilanz", "&Integratoren vergleichen"}},
        {"es", "&Ver", "E&xplicar", {"&Ejes separadores", "&Inspector de colisiones"},
         {"&Balance de energía", "&Comparar integradores"}},
    };
    for (const Expected& language : languages) {
        QVERIFY(startIn(QString::fromLatin1(language.code)));
        MainWindow window;
        const QString explain = QString::fromUtf8(language.explain);
        QVERIFY2(menuTitles(window).contains(explain), qPrintable(menuTitles(window).join(QLatin1Char('|'))));
        const QStringList explainEntries = menuEntries(window, explain);
        for (const char* entry : language.explainEntries)
            QVERIFY2(explainEntries.contains(QString::fromUtf8(entry)), qPrintable(explainEntries.join(QLatin1Char('|'))));
        const QStringList viewEntries = menuEntries(window, QString::fromUtf8(language.view));
        for (const char* entry : language.viewEntries)
            QVERIFY2(viewEntries.contains(QString::fromUtf8(entry)), qPrintable(viewEntries.join(QLatin1Char('|'))));
    }
}

// The graph's quantity boxes and its axis titles (GraphQuantity's labels, translated outside any
// class) are in the window's language too.
void LanguageTest::graphQuantitiesSpeakTheLanguage()
{
    // An aggregate, so that the lists live as long as the array (in a std::pair they would not).
    struct Expected {
        const char* code;
        std::initializer_list<const char*> labels;
    };
    const Expected languages[] = {
        {"de", {"Geschwindigkeit (m/s)", "kinetische Energie (J)", "Drehimpuls der Welt (kg·m²/s)"}},
        {"es", {"rapidez (m/s)", "energía cinética (J)", "momento angular del mundo (kg·m²/s)"}},
    };
    for (const auto& [code, labels] : languages) {
        QVERIFY(startIn(QString::fromLatin1(code)));
        MainWindow window;
        window.setScene(ballWorld(), QStringLiteral("ball"));
        window.newGraphAction()->trigger();
        QCOMPARE(window.graphPanels().size(), std::size_t{1});
        auto* yBox = window.graphPanels().front()->findChild<QComboBox*>(QStringLiteral("graphY"));
        QVERIFY(yBox);
        QStringList items;
        for (int i = 0; i < yBox->count(); ++i)
            items << yBox->itemText(i);
        for (const char* label : labels)
            QVERIFY2(items.contains(QString::fromUtf8(label)), qPrintable(items.join(QLatin1Char('|'))));
        QVERIFY(!items.contains(QStringLiteral("speed (m/s)")));
    }
}

void LanguageTest::menuLettersAreUniqueInEachMenu()
{
    // A translated menu whose entries share an underlined letter makes Alt+letter cycle instead of
    // choosing: each menu, and the menu bar, must give every entry a letter of its own.
    QStringList clashes;
    for (const char* code : {"de", "es"}) {
        QVERIFY(startIn(QString::fromLatin1(code)));
        MainWindow window;
        const QString prefix = QString::fromLatin1(code) + QLatin1String(", ");
        clashes << mnemonicClashes(prefix + QStringLiteral("menu bar"), window.menuBar()->actions());
        for (QMenu* menu : window.findChildren<QMenu*>())
            clashes << mnemonicClashes(prefix + menu->title(), menu->actions());
    }
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1String("; "))));
}

void LanguageTest::englishNeedsNoTranslation()
{
    QVERIFY(!startIn(QStringLiteral("en")));
    MainWindow window;
    QVERIFY(menuTitles(window).contains(QStringLiteral("&File")));
    QCOMPARE(QLocale().language(), QLocale::English);
}

void LanguageTest::numbersFollowTheLocaleButSceneFilesDoNot()
{
    QVERIFY(startIn(QStringLiteral("de")));
    MainWindow window;
    window.setScene(ballWorld(), QStringLiteral("ball"));
    window.document().setSelection(view::Selection{{0}, {}, {}});

    // The readouts and the pane write a decimal comma …
    QLabel* time = statusLabel(window, QStringLiteral("Simulierte Zeit"));
    QVERIFY(time);
    QCOMPARE(time->text(), QStringLiteral("t = 0,000 s"));
    auto* radius = window.propertyPane()->findChild<QLineEdit*>(QStringLiteral("radius"));
    QVERIFY(radius);
    QCOMPARE(radius->text(), QStringLiteral("0,5"));
    auto* positionX = window.propertyPane()->findChild<QLineEdit*>(QStringLiteral("positionX"));
    QCOMPARE(positionX->text(), QStringLiteral("1,5"));

    // … and read one: "0,25" is a quarter of a metre, not 25.
    typeAndEnter(radius, QStringLiteral("0,25"));
    const auto* circle = std::get_if<model::Circle>(&window.runner().world().bodies[0].shape);
    QVERIFY(circle);
    QCOMPARE(circle->radius, 0.25);

    // The scene file has a decimal point whatever the window's language.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ball.json"));
    QVERIFY(window.saveTo(path));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    QVERIFY2(text.contains(QStringLiteral("0.25")) && text.contains(QStringLiteral("1.5")), qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("0,25")) && !text.contains(QStringLiteral("1,5")), qPrintable(text));
    const model::SceneLoadResult loaded = model::loadSceneFile(path.toStdString());
    QVERIFY(loaded.ok());
    QCOMPARE(std::get<model::Circle>(loaded.world->bodies[0].shape).radius, 0.25);
}

// What a user reads off the window while measuring (the timeline, the probe's label, the ruler, the
// graph under the cursor, the vector legend) writes a decimal comma in German, as the pane does.
void LanguageTest::readoutsFollowTheLocale()
{
    QVERIFY(startIn(QStringLiteral("de")));
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showLarge(window));
    view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();

    // The ruler, from the ball's centre to the marker's top-right corner.
    QTest::keyClick(viewport, Qt::Key_M);
    auto* ruler = dynamic_cast<view::RulerTool*>(canvas.tool());
    QVERIFY(ruler);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0, 0)).toPoint());
    QTest::mouseMove(viewport, canvas.toView(QPointF(1, 0.5)).toPoint());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(2.1, 1.1)).toPoint());
    QCOMPARE(ruler->text(), QStringLiteral("2,371 m"));
    QTest::keyClick(viewport, Qt::Key_Escape);

    // A graph of the ball's x against time, and its probe, before half a second of run.
    window.document().setSelection(view::Selection{{0}, {}, {}});
    window.newGraphAction()->trigger();
    QCOMPARE(window.graphPanels().size(), std::size_t{1});
    view::GraphPanel* graph = window.graphPanels().front();
    auto* yBox = graph->findChild<QComboBox*>(QStringLiteral("graphY"));
    QVERIFY(yBox);
    const int x = yBox->findData(static_cast<int>(view::GraphQuantity::X));
    QVERIFY(x >= 0);
    yBox->setCurrentIndex(x);
    emit yBox->activated(x);
    QTest::keyClick(viewport, Qt::Key_I);
    auto* probe = dynamic_cast<view::ProbeTool*>(canvas.tool());
    QVERIFY(probe);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0, 0)).toPoint());
    QVERIFY(probe->body().has_value());
    window.runner().stepBy(120);
    QCOMPARE(window.runner().world().stepCount, std::int64_t{120});

    auto* timeline = window.findChild<QLabel*>(QStringLiteral("timelineLabel"));
    QVERIFY(timeline);
    QCOMPARE(timeline->text(), QStringLiteral("t = 0,500 s von 0,500 s"));

    const QStringList probeLines = probe->text().split(QLatin1Char('\n'));
    QVERIFY2(probeLines.contains(QStringLiteral("x = 1,000 m, y = 0,000 m")), qPrintable(probe->text()));
    QVERIFY2(probeLines.contains(QStringLiteral("vx = 2,000 m/s, vy = 0,000 m/s")), qPrintable(probe->text()));
    QVERIFY2(!hasDecimalPoint(probe->text()), qPrintable(probe->text()));

    // Hovered halfway along the run, the graph reads the time and x of the step under the cursor,
    // with decimal commas and a semicolon between the two.
    QChartView* chartView = graph->chartView();
    QChart* chart = chartView->chart();
    auto* timeAxis = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).front());
    QVERIFY(timeAxis);
    QTRY_VERIFY(chartView->isVisible() && !chart->plotArea().isEmpty() && timeAxis->max() >= 0.5);
    const QPointF middle = chart->mapToPosition(QPointF(0.25, 0.5), chart->series().front());
    QTest::mouseMove(chartView->viewport(), chartView->mapFromScene(middle));
    auto* readout = graph->findChild<QLabel*>(QStringLiteral("graphReadout"));
    QVERIFY(readout);
    static const QRegularExpression hovered(QStringLiteral("^time = 0,[0-9]+; x = 0,[0-9]+$"));
    QVERIFY2(hovered.match(readout->text()).hasMatch(), qPrintable(readout->text()));
    // The CSV it exports keeps the decimal point: its commas separate the columns.
    const QStringList rows = test::exportedCsvRows(*graph);
    QCOMPARE(rows.size(), 122); // the header and steps 0 to 120
    const QStringList last = rows.last().split(QLatin1Char(','));
    QCOMPARE(last.size(), 3);
    bool timeRead = false;
    bool xRead = false;
    QVERIFY2(std::abs(QLocale::c().toDouble(last[0], &timeRead) - 0.5) < 1e-9 && timeRead, qPrintable(rows.last()));
    QVERIFY2(std::abs(QLocale::c().toDouble(last[2], &xRead) - 1.0) < 1e-9 && xRead, qPrintable(rows.last()));

    // The vector legend gives its scale with a comma too.
    window.vectorAction(view::VectorKind::Velocity)->trigger();
    const QStringList legend = canvas.instruments().legendLines();
    QCOMPARE(legend.size(), 1);
    QVERIFY2(legend.front().endsWith(QStringLiteral("1 m/s = 0,25 m")), qPrintable(legend.front()));
}

// Explain › Separating Axes and the Collision Inspector, read in a German window, write their
// numbers with a decimal comma, and a semicolon between the numbers of a point, a vector or a
// matrix row, so that "(0,000; 1,000)" cannot be read as three numbers.
void LanguageTest::explainersFollowTheLocale()
{
    QVERIFY(startIn(QStringLiteral("de")));
    // A 2 m × 1 m box of 2 kg lying flat on a fixed slab, centred 0.25 m right of the slab's centre
    // and falling at 2 m/s: its bottom face, from x = −0.75 to 1.25 m, strikes at two points at once
    // (r_B×n = ∓1 m, 1/I_B = 1.2 1/(kg·m²), so K = [[1.7, −0.7], [−0.7, 1.7]] 1/kg), e = 0.5.
    model::World world;
    world.settings.gravity = impetus::Vec2::Zero();
    model::Body slab = test::makeBody("slab", model::Box{10, 1}, impetus::Vec2(0, -0.5), true);
    model::Body box = test::makeBody("box", model::Box{2, 1}, impetus::Vec2(0.25, 0.5));
    box.massSpec = {model::MassMode::Mass, 2.0};
    box.state.velocity = impetus::Vec2(0, -2);
    box.material.restitution = 0.5;
    box.updateDerived();
    world.bodies.push_back(slab);
    world.bodies.push_back(box);

    MainWindow window;
    window.setScene(world, QStringLiteral("impact"));
    QVERIFY(showLarge(window));
    view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    static const QRegularExpression decimalComma(QStringLiteral("[0-9],[0-9]"));

    // Explain › Separating Axes on the slab and the box, clicked and Shift-clicked; every axis and
    // the summary, stepped through with N.
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(-3, -0.5)).toPoint());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, canvas.toView(QPointF(0.25, 0.5)).toPoint());
    auto* separatingAxes = window.findChild<QAction*>(QStringLiteral("separatingAxesAction"));
    QVERIFY(separatingAxes && separatingAxes->isEnabled());
    separatingAxes->trigger();
    auto* explainer = window.findChild<view::SatExplainer*>(QStringLiteral("satExplainer"));
    QVERIFY(explainer && explainer->isOpen());
    const std::size_t axes = explainer->current()->trace.axes.size();
    QCOMPARE(axes, std::size_t{8});
    QStringList panels{explainer->panelText()};
    while (explainer->currentAxis() < axes) {
        QTest::keyClick(&canvas, Qt::Key_N);
        panels << explainer->panelText();
    }
    QCOMPARE(panels.size(), 9);
    for (const QString& panel : panels) {
        QVERIFY2(panel.contains(decimalComma), qPrintable(panel));
        QVERIFY2(!hasDecimalPoint(panel), qPrintable(panel));
    }
    const QStringList second = panels[1].split(QLatin1Char('\n'));
    QVERIFY2(second.contains(QStringLiteral("Achse 2 von 8: Normale der Seite 2 von A, Richtung (1,000; 0,000)")),
             qPrintable(panels[1]));
    QVERIFY2(second.contains(QStringLiteral("Projektionen: A von -5000,000 bis 5000,000 mm, B von -750,000 bis "
                                            "1250,000 mm")),
             qPrintable(panels[1]));
    const QStringList summary = panels.last().split(QLatin1Char('\n'));
    QVERIFY2(summary.contains(QStringLiteral("Minimaler Verschiebungsvektor: 0,000 mm entlang (0,000; 1,000) "
                                             "(schiebt B von A weg)")),
             qPrintable(panels.last()));
    QVERIFY2(summary.contains(QStringLiteral("Kontaktpunkt 1: (-0,750; 0,000) m, Abstand 0,000 mm")),
             qPrintable(panels.last()));
    QTest::keyClick(&canvas, Qt::Key_Escape); // closes the explainer
    QVERIFY(!explainer->isOpen());
    QTest::keyClick(&canvas, Qt::Key_Escape); // clears the selection, so → steps instead of nudging
    QVERIFY(window.document().selection().empty());

    // Explain › Collision Inspector; one step (→ on the canvas) and the impact clicked in the log.
    auto* inspectorAction = window.findChild<QAction*>(QStringLiteral("collisionInspectorAction"));
    QVERIFY(inspectorAction);
    inspectorAction->trigger();
    auto* inspector = window.findChild<view::CollisionInspector*>(QStringLiteral("collisionInspector"));
    QVERIFY(inspector);
    QTRY_VERIFY(inspector->isVisible());
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Right);
    QTRY_COMPARE(inspector->entries().size(), std::size_t{1});
    QListWidget* log = inspector->list();
    QCOMPARE(log->count(), 1);
    QCOMPARE(log->item(0)->text(), QStringLiteral("t = 0,0042 s: slab und box, Kraftstoß 6 N·s"));
    QTest::mouseClick(log->viewport(), Qt::LeftButton, Qt::NoModifier, log->visualItemRect(log->item(0)).center());
    QCOMPARE(inspector->selected(), std::optional<int>(0));
    const QString formula = inspector->formulaText();
    QVERIFY2(formula.contains(decimalComma), qPrintable(formula));
    QVERIFY2(!hasDecimalPoint(formula), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("slab und box bei t = 0,0042 s")), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("Normale n = (0; 1)")), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("rB = (-1; -0,5) m")), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("e = 0,5; μ = ")), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("/ 1,7 = 1,76471 N·s")), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("K = [[1,7; -0,7]; [-0,7; 1,7]] 1/kg")), qPrintable(formula));
    QVERIFY2(formula.contains(QStringLiteral("Impuls des Paars: (0; -4) → (0; 2) kg·m/s")), qPrintable(formula));
}

void LanguageTest::languageMenuKeepsTheChoiceForTheNextStart()
{
    MainWindow window;
    auto* menu = window.findChild<QMenu*>(QStringLiteral("languageMenu"));
    QVERIFY(menu);
    QStringList names;
    QAction* spanish = nullptr;
    QAction* system = nullptr;
    for (QAction* action : menu->actions()) {
        names << action->text();
        if (action->data().toString() == QStringLiteral("es"))
            spanish = action;
        if (!action->isSeparator() && action->data().toString().isEmpty())
            system = action;
    }
    // Each language is named in itself, so a user finds theirs whatever the window speaks.
    QVERIFY2(names.contains(QStringLiteral("Deutsch")) && names.contains(QStringLiteral("Español")),
             qPrintable(names.join(QLatin1Char('|'))));
    QVERIFY(spanish && system);
    QVERIFY(system->isChecked());

    spanish->trigger();
    QVERIFY(spanish->isChecked());
    QCOMPARE(QSettings().value(QLatin1String(view::kLanguageSettingKey)).toString(), QStringLiteral("es"));
    QCOMPARE(view::chosenLocale().language(), QLocale::Spanish);
    QCOMPARE(window.statusBar()->currentMessage(), QStringLiteral("The language changes the next time Impetus starts."));

    system->trigger();
    QVERIFY(!QSettings().contains(QLatin1String(view::kLanguageSettingKey)));
    QCOMPARE(view::chosenLocale().language(), QLocale::system().language());
}

void LanguageTest::unknownLanguageSettingMeansTheSystemLanguage()
{
    QSettings().setValue(QLatin1String(view::kLanguageSettingKey), QStringLiteral("tlh"));
    QVERIFY(view::languageSetting().isEmpty());
    QCOMPARE(view::chosenLocale().language(), QLocale::system().language());
}

QTEST_MAIN(LanguageTest)
#include "language_test.moc"
