#include "view/property_pane.h"

#include "view/number_text.h"

#include "view/message_label.h"

#include "controller/diagnostics.h"
#include "controller/soft/soft_body_builder.h"
#include "model/polygon.h"
#include "view/lesson_session.h"
#include "view/view_constants.h"

#include <QAccessible>
#include <QApplication>
#include <QCheckBox>
#include <QColor>
#include <QColorDialog>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPalette>
#include <QPixmap>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <initializer_list>
#include <cmath>
#include <numbers>
#include <utility>

namespace impetus::view {

namespace {

/// `soft` with a damping ratio of 1: controller::softSpringDamping then gives 2·√(k·m/2), the
/// coefficient that one unit of ζ stands for.
model::SoftSettings ratioOne(model::SoftSettings soft)
{
    soft.dampingMode = model::SoftDampingMode::Ratio;
    soft.dampingRatio = 1;
    return soft;
}

/// Significant digits a number is shown with. Six reads well in a narrow pane and is finer than
/// anything a student measures; a value the user does not touch keeps its full precision, because
/// only edited fields are parsed back.
constexpr int kSignificantDigits = 6;

/// Degrees per radian: angles are shown in degrees, which students read, and kept in radians.
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;


/// Side of the colour swatch on the colour button, px.
constexpr int kSwatchSizePx = 14;

/// Vertex rows the table shows before it scrolls: a quadrilateral and a bit, without letting a
/// 50-vertex polygon push the rest of the pane out of sight.
constexpr int kVisibleVertexRows = 6;

/// An edit that copies `current` (a member of the pane, read when the edit is applied), changes
/// the copy with `set` and hands it to `commit`, which checks it, emits and may refuse it.
template <class T, class Commit>
std::function<std::optional<QString>(double)> editCopy(const T& current, std::function<void(T&, double)> set,
                                                       Commit commit)
{
    return [&current, set = std::move(set), commit = std::move(commit)](double value) {
        T copy = current;
        set(copy, value);
        return commit(std::move(copy));
    };
}

/// `widget` with its object name (for tests and style sheets) and accessible name set.
template <class W>
W* named(W* widget, const char* objectName, const QString& accessibleName)
{
    widget->setObjectName(QString::fromLatin1(objectName));
    widget->setAccessibleName(accessibleName);
    return widget;
}

/// Adds the row `label` · `field` to `form`; the label's buddy is `buddy`, the widget that takes
/// the focus (field itself, or the first edit in it).
void addLabelledRow(QFormLayout* form, const QString& label, QWidget* field, QWidget* buddy)
{
    auto* rowLabel = new QLabel(label);
    rowLabel->setBuddy(buddy);
    form->addRow(rowLabel, field);
}

/// A row widget: `widgets` side by side, the line edits stretching, then `unit`.
QWidget* rowWith(std::initializer_list<QWidget*> widgets, const QString& unit)
{
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    for (QWidget* widget : widgets)
        layout->addWidget(widget, qobject_cast<QLineEdit*>(widget) ? 1 : 0);
    layout->addWidget(new QLabel(unit));
    return row;
}

/// Characters a combo box is sized for; longer entries are elided in the closed box.
constexpr int kComboMinimumCharacters = 12;

/// The text that asks for SoftSettings::autoDensity, as in the scene format.
constexpr char kAutoText[] = "auto";

QString toQString(const std::string& text) { return QString::fromStdString(text); }

QColor toQColor(const model::Color& color) { return QColor(color.r, color.g, color.b); }

/// A size of the body's shape when it is an S, else 0 (the row is hidden then), m.
template <class S>
double shapeSize(const model::Body& body, Scalar S::*member)
{
    const auto* shape = std::get_if<S>(&body.shape);
    return shape ? shape->*member : 0.0;
}

/// Sets a size of the body's shape when it is an S.
template <class S>
void setShapeSize(model::Body& body, Scalar S::*member, double value)
{
    if (auto* shape = std::get_if<S>(&body.shape))
        shape->*member = value;
}

/// The lesson attribute that the body field called `name` edits; nullopt for read-only fields.
std::optional<model::BodyAttribute> bodyAttributeOf(const QString& name)
{
    using A = model::BodyAttribute;
    static const std::pair<const char*, A> kFields[] = {
        {"name", A::Name},           {"radius", A::ShapeSize},      {"radiusX", A::ShapeSize},
        {"radiusY", A::ShapeSize},   {"width", A::ShapeSize},       {"height", A::ShapeSize},
        {"vertices", A::ShapeSize},  {"addVertex", A::ShapeSize},   {"removeVertex", A::ShapeSize},
        {"positionX", A::Position},  {"positionY", A::Position},    {"angle", A::Angle},
        {"velocityX", A::Velocity},  {"velocityY", A::Velocity},    {"angularVelocity", A::AngularVelocity},
        {"massMode", A::Mass},       {"density", A::Mass},          {"mass", A::Mass},
        {"restitution", A::Restitution}, {"friction", A::Friction}, {"fixed", A::Fixed},
        {"color", A::FillColor},     {"soft", A::Soft},             {"softDensity", A::Soft},
        {"softStiffness", A::Soft},  {"softDamping", A::Soft},        {"softDampingRatio", A::Soft}};
    for (const auto& [field, attribute] : kFields) {
        if (name == QLatin1String(field))
            return attribute;
    }
    return std::nullopt;
}

/// The lesson attribute that the world field called `name` edits.
std::optional<model::WorldAttribute> worldAttributeOf(const QString& name)
{
    using A = model::WorldAttribute;
    static const std::pair<const char*, A> kFields[] = {
        {"gravityX", A::Gravity}, {"gravityY", A::Gravity}, {"integrator", A::Integrator},
        {"timeStep", A::TimeStep}, {"drag", A::Drag}};
    for (const auto& [field, attribute] : kFields) {
        if (name == QLatin1String(field))
            return attribute;
    }
    return std::nullopt;
}

/// The lesson attribute that the spring field called `name` edits.
std::optional<model::SpringAttribute> springAttributeOf(const QString& name)
{
    using A = model::SpringAttribute;
    if (name == QLatin1String("springStiffness"))
        return A::Stiffness;
    if (name == QLatin1String("springDamping"))
        return A::Damping;
    if (name == QLatin1String("springRestLength"))
        return A::RestLength;
    if (name.startsWith(QLatin1String("springAnchor")))
        return A::Anchors;
    return std::nullopt;
}

/// The joint attribute a joint page field edits, from its object name: every field of a joint
/// that can be typed in is one of its anchors (a pin's hinge, a rod's ends).
std::optional<model::JointAttribute> jointAttributeOf(const QString& name)
{
    if (name.startsWith(QLatin1String("pinAnchor")) || name.startsWith(QLatin1String("rodAnchor")))
        return model::JointAttribute::Anchors;
    return std::nullopt;
}

} // namespace

/// One numeric line edit bound to one model value.
struct PropertyPane::NumberField {
    Page page = Page::World;
    QLineEdit* edit = nullptr;
    QWidget* row = nullptr; ///< the widget that holds the edit in its form row
    QString label; ///< names the quantity in messages, e.g. "Restitution"
    Bound bound = Bound::Any;
    double displayScale = 1; ///< shown value = model value × displayScale (rad → °)
    std::function<double()> read; ///< the model value, from the pane's copy
    Apply apply; ///< empty: a read-only field
    QString shown; ///< the text last put in the edit from the model
};

PropertyPane::PropertyPane(QWidget* parent)
    : QWidget(parent)
{
    setAccessibleName(tr("Attributes"));
    m_locale = locale();
    // "1,234" would read as 1234 in English and as 1.234 in German; a pane that accepts only
    // plain numbers cannot misread either.
    m_locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);

    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("title"));
    m_title->setAccessibleName(tr("Shown item"));
    QFont titleFont = m_title->font();
    titleFont.setBold(true);
    m_title->setFont(titleFont);
    layout->addWidget(m_title);

    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("note"));
    m_note->setAccessibleName(tr("Selection note"));
    m_note->setWordWrap(true);
    m_note->hide();
    layout->addWidget(m_note);

    m_lockNote = new QLabel(this);
    m_lockNote->setObjectName(QStringLiteral("lockNote"));
    m_lockNote->setAccessibleName(tr("Lock note"));
    m_lockNote->setWordWrap(true);
    m_lockNote->setTextFormat(Qt::PlainText);
    m_lockNote->hide();
    layout->addWidget(m_lockNote);

    m_message = makeMessageLabel(QStringLiteral("message"), tr("Message"), this);
    layout->addWidget(m_message);

    m_pages = new QWidget;
    auto* pagesLayout = new QVBoxLayout(m_pages);
    pagesLayout->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    // The fields take the focus; the scroll area itself would only be an empty tab stop.
    scroll->setFocusPolicy(Qt::NoFocus);
    scroll->setWidget(m_pages);
    layout->addWidget(scroll, 1);

    // The pages are built in the order of Page, and each page's fields top to bottom, which is
    // the tab order.
    buildWorldPage();
    buildBodyPage();
    buildSpringPage();
    buildJointPage();
    display(false);
}

