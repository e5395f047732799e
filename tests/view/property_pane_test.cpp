// PropertyPane, driven as a user would: typing into fields and pressing Enter, Tab, Space and the
// arrow keys, and checking what it emits, what it refuses and what it shows.

#include "test_worlds.h"
#include "view/property_pane.h"

#include "controller/soft/soft_body_builder.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include <cmath>
#include <numbers>
#include <set>

using impetus::Vec2;
using impetus::view::PropertyPane;
using impetus::view::Selection;
namespace model = impetus::model;
namespace controller = impetus::controller;
namespace test = impetus::view::test;

namespace {

constexpr double kPi = std::numbers::pi;

/// A crate (2 m × 1 m box, turned 30°, moving), a ball, a wedge (a 2 m × 1 m quadrilateral),
/// a spring from the crate to a world point, a rod from the crate to the ball and a pin between
/// the wedge and the world.
model::World editorWorld()
{
    model::World world;
    model::Body crate = test::makeBody("crate", model::Box{2, 1}, Vec2(1, 2));
    crate.state.angle = kPi / 6;
    crate.state.velocity = Vec2(3, -1);
    crate.state.angularVelocity = 0.5;
    crate.material = model::Material{0.5, 0.4};
    world.bodies.push_back(crate);
    world.bodies.push_back(test::makeBody("ball", model::Circle{0.25}, Vec2(4, 2)));
    model::Body wedge =
        test::makeBody("wedge", model::Polygon{{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)}}, Vec2(-3, 1));
    wedge.state.angle = kPi / 2;
    world.bodies.push_back(wedge);

    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.anchorA = Vec2(0.5, 0);
    spring.anchorB = Vec2(1, 5);
    spring.stiffness = 80;
    spring.damping = 0.5;
    spring.restLength = 1.5;
    world.springs.push_back(spring);

    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.bodyB = model::BodyId{1};
    rod.length = (world.bodies[1].state.position - world.bodies[0].state.position).norm();
    world.joints.push_back(rod);

    model::Joint pin;
    pin.type = model::JointType::Pin;
    pin.bodyA = model::BodyId{2};
    pin.worldAnchor = Vec2(-3, 1);
    pin.anchorA = Vec2::Zero();
    pin.anchorB = pin.worldAnchor;
    world.joints.push_back(pin);
    return world;
}

Selection bodySelection(int index) { return Selection{{index}, {}, {}}; }

/// Selects everything in `edit`, deletes it and types `text` as a user would, then presses Enter.
void typeAndEnter(QWidget* edit, const QString& text)
{
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

/// Edits a cell of `table` from the keyboard: F2, new text, Enter.
void editCell(QTableWidget* table, int row, int column, const QString& text)
{
    table->setCurrentCell(row, column);
    QTest::keyClick(table, Qt::Key_F2);
    auto* editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
    QVERIFY(editor && table->isAncestorOf(editor));
    typeAndEnter(editor, text);
    // The item delegate commits the editor's text with a queued call, then deletes the editor later.
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

/// Shows `pane` in its own window and waits until it is active, so that keyboard focus works.
bool showActive(PropertyPane& pane)
{
    pane.resize(360, 900);
    pane.show();
    pane.activateWindow();
    return QTest::qWaitForWindowActive(&pane);
}

/// The second argument of the one bodyEdited signal `spy` holds.
model::Body editedBody(const QSignalSpy& spy) { return spy.at(0).at(1).value<model::Body>(); }

/// A polygon vertex of `body` in world coordinates, m.
Vec2 worldVertex(const model::Body& body, std::size_t i)
{
    const Vec2 local = std::get<model::Polygon>(body.shape).vertices[i] - body.geometry.centroidOffset;
    return body.worldPoint(local);
}

} // namespace

class PropertyPaneTest : public QObject {
    Q_OBJECT

private slots:
    void showsTheSelectedBoxWithAngleInDegrees();
    void restitutionEditEmitsOnceWithOnlyThatChanged();
    void angleIsTypedInDegrees();
    void exponentsAreWrittenWithASmallEAndReadBack();
    void badValueIsRefusedWithMessage_data();
    void badValueIsRefusedWithMessage();
    void switchingToMassKeepsTheMassAndLocksDensity();
    void duplicateNameIsRefused();
    void bowtieVertexEditIsRefused();
    void vertexEditKeepsOtherVerticesInPlace();
    void worldSettingsAreEditable();
    void springIsEditable();
    void rodEditRecomputesLengthAndRefusesZeroLength();
    void pinHingeEditRecomputesBodyAnchors();
    void fixedAndColourAreEditable();
    void softModeToggleAndAuto();
    void softDampingShowsTheRatioAndItsCoefficient();
    void refreshUpdatesLiveValuesButNotTheFocusedField();
    void refreshAfterTheBodyIsGoneShowsTheWorld();
    void multiSelectionShowsTheFirstBodyWithANote();
    void tabReachesEveryField_data();
    void tabReachesEveryField();
    void everyFieldHasAnAccessibleName();

private:
    /// Presses Tab from the pane's first field until the focus comes back to it. Returns the
    /// fields visited in order, or nothing when a visible, enabled field was not reached; sets
    /// `expectedCount` to the number of such fields.
    static std::vector<QWidget*> tabFromFirstField(PropertyPane& pane, std::size_t& expectedCount);
};

void PropertyPaneTest::showsTheSelectedBoxWithAngleInDegrees()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), bodySelection(0));
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("Body “crate”"));
    QCOMPARE(pane.findChild<QLineEdit*>("name")->text(), QString("crate"));
    QCOMPARE(pane.findChild<QLineEdit*>("shapeType")->text(), QString("Box"));
    QCOMPARE(pane.findChild<QLineEdit*>("width")->text(), QString("2"));
    QCOMPARE(pane.findChild<QLineEdit*>("height")->text(), QString("1"));
    QCOMPARE(pane.findChild<QLineEdit*>("positionX")->text(), QString("1"));
    QCOMPARE(pane.findChild<QLineEdit*>("positionY")->text(), QString("2"));
    QCOMPARE(pane.findChild<QLineEdit*>("angle")->text(), QString("30"));
    QCOMPARE(pane.findChild<QLineEdit*>("velocityX")->text(), QString("3"));
    QCOMPARE(pane.findChild<QLineEdit*>("velocityY")->text(), QString("-1"));
    // 0.5 rad/s in degrees per second.
    QCOMPARE(pane.findChild<QLineEdit*>("angularVelocity")->text(), QString("28.6479"));
    QCOMPARE(pane.findChild<QLineEdit*>("density")->text(), QString("1"));
    QCOMPARE(pane.findChild<QLineEdit*>("mass")->text(), QString("2"));
    QVERIFY(pane.findChild<QLineEdit*>("mass")->isReadOnly());
    // I = m(w² + h²)/12 = 2·5/12.
    QCOMPARE(pane.findChild<QLineEdit*>("inertia")->text(), QString("0.833333"));
    QVERIFY(pane.findChild<QLineEdit*>("inertia")->isReadOnly());
    QCOMPARE(pane.findChild<QLineEdit*>("restitution")->text(), QString("0.5"));
    QCOMPARE(pane.findChild<QLineEdit*>("friction")->text(), QString("0.4"));
    QCOMPARE(pane.findChild<QPushButton*>("color")->text(), QString("#3b82f6"));
    // Only the box's size rows are shown.
    QVERIFY(!pane.findChild<QLineEdit*>("width")->isHidden() && pane.findChild<QLineEdit*>("width")->isVisibleTo(&pane));
    QVERIFY(!pane.findChild<QLineEdit*>("radius")->isVisibleTo(&pane));
    QVERIFY(!pane.findChild<QTableWidget*>("vertices")->isVisibleTo(&pane));
}

