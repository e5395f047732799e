#include "view/tools/connection_tool.h"

#include "view/canvas_view.h"
#include "view/scene_document.h"
#include "view/tools/drag_shape_tools.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QLineF>
#include <QPainter>

#include <cmath>

namespace impetus::view {

Vec2 bodyFramePoint(const model::Body& body, const Vec2& world)
{
    const Vec2 d = world - body.state.position;
    const double c = std::cos(body.state.angle);
    const double s = std::sin(body.state.angle);
    return Vec2(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
}

Attachment ConnectionDragTool::attachmentAt(const QPointF& point, std::optional<model::BodyId> except) const
{
    for (const int i : m_canvas.bodiesAt(point)) {
        const model::BodyId id{static_cast<std::uint32_t>(i)};
        if (except && *except == id)
            continue;
        return Attachment{id, bodyFramePoint(m_document.world().body(id), toVec2(point))};
    }
    return Attachment{std::nullopt, toVec2(point)};
}

void ConnectionDragTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    const QPointF point = m_canvas.snapped(event.scenePos);
    Attachment start = attachmentAt(point, std::nullopt);
    if (!start.body) {
        m_canvas.showMessage(event.scenePos, startHint());
        return;
    }
    m_start = start;
    m_from = point;
    m_cursor = point;
    m_pressView = event.viewPos;
}

void ConnectionDragTool::mouseMove(const ToolEvent& event) { m_cursor = m_canvas.snapped(event.scenePos); }

void ConnectionDragTool::mouseRelease(const ToolEvent& event)
{
    if (!m_start || event.button != Qt::LeftButton)
        return;
    const Attachment start = *m_start;
    m_start.reset();
    const QPointF point = m_canvas.snapped(event.scenePos);
    if (QLineF(m_pressView, event.viewPos).length() < constants::kMinimumDragPx) {
        m_canvas.showMessage(event.scenePos, startHint());
        return;
    }
    connectEnds(start, m_from, attachmentAt(point, start.body), point);
}

bool ConnectionDragTool::wantsKey(int key, Qt::KeyboardModifiers) const
{
    return m_start.has_value() && key == Qt::Key_Escape;
}

bool ConnectionDragTool::keyPress(QKeyEvent* event)
{
    if (!wantsKey(event->key(), event->modifiers()))
        return false;
    m_start.reset();
    return true;
}

void ConnectionDragTool::paintOverlay(QPainter& painter, double) const
{
    if (!m_start)
        return;
    QPainterPath path(m_from);
    path.lineTo(m_cursor);
    paintPreview(painter, path);
}

} // namespace impetus::view
