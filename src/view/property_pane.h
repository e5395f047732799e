#pragma once
/// \file property_pane.h
/// The attribute pane: the editable properties of the selected body, spring or joint, or of the
/// world when nothing is selected.

#include "model/scene_warnings.h"
#include "model/world.h"
#include "view/canvas_instruments.h"
#include "view/selection.h"

#include <QLocale>
#include <QStringList>
#include <QString>
#include <QWidget>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QCheckBox;
class QColorDialog;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace impetus::view {

class LessonSession;

/// Shows and edits the attributes of what is selected: one body (name, size or vertex table,
/// pose, velocities, density or mass, material, fixed, colour, soft mode), one spring (anchors,
/// stiffness, damping, rest length), one joint (a pin's hinge where it is now, as a world point;
/// a rod's anchors, its length read-only), or the world settings (gravity, integrator, time step,
/// drag) when nothing is selected.
///
/// The pane never changes the world itself. A valid edit emits exactly one of the *Edited signals,
/// when the user presses Enter, leaves the field, or picks from a combo box; the lead wires them to
/// undo commands. A bad value (not a number, out of range, a duplicate name, a polygon that is not
/// simple) is refused: a message naming the problem appears in the pane's message area, the field
/// goes back to the model's value and no signal is emitted.
///
/// Units are shown next to every field. Angles are shown in degrees and angular velocities in
/// degrees per second; the model keeps radians. Every field has an object name and an accessible
/// name, and the fields are in tab order from top to bottom.
class PropertyPane : public QWidget {
    Q_OBJECT

public:
    /// An empty pane (it shows default world settings until showSelection() is called).
    explicit PropertyPane(QWidget* parent = nullptr);
    /// Disconnects the fields from the pane before they are deleted.
    ~PropertyPane() override;

    /// Shows the attributes of the selection in `world`: one body, one spring, one joint, or the
    /// world settings when the selection is empty. For a multi-selection it shows the first body
    /// (else the first spring, else the first joint) under a note saying how many are selected.
    /// Indices outside the world are ignored. Clears the message area.
    void showSelection(const model::World& world, const Selection& selection);

    /// Reloads what is shown from `world` (the same selection): live values such as position,
    /// angle, velocity, angular velocity, mass and inertia while the simulation runs. The field
    /// that has keyboard focus keeps its text, so a user typing while the simulation runs is not
    /// disturbed. If the shown item no longer exists, the pane shows the world settings.
    void refresh(const model::World& world);

    /// The text of the message area: the last refusal, or empty.
    QString message() const;

    /// Where the body page's "Show vectors" boxes read whether body `name` shows arrows of a kind
    /// on the canvas (CanvasInstruments::showsBodyVector()); without it they show none ticked.
    void setBodyVectorsShown(std::function<bool(const std::string& name, VectorKind kind)> shown);

    /// Obeys `session`'s locks from now on (nullptr: none): locked fields are read-only or
    /// disabled, a note (object name "lockNote") says why, and edits they would make are refused.
    /// The session must outlive the pane. Call showSelection() to show the change.
    void setLessonSession(const LessonSession* session) { m_lesson = session; }

    /// The text of the lock note: why fields are locked, or empty when none is.
    QString lockNote() const;

signals:
    /// The user changed body `index`; `body` is the whole new body (derived fields updated with
    /// Body::updateDerived()). Its state is the one of the last showSelection()/refresh().
    /// `actionName` is a translated short name for the undo menu, e.g. "Change restitution".
    void bodyEdited(int index, const impetus::model::Body& body, const QString& actionName);
    /// The user changed spring `index`; `spring` is the whole new spring.
    void springEdited(int index, const impetus::model::Spring& spring, const QString& actionName);
    /// The user changed joint `index`; `joint` is the whole new joint, its derived anchors (pin)
    /// or length (rod) recomputed from the bodies' current poses.
    void jointEdited(int index, const impetus::model::Joint& joint, const QString& actionName);
    /// The user changed the world settings; `settings` are the whole new settings.
    void worldSettingsEdited(const impetus::model::WorldSettings& settings, const QString& actionName);
    /// The user ticked (`on`) or cleared a "Show vectors" box of body `name`: a view setting, not
    /// an edit of the body.
    void bodyVectorToggled(const QString& name, impetus::view::VectorKind kind, bool on);

private:
    /// What the pane shows; also the index of its page in m_pageWidgets.
    enum class Page { World, Body, Spring, Joint };
    /// The range a number must lie in.
    enum class Bound { Any, Positive, NonNegative, UnitInterval };
    /// Applies a checked value (in model units) and emits; returns a message when it is refused.
    using Apply = std::function<std::optional<QString>(double)>;
    struct NumberField;