PropertyPane::~PropertyPane()
{
    // ~QWidget deletes the fields after this destructor has run; the focused one then loses the
    // focus and emits editingFinished, whose handlers must no longer reach this half-destroyed pane.
    for (QObject* child : findChildren<QObject*>())
        child->disconnect(this);
}

QString PropertyPane::message() const { return m_message->text(); }

QString PropertyPane::lockNote() const { return m_lockNote->text(); }

// ---- Building -----------------------------------------------------------------------------------

QFormLayout* PropertyPane::addPage(Page page, const QString& accessibleName)
{
    auto* widget = new QWidget;
    widget->setAccessibleName(accessibleName);
    auto* column = new QVBoxLayout(widget);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // In a narrow dock a long label goes above its field instead of pushing the units out of view.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    column->addLayout(form);
    // The rows keep their natural height at the top; the free space stays below them.
    column->addStretch(1);
    m_pages->layout()->addWidget(widget);
    m_pageWidgets.push_back(widget);
    m_forms.push_back(form);
    Q_ASSERT(m_forms.size() == static_cast<std::size_t>(page) + 1);
    return form;
}

PropertyPane::NumberField& PropertyPane::makeNumber(Page page, const QString& objectName, const QString& label,
                                                   const QString& unit, Bound bound, std::function<double()> read,
                                                   Apply apply)
{
    auto field = std::make_unique<NumberField>();
    field->page = page;
    field->label = label;
    field->bound = bound;
    field->read = std::move(read);
    field->apply = std::move(apply);
    field->edit = new QLineEdit;
    field->edit->setObjectName(objectName);
    field->edit->setAccessibleName(label);
    if (!unit.isEmpty())
        field->edit->setAccessibleDescription(tr("Unit: %1").arg(unit));
    field->edit->setReadOnly(!field->apply);
    NumberField& ref = *field;
    m_numbers.push_back(std::move(field));
    connect(ref.edit, &QLineEdit::editingFinished, this, [this, &ref] { onNumberEdited(ref); });
    return ref;
}

PropertyPane::NumberField& PropertyPane::addNumber(Page page, QFormLayout* form, const QString& objectName,
                                                  const QString& label, const QString& unit, Bound bound,
                                                  std::function<double()> read, Apply apply)
{
    NumberField& field = makeNumber(page, objectName, label, unit, bound, std::move(read), std::move(apply));
    field.row = rowWith({field.edit}, unit);
    addLabelledRow(form, label, field.row, field.edit);
    return field;
}

QWidget* PropertyPane::addVector(Page page, QFormLayout* form, const QString& objectName, const QString& label,
                                 const QString& unit, std::function<Vec2()> read,
                                 const std::function<Apply(int axis)>& apply)
{
    const QString axisNames[2] = {QStringLiteral("x"), QStringLiteral("y")};
    NumberField* fields[2] = {};
    QLabel* axisLabels[2] = {};
    for (int axis = 0; axis < 2; ++axis) {
        NumberField& field =
            makeNumber(page, objectName + axisNames[axis].toUpper(), tr("%1 %2").arg(label, axisNames[axis]), unit,
                       Bound::Any, [read, axis] { return read()[axis]; }, apply ? apply(axis) : Apply{});
        fields[axis] = &field;
        axisLabels[axis] = new QLabel(axisNames[axis]);
        axisLabels[axis]->setBuddy(field.edit);
    }
    QWidget* row = rowWith({axisLabels[0], fields[0]->edit, axisLabels[1], fields[1]->edit}, unit);
    fields[0]->row = row;
    fields[1]->row = row;
    addLabelledRow(form, label, row, fields[0]->edit);
    return row;
}

QLineEdit* PropertyPane::addText(QFormLayout* form, const QString& objectName, const QString& label)
{
    auto* edit = new QLineEdit;
    edit->setObjectName(objectName);
    edit->setAccessibleName(label);
    addLabelledRow(form, label, edit, edit);
    return edit;
}

void PropertyPane::buildWorldPage()
{
    QFormLayout* form = addPage(Page::World, tr("World settings"));
    addVector(Page::World, form, QStringLiteral("gravity"), tr("Gravity"), tr("m/s²"),
              [this] { return m_settings.gravity; },
              [this](int axis) {
                  return editWorld([axis](model::WorldSettings& s, double v) { s.gravity[axis] = v; },
                                   tr("Change gravity"));
              });

    m_integrator = named(new QComboBox, "integrator", tr("Integrator"));
    m_integrator->addItem(tr("Explicit Euler (euler)"), static_cast<int>(model::IntegratorKind::Euler));
    m_integrator->addItem(tr("Semi-implicit Euler (semi-implicit-euler)"),
                          static_cast<int>(model::IntegratorKind::SemiImplicitEuler));
    m_integrator->addItem(tr("Runge–Kutta 4 (rk4)"), static_cast<int>(model::IntegratorKind::Rk4));
    // The longest name would make the narrow dock scroll sideways; the open list shows it whole.
    m_integrator->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_integrator->setMinimumContentsLength(kComboMinimumCharacters);
    addLabelledRow(form, tr("Integrator"), m_integrator, m_integrator);
    connect(m_integrator, &QComboBox::activated, this, &PropertyPane::onIntegratorActivated);

    addNumber(Page::World, form, QStringLiteral("timeStep"), tr("Time step"), tr("s"), Bound::Positive,
              [this] { return m_settings.timeStep; },
              [this, apply = editWorld([](model::WorldSettings& s, double v) { s.timeStep = v; },
                                       tr("Change time step"))](double value) -> std::optional<QString> {
                  if (value < constants::kMinEditableTimeStep || value > constants::kMaxEditableTimeStep) {
                      return tr("Time step must be from %1 s to %2 s (got %3 s).")
                          .arg(formatNumber(constants::kMinEditableTimeStep),
                               formatNumber(constants::kMaxEditableTimeStep), formatNumber(value));
                  }
                  return apply(value);
              });
    addNumber(Page::World, form, QStringLiteral("drag"), tr("Drag"), tr("N·s/m"), Bound::NonNegative,
              [this] { return m_settings.drag; },
              editWorld([](model::WorldSettings& s, double v) { s.drag = v; }, tr("Change drag")));

    // Legal settings outside what the engine is tested for (issue 17): said where they are set.
    m_worldWarnings = makeMessageLabel(QStringLiteral("worldWarnings"), tr("Warnings"));
    form->addRow(m_worldWarnings);
}