void PropertyPaneTest::restitutionEditEmitsOnceWithOnlyThatChanged()
{
    const model::World world = editorWorld();
    PropertyPane pane;
    pane.showSelection(world, bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* restitution = pane.findChild<QLineEdit*>("restitution");
    typeAndEnter(restitution, "0.8");
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).toInt(), 0);
    QCOMPARE(spy.at(0).at(2).toString(), QString("Change restitution"));
    model::Body expected = world.bodies[0];
    expected.material.restitution = 0.8;
    QVERIFY(editedBody(spy) == expected);
    QVERIFY(pane.message().isEmpty());
    // Enter again, with nothing changed, emits nothing more; neither does typing the same value.
    QTest::keyClick(restitution, Qt::Key_Return);
    typeAndEnter(restitution, "0.80");
    QCOMPARE(spy.count(), 1);
}

void PropertyPaneTest::angleIsTypedInDegrees()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    typeAndEnter(pane.findChild<QLineEdit*>("angle"), "90");
    typeAndEnter(pane.findChild<QLineEdit*>("angularVelocity"), "-180");
    QCOMPARE(spy.count(), 2);
    QCOMPARE(spy.at(0).at(1).value<model::Body>().state.angle, kPi / 2);
    QCOMPARE(spy.at(1).at(1).value<model::Body>().state.angle, kPi / 2);
    QCOMPARE(spy.at(1).at(1).value<model::Body>().state.angularVelocity, -kPi);
    QCOMPARE(pane.findChild<QLineEdit*>("angle")->text(), QString("90"));
}

// Very large and very small values are written with an exponent, with a small e as every readout
// writes it ("2.5e+06", not QLocale's "2.5E+06"), in German with its decimal comma; what the
// pane writes reads back as the same number.
void PropertyPaneTest::exponentsAreWrittenWithASmallEAndReadBack()
{
    const QLocale before;
    for (const QLocale::Language language : {QLocale::English, QLocale::German}) {
        QLocale::setDefault(QLocale(language));
        const bool german = language == QLocale::German;
        PropertyPane pane;
        model::World world = editorWorld();
        pane.showSelection(world, bodySelection(0));
        QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
        auto* density = pane.findChild<QLineEdit*>("density");
        typeAndEnter(density, german ? QStringLiteral("2,5e6") : QStringLiteral("2.5e6"));
        QCOMPARE(spy.count(), 1);
        world.bodies[0] = editedBody(spy);
        QCOMPARE(world.bodies[0].mass, 5e6); // 2 m² at 2.5e6 kg/m²
        pane.showSelection(world, bodySelection(0));
        QCOMPARE(density->text(), german ? QStringLiteral("2,5e+06") : QStringLiteral("2.5e+06"));
        QCOMPARE(pane.findChild<QLineEdit*>("mass")->text(), QStringLiteral("5e+06"));

        // The text written, typed back unchanged, is the same number: no edit is made.
        auto* friction = pane.findChild<QLineEdit*>("friction");
        typeAndEnter(friction, german ? QStringLiteral("2,5E-7") : QStringLiteral("2.5E-7"));
        QCOMPARE(spy.count(), 2);
        world.bodies[0] = spy.at(1).at(1).value<model::Body>();
        QCOMPARE(world.bodies[0].material.friction, 2.5e-7);
        pane.showSelection(world, bodySelection(0));
        const QString shown = friction->text();
        QCOMPARE(shown, german ? QStringLiteral("2,5e-07") : QStringLiteral("2.5e-07"));
        typeAndEnter(friction, shown);
        QCOMPARE(spy.count(), 2);
    }
    QLocale::setDefault(before);
}