    void buildWorldPage();
    void buildBodyPage();
    void buildSpringPage();
    void buildJointPage();
    QFormLayout* addPage(Page page, const QString& accessibleName);

    /// A numeric line edit called `label` (its accessible name) bound to `read`; `apply` empty
    /// makes it read-only. Not yet placed in a layout.
    NumberField& makeNumber(Page page, const QString& objectName, const QString& label, const QString& unit,
                            Bound bound, std::function<double()> read, Apply apply);
    /// makeNumber() in its own row of `form`, with the unit after the field.
    NumberField& addNumber(Page page, QFormLayout* form, const QString& objectName, const QString& label,
                           const QString& unit, Bound bound, std::function<double()> read, Apply apply);
    /// An x/y pair in one row of `form`; the fields are called "<label> x" and "<label> y".
    /// Returns the row's field widget.
    QWidget* addVector(Page page, QFormLayout* form, const QString& objectName, const QString& label,
                       const QString& unit, std::function<Vec2()> read, const std::function<Apply(int axis)>& apply);
    QLineEdit* addText(QFormLayout* form, const QString& objectName, const QString& label);

    /// Edits of the shown item: copy it, change the copy with `set`, then commit it.
    Apply editBody(std::function<void(model::Body&, double)> set, const QString& actionName);
    Apply editSpring(std::function<void(model::Spring&, double)> set, const QString& actionName);
    Apply editJoint(std::function<void(model::Joint&, double)> set, const QString& actionName);
    Apply editWorld(std::function<void(model::WorldSettings&, double)> set, const QString& actionName);
    /// Updates the derived fields and checks the body (finite, positive mass and inertia); when it
    /// differs from the shown body, makes it the shown body and emits bodyEdited. A message when
    /// refused. commitJoint() and commitWorldSettings() do the same for the other items.
    std::optional<QString> commitBody(model::Body body, const QString& actionName);
    /// commitBody(), then the outcome in the message area and the body in the widgets.
    void applyBody(model::Body body, const QString& actionName);
    std::optional<QString> commitJoint(model::Joint joint, const QString& actionName);
    std::optional<QString> commitWorldSettings(const model::WorldSettings& settings, const QString& actionName);
    /// Checks the polygon (model::validatePolygon) and commits the body with it, moved so that the
    /// vertices keep their world positions where they did not change.
    std::optional<QString> commitVertices(std::vector<Vec2> vertices, const QString& actionName);

    void onNumberEdited(NumberField& field);
    void onNameEdited();
    void onSoftDensityEdited();
    void onVertexEdited(QTableWidgetItem* item);
    void addVertex();
    void removeVertex();
    void onMassModeActivated(int index);
    void onIntegratorActivated(int index);
    void onFixedClicked(bool checked);
    void onSoftClicked(bool checked);
    void chooseColor();
    void onColorChosen(const QColor& color);

    /// Copies what the selection shows from `world` and picks the page. `following`: a step of a
    /// run, which leaves the shown spring's warning as it was judged (judgeSpring).
    void load(const model::World& world, bool following = false);
    /// Judges spring `spring` of `world` at its bodies' present poses: its warning and the time
    /// step the pane offers.
    void judgeSpring(const model::World& world, std::size_t spring);
    /// Puts the copies into the widgets; a focused field keeps its text unless `replaceFocused`.
    void display(bool replaceFocused);
    void displayBody(bool replaceFocused);
    void displaySoftDensity(bool replaceFocused);
    void displaySpring();
    void displayJoint();
    void fillVertexTable();
    /// True when the lesson locks what `field` (a widget of the shown page) edits.
    bool locked(const QWidget* field) const;
    /// Makes locked fields read-only or disabled, and shows why in the lock note.
    void applyLocks();
    void refuse(const QString& message);
    /// refuse(*problem), or clearMessage() when there is no problem.
    void report(const std::optional<QString>& problem);
    void clearMessage();
    /// Parses `text` into `value` and checks it against `bound`; a message naming `label` if not.
    std::optional<QString> checkNumber(const QString& label, const QString& text, Bound bound, double& value) const;
    QString formatNumber(double value) const;
    std::optional<double> parseNumber(const QString& text) const;