void PropertyPane::buildBodyPage()
{
    QFormLayout* form = addPage(Page::Body, tr("Body attributes"));
    m_name = addText(form, QStringLiteral("name"), tr("Name"));
    connect(m_name, &QLineEdit::editingFinished, this, &PropertyPane::onNameEdited);
    m_shapeType = addText(form, QStringLiteral("shapeType"), tr("Shape"));
    m_shapeType->setReadOnly(true);

    const auto addSize = [this, form](const char* objectName, const QString& label, auto member) {
        return addNumber(Page::Body, form, QString::fromLatin1(objectName), label, tr("m"), Bound::Positive,
                         [this, member] { return shapeSize(m_body, member); },
                         editBody([member](model::Body& b, double v) { setShapeSize(b, member, v); },
                                  tr("Resize body")))
            .row;
    };
    m_radiusRow = addSize("radius", tr("Radius"), &model::Circle::radius);
    m_radiusXRow = addSize("radiusX", tr("Semi-axis x"), &model::Ellipse::radiusX);
    m_radiusYRow = addSize("radiusY", tr("Semi-axis y"), &model::Ellipse::radiusY);
    m_widthRow = addSize("width", tr("Width"), &model::Box::width);
    m_heightRow = addSize("height", tr("Height"), &model::Box::height);

    m_verticesRow = new QWidget;
    auto* verticesLayout = new QVBoxLayout(m_verticesRow);
    verticesLayout->setContentsMargins(0, 0, 0, 0);
    m_vertices = new QTableWidget(0, 2);
    m_vertices->setObjectName(QStringLiteral("vertices"));
    m_vertices->setAccessibleName(tr("Vertices"));
    m_vertices->setAccessibleDescription(tr("Polygon vertices in the body's own frame, in metres"));
    m_vertices->setHorizontalHeaderLabels({tr("x (m)"), tr("y (m)")});
    m_vertices->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_vertices->setSelectionMode(QAbstractItemView::SingleSelection);
    // Tab leaves the table for the next field; the arrow keys move between cells.
    m_vertices->setTabKeyNavigation(false);
    m_vertices->setFixedHeight(m_vertices->horizontalHeader()->sizeHint().height() +
                               kVisibleVertexRows * m_vertices->verticalHeader()->defaultSectionSize() +
                               2 * m_vertices->frameWidth());
    connect(m_vertices, &QTableWidget::itemChanged, this, &PropertyPane::onVertexEdited);
    m_vertexEditTriggers = static_cast<int>(m_vertices->editTriggers());
    verticesLayout->addWidget(m_vertices);
    auto* buttons = new QHBoxLayout;
    m_addVertex = named(new QPushButton(tr("Add vertex")), "addVertex", tr("Add vertex"));
    m_addVertex->setToolTip(tr("Insert a vertex halfway along the edge after the current vertex"));
    m_removeVertex = named(new QPushButton(tr("Remove vertex")), "removeVertex", tr("Remove vertex"));
    m_removeVertex->setToolTip(tr("Remove the current vertex"));
    connect(m_addVertex, &QPushButton::clicked, this, &PropertyPane::addVertex);
    connect(m_removeVertex, &QPushButton::clicked, this, &PropertyPane::removeVertex);
    buttons->addWidget(m_addVertex);
    buttons->addWidget(m_removeVertex);
    verticesLayout->addLayout(buttons);
    addLabelledRow(form, tr("Vertices"), m_verticesRow, m_vertices);

    addVector(Page::Body, form, QStringLiteral("position"), tr("Position"), tr("m"),
              [this] { return m_body.state.position; },
              [this](int axis) {
                  return editBody([axis](model::Body& b, double v) { b.state.position[axis] = v; }, tr("Move body"));
              });
    NumberField& angle =
        addNumber(Page::Body, form, QStringLiteral("angle"), tr("Angle"), tr("°"), Bound::Any,
                  [this] { return m_body.state.angle; },
                  editBody([](model::Body& b, double v) { b.state.angle = v; }, tr("Rotate body")));
    angle.displayScale = kDegreesPerRadian;
    addVector(Page::Body, form, QStringLiteral("velocity"), tr("Velocity"), tr("m/s"),
              [this] { return m_body.state.velocity; },
              [this](int axis) {
                  return editBody([axis](model::Body& b, double v) { b.state.velocity[axis] = v; },
                                  tr("Change velocity"));
              });
    NumberField& spin = addNumber(
        Page::Body, form, QStringLiteral("angularVelocity"), tr("Angular velocity"), tr("°/s"), Bound::Any,
        [this] { return m_body.state.angularVelocity; },
        editBody([](model::Body& b, double v) { b.state.angularVelocity = v; }, tr("Change angular velocity")));
    spin.displayScale = kDegreesPerRadian;

    m_massMode = named(new QComboBox, "massMode", tr("Mass given as"));
    m_massMode->setAccessibleDescription(tr("Choose whether you give the density or the mass; the other follows "
                                            "from the area"));
    m_massMode->addItem(tr("Density"), static_cast<int>(model::MassMode::Density));
    m_massMode->addItem(tr("Mass"), static_cast<int>(model::MassMode::Mass));
    addLabelledRow(form, tr("Mass given as"), m_massMode, m_massMode);
    connect(m_massMode, &QComboBox::activated, this, &PropertyPane::onMassModeActivated);
    m_density = &addNumber(Page::Body, form, QStringLiteral("density"), tr("Density"), tr("kg/m²"), Bound::Positive,
                           [this] { return m_body.density(); },
                           editBody(
                               [](model::Body& b, double v) {
                                   b.massSpec = model::MassSpec{model::MassMode::Density, v};
                               },
                               tr("Change density")));
    m_mass = &addNumber(Page::Body, form, QStringLiteral("mass"), tr("Mass"), tr("kg"), Bound::Positive,
                        [this] { return m_body.mass; },
                        editBody([](model::Body& b,
                                    double v) { b.massSpec = model::MassSpec{model::MassMode::Mass, v}; },
                                 tr("Change mass")));
    addNumber(Page::Body, form, QStringLiteral("inertia"), tr("Moment of inertia"), tr("kg·m²"), Bound::Any,
              [this] { return m_body.inertia; }, {});

    addNumber(Page::Body, form, QStringLiteral("restitution"), tr("Restitution"), tr("(0–1)"), Bound::UnitInterval,
              [this] { return m_body.material.restitution; },
              editBody([](model::Body& b, double v) { b.material.restitution = v; }, tr("Change restitution")));
    addNumber(Page::Body, form, QStringLiteral("friction"), tr("Friction"), tr("(≥ 0)"), Bound::NonNegative,
              [this] { return m_body.material.friction; },
              editBody([](model::Body& b, double v) { b.material.friction = v; }, tr("Change friction")));

    m_fixed = named(new QCheckBox(tr("Fixed")), "fixed", tr("Fixed"));
    m_fixed->setToolTip(tr("A fixed body has infinite mass: it moves only with the velocity it is given"));
    form->addRow(QString(), m_fixed);
    connect(m_fixed, &QCheckBox::clicked, this, &PropertyPane::onFixedClicked);

    m_color = named(new QPushButton, "color", tr("Colour"));
    addLabelledRow(form, tr("Colour"), m_color, m_color);
    connect(m_color, &QPushButton::clicked, this, &PropertyPane::chooseColor);

    m_soft = named(new QCheckBox(tr("Soft body")), "soft", tr("Soft body"));
    m_soft->setToolTip(tr("Simulate the body as a grid of small ellipses joined by springs"));
    form->addRow(QString(), m_soft);
    connect(m_soft, &QCheckBox::clicked, this, &PropertyPane::onSoftClicked);

    m_softDensity = named(new QLineEdit, "softDensity", tr("Ellipses per square metre"));
    m_softDensity->setAccessibleDescription(tr("A number greater than 0, or “auto”"));
    m_softDensity->setPlaceholderText(tr("a number or “auto”"));
    addLabelledRow(form, tr("Ellipses per m²"), rowWith({m_softDensity}, tr("1/m²")), m_softDensity);
    connect(m_softDensity, &QLineEdit::editingFinished, this, &PropertyPane::onSoftDensityEdited);
    m_softGrid = named(new QLabel, "softGrid", tr("Soft grid"));
    m_softGrid->setWordWrap(true);
    m_softGrid->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(QString(), m_softGrid);

    // Soft fields are only enabled while the body is soft, so m_body.soft is present when they apply.
    m_softStiffness = &addNumber(Page::Body, form, QStringLiteral("softStiffness"), tr("Soft stiffness"), tr("N/m"),
                                 Bound::Positive,
                                 [this] { return m_body.soft.value_or(model::SoftSettings{}).stiffness; },
                                 editBody([](model::Body& b, double v) { b.soft.value().stiffness = v; },
                                          tr("Change soft stiffness")));
    // The damping as a ratio ζ (what the body is given by default) and as the coefficient c of
    // each grid spring. Both always show; typing one makes it the one the body keeps, and the
    // other then shows its equivalent for the grid as built (controller::softSpringDamping).
    m_softDampingRatio = &addNumber(
        Page::Body, form, QStringLiteral("softDampingRatio"), tr("Soft damping ratio ζ"), QString(), Bound::NonNegative,
        [this] {
            const model::SoftSettings soft = m_body.soft.value_or(model::SoftSettings{});
            if (soft.dampingMode == model::SoftDampingMode::Ratio || !(m_softEllipseMass > 0))
                return soft.dampingRatio;
            return soft.damping / controller::softSpringDamping(ratioOne(soft), m_softEllipseMass);
        },
        editBody(
            [](model::Body& b, double v) {
                b.soft.value().dampingMode = model::SoftDampingMode::Ratio;
                b.soft.value().dampingRatio = v;
            },
            tr("Change soft damping ratio")));
    m_softDamping = &addNumber(
        Page::Body, form, QStringLiteral("softDamping"), tr("Soft damping"), tr("N·s/m"), Bound::NonNegative,
        [this] {
            const model::SoftSettings soft = m_body.soft.value_or(model::SoftSettings{});
            if (soft.dampingMode == model::SoftDampingMode::Coefficient || !(m_softEllipseMass > 0))
                return soft.damping;
            return controller::softSpringDamping(soft, m_softEllipseMass);
        },
        editBody(
            [](model::Body& b, double v) {
                b.soft.value().dampingMode = model::SoftDampingMode::Coefficient;
                b.soft.value().damping = v;
            },
            tr("Change soft damping")));

    // Arrows for this body alone, on top of the View menu's: how the canvas shows the body, not
    // what it is, so a tick is no edit and has no undo.
    auto* vectors = named(new QGroupBox(tr("Show vectors")), "bodyVectors", tr("Show vectors"));
    auto* grid = new QGridLayout(vectors);
    struct VectorBox {
        VectorKind kind;
        QString text;
        const char* objectName;
    };
    const std::array<VectorBox, kVectorKindCount> kinds = {{
        {VectorKind::Velocity, tr("Velocity"), "bodyVelocityVectors"},
        {VectorKind::Acceleration, tr("Acceleration"), "bodyAccelerationVectors"},
        {VectorKind::NetForce, tr("Net force"), "bodyNetForceVectors"},
        {VectorKind::ForceParts, tr("Force parts"), "bodyForcePartVectors"},
        {VectorKind::Momentum, tr("Momentum"), "bodyMomentumVectors"},
    }};
    constexpr int kColumns = 2;
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        const VectorKind kind = kinds[k].kind;
        const QString text = kinds[k].text;
        auto* box = new QCheckBox(text, vectors);
        box->setObjectName(QString::fromLatin1(kinds[k].objectName));
        box->setAccessibleName(tr("Show %1 arrows of this body").arg(text.toLower()));
        grid->addWidget(box, static_cast<int>(k) / kColumns, static_cast<int>(k) % kColumns);
        connect(box, &QCheckBox::clicked, this,
                [this, kind](bool on) { emit bodyVectorToggled(toQString(m_body.name), kind, on); });
        m_bodyVectors[static_cast<std::size_t>(kind)] = box;
    }
    form->addRow(vectors);
}

