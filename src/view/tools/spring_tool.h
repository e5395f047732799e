#pragma once
/// \file spring_tool.h
/// The Spring tool.

#include "view/tools/connection_tool.h"

namespace impetus::view {

/// Drag from a body to another body or to a point in space: a spring between the two points,
/// at rest at its drawn length, with the default stiffness and no damping.
class SpringTool : public ConnectionDragTool {
public:
    using ConnectionDragTool::ConnectionDragTool;
    ToolKind kind() const override { return ToolKind::Spring; }

protected:
    void connectEnds(const Attachment& a, const QPointF& from, const Attachment& b, const QPointF& to) override;
    QString startHint() const override;
};

} // namespace impetus::view