void PropertyPaneTest::badValueIsRefusedWithMessage_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("original");
    QTest::addColumn<QString>("reason");
    QTest::newRow("text") << "restitution" << "abc" << "0.5" << "Restitution: “abc” is not a number.";
    QTest::newRow("restitution 2") << "restitution" << "2" << "0.5" << "Restitution must be between 0 and 1 (got 2).";
    QTest::newRow("restitution -1") << "restitution" << "-1" << "0.5"
                                    << "Restitution must be between 0 and 1 (got -1).";
    QTest::newRow("friction -1") << "friction" << "-1" << "0.4" << "Friction must be 0 or greater (got -1).";
    QTest::newRow("width 0") << "width" << "0" << "2" << "Width must be greater than 0 (got 0).";
    QTest::newRow("width -2") << "width" << "-2" << "2" << "Width must be greater than 0 (got -2).";
    QTest::newRow("density 0") << "density" << "0" << "1" << "Density must be greater than 0 (got 0).";
    QTest::newRow("nan") << "positionX" << "nan" << "1" << "Position x must be a finite number (got nan).";
    QTest::newRow("infinite") << "velocityY" << "inf" << "-1" << "Velocity y must be a finite number (got inf).";
    QTest::newRow("empty") << "angle" << "" << "30" << "Angle: “” is not a number.";
    QTest::newRow("huge width") << "width" << "1e200" << "2"
                                << "The size or density is too extreme to simulate (mass 1e+200 kg, moment of "
                                   "inertia inf kg·m²).";
}

void PropertyPaneTest::badValueIsRefusedWithMessage()
{
    QFETCH(QString, field);
    QFETCH(QString, text);
    QFETCH(QString, original);
    QFETCH(QString, reason);
    PropertyPane pane;
    pane.show();
    pane.showSelection(editorWorld(), bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* edit = pane.findChild<QLineEdit*>(field);
    QVERIFY(edit);
    typeAndEnter(edit, text);
    QCOMPARE(spy.count(), 0);
    QCOMPARE(pane.message(), reason);
    QVERIFY(pane.findChild<QLabel*>("message")->isVisible());
    QCOMPARE(edit->text(), original);
    // The next good edit clears the message.
    typeAndEnter(pane.findChild<QLineEdit*>("friction"), "0.7");
    QCOMPARE(spy.count(), 1);
    QVERIFY(pane.message().isEmpty());
    QVERIFY(!pane.findChild<QLabel*>("message")->isVisible());
}

void PropertyPaneTest::switchingToMassKeepsTheMassAndLocksDensity()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* mode = pane.findChild<QComboBox*>("massMode");
    auto* density = pane.findChild<QLineEdit*>("density");
    auto* mass = pane.findChild<QLineEdit*>("mass");
    QVERIFY(!density->isReadOnly());
    QTest::keyClick(mode, Qt::Key_Down);
    QCOMPARE(spy.count(), 1);
    model::Body body = editedBody(spy);
    QCOMPARE(body.massSpec.mode, model::MassMode::Mass);
    QCOMPARE(body.massSpec.value, 2.0);
    QCOMPARE(body.mass, 2.0);
    QVERIFY(density->isReadOnly());
    QVERIFY(!mass->isReadOnly());

    // With the mass given, a bigger crate keeps its mass and gets thinner.
    typeAndEnter(pane.findChild<QLineEdit*>("width"), "4");
    QCOMPARE(spy.count(), 2);
    body = spy.at(1).at(1).value<model::Body>();
    QCOMPARE(body.mass, 2.0);
    QCOMPARE(body.density(), 0.5);
    QCOMPARE(density->text(), QString("0.5"));
    QCOMPARE(mass->text(), QString("2"));
    // The read-only density cannot be typed into.
    typeAndEnter(density, "7");
    QCOMPARE(spy.count(), 2);
    QCOMPARE(density->text(), QString("0.5"));
    typeAndEnter(mass, "3");
    QCOMPARE(spy.count(), 3);
    QCOMPARE(spy.at(2).at(1).value<model::Body>().mass, 3.0);
    QCOMPARE(spy.at(2).at(2).toString(), QString("Change mass"));
}