void PropertyPane::setBodyVectorsShown(std::function<bool(const std::string& name, VectorKind kind)> shown)
{
    m_bodyVectorsShown = std::move(shown);
    if (m_page == Page::Body)
        display(false);
}

void PropertyPane::buildSpringPage()
{
    QFormLayout* form = addPage(Page::Spring, tr("Spring attributes"));
    m_springBodyA = addText(form, QStringLiteral("springBodyA"), tr("Body A"));
    m_springBodyA->setReadOnly(true);
    QWidget* anchorA = addVector(Page::Spring, form, QStringLiteral("springAnchorA"), tr("Anchor A"), tr("m"),
              [this] { return m_spring.anchorA; },
              [this](int axis) {
                  return editSpring([axis](model::Spring& s, double v) { s.anchorA[axis] = v; }, tr("Move spring end"));
              });
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(anchorA)))
        label->setText(tr("Anchor A (body frame)"));
    m_springBodyB = addText(form, QStringLiteral("springBodyB"), tr("Body B"));
    m_springBodyB->setReadOnly(true);
    m_springAnchorBRow = addVector(Page::Spring, form, QStringLiteral("springAnchorB"), tr("Anchor B"), tr("m"),
                                   [this] { return m_spring.anchorB; },
                                   [this](int axis) {
                                       return editSpring([axis](model::Spring& s, double v) { s.anchorB[axis] = v; },
                                                         tr("Move spring end"));
                                   });
    addNumber(Page::Spring, form, QStringLiteral("springStiffness"), tr("Stiffness"), tr("N/m"), Bound::NonNegative,
              [this] { return m_spring.stiffness; },
              editSpring([](model::Spring& s, double v) { s.stiffness = v; }, tr("Change spring stiffness")));
    addNumber(Page::Spring, form, QStringLiteral("springDamping"), tr("Damping"), tr("N·s/m"), Bound::NonNegative,
              [this] { return m_spring.damping; },
              editSpring([](model::Spring& s, double v) { s.damping = v; }, tr("Change spring damping")));
    addNumber(Page::Spring, form, QStringLiteral("springRestLength"), tr("Rest length"), tr("m"),
              Bound::NonNegative, [this] { return m_spring.restLength; },
              editSpring([](model::Spring& s, double v) { s.restLength = v; }, tr("Change rest length")));
    // A spring too stiff for the step, said where its stiffness is typed (the world page lists it
    // too), with the step that holds it a click away.
    m_springWarnings = makeMessageLabel(QStringLiteral("springWarnings"), tr("Warnings"));
    form->addRow(m_springWarnings);
    m_useStableStep = new QPushButton(this);
    m_useStableStep->setObjectName(QStringLiteral("springUseStableStep"));
    m_useStableStep->setAccessibleName(tr("Use the time step that holds this spring"));
    m_useStableStep->hide();
    form->addRow(m_useStableStep);
    connect(m_useStableStep, &QPushButton::clicked, this, [this] {
        if (!m_stableStep)
            return;
        model::WorldSettings settings = m_settings;
        settings.timeStep = *m_stableStep;
        if (const std::optional<QString> refused = commitWorldSettings(settings, tr("Change time step")))
            refuse(*refused);
    });
}

void PropertyPane::buildJointPage()
{
    QFormLayout* form = addPage(Page::Joint, tr("Joint attributes"));
    m_jointType = addText(form, QStringLiteral("jointType"), tr("Type"));
    m_jointType->setReadOnly(true);
    m_jointBodyA = addText(form, QStringLiteral("jointBodyA"), tr("Body A"));
    m_jointBodyA->setReadOnly(true);
    m_jointBodyB = addText(form, QStringLiteral("jointBodyB"), tr("Body B"));
    m_jointBodyB->setReadOnly(true);
    m_pinAnchorRow = addVector(Page::Joint, form, QStringLiteral("pinAnchor"), tr("Hinge"), tr("m"),
                               [this] { return m_joint.worldAnchor; },
                               [this](int axis) {
                                   return editJoint([axis](model::Joint& j, double v) { j.worldAnchor[axis] = v; },
                                                    tr("Move hinge"));
                               });
    m_rodAnchorARow = addVector(Page::Joint, form, QStringLiteral("rodAnchorA"), tr("Anchor A"), tr("m"),
                                [this] { return m_joint.anchorA; },
                                [this](int axis) {
                                    return editJoint([axis](model::Joint& j, double v) { j.anchorA[axis] = v; },
                                                     tr("Move rod end"));
                                });
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(m_pinAnchorRow)))
        label->setText(tr("Hinge (world point)"));
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(m_rodAnchorARow)))
        label->setText(tr("Anchor A (body frame)"));
    m_rodAnchorBRow = addVector(Page::Joint, form, QStringLiteral("rodAnchorB"), tr("Anchor B"), tr("m"),
                                [this] { return m_joint.anchorB; },
                                [this](int axis) {
                                    return editJoint([axis](model::Joint& j, double v) { j.anchorB[axis] = v; },
                                                     tr("Move rod end"));
                                });
    m_rodLengthRow = addNumber(Page::Joint, form, QStringLiteral("rodLength"), tr("Length"), tr("m"), Bound::Any,
                               [this] { return m_joint.length; }, {})
                         .row;
}

