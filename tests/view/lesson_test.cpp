// Lessons in the window (issue 15, item 2): the locks on the canvas and in the attribute pane, the
// lesson panel's questions, and Lesson › Edit. The real main window, offscreen, driven with QTest
// mouse and key events as a student or a teacher would.

#include "model/scene_io.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/canvas_view.h"
#include "view/lesson_session.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>

#include <memory>

using impetus::Vec2;
using impetus::view::CanvasView;
using impetus::view::MainWindow;
using impetus::view::PropertyPane;
using impetus::view::Selection;
using impetus::view::ToolKind;
namespace model = impetus::model;
namespace test = impetus::view::test;

namespace {

/// No gravity, so nothing moves by itself: a fixed floor, a block students may not touch, and a
/// ball whose friction (only) they may change. One question: 2 + 2 = 4 ± 0.1.
model::World lockedWorld()
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    world.bodies.push_back(test::makeBody("floor", model::Box{6, 0.2}, Vec2(0, -1), true));
    world.bodies.push_back(test::makeBody("block", model::Box{0.8, 0.8}, Vec2(-1, 0.5)));
    world.bodies.push_back(test::makeBody("ball", model::Circle{0.3}, Vec2(1.5, 0.5)));
    model::Lesson lesson;
    lesson.title = "Locks";
    model::BodyAttributes friction;
    friction.set(static_cast<std::size_t>(model::BodyAttribute::Friction));
    lesson.setEditable(model::BodyId{2}, friction);
    lesson.questions.push_back(model::LessonQuestion{"2 + 2?", 4, "", 0.1});
    world.lesson = lesson;
    return world;
}

QPoint pixelOf(const CanvasView& canvas, const QPointF& scene) { return canvas.toView(scene).toPoint(); }

void drag(QWidget* viewport, const QPoint& from, const QPoint& to, Qt::KeyboardModifiers modifiers = {})
{
    QTest::mousePress(viewport, Qt::LeftButton, modifiers, from);
    QTest::mouseMove(viewport, (from + to) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, Qt::LeftButton, modifiers, to);
}

/// Replaces the text of `edit` by typing `text`, then Enter, as a user does.
void typeInto(QLineEdit* edit, const QString& text)
{
    edit->setFocus();
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

/// Types `text` into cell (`row`, `column`) of `table`: F2 opens the cell's editor, Enter commits.
void typeIntoCell(QTableWidget* table, int row, int column, const QString& text)
{
    table->setFocus();
    table->setCurrentCell(row, column);
    QTest::keyClick(table, Qt::Key_F2);
    QWidget* editor = QApplication::focusWidget();
    QVERIFY(editor && editor != table);
    QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(editor, text);
    QTest::keyClick(editor, Qt::Key_Return);
    // The item delegate commits the cell's text from the event loop, after the key.
    QCoreApplication::processEvents();
}

} // namespace

class LessonTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void lockedBodyCannotBeDraggedOrEditedAndThePaneSaysWhy();
    void unlockedAttributeCanBeEdited();
    void questionAcceptsARightAnswerAndRefusesAWrongOne();
    void lessonExampleOpensWithItsPanelAndLocks();
    void editLiftsTheLocksAndAddsAQuestionThatIsSaved();
    void editUnlocksABodyForStudentsAndIsUndoable();
    void editUnlocksOneAttributeOfASpring();
    void lockTreeTellsABodyNamedLikeASpringFromTheSpring();
    void editLetsStudentsMoveOneJointsAnchors();

private:
    void open(model::World world);
    template <class W>
    W* child(const char* name) const
    {
        return m_window->findChild<W*>(QString::fromLatin1(name));
    }
    QAction* editAction() const { return child<QAction>("editLessonAction"); }

    test::TemporarySettings m_settings;
    std::unique_ptr<MainWindow> m_window;
};

void LessonTest::init() { open(lockedWorld()); }

void LessonTest::cleanup()
{
    m_window->document().undoStack()->setClean();
    m_window.reset();
}

void LessonTest::open(model::World world)
{
    if (m_window)
        m_window->document().undoStack()->setClean();
    m_window = std::make_unique<MainWindow>();
    m_window->setScene(std::move(world), QStringLiteral("lesson"));
    m_window->resize(1100, 760);
    m_window->show();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    m_window->canvas().setFocus();
}

