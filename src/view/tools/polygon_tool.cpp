#include "view/tools/polygon_tool.h"

#include "model/polygon.h"
#include "view/canvas_view.h"
#include "view/scene_document.h"
#include "view/tools/drag_shape_tools.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QLineF>
#include <QPainter>
#include <QPolygonF>

namespace impetus::view {

void PolygonTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    m_cursor = event.scenePos;
    if (m_vertices.size() >= 1 && nearFirstVertex(event.viewPos)) {
        tryClose(event.scenePos);
        return;
    }
    // A second click on the last corner (the second press of a double click) adds nothing.
    const QPointF corner = m_canvas.snapped(event.scenePos);
    if (!m_vertices.empty()
        && QLineF(m_canvas.toView(m_vertices.back()), m_canvas.toView(corner)).length() <= constants::kCloseToFirstVertexPx)
        return;
    m_vertices.push_back(corner);
}

void PolygonTool::mouseMove(const ToolEvent& event) { m_cursor = m_canvas.snapped(event.scenePos); }

void PolygonTool::mouseDoubleClick(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton || m_vertices.empty())
        return;
    // The double click's first press has placed its corner already; the second only closes.
    tryClose(event.scenePos);
}

bool PolygonTool::nearFirstVertex(const QPointF& viewPos) const
{
    return QLineF(m_canvas.toView(m_vertices.front()), viewPos).length() <= constants::kCloseToFirstVertexPx;
}

bool PolygonTool::wantsKey(int key, Qt::KeyboardModifiers) const
{
    return !m_vertices.empty()
        && (key == Qt::Key_Return || key == Qt::Key_Enter || key == Qt::Key_Escape || key == Qt::Key_Backspace);
}

bool PolygonTool::keyPress(QKeyEvent* event)
{
    if (!wantsKey(event->key(), event->modifiers()))
        return false;
    switch (event->key()) {
    case Qt::Key_Escape:
        m_vertices.clear();
        break;
    case Qt::Key_Backspace:
        m_vertices.pop_back();
        break;
    default:
        tryClose(m_vertices.back());
        break;
    }
    return true;
}

bool PolygonTool::tryClose(const QPointF& messageAt)
{
    std::vector<Vec2> corners;
    corners.reserve(m_vertices.size());
    for (const QPointF& p : m_vertices)
        corners.push_back(toVec2(p));
    const std::vector<model::PolygonIssue> issues = model::validatePolygon(corners);
    if (!issues.empty()) {
        QString reason;
        switch (issues.front().kind) {
        case model::PolygonIssueKind::TooFewVertices:
            reason = tr("a polygon needs at least 3 different corners");
            break;
        case model::PolygonIssueKind::NonFiniteVertex:
            reason = tr("a corner is not a finite point");
            break;
        case model::PolygonIssueKind::DuplicateVertex:
            reason = tr("two corners are at the same point");
            break;
        case model::PolygonIssueKind::ZeroArea:
            reason = tr("it is too small or flat to have an area");
            break;
        case model::PolygonIssueKind::SelfIntersection:
            reason = tr("its edges cross each other");
            break;
        }
        m_canvas.showMessage(messageAt, tr("Cannot close the polygon: %1. Move or remove a corner (Backspace), "
                                           "or press Escape to give up.")
                                            .arg(reason));
        return false;
    }
    // The model finds the centroid: build the body once in world coordinates, then put its
    // origin on the centroid so that the position is the centre of mass.
    model::Body body;
    body.name = m_document.uniqueBodyName(tr("polygon")).toStdString();
    body.shape = model::Polygon{corners};
    body.updateDerived();
    const Vec2 centroid = body.geometry.centroidOffset;
    for (Vec2& corner : corners)
        corner -= centroid;
    body.shape = model::Polygon{corners};
    body.state.position = centroid;
    m_vertices.clear();
    m_document.addBody(std::move(body), tr("Draw polygon"));
    return true;
}

void PolygonTool::paintOverlay(QPainter& painter, double pixelsPerMetre) const
{
    if (m_vertices.empty())
        return;
    QPainterPath path(m_vertices.front());
    for (std::size_t i = 1; i < m_vertices.size(); ++i)
        path.lineTo(m_vertices[i]);
    path.lineTo(m_cursor);
    paintPreview(painter, path);
    // The first corner is a target: clicking it closes the polygon.
    const double r = constants::kCloseToFirstVertexPx / pixelsPerMetre;
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(m_vertices.front(), r, r);
}

} // namespace impetus::view
