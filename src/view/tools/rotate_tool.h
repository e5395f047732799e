#pragma once
/// \file rotate_tool.h
/// Turning bodies by dragging: the Rotate tool, and the rotation gesture the Select tool uses with
/// Ctrl held.

#include "view/scene_document.h"
#include "view/tools/tool.h"

#include <optional>
#include <vector>

namespace impetus::view {

class LessonSession;

/// One drag that turns some bodies rigidly about a pivot: each body's centre turns about the
/// pivot and its angle grows by the same amount, the angle swept by the cursor about the pivot.
/// The whole drag is one undo command.
class RotationGesture {
    Q_DECLARE_TR_FUNCTIONS(RotationGesture)

public:
    /// Starts turning bodies `bodies` of `document` about the mean of their centres, the cursor at
    /// `scenePos`. Nothing happens for no bodies, or when `lesson` (if any) locks them; then the
    /// lock's reason is returned.
    std::optional<QString> begin(SceneDocument& document, std::vector<int> bodies, const QPointF& scenePos,
                                 const LessonSession* lesson);
    /// Turns the bodies by the angle from the start to `scenePos`, in steps of
    /// constants::kRotationSnapDegrees when `snap`.
    void update(SceneDocument& document, const QPointF& scenePos, bool snap);
    /// Ends the drag.
    void end() { m_active = false; }
    /// Gives the drag up: puts the bodies back as they were at begin() (the gesture's command
    /// then changes nothing and leaves the undo stack) and ends it.
    void cancel(SceneDocument& document);
    /// True between begin() and end().
    bool isActive() const { return m_active; }
    /// The pivot, m.
    QPointF pivot() const { return toQPointF(m_pivot); }
    /// The cursor at the start, m.
    QPointF start() const { return m_start; }

private:
    bool m_active = false;
    int m_gesture = 0;
    std::vector<int> m_bodies;
    std::vector<BodyPose> m_startPoses;
    Vec2 m_pivot = Vec2::Zero();
    QPointF m_start;
};

/// Paints a rotation in progress: the pivot and a line from it to `cursor`.
void paintRotation(QPainter& painter, double pixelsPerMetre, const QPointF& pivot, const QPointF& cursor);

/// The Rotate tool: press on a body (it becomes the selection unless it is selected already) or
/// anywhere with bodies selected, and drag around their centre to turn them. Shift snaps the angle
/// to constants::kRotationSnapDegrees. Escape during the drag turns them back. Bodies a lesson
/// locks do not turn; the canvas says why.
class RotateTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::Rotate; }
    void cancel() override;
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseRelease(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;
    Qt::CursorShape cursorShape() const override { return Qt::PointingHandCursor; }

private:
    RotationGesture m_rotation;
    QPointF m_cursor;
};

} // namespace impetus::view
