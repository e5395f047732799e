// Draws the narrow phase's own trace of a pair of bodies. Every number shown is read from the
// trace (controller::CollisionTrace); this file computes only where to draw it.

#include "view/sat_explainer.h"

#include "view/canvas_view.h"
#include "view/explain_constants.h"
#include "view/scene_document.h"

#include <QCoreApplication>
#include <QEvent>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QtMath>

#include <algorithm>
#include <cmath>

namespace impetus::view {

namespace {

QPointF toPoint(const Vec2& v) { return {v.x(), v.y()}; }

// The panel's numbers are in the window's number format ("500,000 mm" in German), as the status
// bar's and the probe's.

/// A number with the panel's three decimals.
QString decimals(Scalar x) { return QLocale().toString(x, 'f', 3); }

QString mm(Scalar metres) { return decimals(metres * constants::kMillimetresPerMetre); }

QString vec(const Vec2& v)
{
    //: A point or a direction: its x and y. Where the decimal separator is a comma, separate them
    //: with a semicolon: (0,600; 0,800).
    return QCoreApplication::translate("impetus::view::SatExplainer", "(%1, %2)")
        .arg(decimals(v.x()), decimals(v.y()));
}

const QColor& ownerColor(int owner) { return owner == 0 ? constants::kExplainPieceA : constants::kExplainPieceB; }

QPen cosmeticPen(const QColor& color, double widthPx, Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(color, widthPx, style, Qt::RoundCap, Qt::RoundJoin);
    pen.setCosmetic(true);
    return pen;
}

/// The explainer's drawing, in scene coordinates (m, y up), lengths on screen given in px.
class SatExplainerItem : public QGraphicsItem {
public:
    SatExplainerItem(const SatExplainer& explainer, const CanvasView& canvas)
        : m_explainer(explainer)
        , m_canvas(canvas)
    {
        setZValue(1e6); // above the bodies and the instruments
    }

    /// The explainer's traces changed: new bounds, new drawing.
    void refresh()
    {
        prepareGeometryChange();
        update();
    }

    QRectF boundingRect() const override
    {
        QRectF bounds;
        for (const controller::PiecePairTrace& pair : m_explainer.traces()) {
            for (const controller::TracedPiece* piece : {&pair.a, &pair.b}) {
                const Scalar r = reach(*piece);
                bounds |= QRectF(piece->center.x() - r, piece->center.y() - r, 2 * r, 2 * r);
            }
        }
        // The projection line is drawn beside the pair, up to about its size again away.
        return bounds.adjusted(-bounds.width() - 1, -bounds.height() - 1, bounds.width() + 1, bounds.height() + 1);
    }

    void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override
    {
        const controller::PiecePairTrace* pair = m_explainer.current();
        if (pair == nullptr)
            return;
        m_metresPerPx = 1.0 / m_canvas.pixelsPerMetre();
        painter->setRenderHint(QPainter::Antialiasing);
        drawPiece(*painter, pair->a, constants::kExplainPieceA);
        drawPiece(*painter, pair->b, constants::kExplainPieceB);
        const controller::CollisionTrace& trace = pair->trace;
        // Every tested face's normal, faint: the candidates.
        for (const controller::TracedAxis& axis : trace.axes) {
            if (axis.kind == controller::AxisKind::Face)
                drawNormal(*painter, axis, constants::kExplainFaint, constants::kExplainThinPx);
        }
        const std::size_t k = m_explainer.currentAxis();
        if (k < trace.axes.size()) {
            const controller::TracedAxis& axis = trace.axes[k];
            drawFace(*painter, axis, ownerColor(axis.owner));
            drawNormal(*painter, axis, ownerColor(axis.owner), constants::kExplainBoldPx);
            drawProjection(*painter, *pair, axis);
        } else {
            drawSummary(*painter, *pair);
        }
    }

private:
    static Scalar reach(const controller::TracedPiece& piece)
    {
        Scalar r = std::max(piece.radiusX, piece.radiusY);
        for (const Vec2& v : piece.vertices)
            r = std::max(r, (v - piece.center).norm());
        return r;
    }