// ---- Applying edits -----------------------------------------------------------------------------

PropertyPane::Apply PropertyPane::editBody(std::function<void(model::Body&, double)> set, const QString& actionName)
{
    return editCopy(m_body, std::move(set),
                    [this, actionName](model::Body body) { return commitBody(std::move(body), actionName); });
}

PropertyPane::Apply PropertyPane::editSpring(std::function<void(model::Spring&, double)> set,
                                             const QString& actionName)
{
    return editCopy(m_spring, std::move(set), [this, actionName](const model::Spring& spring) -> std::optional<QString> {
        if (m_lesson && spring != m_spring) {
            if (std::optional<QString> lock = m_lesson->refusal(m_index, m_spring, spring))
                return lock;
        }
        if (spring != m_spring) {
            m_spring = spring;
            emit springEdited(m_index, m_spring, actionName);
        }
        return std::optional<QString>();
    });
}

PropertyPane::Apply PropertyPane::editJoint(std::function<void(model::Joint&, double)> set, const QString& actionName)
{
    return editCopy(m_joint, std::move(set),
                    [this, actionName](model::Joint joint) { return commitJoint(std::move(joint), actionName); });
}

PropertyPane::Apply PropertyPane::editWorld(std::function<void(model::WorldSettings&, double)> set,
                                            const QString& actionName)
{
    return editCopy(m_settings, std::move(set), [this, actionName](const model::WorldSettings& settings) {
        return commitWorldSettings(settings, actionName);
    });
}

std::optional<QString> PropertyPane::commitBody(model::Body body, const QString& actionName)
{
    body.updateDerived();
    // Sizes and densities that are each fine can multiply out to nothing or to infinity; the
    // engine divides by both, so such a body would turn the first step into NaN (the scene loader
    // refuses it for the same reason).
    const bool usable = std::isfinite(body.mass) && body.mass > 0 && std::isfinite(body.inertia) && body.inertia > 0;
    if (!usable) {
        return tr("The size or density is too extreme to simulate (mass %1 kg, moment of inertia %2 kg·m²).")
            .arg(formatNumber(body.mass), formatNumber(body.inertia));
    }
    if (body == m_body)
        return std::nullopt;
    if (m_lesson) {
        if (std::optional<QString> lock = m_lesson->refusal(m_index, m_body, body))
            return lock;
    }
    m_body = std::move(body);
    emit bodyEdited(m_index, m_body, actionName);
    display(true);
    return std::nullopt;
}

std::optional<QString> PropertyPane::commitJoint(model::Joint joint, const QString& actionName)
{
    // The derived anchors and length follow from the edited ones and the bodies' current poses,
    // exactly as the scene loader derives them at load time.
    if (joint.type == model::JointType::Pin) {
        joint.anchorA = rotate(Vec2(joint.worldAnchor - m_endStateA.position), -m_endStateA.angle);
        joint.anchorB = m_endStateB ? rotate(Vec2(joint.worldAnchor - m_endStateB->position), -m_endStateB->angle)
                                    : joint.worldAnchor;
    } else {
        const Vec2 endA = m_endStateA.position + rotate(joint.anchorA, m_endStateA.angle);
        const Vec2 endB = m_endStateB ? Vec2(m_endStateB->position + rotate(joint.anchorB, m_endStateB->angle))
                                      : joint.anchorB;
        joint.length = (endB - endA).norm();
        const double scale = std::max({1.0, endA.norm(), endB.norm()});
        if (!(joint.length > impetus::constants::kRelativePointTolerance * scale))
            return tr("A rod needs two different ends: both anchors are at the same point.");
    }
    if (joint == m_joint)
        return std::nullopt;
    if (m_lesson) {
        if (std::optional<QString> lock = m_lesson->refusal(m_index, m_joint, joint))
            return lock;
    }
    m_joint = joint;
    emit jointEdited(m_index, m_joint, actionName);
    display(true);
    return std::nullopt;
}

void PropertyPane::onNumberEdited(NumberField& field)
{
    if (!field.apply || field.edit->isReadOnly() || !field.edit->isEnabled() || field.page != m_page ||
        !field.row->isVisibleTo(this))
        return;
    const QString text = field.edit->text().trimmed();
    if (text == field.shown)
        return;
    double shownValue = 0;
    std::optional<QString> problem = checkNumber(field.label, text, field.bound, shownValue);
    if (!problem)
        problem = field.apply(shownValue / field.displayScale);
    report(problem);
    // Refused or applied, the field shows the model's value, in the pane's format.
    field.shown = formatNumber(field.read() * field.displayScale);
    field.edit->setText(field.shown);
}

void PropertyPane::onNameEdited()
{
    if (m_page != Page::Body)
        return;
    const QString shown = toQString(m_body.name);
    // Spaces at either end of a name are invisible in the pane and on the canvas, so never meant.
    const QString name = m_name->text().trimmed();
    if (name == shown) {
        m_name->setText(shown);
        return;
    }
    const std::string newName = name.toStdString();
    const auto other = std::find(m_bodyNames.begin(), m_bodyNames.end(), newName);
    if (name.isEmpty()) {
        refuse(tr("Name: a body needs a name."));
    } else if (other != m_bodyNames.end() && other - m_bodyNames.begin() != m_index) {
        refuse(tr("Name: another body is already called “%1”; names must be unique.").arg(name));
    } else {
        model::Body body = m_body;
        body.name = newName;
        clearMessage();
        if (const std::optional<QString> problem = commitBody(std::move(body), tr("Rename body")))
            refuse(*problem);
        else
            m_bodyNames[static_cast<std::size_t>(m_index)] = newName;
    }
    m_name->setText(toQString(m_body.name));
}

void PropertyPane::onSoftDensityEdited()
{
    if (m_page != Page::Body || !m_body.soft)
        return;
    const QString text = m_softDensity->text().trimmed();
    if (text == m_softDensityShown)
        return;
    model::SoftSettings soft = *m_body.soft;
    const std::optional<double> value = parseNumber(text);
    const QString label = tr("Ellipses per m²");
    std::optional<QString> problem;
    if (text.compare(QLatin1String(kAutoText), Qt::CaseInsensitive) == 0 ||
        text.compare(tr("auto"), Qt::CaseInsensitive) == 0) {
        soft.autoDensity = true;
    } else if (!value) {
        problem = tr("%1: “%2” is neither a number nor “auto”.").arg(label, text);
    } else if (!std::isfinite(*value) || !(*value > 0)) {
        problem = tr("%1 must be a number greater than 0, or “auto” (got %2).").arg(label, text);
    } else {
        soft.autoDensity = false;
        soft.ellipsesPerSquareMeter = *value;
    }
    if (!problem) {
        model::Body body = m_body;
        body.soft = soft;
        problem = commitBody(std::move(body), tr("Change soft density"));
    }
    report(problem);
    displaySoftDensity(true);
}

void PropertyPane::onVertexEdited(QTableWidgetItem* item)
{
    const auto* polygon = std::get_if<model::Polygon>(&m_body.shape);
    if (m_page != Page::Body || !polygon || item->row() >= static_cast<int>(polygon->vertices.size()))
        return;
    const QString text = item->text().trimmed();
    const QString label = tr("Vertex %1 %2").arg(item->row()).arg(item->column() == 0 ? QStringLiteral("x")
                                                                                        : QStringLiteral("y"));
    double value = 0;
    std::optional<QString> problem = checkNumber(label, text, Bound::Any, value);
    if (!problem) {
        std::vector<Vec2> vertices = polygon->vertices;
        vertices[static_cast<std::size_t>(item->row())][item->column()] = value;
        problem = commitVertices(std::move(vertices), tr("Move vertex"));
    }
    report(problem);
    fillVertexTable();
}

