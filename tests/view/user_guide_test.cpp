// docs/user-guide.md keeps up with the app: the real main window is walked (its menu bar with every
// sub-menu, its tool bars, its docks and the buttons of the graph, lesson and attribute docks), and
// every text a user can click, and every key of every action, must be named in the guide. A new menu
// entry, tool or shortcut without a line in the guide fails here, with the list of what is missing.
// The guide's pictures must exist in docs/images/.

#include "test_settings.h"
#include "view/language.h"
#include "view/main_window.h"
#include "view/scene_document.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

#include <algorithm>
#include <memory>

using impetus::view::MainWindow;
namespace test = impetus::view::test;
namespace view = impetus::view;

namespace {

/// What the guide must say for `text` shown in the app: the text without its mnemonic `&` and
/// without a closing "…" (the guide writes "Save As…" or "Save As" as the sentence needs) or ":".
QString spoken(QString text)
{
    text.remove(QLatin1Char('&'));
    if (text.endsWith(QStringLiteral("…")) || text.endsWith(QLatin1Char(':')))
        text.chop(1);
    return text.trimmed();
}

/// How the guide writes a key: as Qt's portable text ("Ctrl+Shift+G", "F11", "]"), in bold, except
/// the arrow keys, which it draws as arrows like the tooltips do.
QString spokenKey(const QKeySequence& key)
{
    QString text = key.toString(QKeySequence::PortableText);
    if (text == QLatin1String("Right"))
        text = QStringLiteral("→");
    else if (text == QLatin1String("Left"))
        text = QStringLiteral("←");
    return QStringLiteral("**%1**").arg(text);
}

/// Collects the texts of `menu`'s entries and of its sub-menus' entries, each as "Menu › Entry".
/// Open Recent is filled from the user's own files only when it opens; its entries are file names,
/// not features, so they are not walked here (the menu itself is).
void collectMenu(const QMenu& menu, const QString& path, QStringList& texts, QList<QAction*>& actions)
{
    for (QAction* action : menu.actions()) {
        if (action->isSeparator())
            continue;
        actions << action;
        texts << path + QStringLiteral(" › ") + spoken(action->text());
        if (action->menu())
            collectMenu(*action->menu(), path + QStringLiteral(" › ") + spoken(action->text()), texts, actions);
    }
}

} // namespace

class UserGuideTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void everyMenuEntryIsInTheGuide();
    void everyToolBarEntryIsInTheGuide();
    void everyShortcutIsInTheGuide();
    void everyDockAndItsButtonsAreInTheGuide();
    void everyPictureOfTheGuideExists();

private:
    /// The entries of `items` (each "where › text", the text last) whose text the guide does not
    /// mention.
    QStringList missing(const QStringList& items) const;

    QString m_guide;
    std::unique_ptr<test::TemporarySettings> m_settings;
    std::unique_ptr<MainWindow> m_window;
};

void UserGuideTest::initTestCase()
{
    QFile file(QStringLiteral(IMPETUS_USER_GUIDE));
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
    m_guide = QString::fromUtf8(file.readAll());
    QVERIFY(m_guide.size() > 1000);
}

