#include "view/tools/joint_tool.h"

#include "view/canvas_view.h"
#include "view/scene_document.h"

#include <QLineF>

namespace impetus::view {

void JointTool::mousePress(const ToolEvent& event)
{
    if (m_type == model::JointType::Rod) {
        ConnectionDragTool::mousePress(event);
        return;
    }
    if (event.button == Qt::LeftButton)
        addPin(m_canvas.snapped(event.scenePos));
}

void JointTool::mouseMove(const ToolEvent& event)
{
    if (m_type == model::JointType::Rod)
        ConnectionDragTool::mouseMove(event);
}

void JointTool::mouseRelease(const ToolEvent& event)
{
    if (m_type == model::JointType::Rod)
        ConnectionDragTool::mouseRelease(event);
}

void JointTool::paintOverlay(QPainter& painter, double pixelsPerMetre) const
{
    if (m_type == model::JointType::Rod)
        ConnectionDragTool::paintOverlay(painter, pixelsPerMetre);
}

void JointTool::addPin(const QPointF& scenePos)
{
    const Attachment a = attachmentAt(scenePos, std::nullopt);
    if (!a.body) {
        m_canvas.showMessage(scenePos, startHint());
        return;
    }
    const Attachment b = attachmentAt(scenePos, a.body);
    model::Joint joint;
    joint.type = model::JointType::Pin;
    joint.bodyA = *a.body;
    joint.bodyB = b.body;
    joint.worldAnchor = toVec2(scenePos);
    joint.anchorA = a.anchor;
    joint.anchorB = b.anchor;
    m_document.addJoint(joint, tr("Add pin"));
}

void JointTool::connectEnds(const Attachment& a, const QPointF& from, const Attachment& b, const QPointF& to)
{
    model::Joint joint;
    joint.type = model::JointType::Rod;
    joint.bodyA = *a.body;
    joint.bodyB = b.body;
    joint.anchorA = a.anchor;
    joint.anchorB = b.anchor;
    joint.length = QLineF(from, to).length();
    m_document.addJoint(joint, tr("Add rod"));
}

QString JointTool::startHint() const
{
    if (m_type == model::JointType::Pin)
        return tr("Click on a body to pin it there: to the body under it, or to the world.");
    return tr("Drag from a body to another body, or to a point in space, to add a rod.");
}

} // namespace impetus::view