void PropertyPane::addVertex()
{
    const auto* polygon = std::get_if<model::Polygon>(&m_body.shape);
    if (!polygon || polygon->vertices.empty())
        return;
    const int count = static_cast<int>(polygon->vertices.size());
    const int row = m_vertices->currentRow() >= 0 ? m_vertices->currentRow() : count - 1;
    std::vector<Vec2> vertices = polygon->vertices;
    const auto at = static_cast<std::size_t>(row);
    // Halfway along an edge keeps the outline as it is; the user then moves the new vertex.
    const Vec2 midpoint = (vertices[at] + vertices[(at + 1) % vertices.size()]) / 2;
    vertices.insert(vertices.begin() + row + 1, midpoint);
    report(commitVertices(std::move(vertices), tr("Add vertex")));
    fillVertexTable();
    m_vertices->setCurrentCell(row + 1, 0);
}

void PropertyPane::removeVertex()
{
    const auto* polygon = std::get_if<model::Polygon>(&m_body.shape);
    if (!polygon)
        return;
    const int row = m_vertices->currentRow();
    if (row < 0 || row >= static_cast<int>(polygon->vertices.size())) {
        refuse(tr("Vertices: choose the vertex to remove in the table first."));
        return;
    }
    std::vector<Vec2> vertices = polygon->vertices;
    vertices.erase(vertices.begin() + row);
    report(commitVertices(std::move(vertices), tr("Remove vertex")));
    fillVertexTable();
    m_vertices->setCurrentCell(std::min(row, m_vertices->rowCount() - 1), 0);
}

std::optional<QString> PropertyPane::commitVertices(std::vector<Vec2> vertices, const QString& actionName)
{
    const std::vector<model::PolygonIssue> issues = model::validatePolygon(vertices);
    if (!issues.empty()) {
        QStringList reasons;
        for (const model::PolygonIssue& issue : issues)
            reasons << toQString(issue.message);
        return tr("Vertices: the shape is refused: %1.").arg(reasons.join(QStringLiteral("; ")));
    }
    model::Body body = m_body;
    body.shape = model::Polygon{std::move(vertices)};
    body.updateDerived();
    // Moving one vertex moves the centroid, which is the body's position. Shift the position with
    // it, so that the vertices the user did not touch stay where they are in the world.
    const Vec2 shift = body.geometry.centroidOffset - m_body.geometry.centroidOffset;
    body.state.position += rotate(shift, body.state.angle);
    return commitBody(std::move(body), actionName);
}

void PropertyPane::applyBody(model::Body body, const QString& actionName)
{
    report(commitBody(std::move(body), actionName));
    // A refused change must not leave a check box or combo box showing it.
    displayBody(true);
}

void PropertyPane::onMassModeActivated(int index)
{
    if (m_page != Page::Body)
        return;
    const auto mode = static_cast<model::MassMode>(m_massMode->itemData(index).toInt());
    if (mode == m_body.massSpec.mode)
        return;
    model::Body body = m_body;
    // Switching keeps the body as heavy as it is: the new number is the one the old one gave.
    if (mode == model::MassMode::Mass)
        body.massSpec = model::MassSpec{mode, m_body.mass};
    else
        body.massSpec = model::MassSpec{mode, m_body.density()};
    applyBody(std::move(body), mode == model::MassMode::Mass ? tr("Give mass instead of density")
                                                             : tr("Give density instead of mass"));
}

void PropertyPane::onIntegratorActivated(int index)
{
    if (m_page != Page::World)
        return;
    model::WorldSettings settings = m_settings;
    settings.integrator = static_cast<model::IntegratorKind>(m_integrator->itemData(index).toInt());
    report(commitWorldSettings(settings, tr("Change integrator")));
    display(true);
}

std::optional<QString> PropertyPane::commitWorldSettings(const model::WorldSettings& settings,
                                                         const QString& actionName)
{
    if (settings == m_settings)
        return std::nullopt;
    if (m_lesson) {
        if (std::optional<QString> lock = m_lesson->refusal(m_settings, settings))
            return lock;
    }
    m_settings = settings;
    emit worldSettingsEdited(m_settings, actionName);
    return std::nullopt;
}

void PropertyPane::onFixedClicked(bool checked)
{
    if (m_page != Page::Body)
        return;
    model::Body body = m_body;
    body.fixed = checked;
    applyBody(std::move(body), checked ? tr("Fix body") : tr("Free body"));
}

void PropertyPane::onSoftClicked(bool checked)
{
    if (m_page != Page::Body)
        return;
    model::Body body = m_body;
    if (checked)
        body.soft = model::SoftSettings{};
    else
        body.soft.reset();
    applyBody(std::move(body), checked ? tr("Turn on soft mode") : tr("Turn off soft mode"));
}

void PropertyPane::chooseColor()
{
    if (!m_colorDialog) {
        m_colorDialog = new QColorDialog(this);
        m_colorDialog->setObjectName(QStringLiteral("colorDialog"));
        m_colorDialog->setWindowTitle(tr("Body Colour"));
        // Qt's own dialog behaves the same on every desktop and can be driven by tests.
        m_colorDialog->setOption(QColorDialog::DontUseNativeDialog);
        connect(m_colorDialog, &QColorDialog::colorSelected, this, &PropertyPane::onColorChosen);
    }
    m_colorDialog->setCurrentColor(toQColor(m_body.color));
    m_colorDialog->open();
}

void PropertyPane::onColorChosen(const QColor& color)
{
    if (m_page != Page::Body || !color.isValid())
        return;
    model::Body body = m_body;
    body.color = model::Color{static_cast<std::uint8_t>(color.red()), static_cast<std::uint8_t>(color.green()),
                              static_cast<std::uint8_t>(color.blue())};
    applyBody(std::move(body), tr("Change colour"));
}

// ---- Showing ------------------------------------------------------------------------------------

void PropertyPane::showSelection(const model::World& world, const Selection& selection)
{
    m_selection = selection;
    load(world);
    clearMessage();
    display(true);
}

void PropertyPane::refresh(const model::World& world)
{
    const Page before = m_page;
    load(world, true);
    display(m_page != before);
}

