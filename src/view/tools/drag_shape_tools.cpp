#include "view/tools/drag_shape_tools.h"

#include "view/canvas_view.h"
#include "view/scene_document.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QLineF>
#include <QPainter>

namespace impetus::view {

void DragShapeTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    m_dragging = true;
    m_from = m_canvas.snapped(event.scenePos);
    m_to = m_from;
    m_pressView = event.viewPos;
}

void DragShapeTool::mouseMove(const ToolEvent& event)
{
    if (m_dragging)
        m_to = m_canvas.snapped(event.scenePos);
}

void DragShapeTool::mouseRelease(const ToolEvent& event)
{
    if (!m_dragging || event.button != Qt::LeftButton)
        return;
    m_dragging = false;
    m_to = m_canvas.snapped(event.scenePos);
    // A click, or a drag too short to mean a size, draws nothing rather than a speck.
    if (QLineF(m_pressView, event.viewPos).length() < constants::kMinimumDragPx)
        return;
    std::optional<Outline> outline = outlineFor(m_from, m_to);
    if (!outline)
        return;
    model::Body body;
    body.name = m_document.uniqueBodyName(baseName()).toStdString();
    body.shape = std::move(outline->shape);
    body.state.position = toVec2(outline->centre);
    m_document.addBody(std::move(body), actionName());
}

bool DragShapeTool::wantsKey(int key, Qt::KeyboardModifiers) const { return m_dragging && key == Qt::Key_Escape; }

bool DragShapeTool::keyPress(QKeyEvent* event)
{
    if (!wantsKey(event->key(), event->modifiers()))
        return false;
    // The release that follows finds no drag and draws nothing.
    m_dragging = false;
    return true;
}

void DragShapeTool::paintOverlay(QPainter& painter, double) const
{
    if (!m_dragging)
        return;
    if (const std::optional<Outline> outline = outlineFor(m_from, m_to))
        paintPreview(painter, outline->preview);
}

void paintPreview(QPainter& painter, const QPainterPath& path)
{
    QPen pen(constants::kPreviewColor, constants::kOutlineWidthPx, Qt::DashLine);
    pen.setCosmetic(true);
    painter.setPen(pen);
    QColor fill = constants::kPreviewColor;
    // QColor keeps its alpha as a float; the constant is a double like every other.
    fill.setAlphaF(static_cast<float>(constants::kPreviewFillAlpha));
    painter.setBrush(fill);
    painter.drawPath(path);
}

std::optional<DragShapeTool::Outline> BoxTool::outlineFor(const QPointF& from, const QPointF& to) const
{
    const QRectF rect = QRectF(from, to).normalized();
    if (!(rect.width() > 0) || !(rect.height() > 0))
        return std::nullopt;
    QPainterPath path;
    path.addRect(rect);
    return Outline{model::Box{rect.width(), rect.height()}, rect.center(), path};
}

std::optional<DragShapeTool::Outline> CircleTool::outlineFor(const QPointF& from, const QPointF& to) const
{
    const double radius = QLineF(from, to).length();
    if (!(radius > 0))
        return std::nullopt;
    QPainterPath path;
    path.addEllipse(from, radius, radius);
    return Outline{model::Circle{radius}, from, path};
}

std::optional<DragShapeTool::Outline> EllipseTool::outlineFor(const QPointF& from, const QPointF& to) const
{
    const QRectF rect = QRectF(from, to).normalized();
    if (!(rect.width() > 0) || !(rect.height() > 0))
        return std::nullopt;
    QPainterPath path;
    path.addEllipse(rect);
    return Outline{model::Ellipse{rect.width() / 2, rect.height() / 2}, rect.center(), path};
}

} // namespace impetus::view