void LessonTest::lockedBodyCannotBeDraggedOrEditedAndThePaneSaysWhy()
{
    CanvasView& canvas = m_window->canvas();
    const model::World before = m_window->runner().world();

    // A drag on the block selects it but does not move it; the canvas says why.
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-1, 0.5)), pixelOf(canvas, QPointF(0, 1.5)));
    QCOMPARE(m_window->document().selection(), (Selection{{1}, {}, {}}));
    QCOMPARE(m_window->runner().world().bodies[1].state.position, Vec2(-1, 0.5));
    QVERIFY2(canvas.lastMessage().contains(QStringLiteral("Locked by the lesson")), qPrintable(canvas.lastMessage()));
    QVERIFY(canvas.lastMessage().contains(QStringLiteral("block")));

    // Nor do the arrow keys nudge it, Ctrl+drag or the Rotate tool turn it, or Del delete it.
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Right);
    QTest::keyClick(&canvas, Qt::Key_Up);
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-0.7, 0.5)), pixelOf(canvas, QPointF(-1, 1.2)), Qt::ControlModifier);
    QTest::keyClick(&canvas, Qt::Key_T);
    QCOMPARE(canvas.toolKind(), ToolKind::Rotate);
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-0.7, 0.5)), pixelOf(canvas, QPointF(-1, 1.2)));
    QVERIFY(canvas.lastMessage().contains(QStringLiteral("can't be turned")));
    QTest::keyClick(&canvas, Qt::Key_S);
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QVERIFY(m_window->runner().world().bodies == before.bodies);
    QCOMPARE(m_window->document().undoStack()->count(), 0);

    // No new bodies either: the drawing tools are off while the locks are in force.
    QVERIFY(!m_window->toolAction(ToolKind::Box)->isEnabled());
    QTest::keyClick(&canvas, Qt::Key_B);
    QCOMPARE(canvas.toolKind(), ToolKind::Select);

    // The pane shows the block with its fields read-only and says why.
    PropertyPane* pane = m_window->propertyPane();
    auto* label = pane->findChild<QLabel*>(QStringLiteral("lockNote"));
    QVERIFY(label && label->isVisible());
    QVERIFY2(pane->lockNote().contains(QStringLiteral("Locked by the lesson")), qPrintable(pane->lockNote()));
    auto* friction = pane->findChild<QLineEdit*>(QStringLiteral("friction"));
    QVERIFY(friction->isReadOnly());
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("positionX"))->isReadOnly());
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("name"))->isReadOnly());
    QVERIFY(!pane->findChild<QWidget*>(QStringLiteral("fixed"))->isEnabled());
    typeInto(friction, QStringLiteral("0.9"));
    QCOMPARE(m_window->runner().world().bodies[1].material.friction, before.bodies[1].material.friction);
    QCOMPARE(m_window->document().undoStack()->count(), 0);

    // The world settings are locked too, and say so.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0, 2.5)));
    QVERIFY(m_window->document().selection().empty());
    QVERIFY(pane->lockNote().contains(QStringLiteral("world settings")));
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("gravityY"))->isReadOnly());
}

void LessonTest::unlockedAttributeCanBeEdited()
{
    CanvasView& canvas = m_window->canvas();
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(1.5, 0.5)));
    QCOMPARE(m_window->document().selection(), (Selection{{2}, {}, {}}));
    PropertyPane* pane = m_window->propertyPane();
    QVERIFY2(pane->lockNote().contains(QStringLiteral("friction")), qPrintable(pane->lockNote()));
    auto* friction = pane->findChild<QLineEdit*>(QStringLiteral("friction"));
    QVERIFY(!friction->isReadOnly());
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("restitution"))->isReadOnly());
    typeInto(friction, QStringLiteral("0.8"));
    QCOMPARE(m_window->runner().world().bodies[2].material.friction, 0.8);
    QCOMPARE(m_window->document().undoStack()->count(), 1);
    // The ball's friction may change, its place may not.
    drag(canvas.viewport(), pixelOf(canvas, QPointF(1.5, 0.5)), pixelOf(canvas, QPointF(2.5, 1.5)));
    QCOMPARE(m_window->runner().world().bodies[2].state.position, Vec2(1.5, 0.5));
    m_window->undoAction()->trigger();
    QCOMPARE(m_window->runner().world().bodies[2].material.friction, 0.5);
}