void UserGuideTest::init()
{
    m_settings = std::make_unique<test::TemporarySettings>();
    // The guide is written in English: the window must be too, whatever the machine's locale.
    view::setLanguageSetting(QStringLiteral("en"));
    view::applyLanguage(*QCoreApplication::instance(), view::chosenLocale());
    m_window = std::make_unique<MainWindow>();
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void UserGuideTest::cleanup()
{
    if (m_window)
        m_window->document().undoStack()->setClean(); // no "save changes?" box on close
    m_window.reset();
    m_settings.reset();
}

QStringList UserGuideTest::missing(const QStringList& items) const
{
    QStringList absent;
    for (const QString& item : items) {
        const QString text = item.section(QStringLiteral(" › "), -1);
        if (!text.isEmpty() && !m_guide.contains(text))
            absent << item;
    }
    return absent;
}

void UserGuideTest::everyMenuEntryIsInTheGuide()
{
    QStringList texts;
    QList<QAction*> actions;
    for (QAction* top : m_window->menuBar()->actions()) {
        QVERIFY(top->menu());
        texts << spoken(top->text());
        collectMenu(*top->menu(), spoken(top->text()), texts, actions);
    }
    // The walk found the menus the app is known to have (a walk that saw nothing would pass).
    for (const char* menu : {"File", "Edit", "View", "Tools", "Simulation", "Examples", "Lesson"})
        QVERIFY2(texts.contains(QLatin1String(menu)), menu);
    QVERIFY(texts.contains(QStringLiteral("View › Language › Deutsch")));
    QVERIFY(texts.contains(QStringLiteral("View › Vectors › Force Parts")));
    QVERIFY(texts.contains(QStringLiteral("Examples › Lesson: pendulum period and length")));
    QVERIFY(texts.size() > 70);
    const QStringList absent = missing(texts);
    QVERIFY2(absent.isEmpty(), qPrintable(QStringLiteral("not in docs/user-guide.md: ") + absent.join(QStringLiteral("; "))));
}

void UserGuideTest::everyToolBarEntryIsInTheGuide()
{
    QStringList texts;
    const QList<QToolBar*> bars = m_window->findChildren<QToolBar*>();
    QCOMPARE(bars.size(), 2); // the run controls and the drawing tools
    for (QToolBar* bar : bars) {
        texts << spoken(bar->windowTitle());
        for (QAction* action : bar->actions()) {
            if (action->isSeparator())
                continue;
            QWidget* widget = bar->widgetForAction(action);
            // The speed box comes with its label; a box has no text of its own.
            if (auto* label = qobject_cast<QLabel*>(widget))
                texts << bar->windowTitle() + QStringLiteral(" › ") + spoken(label->text());
            else if (!action->text().isEmpty())
                texts << bar->windowTitle() + QStringLiteral(" › ") + spoken(action->text());
        }
    }
    QVERIFY(texts.contains(QStringLiteral("Run controls › Speed")));
    QVERIFY(texts.contains(QStringLiteral("Tools › Probe")));
    const QStringList absent = missing(texts);
    QVERIFY2(absent.isEmpty(), qPrintable(QStringLiteral("not in docs/user-guide.md: ") + absent.join(QStringLiteral("; "))));
}

void UserGuideTest::everyShortcutIsInTheGuide()
{
    QStringList absent;
    int keys = 0;
    for (QAction* action : m_window->findChildren<QAction*>()) {
        for (const QKeySequence& key : action->shortcuts()) {
            ++keys;
            if (!m_guide.contains(spokenKey(key)))
                absent << QStringLiteral("%1 (%2)").arg(spoken(action->text()), spokenKey(key));
        }
    }
    // File, Edit, the twelve tools, the run controls, the arrows, the graph, projector mode, …
    QVERIFY(keys > 30);
    QVERIFY2(absent.isEmpty(), qPrintable(QStringLiteral("keys not in docs/user-guide.md: ") + absent.join(QStringLiteral("; "))));
}

void UserGuideTest::everyDockAndItsButtonsAreInTheGuide()
{
    // A lesson and a graph open bring up every dock and every button in them: the lesson panel's
    // Check, the lesson editor's questions, the pane's (built once, shown as the selection needs)
    // and the graph's exports.
    QVERIFY(m_window->openScene(QStringLiteral(":/examples/lesson-incline-friction.json")).isEmpty());
    m_window->newGraphAction()->trigger();
    const auto collect = [this](QStringList& texts) {
        for (QDockWidget* dock : m_window->findChildren<QDockWidget*>()) {
            // Left out on purpose: a graph dock's title is what it plots ("y of block"), which is
            // the user's choice, not a feature; its buttons are checked.
            if (dock->objectName() != QLatin1String("graphDock"))
                texts << spoken(dock->windowTitle());
            for (QPushButton* button : dock->findChildren<QPushButton*>())
                if (!button->text().isEmpty())
                    texts << dock->windowTitle() + QStringLiteral(" › ") + spoken(button->text());
            for (QCheckBox* box : dock->findChildren<QCheckBox*>())
                if (!box->text().isEmpty())
                    texts << dock->windowTitle() + QStringLiteral(" › ") + spoken(box->text());
        }
    };
    QStringList texts;
    collect(texts);
    auto* edit = m_window->findChild<QAction*>(QStringLiteral("editLessonAction"));
    QVERIFY(edit);
    edit->trigger();
    collect(texts);
    for (const char* expected : {"Lesson › Check", "Lesson (editing) › Add Question", "Attributes › Add vertex",
                                 "Attributes › Soft body", "Export CSV"})
        QVERIFY2(std::ranges::any_of(texts, [&](const QString& text) { return text.endsWith(QString::fromUtf8(expected)); }),
                 expected);
    const QStringList absent = missing(texts);
    QVERIFY2(absent.isEmpty(), qPrintable(QStringLiteral("not in docs/user-guide.md: ") + absent.join(QStringLiteral("; "))));
}

void UserGuideTest::everyPictureOfTheGuideExists()
{
    const QRegularExpression picture(QStringLiteral(R"(\]\((images/[^)\s]+\.png)\))"));
    const QString folder = QFileInfo(QStringLiteral(IMPETUS_USER_GUIDE)).absolutePath();
    int count = 0;
    for (const QRegularExpressionMatch& match : picture.globalMatch(m_guide)) {
        ++count;
        QVERIFY2(QFileInfo::exists(folder + QLatin1Char('/') + match.captured(1)), qPrintable(match.captured(1)));
    }
    QVERIFY(count >= 10);
}

QTEST_MAIN(UserGuideTest)
#include "user_guide_test.moc"