void PropertyPaneTest::duplicateNameIsRefused()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* name = pane.findChild<QLineEdit*>("name");
    typeAndEnter(name, "ball");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(pane.message(), QString("Name: another body is already called “ball”; names must be unique."));
    QCOMPARE(name->text(), QString("crate"));
    typeAndEnter(name, "  ");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(pane.message(), QString("Name: a body needs a name."));
    typeAndEnter(name, "big crate");
    QCOMPARE(spy.count(), 1);
    QCOMPARE(editedBody(spy).name, std::string("big crate"));
    QCOMPARE(spy.at(0).at(2).toString(), QString("Rename body"));
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("Body “big crate”"));
}

void PropertyPaneTest::bowtieVertexEditIsRefused()
{
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(editorWorld(), bodySelection(2));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* table = pane.findChild<QTableWidget*>("vertices");
    QVERIFY(table->isVisibleTo(&pane));
    QCOMPARE(table->rowCount(), 4);
    QCOMPARE(table->item(2, 0)->text(), QString("2"));
    // Vertex 2 from (2, 1) to (-1, 1): edge 1 then crosses edge 3, a bow tie.
    editCell(table, 2, 0, "-1");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(pane.message(), QString("Vertices: the shape is refused: polygon self-intersects (edges 1 and 3)."));
    QCOMPARE(table->item(2, 0)->text(), QString("2"));
    // Not a number.
    editCell(table, 1, 1, "x");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(pane.message(), QString("Vertex 1 y: “x” is not a number."));
    QCOMPARE(table->item(1, 1)->text(), QString("0"));
    // Removing a vertex of a triangle-to-be is fine; removing down to two is refused.
    table->setCurrentCell(3, 0);
    QTest::mouseClick(pane.findChild<QPushButton*>("removeVertex"), Qt::LeftButton);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(table->rowCount(), 3);
    table->setCurrentCell(0, 0);
    QTest::mouseClick(pane.findChild<QPushButton*>("removeVertex"), Qt::LeftButton);
    QCOMPARE(spy.count(), 1);
    QVERIFY(pane.message().startsWith("Vertices: the shape is refused: "));
    QCOMPARE(table->rowCount(), 3);
}

void PropertyPaneTest::vertexEditKeepsOtherVerticesInPlace()
{
    const model::World world = editorWorld();
    const model::Body& before = world.bodies[2];
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(world, bodySelection(2));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* table = pane.findChild<QTableWidget*>("vertices");
    editCell(table, 2, 1, "3");
    QCOMPARE(spy.count(), 1);
    const model::Body after = editedBody(spy);
    QCOMPARE(spy.at(0).at(2).toString(), QString("Move vertex"));
    const auto& vertices = std::get<model::Polygon>(after.shape).vertices;
    QCOMPARE(vertices[2], Vec2(2, 3));
    // The centroid moved, and the position with it, so that untouched vertices stay put.
    QVERIFY(after.state.position != before.state.position);
    for (const std::size_t i : {0u, 1u, 3u})
        QVERIFY((worldVertex(after, i) - worldVertex(before, i)).norm() < 1e-12);
    // The new vertex is where the user put it, in the body frame of the unchanged pose.
    const Vec2 expected = before.state.position + impetus::rotate(Vec2(Vec2(2, 3) - before.geometry.centroidOffset),
                                                         before.state.angle);
    QVERIFY((worldVertex(after, 2) - expected).norm() < 1e-12);
    // The quadrilateral of area 2 gained the triangle (2,0)-(2,3)-(2,1)... area (2·1 + 2·3)/2 = 4.
    QCOMPARE(after.area, 4.0);
    QCOMPARE(pane.findChild<QLineEdit*>("mass")->text(), QString("4"));

    // Add a vertex after vertex 0: halfway along edge 0, the shape and area are unchanged.
    table->setCurrentCell(0, 0);
    QTest::mouseClick(pane.findChild<QPushButton*>("addVertex"), Qt::LeftButton);
    QCOMPARE(spy.count(), 2);
    const model::Body added = spy.at(1).at(1).value<model::Body>();
    QCOMPARE(std::get<model::Polygon>(added.shape).vertices.size(), std::size_t(5));
    QCOMPARE(std::get<model::Polygon>(added.shape).vertices[1], Vec2(1, 0));
    QCOMPARE(added.area, 4.0);
    QCOMPARE(table->rowCount(), 5);
}