void LessonTest::questionAcceptsARightAnswerAndRefusesAWrongOne()
{
    auto* dock = child<QDockWidget>("lessonDock");
    QVERIFY(dock && dock->isVisible());
    QCOMPARE(child<QLabel>("lessonTitle")->text(), QStringLiteral("Locks"));
    auto* answer = child<QLineEdit>("lessonAnswer0");
    auto* check = child<QPushButton>("lessonCheck0");
    auto* result = child<QLabel>("lessonResult0");
    QVERIFY(answer && check && result);

    answer->setFocus();
    QTest::keyClicks(answer, QStringLiteral("5"));
    QTest::mouseClick(check, Qt::LeftButton);
    QVERIFY(result->isVisible());
    QVERIFY2(result->text().startsWith(QStringLiteral("Wrong: 1 too high")), qPrintable(result->text()));

    QTest::keyClick(answer, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(answer, QStringLiteral("3.5"));
    QTest::keyClick(answer, Qt::Key_Return);
    QVERIFY2(result->text().startsWith(QStringLiteral("Wrong: 0.5 too low")), qPrintable(result->text()));

    QTest::keyClick(answer, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(answer, QStringLiteral("4.05"));
    QTest::mouseClick(check, Qt::LeftButton);
    QVERIFY2(result->text().startsWith(QStringLiteral("Right!")), qPrintable(result->text()));

    QTest::keyClick(answer, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(answer, QStringLiteral("four"));
    QTest::mouseClick(check, Qt::LeftButton);
    QVERIFY2(result->text().contains(QStringLiteral("not a number")), qPrintable(result->text()));
    // Checking is not an edit.
    QCOMPARE(m_window->document().undoStack()->count(), 0);
}

void LessonTest::lessonExampleOpensWithItsPanelAndLocks()
{
    // A scene without a lesson hides the panel; the incline lesson shows it, with its locks.
    m_window->setScene(model::World{}, QStringLiteral("empty"));
    QVERIFY(!child<QDockWidget>("lessonDock")->isVisible());
    QVERIFY(m_window->toolAction(ToolKind::Box)->isEnabled());
    QVERIFY(m_window->openScene(QStringLiteral(":/examples/lesson-incline-friction.json")).isEmpty());
    QVERIFY(child<QDockWidget>("lessonDock")->isVisible());
    QVERIFY(child<QLabel>("lessonTitle")->text().contains(QStringLiteral("incline")));
    QVERIFY(child<QLabel>("lessonLocks")->text().contains(QStringLiteral("board")));
    QVERIFY(m_window->lesson().locksInForce());
    QVERIFY(!m_window->toolAction(ToolKind::Box)->isEnabled());

    // The board and the block turn together; the floor does not move.
    CanvasView& canvas = m_window->canvas();
    canvas.setFocus();
    const model::World& world = m_window->runner().world();
    m_window->document().setSelection(Selection{{1, 2}, {}, {}});
    const double boardAngle = world.bodies[1].state.angle;
    QTest::keyClick(&canvas, Qt::Key_T);
    const QPointF pivot = QPointF((world.bodies[1].state.position.x() + world.bodies[2].state.position.x()) / 2,
                                 (world.bodies[1].state.position.y() + world.bodies[2].state.position.y()) / 2);
    drag(canvas.viewport(), pixelOf(canvas, pivot + QPointF(2, 0)), pixelOf(canvas, pivot + QPointF(2, 1)));
    QVERIFY(world.bodies[1].state.angle > boardAngle + 0.1);
    QCOMPARE(world.bodies[2].state.angle, world.bodies[1].state.angle);
    QTest::keyClick(&canvas, Qt::Key_S);
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-5, -0.25)), pixelOf(canvas, QPointF(-4, 0.5)));
    QCOMPARE(world.bodies[0].state.position, Vec2(1, -0.25));
}

