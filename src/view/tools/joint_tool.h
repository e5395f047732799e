#pragma once
/// \file joint_tool.h
/// The Pin and Rod tools.

#include "model/joint.h"
#include "view/tools/connection_tool.h"

namespace impetus::view {

/// Pin: click on a body to hinge it there, to the body under it at that point or, with none, to
/// the world. Rod: drag from a body to another body or a point in space, for a massless rod that
/// keeps the drawn length.
class JointTool : public ConnectionDragTool {
public:
    /// A Pin or Rod tool, by `type`.
    JointTool(SceneDocument& document, CanvasView& canvas, model::JointType type)
        : ConnectionDragTool(document, canvas)
        , m_type(type)
    {
    }
    ToolKind kind() const override { return m_type == model::JointType::Pin ? ToolKind::Pin : ToolKind::Rod; }
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseRelease(const ToolEvent& event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;

protected:
    void connectEnds(const Attachment& a, const QPointF& from, const Attachment& b, const QPointF& to) override;
    QString startHint() const override;

private:
    void addPin(const QPointF& scenePos);

    model::JointType m_type;
};

} // namespace impetus::view