void PropertyPaneTest::worldSettingsAreEditable()
{
    const model::World world = editorWorld();
    PropertyPane pane;
    pane.showSelection(world, Selection{});
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("World"));
    QSignalSpy spy(&pane, &PropertyPane::worldSettingsEdited);
    auto* gravityY = pane.findChild<QLineEdit*>("gravityY");
    QCOMPARE(gravityY->text(), QString("-9.81"));
    QCOMPARE(pane.findChild<QLineEdit*>("timeStep")->text(), QString("0.00416667"));
    typeAndEnter(gravityY, "-1.62");
    QCOMPARE(spy.count(), 1);
    model::WorldSettings expected = world.settings;
    expected.gravity = Vec2(0, -1.62);
    QVERIFY(spy.at(0).at(0).value<model::WorldSettings>() == expected);
    QCOMPARE(spy.at(0).at(1).toString(), QString("Change gravity"));

    typeAndEnter(pane.findChild<QLineEdit*>("timeStep"), "0");
    QCOMPARE(pane.message(), QString("Time step must be greater than 0 (got 0)."));
    typeAndEnter(pane.findChild<QLineEdit*>("drag"), "-0.1");
    QCOMPARE(pane.message(), QString("Drag must be 0 or greater (got -0.1)."));
    QCOMPARE(spy.count(), 1);
    // A step the window could not keep up with, or one too coarse to mean anything, is refused
    // with the range.
    typeAndEnter(pane.findChild<QLineEdit*>("timeStep"), "1e-9");
    QCOMPARE(pane.message(), QString("Time step must be from 1e-05 s to 0.1 s (got 1e-09 s)."));
    QCOMPARE(pane.findChild<QLineEdit*>("timeStep")->text(), QString("0.00416667"));
    typeAndEnter(pane.findChild<QLineEdit*>("timeStep"), "0.5");
    QCOMPARE(pane.message(), QString("Time step must be from 1e-05 s to 0.1 s (got 0.5 s)."));
    QCOMPARE(spy.count(), 1);
    typeAndEnter(pane.findChild<QLineEdit*>("timeStep"), "0.01");
    QCOMPARE(spy.count(), 2);
    QCOMPARE(spy.at(1).at(0).value<model::WorldSettings>().timeStep, 0.01);
    // The untouched gravity x and the earlier edit are kept.
    QCOMPARE(spy.at(1).at(0).value<model::WorldSettings>().gravity, Vec2(0, -1.62));

    auto* integrator = pane.findChild<QComboBox*>("integrator");
    QCOMPARE(integrator->currentText(), QString("Runge–Kutta 4 (rk4)"));
    QTest::keyClick(integrator, Qt::Key_Up);
    QCOMPARE(spy.count(), 3);
    QCOMPARE(spy.at(2).at(0).value<model::WorldSettings>().integrator, model::IntegratorKind::SemiImplicitEuler);
    QCOMPARE(spy.at(2).at(1).toString(), QString("Change integrator"));
}

void PropertyPaneTest::springIsEditable()
{
    const model::World world = editorWorld();
    PropertyPane pane;
    pane.showSelection(world, Selection{{}, {0}, {}});
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("Spring 0"));
    QCOMPARE(pane.findChild<QLineEdit*>("springBodyA")->text(), QString("crate"));
    QVERIFY(pane.findChild<QLineEdit*>("springBodyA")->isReadOnly());
    QCOMPARE(pane.findChild<QLineEdit*>("springBodyB")->text(), QString("(world)"));
    QCOMPARE(pane.findChild<QLineEdit*>("springAnchorBY")->text(), QString("5"));
    QSignalSpy spy(&pane, &PropertyPane::springEdited);
    typeAndEnter(pane.findChild<QLineEdit*>("springStiffness"), "250");
    typeAndEnter(pane.findChild<QLineEdit*>("springDamping"), "-1");
    QCOMPARE(pane.message(), QString("Damping must be 0 or greater (got -1)."));
    typeAndEnter(pane.findChild<QLineEdit*>("springRestLength"), "2");
    typeAndEnter(pane.findChild<QLineEdit*>("springAnchorAX"), "-0.5");
    QCOMPARE(spy.count(), 3);
    model::Spring expected = world.springs[0];
    expected.stiffness = 250;
    expected.restLength = 2;
    expected.anchorA = Vec2(-0.5, 0);
    QCOMPARE(spy.at(2).at(0).toInt(), 0);
    QVERIFY(spy.at(2).at(1).value<model::Spring>() == expected);
    QCOMPARE(spy.at(2).at(2).toString(), QString("Move spring end"));
}

void PropertyPaneTest::rodEditRecomputesLengthAndRefusesZeroLength()
{
    const model::World world = editorWorld();
    PropertyPane pane;
    pane.showSelection(world, Selection{{}, {}, {0}});
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("Rod joint 0"));
    QCOMPARE(pane.findChild<QLineEdit*>("jointBodyB")->text(), QString("ball"));
    auto* length = pane.findChild<QLineEdit*>("rodLength");
    QVERIFY(length->isReadOnly());
    QCOMPARE(length->text(), QString("3"));
    QVERIFY(!pane.findChild<QLineEdit*>("pinAnchorX")->isVisibleTo(&pane));
    QSignalSpy spy(&pane, &PropertyPane::jointEdited);
    // Ball anchor 1 m further out along its x axis: the rod is 4 m.
    typeAndEnter(pane.findChild<QLineEdit*>("rodAnchorBX"), "1");
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(1).value<model::Joint>().length, 4.0);
    QCOMPARE(length->text(), QString("4"));
    // Crate anchor at the ball's anchor: in the crate's frame (turned 30°) that is 4 m along
    // (cos 30°, −sin 30°). Both ends on one point is refused.
    typeAndEnter(pane.findChild<QLineEdit*>("rodAnchorBX"), "0");
    QCOMPARE(spy.count(), 2);
    const Vec2 ballInCrate = impetus::rotate(Vec2(3, 0), -kPi / 6);
    typeAndEnter(pane.findChild<QLineEdit*>("rodAnchorAY"), QString::number(ballInCrate.y(), 'g', 17));
    QCOMPARE(spy.count(), 3);
    typeAndEnter(pane.findChild<QLineEdit*>("rodAnchorAX"), QString::number(ballInCrate.x(), 'g', 17));
    QCOMPARE(spy.count(), 3);
    QCOMPARE(pane.message(), QString("A rod needs two different ends: both anchors are at the same point."));
}

