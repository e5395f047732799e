#include "view/tools/measure_tools.h"

#include "view/canvas_view.h"
#include "view/simulation_runner.h"
#include "view/scene_document.h"
#include "view/view_constants.h"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QLineF>
#include <QLocale>
#include <QPainter>

#include <cmath>
#include <numbers>

namespace impetus::view {

namespace {

/// The protractor's arc has a radius of this many arrow heads, px: clear of the vertex's snap.
constexpr double kArcHeads = 3;
/// The labels' paper: white, slightly see-through.
const QColor kLabelFill(255, 255, 255, 230);
/// Space between the ruler's two labels, px.
constexpr double kLabelGapPx = 4;
/// Decimals of the ruler's lengths (mm) and of the protractor's angles (tenths of a degree).
constexpr int kLengthDecimals = 3;
constexpr int kAngleDecimals = 1;

/// `value` with `decimals` decimals in the window's number format ("2,371" in German).
QString measureNumber(double value, int decimals) { return QLocale().toString(value, 'f', decimals); }

/// Draws `text` on a light box centred at the pixel point `at`.
void drawLabel(QPainter& painter, const QPointF& at, const QString& text)
{
    QRectF box(QPointF(0, 0), measureLabelSize(painter.font(), text));
    box.moveCenter(at);
    drawMeasureLabel(painter, box, text, true);
}

/// A pen for the measuring lines: dark, thin and the same on screen at every zoom.
QPen measurePen()
{
    QPen pen(constants::kMeasureColor, constants::kOutlineWidthPx);
    pen.setCosmetic(true);
    return pen;
}

} // namespace

QSizeF measureLabelSize(const QFont& font, const QString& text)
{
    const QFontMetricsF metrics(font);
    const double pad = constants::kLegendPaddingPx;
    // Unbounded width: each line as long as it is.
    const QRectF bounds = metrics.boundingRect(QRectF(0, 0, 0, 0), Qt::AlignLeft | Qt::TextDontClip, text);
    return QSizeF(bounds.width() + 2 * pad, bounds.height() + pad);
}

void drawMeasureLabel(QPainter& painter, const QRectF& box, const QString& text, bool centred)
{
    painter.setPen(QPen(constants::kMeasureColor, 1));
    painter.setBrush(kLabelFill);
    painter.drawRect(box);
    const double pad = constants::kLegendPaddingPx;
    const QRectF inside = centred ? box : box.adjusted(pad, 0, -pad, 0);
    painter.drawText(inside, (centred ? Qt::AlignHCenter : Qt::AlignLeft) | Qt::AlignVCenter, text);
}

QPointF measurePoint(const CanvasView& canvas, const QPointF& scenePos)
{
    const double reach = constants::kMeasureSnapPx / std::max(canvas.pixelsPerMetre(), 1e-12);
    const model::World& world = canvas.runner().world();
    std::optional<QPointF> best;
    double bestDistance = reach;
    const auto consider = [&](const Vec2& p) {
        const double d = QLineF(scenePos, toQPointF(p)).length();
        if (d <= bestDistance) {
            bestDistance = d;
            best = toQPointF(p);
        }
    };
    for (const model::Body& body : world.bodies) {
        consider(body.state.position);
        // Corners of boxes and polygons (the outline of a round shape has no corners to snap to).
        if (std::holds_alternative<model::Box>(body.shape) || std::holds_alternative<model::Polygon>(body.shape)) {
            for (const Vec2& corner : body.geometry.outline)
                consider(body.worldPoint(corner));
        }
    }
    return best ? *best : canvas.snapped(scenePos);
}

void RulerTool::cancel()
{
    m_start.reset();
    m_end.reset();
    m_placing = false;
}

void RulerTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    const QPointF point = measurePoint(m_canvas, event.scenePos);
    m_pressView = event.viewPos;
    if (m_placing) {
        // The second click places the end.
        m_end = point;
        m_placing = false;
        return;
    }
    m_start = point;
    m_end = point;
    m_placing = true;
}

void RulerTool::mouseMove(const ToolEvent& event)
{
    if (m_placing)
        m_end = measurePoint(m_canvas, event.scenePos);
}

void RulerTool::mouseRelease(const ToolEvent& event)
{
    // A drag places both ends at once; a click leaves the end to follow the cursor to the next.
    if (m_placing && event.button == Qt::LeftButton &&
        QLineF(m_pressView, event.viewPos).length() >= constants::kMinimumDragPx) {
        m_end = measurePoint(m_canvas, event.scenePos);
        m_placing = false;
    }
}

