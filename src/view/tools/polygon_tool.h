#pragma once
/// \file polygon_tool.h
/// The Polygon tool: click the corners of any simple polygon, convex or concave.

#include "view/tools/tool.h"

#include <QPointF>

#include <vector>

namespace impetus::view {

/// Each click adds a corner (snapped to the grid when snapping is on). Clicking the first corner
/// again, pressing Enter or double-clicking closes the polygon. A polygon that is not simple —
/// fewer than three corners, crossing edges, no area — is refused with a message at the cursor,
/// and the drawing stays open to fix: Backspace takes the last corner back, Escape drops the
/// drawing. A closed polygon becomes a body centred on its centroid.
class PolygonTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::Polygon; }
    void cancel() override { m_vertices.clear(); }
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseDoubleClick(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;

    /// The corners placed so far, m (empty when not drawing).
    const std::vector<QPointF>& vertices() const { return m_vertices; }

private:
    /// Makes the body, or shows why not at `messageAt` and keeps drawing. True when made.
    bool tryClose(const QPointF& messageAt);
    bool nearFirstVertex(const QPointF& viewPos) const;

    std::vector<QPointF> m_vertices; ///< m
    QPointF m_cursor; ///< m
};

} // namespace impetus::view