void PropertyPane::load(const model::World& world, bool following)
{
    const auto firstValid = [](const std::vector<int>& indices, std::size_t size) {
        for (const int index : indices) {
            if (index >= 0 && static_cast<std::size_t>(index) < size)
                return index;
        }
        return -1;
    };
    const auto nameOf = [&world](const std::optional<model::BodyId>& id) {
        return id && id->index < world.bodies.size() ? toQString(world.body(*id).name) : tr("(world)");
    };
    const auto stateOf = [&world](const std::optional<model::BodyId>& id) -> std::optional<model::BodyState> {
        if (id && id->index < world.bodies.size())
            return world.body(*id).state;
        return std::nullopt;
    };

    const Page shownPage = m_page;
    const int shownIndex = m_index;
    m_settings = world.settings;
    m_page = Page::World;
    m_index = -1;
    m_worldWarningText.clear();
    if (const int body = firstValid(m_selection.bodies, world.bodies.size()); body >= 0) {
        m_page = Page::Body;
        m_index = body;
        m_body = world.bodies[static_cast<std::size_t>(body)];
        // What the engine made of a soft body: how many ellipses, at which density (the one
        // "auto" chose on this machine).
        m_softGridText.clear();
        m_softEllipseMass = 0;
        if (const model::SoftGrid* grid = world.softGrid(model::BodyId{static_cast<std::uint32_t>(body)})) {
            m_softEllipseMass = grid->ellipseMass;
            const bool automatic = m_body.soft && m_body.soft->autoDensity;
            m_softGridText = (automatic ? tr("%L1 ellipses at %L2 per m², chosen by “auto” on this computer")
                                        : tr("%L1 ellipses at %L2 per m²"))
                                 .arg(grid->size())
                                 .arg(grid->ellipsesPerSquareMeter, 0, 'g', 4);
        }
        m_bodyNames.clear();
        m_bodyNames.reserve(world.bodies.size());
        for (const model::Body& b : world.bodies)
            m_bodyNames.push_back(b.name);
    } else if (const int spring = firstValid(m_selection.springs, world.springs.size()); spring >= 0) {
        // While it follows a run the spring's warning stays as it was judged when the spring was
        // shown or last edited: judged at every step's poses (its tension and the bodies' turns
        // change its fastest motion) it came and went as the bodies swung.
        const bool sameSpring = shownPage == Page::Spring && shownIndex == spring &&
                                m_spring == world.springs[static_cast<std::size_t>(spring)];
        m_page = Page::Spring;
        m_index = spring;
        m_spring = world.springs[static_cast<std::size_t>(spring)];
        m_endNameA = nameOf(m_spring.bodyA);
        m_endNameB = nameOf(m_spring.bodyB);
        if (!following || !sameSpring)
            judgeSpring(world, static_cast<std::size_t>(spring));
    } else if (const int joint = firstValid(m_selection.joints, world.joints.size()); joint >= 0) {
        m_page = Page::Joint;
        m_index = joint;
        m_joint = world.joints[static_cast<std::size_t>(joint)];
        m_endNameA = nameOf(m_joint.bodyA);
        m_endNameB = nameOf(m_joint.bodyB);
        m_endStateA = stateOf(m_joint.bodyA).value_or(model::BodyState{});
        m_endStateB = stateOf(m_joint.bodyB);
        // The pin's worldAnchor is where it was made; bodies moved since. Show and edit the hinge
        // where it is now: on body A, or the fixed world point of a pin to the world.
        if (m_joint.type == model::JointType::Pin) {
            m_joint.worldAnchor = m_joint.bodyB
                ? Vec2(m_endStateA.position + rotate(m_joint.anchorA, m_endStateA.angle))
                : m_joint.anchorB;
        }
    }
    if (m_page == Page::World) {
        // The ranges are judged when the page is shown or the world edited, and held while a run
        // goes on, as a spring's page holds its spring's: judged at every step's poses and speeds
        // (bodies that come to touch, a spring's tension, a body's speed) they came and went.
        if (!following || shownPage != Page::World) {
            m_rangeWarnings.clear();
            for (const model::SceneProblem& warning : model::sceneWarnings(world))
                m_rangeWarnings << tr("Warning: %1").arg(QString::fromStdString(warning.toString()));
        }
        QStringList lines = m_rangeWarnings;
        // A run that adds energy where nothing does work (issue 17, F2): judged against the
        // energy the world had at step 0, at every step.
        const controller::Energy energy = controller::computeEnergy(world);
        if (world.stepCount == 0)
            m_energyBaseline = model::energyBaseline(world, energy.total(), energy.kinetic, energy.potential);
        else if (const auto grown = model::energyGrowthWarning(m_energyBaseline, energy.total(), world.time,
                                                                world.settings.integrator))
            lines << tr("Warning: %1").arg(QString::fromStdString(grown->toString()));
        m_worldWarningText = lines.join(QLatin1Char('\n'));
    }
}

void PropertyPane::judgeSpring(const model::World& world, std::size_t spring)
{
    const std::optional<model::SceneProblem> warning = model::springWarning(world, spring);
    m_springWarningText = warning ? tr("Warning: %1").arg(QString::fromStdString(warning->reason)) : QString();
    // The step offered: a little under the longest that holds (so that rounding cannot land on
    // the limit), to three significant digits, down.
    m_stableStep.reset();
    if (!warning)
        return;
    if (const std::optional<double> longest = model::longestStableSpringStep(world, world.springs[spring])) {
        const double wanted = constants::kStableStepShare * *longest;
        const double unit = std::pow(10.0, std::floor(std::log10(wanted)) - 2);
        const double step = std::floor(wanted / unit) * unit;
        if (step >= constants::kMinEditableTimeStep)
            m_stableStep = step;
    }
}

void PropertyPane::display(bool replaceFocused)
{
    // Hidden pages take no room and no tab stops. (A QStackedWidget would be as tall as its
    // tallest page, so the short world page would scroll.)
    for (std::size_t i = 0; i < m_pageWidgets.size(); ++i)
        m_pageWidgets[i]->setVisible(i == static_cast<std::size_t>(m_page));
    const std::size_t selected = m_selection.bodies.size() + m_selection.springs.size() + m_selection.joints.size();
    m_note->setVisible(selected > 1);
    if (selected > 1)
        m_note->setText(tr("%n items selected; the pane shows the first.", nullptr, static_cast<int>(selected)));

    for (const std::unique_ptr<NumberField>& field : m_numbers) {
        if (field->page != m_page || (!replaceFocused && field->edit->hasFocus()))
            continue;
        field->shown = formatNumber(field->read() * field->displayScale);
        field->edit->setText(field->shown);
    }
    switch (m_page) {
    case Page::World:
        m_title->setText(tr("World"));
        m_worldWarnings->setText(m_worldWarningText);
        m_worldWarnings->setVisible(!m_worldWarningText.isEmpty());
        m_integrator->setCurrentIndex(m_integrator->findData(static_cast<int>(m_settings.integrator)));
        break;
    case Page::Body:
        displayBody(replaceFocused);
        break;
    case Page::Spring:
        displaySpring();
        break;
    case Page::Joint:
        displayJoint();
        break;
    }
    applyLocks();
}

bool PropertyPane::locked(const QWidget* field) const
{
    if (!m_lesson)
        return false;
    switch (m_page) {
    case Page::Body: {
        const std::optional<model::BodyAttribute> attribute = bodyAttributeOf(field->objectName());
        return attribute && m_lesson->bodyLock(m_index, *attribute);
    }
    case Page::World: {
        const std::optional<model::WorldAttribute> attribute = worldAttributeOf(field->objectName());
        return attribute && m_lesson->worldLock(*attribute);
    }
    case Page::Spring: {
        const std::optional<model::SpringAttribute> attribute = springAttributeOf(field->objectName());
        return attribute ? m_lesson->springLock(m_index, *attribute).has_value() : m_lesson->locksInForce();
    }
    case Page::Joint: {
        const std::optional<model::JointAttribute> attribute = jointAttributeOf(field->objectName());
        return attribute ? m_lesson->jointLock(m_index, *attribute).has_value() : m_lesson->locksInForce();
    }
    }
    return m_lesson->locksInForce();
}

void PropertyPane::applyLocks()
{
    std::optional<QString> note;
    if (m_lesson) {
        switch (m_page) {
        case Page::World:
            note = m_lesson->worldNote();
            break;
        case Page::Body:
            note = m_lesson->bodyNote(m_index);
            break;
        case Page::Spring:
            note = m_lesson->springNote(m_index);
            break;
        case Page::Joint:
            note = m_lesson->jointNote(m_index);
            break;
        }
    }
    m_lockNote->setText(note.value_or(QString()));
    m_lockNote->setVisible(note.has_value());

    // Which of density and mass is typed in follows the mass mode; the other is computed.
    const bool byMass = m_body.massSpec.mode == model::MassMode::Mass;
    for (const std::unique_ptr<NumberField>& field : m_numbers) {
        if (field->page != m_page)
            continue;
        bool readOnly = !field->apply || locked(field->edit);
        if (field.get() == m_density)
            readOnly = readOnly || byMass;
        if (field.get() == m_mass)
            readOnly = readOnly || !byMass;
        field->edit->setReadOnly(readOnly);
    }
    if (m_page == Page::Body) {
        m_name->setReadOnly(locked(m_name));
        m_vertices->setEditTriggers(locked(m_vertices) ? QAbstractItemView::NoEditTriggers
                                                       : QAbstractItemView::EditTriggers(m_vertexEditTriggers));
        for (QWidget* widget : std::initializer_list<QWidget*>{m_addVertex, m_removeVertex, m_massMode, m_fixed, m_color, m_soft})
            widget->setEnabled(!locked(widget));
        m_softDensity->setEnabled(m_body.soft.has_value() && !locked(m_softDensity));
    } else if (m_page == Page::World) {
        m_integrator->setEnabled(!locked(m_integrator));
    }
}