void LessonTest::editLiftsTheLocksAndAddsAQuestionThatIsSaved()
{
    QAction* edit = editAction();
    QVERIFY(edit);
    edit->trigger();
    QVERIFY(edit->isChecked());
    QVERIFY(!m_window->lesson().locksInForce());
    QVERIFY(m_window->toolAction(ToolKind::Box)->isEnabled());

    // With the locks lifted the block moves.
    CanvasView& canvas = m_window->canvas();
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-1, 0.5)), pixelOf(canvas, QPointF(-1, 1.5)));
    QVERIFY(m_window->runner().world().bodies[1].state.position.y() > 1.2);
    const int edits = m_window->document().undoStack()->count();

    auto* table = child<QTableWidget>("lessonQuestionsTable");
    QVERIFY(table && table->isVisible());
    QCOMPARE(table->rowCount(), 1);
    QTest::mouseClick(child<QPushButton>("addQuestion"), Qt::LeftButton);
    QCOMPARE(table->rowCount(), 2);
    typeIntoCell(table, 1, 0, QStringLiteral("How far did the block move?"));
    typeIntoCell(table, 1, 1, QStringLiteral("1.25"));
    typeIntoCell(table, 1, 2, QStringLiteral("m"));
    typeIntoCell(table, 1, 3, QStringLiteral("0"));
    QVERIFY2(child<QLabel>("lessonEditorMessage")->text().contains(QStringLiteral("greater than 0")),
             qPrintable(child<QLabel>("lessonEditorMessage")->text()));
    typeIntoCell(table, 1, 3, QStringLiteral("0.05"));
    const model::LessonQuestion expected{"How far did the block move?", 1.25, "m", 0.05};
    QCOMPARE(m_window->runner().world().lesson->questions.size(), std::size_t(2));
    QVERIFY(m_window->runner().world().lesson->questions[1] == expected);
    // Add, prompt, answer, unit and tolerance: five edits, each one undoable.
    QCOMPARE(m_window->document().undoStack()->count(), edits + 5);

    // Saved with the scene: the file has the question.
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("lesson.json"));
    QVERIFY(m_window->saveTo(path));
    const model::SceneLoadResult saved = model::loadSceneFile(path.toStdString());
    QVERIFY(saved.ok());
    QVERIFY(saved.world->lesson.has_value());
    QCOMPARE(saved.world->lesson->questions.size(), std::size_t(2));
    QVERIFY(saved.world->lesson->questions[1] == expected);

    // Undo takes the question back out, step by step.
    for (int i = 0; i < 5; ++i)
        m_window->undoAction()->trigger();
    QCOMPARE(m_window->runner().world().lesson->questions.size(), std::size_t(1));
    QCOMPARE(table->rowCount(), 1);

    // Opening the saved file, as a student, brings the locks back.
    QVERIFY(m_window->openScene(path).isEmpty());
    QVERIFY(!edit->isChecked());
    QVERIFY(m_window->lesson().locksInForce());
}

void LessonTest::editUnlocksABodyForStudentsAndIsUndoable()
{
    // A scene without a lesson: Lesson › Edit makes one, named after the scene.
    model::World plain = lockedWorld();
    plain.lesson.reset();
    m_window->setScene(plain, QStringLiteral("my scene"));
    QVERIFY(!m_window->lesson().locksInForce());
    editAction()->trigger();
    QVERIFY(m_window->runner().world().lesson.has_value());
    QCOMPARE(m_window->runner().world().lesson->title, std::string("my scene"));

    // The title, typed, is one undo step.
    auto* title = child<QLineEdit>("lessonTitleEdit");
    title->setFocus();
    QTest::keyClick(title, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(title, QStringLiteral("Push the block"));
    QCOMPARE(m_window->runner().world().lesson->title, std::string("Push the block"));
    const int afterTitle = m_window->document().undoStack()->count();
    QCOMPARE(afterTitle, 2); // Create lesson, Change lesson title

    // Tick the block's velocity in the lock tree.
    auto* tree = child<QTreeWidget>("lessonLocksTree");
    QTreeWidgetItem* block = nullptr;
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        if (tree->topLevelItem(i)->text(0).contains(QStringLiteral("block")))
            block = tree->topLevelItem(i);
    }
    QVERIFY(block);
    tree->expandItem(block);
    QTreeWidgetItem* velocity = nullptr;
    for (int i = 0; i < block->childCount(); ++i) {
        if (block->child(i)->text(0) == QStringLiteral("velocity"))
            velocity = block->child(i);
    }
    QVERIFY(velocity);
    // Space ticks the current item's box, as a click on it would.
    tree->setFocus();
    tree->setCurrentItem(velocity);
    QTest::keyClick(tree, Qt::Key_Space);
    QCOMPARE(velocity->checkState(0), Qt::Checked);
    QVERIFY(m_window->runner().world().lesson->allows(model::BodyId{1}, model::BodyAttribute::Velocity));
    QCOMPARE(block->checkState(0), Qt::PartiallyChecked);

    // As a student, the block's velocity can be typed; its friction cannot.
    editAction()->trigger();
    QVERIFY(m_window->lesson().locksInForce());
    m_window->document().setSelection(Selection{{1}, {}, {}});
    PropertyPane* pane = m_window->propertyPane();
    QVERIFY(!pane->findChild<QLineEdit*>(QStringLiteral("velocityX"))->isReadOnly());
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("friction"))->isReadOnly());
    typeInto(pane->findChild<QLineEdit*>(QStringLiteral("velocityX")), QStringLiteral("2"));
    QCOMPARE(m_window->runner().world().bodies[1].state.velocity, Vec2(2, 0));

    // Undo: the velocity, then the unlock.
    m_window->undoAction()->trigger();
    m_window->undoAction()->trigger();
    QVERIFY(!m_window->runner().world().lesson->allows(model::BodyId{1}, model::BodyAttribute::Velocity));
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("velocityX"))->isReadOnly());
}