    void drawPiece(QPainter& painter, const controller::TracedPiece& piece, const QColor& color) const
    {
        painter.setPen(cosmeticPen(color, constants::kExplainThinPx));
        QColor fill = color;
        fill.setAlpha(constants::kExplainFillAlpha);
        painter.setBrush(fill);
        if (piece.kind == controller::ColliderPiece::Kind::Polygon) {
            QPolygonF polygon;
            for (const Vec2& v : piece.vertices)
                polygon << toPoint(v);
            painter.drawPolygon(polygon);
        } else {
            painter.save();
            painter.translate(toPoint(piece.center));
            painter.rotate(qRadiansToDegrees(std::atan2(piece.s, piece.c)));
            const Scalar ry = piece.kind == controller::ColliderPiece::Kind::Circle ? piece.radiusX : piece.radiusY;
            painter.drawEllipse(QPointF(0, 0), piece.radiusX, ry);
            painter.restore();
        }
        painter.setBrush(Qt::NoBrush);
    }

    void drawArrow(QPainter& painter, const Vec2& from, const Vec2& to, const QColor& color, double widthPx) const
    {
        painter.setPen(cosmeticPen(color, widthPx));
        painter.drawLine(toPoint(from), toPoint(to));
        const Vec2 d = to - from;
        if (d.norm() <= 0)
            return;
        const Vec2 u = d / d.norm();
        const Vec2 side(-u.y(), u.x());
        const Scalar head = constants::kExplainArrowHeadPx * m_metresPerPx;
        painter.setBrush(color);
        painter.drawPolygon(QPolygonF{toPoint(to), toPoint(to - head * u + 0.5 * head * side),
                                      toPoint(to - head * u - 0.5 * head * side)});
        painter.setBrush(Qt::NoBrush);
    }

    void drawNormal(QPainter& painter, const controller::TracedAxis& axis, const QColor& color, double widthPx) const
    {
        const Vec2 base = 0.5 * (axis.faceStart + axis.faceEnd);
        drawArrow(painter, base, base + constants::kExplainNormalPx * m_metresPerPx * axis.normal, color, widthPx);
    }

    void drawFace(QPainter& painter, const controller::TracedAxis& axis, const QColor& color) const
    {
        painter.setPen(cosmeticPen(color, constants::kExplainBoldPx));
        painter.drawLine(toPoint(axis.faceStart), toPoint(axis.faceEnd));
    }

    void drawDot(QPainter& painter, const Vec2& at, const QColor& color, bool filled) const
    {
        painter.setPen(cosmeticPen(color, constants::kExplainThinPx));
        painter.setBrush(filled ? QBrush(color) : QBrush(Qt::NoBrush));
        const Scalar r = constants::kExplainPointPx * m_metresPerPx;
        painter.drawEllipse(toPoint(at), r, r);
        painter.setBrush(Qt::NoBrush);
    }

    /// Both pieces' intervals on the axis, drawn on a line parallel to it beside the pair.
    void drawProjection(QPainter& painter, const controller::PiecePairTrace& pair,
                        const controller::TracedAxis& axis) const
    {
        const Vec2 n = axis.normal;
        // The line runs beside the pair on its right (or upper) side, away from the text panel in
        // the top left corner, just clear of both pieces.
        Vec2 t(-n.y(), n.x());
        if (t.x() < 0 || (t.x() == 0 && t.y() < 0))
            t = -t;
        const Vec2 centre = 0.5 * (pair.a.center + pair.b.center);
        Scalar extent = 0;
        for (const controller::TracedPiece* piece : {&pair.a, &pair.b}) {
            extent = std::max(extent, t.dot(piece->center - centre) + std::max(piece->radiusX, piece->radiusY));
            for (const Vec2& v : piece->vertices)
                extent = std::max(extent, t.dot(v - centre));
        }
        const Vec2 base = centre + (extent + constants::kExplainAxisClearancePx * m_metresPerPx) * t;
        const auto at = [&](Scalar s, Scalar sidePx) {
            return base + (s - n.dot(base)) * n + sidePx * m_metresPerPx * t;
        };
        const Scalar low = std::min(axis.ownerMin, axis.otherMin);
        const Scalar high = std::max(axis.ownerMax, axis.otherMax);
        const Scalar pad = 0.15 * (high - low);
        painter.setPen(cosmeticPen(constants::kExplainFaint, constants::kExplainThinPx, Qt::DashLine));
        painter.drawLine(toPoint(at(low - pad, 0)), toPoint(at(high + pad, 0)));
        const QColor& ownerC = ownerColor(axis.owner);
        const QColor& otherC = ownerColor(1 - axis.owner);
        const Scalar gap = constants::kExplainIntervalGapPx;
        painter.setPen(cosmeticPen(ownerC, constants::kExplainBoldPx));
        painter.drawLine(toPoint(at(axis.ownerMin, gap)), toPoint(at(axis.ownerMax, gap)));
        painter.setPen(cosmeticPen(otherC, constants::kExplainBoldPx));
        painter.drawLine(toPoint(at(axis.otherMin, -gap)), toPoint(at(axis.otherMax, -gap)));
        // The overlap (or the gap) between the owner's far end and the other's near end.
        const QColor& between = axis.separation <= 0 ? constants::kExplainOverlap : constants::kExplainSeparating;
        painter.setPen(cosmeticPen(between, constants::kExplainBoldPx));
        painter.drawLine(toPoint(at(axis.otherMin, 0)), toPoint(at(axis.ownerMax, 0)));
        // Thin projectors from the face to the line show where the interval comes from.
        painter.setPen(cosmeticPen(ownerC, constants::kExplainThinPx, Qt::DotLine));
        painter.drawLine(toPoint(axis.faceStart), toPoint(at(n.dot(axis.faceStart), gap)));
    }