void PropertyPaneTest::pinHingeEditRecomputesBodyAnchors()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), Selection{{}, {}, {1}});
    QCOMPARE(pane.findChild<QLineEdit*>("jointType")->text(), QString("Pin"));
    QCOMPARE(pane.findChild<QLineEdit*>("jointBodyA")->text(), QString("wedge"));
    QVERIFY(!pane.findChild<QLineEdit*>("rodLength")->isVisibleTo(&pane));
    QSignalSpy spy(&pane, &PropertyPane::jointEdited);
    typeAndEnter(pane.findChild<QLineEdit*>("pinAnchorY"), "2");
    QCOMPARE(spy.count(), 1);
    const model::Joint pin = spy.at(0).at(1).value<model::Joint>();
    QCOMPARE(pin.worldAnchor, Vec2(-3, 2));
    // The wedge is at (−3, 1) turned 90°: a point 1 m above it is 1 m along its own x axis.
    QVERIFY((pin.anchorA - Vec2(1, 0)).norm() < 1e-12);
    QCOMPARE(pin.anchorB, Vec2(-3, 2));
}

void PropertyPaneTest::fixedAndColourAreEditable()
{
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(editorWorld(), bodySelection(1));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* fixed = pane.findChild<QCheckBox*>("fixed");
    fixed->setFocus();
    QTest::keyClick(fixed, Qt::Key_Space);
    QCOMPARE(spy.count(), 1);
    QVERIFY(editedBody(spy).fixed);
    QCOMPARE(editedBody(spy).invMass, 0.0);
    QCOMPARE(spy.at(0).at(2).toString(), QString("Fix body"));

    QTest::mouseClick(pane.findChild<QPushButton*>("color"), Qt::LeftButton);
    auto* dialog = pane.findChild<QColorDialog*>("colorDialog");
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    dialog->setCurrentColor(QColor(0x12, 0x34, 0x56));
    QTest::keyClick(dialog, Qt::Key_Return);
    QCOMPARE(spy.count(), 2);
    QCOMPARE(spy.at(1).at(1).value<model::Body>().color, (model::Color{0x12, 0x34, 0x56}));
    QVERIFY(spy.at(1).at(1).value<model::Body>().fixed);
    QCOMPARE(pane.findChild<QPushButton*>("color")->text(), QString("#123456"));
}

void PropertyPaneTest::softDampingShowsTheRatioAndItsCoefficient()
{
    // A 1 kg, 1 m soft box at the defaults: 64 ellipses of 1/64 kg, ζ = 2, so each grid spring has
    // c = 2·2·√(2000·(1/64)/2) = 15.811 N·s/m. The pane shows ζ and, beside it, that coefficient.
    model::World world;
    model::Body box;
    box.name = "jelly";
    box.shape = model::Box{1, 1};
    box.massSpec = {model::MassMode::Mass, 1};
    box.soft = model::SoftSettings{};
    box.updateDerived();
    world.bodies.push_back(box);
    controller::prepareSoftBodies(world);
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(world, bodySelection(0));
    QCOMPARE(pane.findChild<QLineEdit*>("softDampingRatio")->text(), QString("2"));
    const double coefficient = pane.findChild<QLineEdit*>("softDamping")->text().toDouble();
    QVERIFY2(std::abs(coefficient - 4 * std::sqrt(2000.0 / 128)) < 1e-3, qPrintable(QString::number(coefficient)));

    // A body given the coefficient shows the ratio that coefficient amounts to on its grid.
    world.bodies[0].soft->dampingMode = model::SoftDampingMode::Coefficient;
    world.bodies[0].soft->damping = std::sqrt(2000.0 / 128); // ζ = 0.5
    controller::prepareSoftBodies(world);
    pane.showSelection(world, bodySelection(0));
    QCOMPARE(pane.findChild<QLineEdit*>("softDampingRatio")->text(), QString("0.5"));
}