// A spring lab: the teacher lets students change the stiffness of the ball's spring and nothing
// else of it. Before, the spring is locked whole; after, only its stiffness field takes typing,
// the pane says so, and the edit is one undo step. Deleting the ball (as the teacher) takes the
// spring and its entry with it; Undo brings both back.
void LessonTest::editUnlocksOneAttributeOfASpring()
{
    model::World world = lockedWorld();
    model::Spring spring;
    spring.bodyA = model::BodyId{2};
    spring.anchorB = Vec2(1.5, 2.5);
    spring.stiffness = 80;
    spring.damping = 0.5;
    spring.restLength = 1.5;
    world.springs.push_back(spring);
    open(world);
    PropertyPane* pane = m_window->propertyPane();
    m_window->document().setSelection(Selection{{}, {0}, {}});
    auto* stiffness = pane->findChild<QLineEdit*>(QStringLiteral("springStiffness"));
    auto* damping = pane->findChild<QLineEdit*>(QStringLiteral("springDamping"));
    QVERIFY(stiffness && damping);
    QVERIFY(stiffness->isReadOnly());
    QCOMPARE(pane->lockNote(), QStringLiteral("Locked by the lesson: this spring can't be changed."));

    editAction()->trigger();
    auto* tree = child<QTreeWidget>("lessonLocksTree");
    QTreeWidgetItem* springItem = nullptr;
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        if (tree->topLevelItem(i)->text(0) == QStringLiteral("Spring 0 (“ball” to the world)"))
            springItem = tree->topLevelItem(i);
    }
    QVERIFY(springItem);
    tree->expandItem(springItem);
    QTreeWidgetItem* stiffnessItem = nullptr;
    for (int i = 0; i < springItem->childCount(); ++i) {
        if (springItem->child(i)->text(0) == QStringLiteral("stiffness"))
            stiffnessItem = springItem->child(i);
    }
    QVERIFY(stiffnessItem);
    tree->setFocus();
    tree->setCurrentItem(stiffnessItem);
    QTest::keyClick(tree, Qt::Key_Space);
    QVERIFY(m_window->runner().world().lesson->allows(std::size_t{0}, model::SpringAttribute::Stiffness));
    QVERIFY(!m_window->runner().world().lesson->allows(std::size_t{0}, model::SpringAttribute::Damping));
    QCOMPARE(springItem->checkState(0), Qt::PartiallyChecked);

    editAction()->trigger();
    QVERIFY(m_window->lesson().locksInForce());
    m_window->document().setSelection(Selection{{}, {0}, {}});
    QVERIFY(!stiffness->isReadOnly());
    QVERIFY(damping->isReadOnly());
    QVERIFY(pane->findChild<QLineEdit*>(QStringLiteral("springRestLength"))->isReadOnly());
    QCOMPARE(pane->lockNote(), QStringLiteral("Locked by the lesson. You may change its stiffness."));
    // The lesson panel says so too, beside the ball's friction.
    QCOMPARE(child<QLabel>("lessonLocks")->text(),
             QStringLiteral("You may change “ball”: friction; spring 0: stiffness. Everything else is locked by the lesson."));
    const int before = m_window->document().undoStack()->count();
    typeInto(stiffness, QStringLiteral("200"));
    QCOMPARE(m_window->runner().world().springs[0].stiffness, 200.0);
    QCOMPARE(m_window->document().undoStack()->count(), before + 1);
    typeInto(damping, QStringLiteral("3"));
    QCOMPARE(m_window->runner().world().springs[0].damping, 0.5);

    // The teacher deletes the ball: its spring goes, and so does the spring's entry.
    editAction()->trigger();
    m_window->document().setSelection(Selection{{2}, {}, {}});
    m_window->deleteAction()->trigger();
    QVERIFY(m_window->runner().world().springs.empty());
    QVERIFY(m_window->runner().world().lesson->editableSprings.empty());
    m_window->undoAction()->trigger();
    QCOMPARE(m_window->runner().world().springs.size(), std::size_t{1});
    QVERIFY(m_window->runner().world().lesson->allows(std::size_t{0}, model::SpringAttribute::Stiffness));
}