    /// The pair's outcome: reference and incident faces, clipped and contact points, the MTV; or
    /// the separating axis.
    void drawSummary(QPainter& painter, const controller::PiecePairTrace& pair) const
    {
        const controller::CollisionTrace& trace = pair.trace;
        if (trace.separatingAxis) {
            const controller::TracedAxis& axis = trace.axes[*trace.separatingAxis];
            drawFace(painter, axis, constants::kExplainSeparating);
            drawNormal(painter, axis, constants::kExplainSeparating, constants::kExplainBoldPx);
            drawProjection(painter, pair, axis);
            return;
        }
        if (trace.contactAxis) {
            const controller::TracedAxis& axis = trace.axes[*trace.contactAxis];
            if (axis.kind == controller::AxisKind::Face)
                drawFace(painter, axis, constants::kExplainReference);
        }
        if (trace.method == controller::TraceMethod::Sat) {
            painter.setPen(cosmeticPen(constants::kExplainIncident, constants::kExplainBoldPx));
            painter.drawLine(toPoint(trace.incidentStart), toPoint(trace.incidentEnd));
            for (const Vec2& p : trace.clipped)
                drawDot(painter, p, constants::kExplainIncident, false);
        }
        const controller::Manifold& m = trace.result;
        for (int i = 0; i < m.count; ++i) {
            const controller::ContactPoint& p = m.points[static_cast<std::size_t>(i)];
            drawDot(painter, p.point, constants::kExplainOverlap, true);
            // The minimum translation vector: how far B must move along the normal to separate.
            if (p.separation < 0)
                drawArrow(painter, p.point, p.point - p.separation * m.normal, constants::kExplainOverlap,
                          constants::kExplainBoldPx);
        }
    }