void PropertyPane::displayBody(bool replaceFocused)
{
    m_title->setText(tr("Body “%1”").arg(toQString(m_body.name)));
    if (replaceFocused || !m_name->hasFocus())
        m_name->setText(toQString(m_body.name));

    QFormLayout* form = m_forms[static_cast<std::size_t>(Page::Body)];
    const bool circle = std::holds_alternative<model::Circle>(m_body.shape);
    const bool ellipse = std::holds_alternative<model::Ellipse>(m_body.shape);
    const bool box = std::holds_alternative<model::Box>(m_body.shape);
    const bool polygon = std::holds_alternative<model::Polygon>(m_body.shape);
    form->setRowVisible(m_radiusRow, circle);
    form->setRowVisible(m_radiusXRow, ellipse);
    form->setRowVisible(m_radiusYRow, ellipse);
    form->setRowVisible(m_widthRow, box);
    form->setRowVisible(m_heightRow, box);
    form->setRowVisible(m_verticesRow, polygon);
    m_shapeType->setText(circle ? tr("Circle") : ellipse ? tr("Ellipse") : box ? tr("Box") : tr("Polygon"));
    if (polygon) {
        const auto& vertices = std::get<model::Polygon>(m_body.shape).vertices;
        // Refilling the table would close a cell editor, so a table in use waits for the next time.
        const QWidget* focus = QApplication::focusWidget();
        const bool inUse = focus && (focus == m_vertices || m_vertices->isAncestorOf(focus));
        if (vertices != m_shownVertices && (replaceFocused || !inUse))
            fillVertexTable();
    }

    m_massMode->setCurrentIndex(m_massMode->findData(static_cast<int>(m_body.massSpec.mode)));
    m_fixed->setChecked(m_body.fixed);

    const QColor color = toQColor(m_body.color);
    QPixmap swatch(kSwatchSizePx, kSwatchSizePx);
    swatch.fill(color);
    m_color->setIcon(QIcon(swatch));
    m_color->setText(color.name());
    m_color->setAccessibleDescription(tr("Current colour %1; press to choose another").arg(color.name()));

    m_soft->setChecked(m_body.soft.has_value());
    m_softDensity->setEnabled(m_body.soft.has_value());
    m_softStiffness->edit->setEnabled(m_body.soft.has_value());
    m_softDamping->edit->setEnabled(m_body.soft.has_value());
    m_softDampingRatio->edit->setEnabled(m_body.soft.has_value());
    displaySoftDensity(replaceFocused);
    m_softGrid->setText(m_softGridText);
    m_softGrid->setVisible(!m_softGridText.isEmpty());
    for (std::size_t k = 0; k < kVectorKindCount; ++k)
        m_bodyVectors[k]->setChecked(m_bodyVectorsShown && m_bodyVectorsShown(m_body.name, static_cast<VectorKind>(k)));
}

void PropertyPane::displaySoftDensity(bool replaceFocused)
{
    if (!replaceFocused && m_softDensity->hasFocus())
        return;
    const model::SoftSettings soft = m_body.soft.value_or(model::SoftSettings{});
    m_softDensityShown = soft.autoDensity ? QLatin1String(kAutoText) : formatNumber(soft.ellipsesPerSquareMeter);
    m_softDensity->setText(m_softDensityShown);
}

void PropertyPane::fillVertexTable()
{
    const auto* polygon = std::get_if<model::Polygon>(&m_body.shape);
    m_shownVertices = polygon ? polygon->vertices : std::vector<Vec2>{};
    const QSignalBlocker blocker(m_vertices);
    const int current = m_vertices->currentRow();
    const int rows = static_cast<int>(m_shownVertices.size());
    m_vertices->setRowCount(rows);
    QStringList rowNames;
    for (int row = 0; row < rows; ++row) {
        // Numbered from 0, like the vertex and edge numbers in the model's messages.
        rowNames << QString::number(row);
        for (int column = 0; column < 2; ++column) {
            const double value = m_shownVertices[static_cast<std::size_t>(row)][column];
            // Items are updated in place: this runs inside itemChanged, whose item must live on.
            QTableWidgetItem* item = m_vertices->item(row, column);
            if (!item) {
                item = new QTableWidgetItem;
                m_vertices->setItem(row, column, item);
            }
            item->setText(formatNumber(value));
            item->setData(Qt::AccessibleTextRole, tr("Vertex %1 %2 = %3 m")
                                                      .arg(row)
                                                      .arg(column == 0 ? QStringLiteral("x") : QStringLiteral("y"))
                                                      .arg(formatNumber(value)));
        }
    }
    m_vertices->setVerticalHeaderLabels(rowNames);
    if (current >= 0 && current < rows)
        m_vertices->setCurrentCell(current, m_vertices->currentColumn());
}

void PropertyPane::displaySpring()
{
    m_title->setText(tr("Spring %1").arg(m_index));
    m_springBodyA->setText(m_endNameA);
    m_springBodyB->setText(m_endNameB);
    m_springWarnings->setText(m_springWarningText);
    m_springWarnings->setVisible(!m_springWarningText.isEmpty());
    m_useStableStep->setVisible(m_stableStep.has_value());
    if (m_stableStep) {
        m_useStableStep->setText(tr("Use a time step of %1 ms").arg(formatNumber(*m_stableStep * 1000)));
        // Locked with the time step by a lesson that does not let students change it.
        m_useStableStep->setEnabled(!m_lesson || !m_lesson->worldLock(model::WorldAttribute::TimeStep));
    }
    QFormLayout* form = m_forms[static_cast<std::size_t>(Page::Spring)];
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(m_springAnchorBRow)))
        label->setText(m_spring.bodyB ? tr("Anchor B (body frame)") : tr("Anchor B (world point)"));
}

void PropertyPane::displayJoint()
{
    const bool pin = m_joint.type == model::JointType::Pin;
    m_title->setText(pin ? tr("Pin joint %1").arg(m_index) : tr("Rod joint %1").arg(m_index));
    m_jointType->setText(pin ? tr("Pin") : tr("Rod"));
    m_jointBodyA->setText(m_endNameA);
    m_jointBodyB->setText(m_endNameB);
    QFormLayout* form = m_forms[static_cast<std::size_t>(Page::Joint)];
    form->setRowVisible(m_pinAnchorRow, pin);
    form->setRowVisible(m_rodAnchorARow, !pin);
    form->setRowVisible(m_rodAnchorBRow, !pin);
    form->setRowVisible(m_rodLengthRow, !pin);
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(m_rodAnchorBRow)))
        label->setText(m_joint.bodyB ? tr("Anchor B (body frame)") : tr("Anchor B (world point)"));
}

// ---- Messages and numbers -----------------------------------------------------------------------

void PropertyPane::refuse(const QString& message)
{
    m_message->setText(message);
    m_message->show();
    QAccessibleEvent event(m_message, QAccessible::Alert);
    QAccessible::updateAccessibility(&event);
}

void PropertyPane::report(const std::optional<QString>& problem)
{
    if (problem)
        refuse(*problem);
    else
        clearMessage();
}

void PropertyPane::clearMessage()
{
    m_message->clear();
    m_message->hide();
}

std::optional<QString> PropertyPane::checkNumber(const QString& label, const QString& text, Bound bound,
                                                double& value) const
{
    const std::optional<double> parsed = parseNumber(text);
    if (!parsed)
        return tr("%1: “%2” is not a number.").arg(label, text);
    value = *parsed;
    if (!std::isfinite(value))
        return tr("%1 must be a finite number (got %2).").arg(label, text);
    if (bound == Bound::Positive && !(value > 0))
        return tr("%1 must be greater than 0 (got %2).").arg(label, text);
    if (bound == Bound::NonNegative && !(value >= 0))
        return tr("%1 must be 0 or greater (got %2).").arg(label, text);
    if (bound == Bound::UnitInterval && !(value >= 0 && value <= 1))
        return tr("%1 must be between 0 and 1 (got %2).").arg(label, text);
    return std::nullopt;
}

QString PropertyPane::formatNumber(double value) const
{
    // A small e before an exponent, as the readouts write it (number_text.h); both read back.
    return localeNumber(m_locale, value, 'g', kSignificantDigits);
}

std::optional<double> PropertyPane::parseNumber(const QString& text) const
{
    bool ok = false;
    double value = m_locale.toDouble(text, &ok);
    if (!ok) {
        // A decimal point always works, whatever the locale: scene files and textbooks use it.
        QLocale c = QLocale::c();
        c.setNumberOptions(QLocale::RejectGroupSeparator);
        value = c.toDouble(text, &ok);
    }
    if (!ok)
        return std::nullopt;
    return value;
}

} // namespace impetus::view