// A body may be called anything, even what the lock tree calls a spring. A scene with bodies
// "ball" and "Spring 0 (“ball” to the world)" and one with a ball on a spring give the tree the
// same labels; the second must still list a spring (stiffness, …), not a body (name, size, …).
void LessonTest::lockTreeTellsABodyNamedLikeASpringFromTheSpring()
{
    const auto childTexts = [this](int top) {
        QStringList texts;
        QTreeWidgetItem* item = child<QTreeWidget>("lessonLocksTree")->topLevelItem(top);
        for (int i = 0; item && i < item->childCount(); ++i)
            texts << item->child(i)->text(0);
        return texts;
    };
    model::World named;
    named.settings.gravity = Vec2::Zero();
    named.bodies.push_back(test::makeBody("ball", model::Circle{0.3}, Vec2(0, 0)));
    named.bodies.push_back(test::makeBody("Spring 0 (“ball” to the world)", model::Circle{0.3}, Vec2(2, 0)));
    open(named);
    editAction()->trigger();
    QCOMPARE(child<QTreeWidget>("lessonLocksTree")->topLevelItem(2)->text(0), QStringLiteral("“Spring 0 (“ball” to the world)”"));
    QVERIFY(childTexts(2).contains(QStringLiteral("size")));

    model::World sprung;
    sprung.settings.gravity = Vec2::Zero();
    sprung.bodies.push_back(test::makeBody("ball", model::Circle{0.3}, Vec2(0, 0)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.anchorB = Vec2(0, 1);
    sprung.springs.push_back(spring);
    m_window->document().undoStack()->setClean();
    m_window->setScene(sprung, QStringLiteral("sprung"));
    editAction()->trigger();
    QCOMPARE(child<QTreeWidget>("lessonLocksTree")->topLevelItem(2)->text(0), QStringLiteral("Spring 0 (“ball” to the world)"));
    QVERIFY(childTexts(2).contains(QStringLiteral("stiffness")));
    QVERIFY(!childTexts(2).contains(QStringLiteral("size")));
}

// A pendulum lab: the teacher lets students move the ends of the ball's rod (to change its
// length) and leaves the block's pin locked. Before, the rod is locked whole; after, its anchor
// fields take typing, the pane and the lesson panel say so, and the edit is one undo step; the pin
// stays locked. Deleting the ball (as the teacher) takes the rod and its entry with it.
void LessonTest::editLetsStudentsMoveOneJointsAnchors()
{
    model::World world = lockedWorld();
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{2};
    rod.anchorB = Vec2(1.5, 2.5);
    rod.length = 2;
    world.joints.push_back(rod);
    model::Joint pin;
    pin.bodyA = model::BodyId{1};
    pin.worldAnchor = Vec2(-1, 0.9);
    pin.anchorA = Vec2(0, 0.4);
    pin.anchorB = pin.worldAnchor;
    world.joints.push_back(pin);
    open(world);
    PropertyPane* pane = m_window->propertyPane();
    CanvasView& canvas = m_window->canvas();
    const auto selectRod = [&] {
        QTest::keyClick(canvas.viewport(), Qt::Key_S);
        QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(1.5, 1.5)));
    };
    selectRod();
    QCOMPARE(m_window->document().selection(), (Selection{{}, {}, {0}}));
    auto* anchorY = pane->findChild<QLineEdit*>(QStringLiteral("rodAnchorBY"));
    QVERIFY(anchorY);
    QVERIFY(anchorY->isReadOnly());
    QCOMPARE(pane->lockNote(), QStringLiteral("Locked by the lesson: this joint can't be changed."));

    editAction()->trigger();
    auto* tree = child<QTreeWidget>("lessonLocksTree");
    QTreeWidgetItem* rodItem = nullptr;
    bool pinListed = false;
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        rodItem = tree->topLevelItem(i)->text(0) == QStringLiteral("Rod 0 (“ball” to the world)") ? tree->topLevelItem(i) : rodItem;
        pinListed = pinListed || tree->topLevelItem(i)->text(0) == QStringLiteral("Pin 1 (“block” to the world)");
    }
    QVERIFY(rodItem);
    QVERIFY(pinListed);
    QCOMPARE(rodItem->childCount(), 1);
    QCOMPARE(rodItem->child(0)->text(0), QStringLiteral("anchors"));
    tree->expandItem(rodItem);
    tree->setFocus();
    tree->setCurrentItem(rodItem->child(0));
    QTest::keyClick(tree, Qt::Key_Space);
    QVERIFY(m_window->runner().world().lesson->allows(std::size_t{0}, model::JointAttribute::Anchors));
    QVERIFY(!m_window->runner().world().lesson->allows(std::size_t{1}, model::JointAttribute::Anchors));

    editAction()->trigger();
    QVERIFY(m_window->lesson().locksInForce());
    selectRod();
    QVERIFY(!anchorY->isReadOnly());
    QCOMPARE(pane->lockNote(), QStringLiteral("Locked by the lesson. You may change its anchors."));
    QCOMPARE(child<QLabel>("lessonLocks")->text(),
             QStringLiteral("You may change “ball”: friction; joint 0: anchors. Everything else is locked by the lesson."));
    const int before = m_window->document().undoStack()->count();
    typeInto(anchorY, QStringLiteral("3"));
    QCOMPARE(m_window->runner().world().joints[0].anchorB, Vec2(1.5, 3));
    QCOMPARE(m_window->runner().world().joints[0].length, 2.5);
    QCOMPARE(m_window->document().undoStack()->count(), before + 1);

    // The pin is still locked whole, and an edit of its hinge that reached the lesson would be
    // refused with a reason that calls it what its page does.
    m_window->document().setSelection(Selection{{}, {}, {1}});
    auto* hingeX = pane->findChild<QLineEdit*>(QStringLiteral("pinAnchorX"));
    QVERIFY(hingeX && hingeX->isReadOnly());
    QCOMPARE(pane->lockNote(), QStringLiteral("Locked by the lesson: this joint can't be changed."));
    typeInto(hingeX, QStringLiteral("0"));
    QCOMPARE(m_window->runner().world().joints[1].worldAnchor, Vec2(-1, 0.9));
    model::Joint movedPin = m_window->runner().world().joints[1];
    movedPin.worldAnchor = Vec2(0, 0.9);
    QCOMPARE(m_window->lesson().refusal(1, m_window->runner().world().joints[1], movedPin),
             std::optional<QString>(QStringLiteral("Locked by the lesson: the hinge of joint 1 can't be changed.")));
    model::Joint retyped = m_window->runner().world().joints[0];
    retyped.type = model::JointType::Pin;
    QCOMPARE(m_window->lesson().refusal(0, m_window->runner().world().joints[0], retyped),
             std::optional<QString>(QStringLiteral("Locked by the lesson: joint 0 can't be changed to another type or to other bodies.")));
    QCOMPARE(m_window->lesson().refusal(0, m_window->runner().world().joints[0], m_window->runner().world().joints[0]),
             std::optional<QString>());

    // The teacher deletes the ball: its rod goes, and so does the rod's entry; the pin is joint 0.
    editAction()->trigger();
    m_window->document().setSelection(Selection{{2}, {}, {}});
    m_window->deleteAction()->trigger();
    QCOMPARE(m_window->runner().world().joints.size(), std::size_t{1});
    QVERIFY(m_window->runner().world().lesson->editableJoints.empty());
    m_window->undoAction()->trigger();
    QCOMPARE(m_window->runner().world().joints.size(), std::size_t{2});
    QVERIFY(m_window->runner().world().lesson->allows(std::size_t{0}, model::JointAttribute::Anchors));
}

QTEST_MAIN(LessonTest)
#include "lesson_test.moc"