    // What is shown, as copies, so that the pane never holds a pointer into a world that changes.
    Page m_page = Page::World;
    int m_index = -1; ///< index of the shown body, spring or joint; -1 for the world
    Selection m_selection;
    model::WorldSettings m_settings;
    model::Body m_body;
    model::Spring m_spring;
    model::Joint m_joint;
    std::vector<std::string> m_bodyNames; ///< every body's name, for the uniqueness check
    QString m_endNameA, m_endNameB; ///< names of a spring's or joint's bodies ("(world)" for none)
    model::BodyState m_endStateA; ///< pose of a joint's body A
    std::optional<model::BodyState> m_endStateB; ///< pose of a joint's body B, nullopt for the world
    std::vector<Vec2> m_shownVertices; ///< what the vertex table shows
    QString m_softDensityShown; ///< the text last put in the ellipses-per-m² field
    QString m_softGridText; ///< the shown soft body's ellipse count and density, or empty
    QString m_worldWarningText; ///< settings outside the tested ranges (model::sceneWarnings), or empty
    QStringList m_rangeWarnings; ///< the world's range warnings as last judged (load), one line each
    QString m_springWarningText; ///< the shown spring's own warnings (too stiff for the step), or empty
    model::EnergyBaseline m_energyBaseline; ///< the world's energy at step 0, to warn when a run adds energy
    QLocale m_locale; ///< the user's locale, without group separators

    QLabel* m_title = nullptr;
    QLabel* m_note = nullptr;
    QLabel* m_message = nullptr;
    QLabel* m_lockNote = nullptr; ///< why fields are locked by the lesson; hidden when none is
    const LessonSession* m_lesson = nullptr;
    QWidget* m_pages = nullptr; ///< holds the four pages, one visible
    std::vector<QWidget*> m_pageWidgets; ///< indexed by Page
    std::vector<QFormLayout*> m_forms; ///< one per Page
    std::vector<std::unique_ptr<NumberField>> m_numbers;

    QComboBox* m_integrator = nullptr;
    QLineEdit* m_name = nullptr;
    QLineEdit* m_shapeType = nullptr;
    QTableWidget* m_vertices = nullptr;
    int m_vertexEditTriggers = 0; ///< the vertex table's edit triggers when it is not locked
    QPushButton* m_addVertex = nullptr;
    QPushButton* m_removeVertex = nullptr;
    QComboBox* m_massMode = nullptr;
    NumberField* m_density = nullptr;
    NumberField* m_mass = nullptr;
    QCheckBox* m_fixed = nullptr;
    QPushButton* m_color = nullptr;
    QColorDialog* m_colorDialog = nullptr;
    QCheckBox* m_soft = nullptr;
    QLineEdit* m_softDensity = nullptr;
    QLabel* m_softGrid = nullptr; ///< read-only: what the engine built (the "auto" choice)
    std::array<QCheckBox*, kVectorKindCount> m_bodyVectors{}; ///< "Show vectors", by VectorKind
    std::function<bool(const std::string&, VectorKind)> m_bodyVectorsShown;
    QLabel* m_worldWarnings = nullptr; ///< world page: why the settings may give wrong results
    QLabel* m_springWarnings = nullptr; ///< spring page: why this spring may give wrong results
    QPushButton* m_useStableStep = nullptr; ///< spring page: sets the time step that holds the spring
    std::optional<double> m_stableStep; ///< the time step it sets, s; none when the spring holds
    NumberField* m_softStiffness = nullptr;
    NumberField* m_softDamping = nullptr; ///< c of each grid spring, N·s/m
    NumberField* m_softDampingRatio = nullptr; ///< ζ, dimensionless
    /// Mass of each ellipse of the shown soft body's grid, kg; 0 when it has no grid yet.
    double m_softEllipseMass = 0;
    QLineEdit* m_springBodyA = nullptr;
    QLineEdit* m_springBodyB = nullptr;
    QLineEdit* m_jointType = nullptr;
    QLineEdit* m_jointBodyA = nullptr;
    QLineEdit* m_jointBodyB = nullptr;
    // Rows shown for one shape or joint type only, by their field widget.
    QWidget* m_radiusRow = nullptr;
    QWidget* m_radiusXRow = nullptr;
    QWidget* m_radiusYRow = nullptr;
    QWidget* m_widthRow = nullptr;
    QWidget* m_heightRow = nullptr;
    QWidget* m_verticesRow = nullptr;
    QWidget* m_springAnchorBRow = nullptr;
    QWidget* m_pinAnchorRow = nullptr;
    QWidget* m_rodAnchorARow = nullptr;
    QWidget* m_rodAnchorBRow = nullptr;
    QWidget* m_rodLengthRow = nullptr;
};

} // namespace impetus::view