    const SatExplainer& m_explainer;
    const CanvasView& m_canvas;
    mutable Scalar m_metresPerPx = 1;
};

QString bodyName(const model::World& world, int index)
{
    return static_cast<std::size_t>(index) < world.bodies.size()
               ? QString::fromStdString(world.bodies[static_cast<std::size_t>(index)].name)
               : QString();
}

} // namespace

SatExplainer::SatExplainer(CanvasView& canvas, SceneDocument& document, QObject* parent)
    : QObject(parent)
    , m_canvas(canvas)
    , m_canvasAlive(&canvas)
    , m_document(document)
{
    connect(&m_document, &SceneDocument::stepped, this, [this] {
        if (m_open)
            retrace();
    });
    connect(&m_document, &SceneDocument::worldChanged, this, [this] {
        if (m_open)
            retrace();
    });
    connect(&m_document, &SceneDocument::sceneReplaced, this, &SatExplainer::close);
}

SatExplainer::~SatExplainer()
{
    if (m_canvasAlive)
        close();
}

bool SatExplainer::open()
{
    const std::vector<int> bodies = m_document.selection().bodies;
    if (bodies.size() != 2)
        return false;
    m_bodyA = bodies[0];
    m_bodyB = bodies[1];
    if (!m_open) {
        m_open = true;
        m_item = new SatExplainerItem(*this, m_canvas);
        m_canvas.scene()->addItem(m_item);
        m_panel = new QLabel(m_canvas.viewport());
        m_panel->setObjectName(QStringLiteral("satExplainerPanel"));
        m_panel->setTextFormat(Qt::PlainText);
        m_panel->setWordWrap(true);
        m_panel->setMargin(8);
        m_panel->setAutoFillBackground(true);
        QPalette palette = m_panel->palette();
        palette.setColor(QPalette::Window, constants::kExplainPanelBackground);
        m_panel->setPalette(palette);
        m_panel->show();
        m_canvas.installEventFilter(this);
    }
    m_pair = 0;
    m_axis = 0;
    retrace();
    m_canvas.setFocus();
    return true;
}

void SatExplainer::close()
{
    if (!m_open)
        return;
    m_open = false;
    m_canvas.removeEventFilter(this);
    delete m_item;
    m_item = nullptr;
    delete m_panel;
    m_panel = nullptr;
    m_traces.clear();
    emit changed();
}

const controller::PiecePairTrace* SatExplainer::current() const
{
    return m_pair < m_traces.size() ? &m_traces[m_pair] : nullptr;
}

void SatExplainer::next()
{
    const controller::PiecePairTrace* pair = current();
    if (pair == nullptr)
        return;
    // Each pair's axes, then its summary, then the next pair.
    if (m_axis < pair->trace.axes.size()) {
        ++m_axis;
    } else if (m_pair + 1 < m_traces.size()) {
        ++m_pair;
        m_axis = 0;
    }
    updateView();
}

void SatExplainer::previous()
{
    if (m_axis > 0) {
        --m_axis;
    } else if (m_pair > 0) {
        --m_pair;
        m_axis = m_traces[m_pair].trace.axes.size();
    }
    updateView();
}

QString SatExplainer::panelText() const { return m_panel != nullptr ? m_panel->text() : QString(); }

bool SatExplainer::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == &m_canvas && (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const bool ours = key->modifiers() == Qt::NoModifier &&
                          (key->key() == Qt::Key_N || key->key() == Qt::Key_P || key->key() == Qt::Key_Escape);
        if (ours) {
            // Claiming the shortcut keeps N and P from switching tools while the explainer is open.
            event->accept();
            if (event->type() == QEvent::KeyPress) {
                if (key->key() == Qt::Key_N)
                    next();
                else if (key->key() == Qt::Key_P)
                    previous();
                else
                    close();
            }
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

void SatExplainer::retrace()
{
    const model::World& world = m_document.world();
    m_traces = controller::traceBodyPair(world, model::BodyId{static_cast<std::uint32_t>(m_bodyA)},
                                         model::BodyId{static_cast<std::uint32_t>(m_bodyB)});
    if (m_traces.empty()) { // a body was deleted, or the scene changed under the explainer
        close();
        return;
    }
    m_pair = std::min(m_pair, m_traces.size() - 1);
    m_axis = std::min(m_axis, m_traces[m_pair].trace.axes.size());
    updateView();
}

void SatExplainer::updateView()
{
    if (!m_open)
        return;
    if (m_item != nullptr) {
        static_cast<SatExplainerItem*>(m_item)->refresh();
    }
    m_panel->setText(describe());
    m_panel->setMaximumWidth(std::max(200, m_canvas.viewport()->width() / 2));
    m_panel->adjustSize();
    m_panel->move(0, 0);
    m_canvas.viewport()->update();
    emit changed();
}

QString SatExplainer::describe() const
{
    const controller::PiecePairTrace* pair = current();
    if (pair == nullptr)
        return {};
    const model::World& world = m_document.world();
    const controller::CollisionTrace& trace = pair->trace;
    const QString nameA = bodyName(world, static_cast<int>(pair->a.body));
    const QString nameB = bodyName(world, static_cast<int>(pair->b.body));
    QStringList lines;
    lines << tr("Separating axes: A = %1 (blue), B = %2 (orange)").arg(nameA, nameB);
    if (m_traces.size() > 1)
        lines << tr("Convex pieces: %1 of A and %2 of B (pair %3 of %4)")
                     .arg(pair->a.piece + 1)
                     .arg(pair->b.piece + 1)
                     .arg(m_pair + 1)
                     .arg(m_traces.size());
    switch (trace.method) {
    case controller::TraceMethod::Sat:
        lines << tr("Method: SAT over the face normals of both polygons: %1 candidate axes, %2 tested.")
                     .arg(trace.candidateCount)
                     .arg(trace.axes.size());
        break;
    case controller::TraceMethod::PolygonCircle:
        lines << tr("Method: the polygon's face normals, then the feature of the polygon closest to the "
                    "circle's centre (a face or a corner): a circle has no faces of its own.");
        break;
    case controller::TraceMethod::Circles:
        lines << tr("Method: two circles need a single axis, the line through their centres.");
        break;
    case controller::TraceMethod::Gjk:
    case controller::TraceMethod::None:
        lines << tr("Method: GJK and EPA. An ellipse has no faces, so there are no axes to test: GJK finds "
                    "the distance between the shapes, and when they overlap EPA finds the depth and the "
                    "direction of least penetration (to 0.001 mm).");
        if (trace.result.count > 0)
            lines << tr("Result: normal %1, depth %2 mm at %3.")
                         .arg(vec(trace.result.normal), mm(-trace.result.points[0].separation),
                              vec(trace.result.points[0].point));
        else
            lines << tr("Result: the shapes are apart.");
        return lines.join(QLatin1Char('\n'));
    }

    const auto featureName = [&](const controller::TracedAxis& axis) {
        const QString owner = axis.owner == 0 ? tr("A") : tr("B");
        switch (axis.kind) {
        case controller::AxisKind::Face:
            return tr("normal of face %1 of %2").arg(axis.face + 1).arg(owner);
        case controller::AxisKind::ClosestVertex:
            return tr("from corner %1 of %2 to the circle's centre").arg(axis.face + 1).arg(owner);
        case controller::AxisKind::CentreLine:
            break;
        }
        return tr("line of centres, from A to B");
    };
    if (m_axis < trace.axes.size()) {
        const controller::TracedAxis& axis = trace.axes[m_axis];
        lines << tr("Axis %1 of %2: %3, direction %4")
                     .arg(m_axis + 1)
                     .arg(trace.axes.size())
                     .arg(featureName(axis), vec(axis.normal));
        const QString owner = axis.owner == 0 ? tr("A") : tr("B");
        const QString other = axis.owner == 0 ? tr("B") : tr("A");
        lines << tr("Projections: %1 from %2 to %3 mm, %4 from %5 to %6 mm")
                     .arg(owner, mm(axis.ownerMin), mm(axis.ownerMax), other, mm(axis.otherMin), mm(axis.otherMax));
        if (axis.separation <= 0)
            lines << tr("Overlap on this axis: %1 mm").arg(mm(-axis.separation));
        else
            lines << tr("Gap on this axis: %1 mm").arg(mm(axis.separation));
        if (trace.separatingAxis == m_axis)
            lines << tr("This axis separates the shapes: no contact. The search stops here (%1 of %2 axes tested).")
                         .arg(trace.axes.size())
                         .arg(trace.candidateCount);
        else if (trace.contactAxis == m_axis)
            lines << tr("This is the axis of least overlap.");
    } else if (trace.separatingAxis) {
        lines << tr("Separated: axis %1 leaves a gap of %2 mm, so the pair is not in contact.")
                     .arg(*trace.separatingAxis + 1)
                     .arg(mm(trace.axes[*trace.separatingAxis].separation));
    } else if (trace.contactAxis) {
        const controller::TracedAxis& axis = trace.axes[*trace.contactAxis];
        lines << tr("Least overlap: axis %1 (%2), %3 mm")
                     .arg(*trace.contactAxis + 1)
                     .arg(featureName(axis), mm(-axis.separation));
        if (trace.method == controller::TraceMethod::Sat && trace.bestAxisA && trace.bestAxisB && !trace.flipped &&
            trace.axes[*trace.bestAxisB].separation > trace.axes[*trace.bestAxisA].separation)
            lines << tr("B's best face is better by less than the tolerance, so A's face stays the reference: "
                        "resting stacks do not swap faces on rounding noise.");
        lines << tr("Minimum translation vector: %1 mm along %2 (moves B off A)")
                     .arg(mm(-axis.separation), vec(trace.result.normal));
        if (trace.method == controller::TraceMethod::Sat) {
            lines << tr("Reference face (green): face %1 of %2; incident face (purple): face %3 of %4")
                         .arg(axis.face + 1)
                         .arg(trace.flipped ? tr("B") : tr("A"))
                         .arg(trace.incidentFace + 1)
                         .arg(trace.flipped ? tr("A") : tr("B"));
            if (trace.cornerToCorner)
                lines << tr("The incident face lies beyond the reference face's ends (corner to corner): one point.");
            else
                lines << tr("Clipped to the reference face's sides: %1 points; kept (touching): %2")
                             .arg(trace.clipped.size())
                             .arg(trace.result.count);
        }
        for (int i = 0; i < trace.result.count; ++i) {
            const controller::ContactPoint& p = trace.result.points[static_cast<std::size_t>(i)];
            lines << tr("Contact point %1: %2 m, separation %3 mm").arg(i + 1).arg(vec(p.point), mm(p.separation));
        }
    }
    lines << tr("N: next axis   P: previous   Esc: close");
    return lines.join(QLatin1Char('\n'));
}

} // namespace impetus::view
