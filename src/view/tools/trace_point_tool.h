#pragma once
/// \file trace_point_tool.h
/// Trace Point: click a point on a body, and the canvas draws the path that point takes.

#include "view/tools/tool.h"

namespace impetus::view {

/// Trace Point: a click on a body fixes the point under the cursor on that body (in its own frame,
/// so it turns with it), and the canvas draws the path the point takes from then on, with dots as
/// the trails have (CanvasInstruments::setTracedPoint): a wheel's rim point draws a cycloid where
/// its centre draws a line. A body has one traced point at most; a click on another point of it
/// moves it, and a click on the traced point itself (within constants::kTracedPointPickPx) stops
/// tracing it. Esc stops tracing every point. Traced points stay when another tool is chosen;
/// tracing is not an edit (nothing to undo), as trails are not.
class TracePointTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::TracePoint; }
    void mousePress(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    Qt::CursorShape cursorShape() const override { return Qt::CrossCursor; }
};

} // namespace impetus::view