void PropertyPaneTest::softModeToggleAndAuto()
{
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(editorWorld(), bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* soft = pane.findChild<QCheckBox*>("soft");
    auto* density = pane.findChild<QLineEdit*>("softDensity");
    auto* stiffness = pane.findChild<QLineEdit*>("softStiffness");
    QVERIFY(!density->isEnabled());
    QVERIFY(!stiffness->isEnabled());
    soft->setFocus();
    QTest::keyClick(soft, Qt::Key_Space);
    QCOMPARE(spy.count(), 1);
    QVERIFY(editedBody(spy).soft == model::SoftSettings{});
    QVERIFY(density->isEnabled());
    QCOMPARE(density->text(), QString("64"));

    typeAndEnter(density, "auto");
    QCOMPARE(spy.count(), 2);
    QVERIFY(spy.at(1).at(1).value<model::Body>().soft->autoDensity);
    QCOMPARE(density->text(), QString("auto"));
    typeAndEnter(density, "lots");
    QCOMPARE(pane.message(), QString("Ellipses per m²: “lots” is neither a number nor “auto”."));
    QCOMPARE(density->text(), QString("auto"));
    typeAndEnter(density, "0");
    QCOMPARE(pane.message(), QString("Ellipses per m² must be a number greater than 0, or “auto” (got 0)."));
    QCOMPARE(spy.count(), 2);
    typeAndEnter(density, "256");
    typeAndEnter(stiffness, "5000");
    // The damping is a ratio ζ by default; typing the coefficient makes the body keep that.
    auto* dampingRatio = pane.findChild<QLineEdit*>("softDampingRatio");
    QCOMPARE(dampingRatio->text(), QString("2")); // constants::kDefaultSoftDampingRatio
    typeAndEnter(pane.findChild<QLineEdit*>("softDamping"), "2");
    QCOMPARE(spy.count(), 5);
    model::SoftSettings expected;
    expected.ellipsesPerSquareMeter = 256;
    expected.stiffness = 5000;
    expected.dampingMode = model::SoftDampingMode::Coefficient;
    expected.damping = 2;
    QVERIFY(spy.at(4).at(1).value<model::Body>().soft == expected);
    typeAndEnter(dampingRatio, "0.5");
    QCOMPARE(spy.count(), 6);
    expected.dampingMode = model::SoftDampingMode::Ratio;
    expected.dampingRatio = 0.5;
    QVERIFY(spy.at(5).at(1).value<model::Body>().soft == expected);
    QCOMPARE(spy.at(5).at(2).toString(), QString("Change soft damping ratio"));
    typeAndEnter(stiffness, "0");
    QCOMPARE(pane.message(), QString("Soft stiffness must be greater than 0 (got 0)."));

    QTest::keyClick(soft, Qt::Key_Space);
    QCOMPARE(spy.count(), 7);
    QVERIFY(!spy.at(6).at(1).value<model::Body>().soft.has_value());
    QCOMPARE(spy.at(6).at(2).toString(), QString("Turn off soft mode"));
    QVERIFY(!density->isEnabled());
}

void PropertyPaneTest::refreshUpdatesLiveValuesButNotTheFocusedField()
{
    model::World world = editorWorld();
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(world, bodySelection(0));
    QSignalSpy spy(&pane, &PropertyPane::bodyEdited);
    auto* restitution = pane.findChild<QLineEdit*>("restitution");
    restitution->setFocus();
    QVERIFY(restitution->hasFocus());
    QTest::keyClick(restitution, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(restitution, "0.9");

    // A step of the running simulation.
    model::Body& crate = world.bodies[0];
    crate.state.position = Vec2(5, 6);
    crate.state.angle = kPi / 4;
    crate.state.velocity = Vec2(0, -2);
    pane.refresh(world);
    QCOMPARE(pane.findChild<QLineEdit*>("positionX")->text(), QString("5"));
    QCOMPARE(pane.findChild<QLineEdit*>("positionY")->text(), QString("6"));
    QCOMPARE(pane.findChild<QLineEdit*>("angle")->text(), QString("45"));
    QCOMPARE(pane.findChild<QLineEdit*>("velocityY")->text(), QString("-2"));
    QCOMPARE(restitution->text(), QString("0.9"));
    QVERIFY(restitution->hasFocus());
    QCOMPARE(spy.count(), 0);

    // Enter applies the typed value to the body as it is now.
    QTest::keyClick(restitution, Qt::Key_Return);
    QCOMPARE(spy.count(), 1);
    model::Body expected = crate;
    expected.material.restitution = 0.9;
    QVERIFY(editedBody(spy) == expected);

    // A focused field the user has not typed in follows the model once it loses focus, and
    // leaving it emits nothing.
    auto* positionX = pane.findChild<QLineEdit*>("positionX");
    positionX->setFocus();
    crate.state.position = Vec2(7, 6);
    pane.refresh(world);
    QCOMPARE(positionX->text(), QString("5"));
    QTest::keyClick(positionX, Qt::Key_Tab);
    QVERIFY(!positionX->hasFocus());
    QCOMPARE(spy.count(), 1);
    pane.refresh(world);
    QCOMPARE(positionX->text(), QString("7"));
}

void PropertyPaneTest::refreshAfterTheBodyIsGoneShowsTheWorld()
{
    model::World world = editorWorld();
    PropertyPane pane;
    pane.showSelection(world, bodySelection(2));
    world.bodies.pop_back();
    world.joints.pop_back();
    pane.refresh(world);
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("World"));
    QVERIFY(pane.findChild<QLineEdit*>("gravityY")->isVisibleTo(&pane));
}

void PropertyPaneTest::multiSelectionShowsTheFirstBodyWithANote()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), Selection{{1, 2}, {0}, {}});
    QCOMPARE(pane.findChild<QLabel*>("title")->text(), QString("Body “ball”"));
    auto* note = pane.findChild<QLabel*>("note");
    QVERIFY(note->isVisibleTo(&pane));
    QCOMPARE(note->text(), QString("3 items selected; the pane shows the first."));
    QCOMPARE(pane.findChild<QLineEdit*>("radius")->text(), QString("0.25"));
    pane.showSelection(editorWorld(), bodySelection(1));
    QVERIFY(!note->isVisibleTo(&pane));
}