bool RulerTool::wantsKey(int key, Qt::KeyboardModifiers) const { return key == Qt::Key_Escape && m_start; }

bool RulerTool::keyPress(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Escape || !m_start)
        return false;
    cancel();
    return true;
}

std::optional<double> RulerTool::distance() const
{
    if (!m_start || !m_end || m_placing)
        return std::nullopt;
    return QLineF(*m_start, *m_end).length();
}

QString RulerTool::text() const
{
    const std::optional<double> d = distance();
    return d ? tr("%1 m").arg(measureNumber(*d, kLengthDecimals)) : QString();
}

void RulerTool::paintOverlay(QPainter& painter, double) const
{
    if (!m_start || !m_end)
        return;
    const QTransform toPixels = painter.worldTransform();
    const QPointF a = toPixels.map(*m_start);
    const QPointF b = toPixels.map(*m_end);
    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(measurePen());
    painter.drawLine(a, b);
    // Ticks across each end, so the ends read as the ruler's.
    const QLineF line(a, b);
    const QLineF across = line.length() > 0 ? line.normalVector().unitVector() : QLineF(a, a + QPointF(0, 1));
    const QPointF tick = (across.p2() - across.p1()) * constants::kArrowHeadPx / 2;
    painter.drawLine(a - tick, a + tick);
    painter.drawLine(b - tick, b + tick);
    const QString label = tr("%1 m").arg(measureNumber(QLineF(*m_start, *m_end).length(), kLengthDecimals));
    const QString parts = tr("Δx = %1 m, Δy = %2 m")
                              .arg(measureNumber(m_end->x() - m_start->x(), kLengthDecimals),
                                   measureNumber(m_end->y() - m_start->y(), kLengthDecimals));
    drawLabel(painter, (a + b) / 2, label);
    drawLabel(painter, (a + b) / 2 + QPointF(0, QFontMetricsF(painter.font()).height() + kLabelGapPx), parts);
    painter.restore();
}

void ProtractorTool::cancel()
{
    m_points.clear();
    m_done = false;
}

void ProtractorTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    const QPointF point = measurePoint(m_canvas, event.scenePos);
    if (m_done || m_points.empty()) {
        // A new angle: this click is its vertex, and the first arm follows the cursor.
        m_points = {point, point};
        m_done = false;
        return;
    }
    m_points.back() = point;
    if (m_points.size() == 3) {
        m_done = true;
        return;
    }
    m_points.push_back(point); // the second arm follows the cursor
}

void ProtractorTool::mouseMove(const ToolEvent& event)
{
    if (!m_done && m_points.size() >= 2)
        m_points.back() = measurePoint(m_canvas, event.scenePos);
}

bool ProtractorTool::wantsKey(int key, Qt::KeyboardModifiers) const
{
    return key == Qt::Key_Escape && !m_points.empty();
}

bool ProtractorTool::keyPress(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Escape || m_points.empty())
        return false;
    cancel();
    return true;
}

std::optional<double> ProtractorTool::angleDegrees() const
{
    if (!m_done)
        return std::nullopt;
    const QPointF u = m_points[1] - m_points[0];
    const QPointF v = m_points[2] - m_points[0];
    const double angle = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.x() * v.x() + u.y() * v.y());
    return angle * 180 / std::numbers::pi;
}

QString ProtractorTool::text() const
{
    const std::optional<double> angle = angleDegrees();
    return angle ? tr("%1°").arg(measureNumber(*angle, kAngleDecimals)) : QString();
}

void ProtractorTool::paintOverlay(QPainter& painter, double) const
{
    if (m_points.size() < 2)
        return;
    const QTransform toPixels = painter.worldTransform();
    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(measurePen());
    const QPointF vertex = toPixels.map(m_points[0]);
    for (std::size_t i = 1; i < m_points.size(); ++i)
        painter.drawLine(vertex, toPixels.map(m_points[i]));
    if (m_points.size() == 3) {
        // The arc between the arms, on screen (y down): from the first arm's angle, the short way.
        const QLineF first(vertex, toPixels.map(m_points[1]));
        const QLineF second(vertex, toPixels.map(m_points[2]));
        double span = first.angleTo(second);
        if (span > 180)
            span -= 360;
        const double radius = kArcHeads * constants::kArrowHeadPx;
        painter.drawArc(QRectF(vertex - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)),
                        static_cast<int>(first.angle() * 16), static_cast<int>(span * 16));
        if (m_done)
            drawLabel(painter, vertex + QPointF(0, -2 * radius), text());
    }
    painter.restore();
}

} // namespace impetus::view
