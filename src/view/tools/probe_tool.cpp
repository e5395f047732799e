#include "view/tools/probe_tool.h"

#include "view/body_item.h"
#include "view/canvas_view.h"
#include "view/simulation_runner.h"
#include "view/tools/measure_tools.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QLocale>
#include <QPainter>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impetus::view {

namespace {

/// Gap between the body's bounding box and its label, px: close enough to read as the body's,
/// clear of its outline.
constexpr double kLabelGapPx = 12.0;
/// Radius of the ring that marks the probed body's centre of mass, px.
constexpr double kCentreRingPx = 4.0;

/// Decimals of the readout's numbers: mm, mm/s, mJ, as the status bar shows them.
constexpr int kDecimals = 3;

/// `value` with kDecimals decimals in the window's number format ("0,250" in German), and a value
/// that rounds to zero as "0.000", never "-0.000".
QString number(double value)
{
    const double halfLastDigit = 0.5 * std::pow(10.0, -kDecimals);
    return QLocale().toString(std::abs(value) < halfLastDigit ? 0.0 : value, 'f', kDecimals);
}

} // namespace

void ProbeTool::cancel() { m_name.clear(); }

void ProbeTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    const std::optional<int> hit = m_canvas.bodyAt(event.scenePos);
    const std::optional<model::BodyId> probed = body();
    if (!hit || (probed && static_cast<int>(probed->index) == *hit)) {
        // Empty space, or the probed body again: done reading.
        m_name.clear();
        return;
    }
    m_name = m_canvas.runner().world().bodies[static_cast<std::size_t>(*hit)].name;
}

bool ProbeTool::wantsKey(int key, Qt::KeyboardModifiers) const { return key == Qt::Key_Escape && body(); }

bool ProbeTool::keyPress(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Escape || !body())
        return false;
    m_name.clear();
    return true;
}

std::optional<model::BodyId> ProbeTool::body() const
{
    if (m_name.empty())
        return std::nullopt;
    // By name: indices move when a body before it is deleted. A few thousand string compares
    // per paint cost nothing beside the painting.
    const std::vector<model::Body>& bodies = m_canvas.runner().world().bodies;
    const auto it = std::ranges::find(bodies, m_name, &model::Body::name);
    if (it == bodies.end())
        return std::nullopt;
    return model::BodyId{static_cast<std::uint32_t>(it - bodies.begin())};
}

std::optional<controller::BodyReadout> ProbeTool::readout() const
{
    const std::optional<model::BodyId> id = body();
    if (!id)
        return std::nullopt;
    return controller::readBody(m_canvas.runner().world(), *id);
}

QString ProbeTool::text() const
{
    const std::optional<controller::BodyReadout> r = readout();
    if (!r)
        return {};
    const model::Body& probed = m_canvas.runner().world().body(*body());
    const QString name = QString::fromStdString(probed.name);
    QStringList lines;
    lines << (probed.fixed ? tr("%1 (fixed)").arg(name) : name);
    lines << tr("x = %1 m, y = %2 m").arg(number(r->position.x()), number(r->position.y()));
    lines << tr("vx = %1 m/s, vy = %2 m/s").arg(number(r->velocity.x()), number(r->velocity.y()));
    lines << tr("speed = %1 m/s").arg(number(r->speed));
    lines << tr("angle = %1 rad (%2°), ω = %3 rad/s")
                 .arg(number(r->angle))
                 .arg(QLocale().toString(r->angle * 180 / std::numbers::pi, 'f', 1))
                 .arg(number(r->angularVelocity));
    lines << tr("p = (%1, %2) kg·m/s").arg(number(r->momentum.x()), number(r->momentum.y()));
    lines << tr("K = %1 J, U = %2 J, K + U = %3 J")
                 .arg(number(r->kinetic), number(r->potential), number(r->kinetic + r->potential));
    lines << (r->colliding ? tr("collisions: %1, touching now") : tr("collisions: %1")).arg(r->collisions);
    return lines.join(QLatin1Char('\n'));
}

QRectF ProbeTool::placeLabel(model::BodyId id, const QTransform& toPixels, const QFont& font, const QString& text) const
{
    const QRectF viewport(m_canvas.viewport()->rect());
    QRectF around;
    if (const BodyItem* item = m_canvas.bodyItem(id))
        around = toPixels.mapRect(item->sceneBoundingRect());
    else
        around = QRectF(toPixels.map(toQPointF(m_canvas.runner().world().body(id).state.position)), QSizeF(0, 0));
    // To the right of the body, level with its centre, so that it reads as the body's.
    QRectF box(QPointF(0, 0), measureLabelSize(font, text));
    box.moveCenter(QPointF(0, around.center().y()));
    box.moveLeft(around.right() + kLabelGapPx);
    // Kept on screen: a body that leaves the view leaves its label at the edge nearest to it.
    box.moveLeft(std::clamp(box.left(), viewport.left(), std::max(viewport.left(), viewport.right() - box.width())));
    box.moveTop(std::clamp(box.top(), viewport.top(), std::max(viewport.top(), viewport.bottom() - box.height())));
    return box;
}

QRectF ProbeTool::labelRect() const
{
    const std::optional<model::BodyId> id = body();
    if (!id)
        return {};
    return placeLabel(*id, m_canvas.viewportTransform(), m_canvas.viewport()->font(), text());
}

void ProbeTool::paintOverlay(QPainter& painter, double) const
{
    const std::optional<model::BodyId> id = body();
    if (!id)
        return;
    const QString label = text();
    const QTransform toPixels = painter.worldTransform();
    const QRectF box = placeLabel(*id, toPixels, painter.font(), label);
    const QPointF centre = toPixels.map(toQPointF(m_canvas.runner().world().body(*id).state.position));
    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    // A ring on the centre of mass (the point the numbers are about) and a leader to the label.
    QPen pen(constants::kMeasureColor, constants::kOutlineWidthPx);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(centre, kCentreRingPx, kCentreRingPx);
    painter.drawLine(centre, QPointF(box.left(), std::clamp(centre.y(), box.top(), box.bottom())));
    drawMeasureLabel(painter, box, label, false);
    painter.restore();
}

} // namespace impetus::view