std::vector<QWidget*> PropertyPaneTest::tabFromFirstField(PropertyPane& pane, std::size_t& expectedCount)
{
    std::vector<QWidget*> expected;
    for (QWidget* widget : pane.findChildren<QWidget*>()) {
        const bool field = qobject_cast<QLineEdit*>(widget) || qobject_cast<QAbstractButton*>(widget) ||
                           qobject_cast<QComboBox*>(widget) || qobject_cast<QTableWidget*>(widget);
        if (field && (widget->focusPolicy() & Qt::TabFocus) && widget->isVisible() && widget->isEnabled())
            expected.push_back(widget);
    }
    expectedCount = expected.size();

    // Start at the first field in tab order (the window's focus chain starts at the window) and
    // press Tab until the focus comes back round.
    QWidget* first = pane.nextInFocusChain();
    while (first != &pane && std::find(expected.begin(), expected.end(), first) == expected.end())
        first = first->nextInFocusChain();
    first->setFocus();
    std::vector<QWidget*> visited{first};
    for (std::size_t i = 0; i < 2 * expected.size(); ++i) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        if (QApplication::focusWidget() == first)
            break;
        visited.push_back(QApplication::focusWidget());
    }
    const std::set<QWidget*> reached(visited.begin(), visited.end());
    for (QWidget* widget : expected) {
        if (reached.count(widget) != 1)
            qWarning() << "not reached by Tab:" << widget->objectName();
    }
    return reached.size() == expected.size() ? visited : std::vector<QWidget*>{};
}

void PropertyPaneTest::tabReachesEveryField_data()
{
    QTest::addColumn<Selection>("selection");
    QTest::addColumn<int>("fields");
    // Name, shape, vertex table and its two buttons, position ×2, angle, velocity ×2, angular
    // velocity, mass mode, density, mass, inertia, restitution, friction, fixed, colour, soft, the
    // four soft fields (density, stiffness, damping ratio, damping), and the five "Show vectors" boxes.
    QTest::newRow("soft polygon") << bodySelection(2) << 29;
    QTest::newRow("world") << Selection{} << 5;
    QTest::newRow("spring") << Selection{{}, {0}, {}} << 9;
    QTest::newRow("rod") << Selection{{}, {}, {0}} << 8;
    QTest::newRow("pin") << Selection{{}, {}, {1}} << 5;
}

void PropertyPaneTest::tabReachesEveryField()
{
    QFETCH(Selection, selection);
    QFETCH(int, fields);
    model::World world = editorWorld();
    world.bodies[2].soft = model::SoftSettings{};
    PropertyPane pane;
    QVERIFY(showActive(pane));
    pane.showSelection(world, selection);
    std::size_t expectedCount = 0;
    const std::vector<QWidget*> visited = tabFromFirstField(pane, expectedCount);
    QCOMPARE(expectedCount, static_cast<std::size_t>(fields));
    QCOMPARE(visited.size(), expectedCount);
    if (selection != bodySelection(2))
        return;
    // Top to bottom: the name, the vertex table, the position, ..., soft damping, and the vector
    // boxes last, row by row.
    const auto at = [&visited, &pane](const char* objectName) {
        return std::find(visited.begin(), visited.end(), pane.findChild<QWidget*>(objectName)) - visited.begin();
    };
    QCOMPARE(at("name"), 0);
    QVERIFY(at("name") < at("vertices"));
    QVERIFY(at("vertices") < at("positionX"));
    QVERIFY(at("positionX") < at("positionY"));
    QVERIFY(at("positionY") < at("angle"));
    QVERIFY(at("angle") < at("massMode"));
    QVERIFY(at("restitution") < at("friction"));
    QVERIFY(at("friction") < at("fixed"));
    QVERIFY(at("soft") < at("softDensity"));
    QVERIFY(at("softDamping") < at("bodyVelocityVectors"));
    QVERIFY(at("bodyVelocityVectors") < at("bodyAccelerationVectors"));
    QCOMPARE(at("bodyMomentumVectors"), static_cast<std::ptrdiff_t>(visited.size()) - 1);
}

void PropertyPaneTest::everyFieldHasAnAccessibleName()
{
    PropertyPane pane;
    pane.showSelection(editorWorld(), bodySelection(0));
    int checked = 0;
    for (QWidget* widget : pane.findChildren<QWidget*>()) {
        const bool field = qobject_cast<QLineEdit*>(widget) || qobject_cast<QAbstractButton*>(widget) ||
                           qobject_cast<QComboBox*>(widget) || qobject_cast<QTableWidget*>(widget);
        // The parts Qt builds inside a combo box or a table are named by Qt itself.
        bool internal = false;
        for (QWidget* parent = widget->parentWidget(); parent != &pane; parent = parent->parentWidget())
            internal = internal || qobject_cast<QComboBox*>(parent) || qobject_cast<QTableWidget*>(parent);
        if (!field || internal)
            continue;
        QVERIFY2(!widget->accessibleName().isEmpty(), qPrintable(widget->objectName()));
        ++checked;
    }
    QVERIFY(checked > 40);
    QCOMPARE(pane.findChild<QLineEdit*>("restitution")->accessibleName(), QString("Restitution"));
    QCOMPARE(pane.findChild<QLineEdit*>("positionX")->accessibleName(), QString("Position x"));
    QCOMPARE(pane.findChild<QLineEdit*>("angle")->accessibleDescription(), QString("Unit: °"));
}

QTEST_MAIN(PropertyPaneTest)
#include "property_pane_test.moc"
