#pragma once
/// \file select_tool.h
/// The Select tool: pick, rubber-band, move, nudge, and turn with Ctrl.

#include "view/scene_document.h"
#include "view/tools/rotate_tool.h"
#include "view/tools/tool.h"

#include <vector>

namespace impetus::view {

/// Click a body, spring or joint to select it (Shift adds or removes it); drag on empty space for
/// a rubber band that selects what lies wholly inside; drag a body to move the selected bodies
/// (snapped to the grid when snapping is on); Ctrl+drag turns them about their centre. The arrow
/// keys nudge the selected bodies by a tenth of a grid spacing (Shift: a whole spacing). Escape
/// during a drag gives it up (moved or turned bodies go back, a rubber band leaves the selection
/// as it was); otherwise it clears the selection. Bodies a lesson locks are selected but neither
/// move, turn nor nudge; the canvas says why.
class SelectTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::Select; }
    void cancel() override;
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseRelease(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;
    Qt::CursorShape cursorShape() const override { return Qt::ArrowCursor; }

private:
    /// Locked: a press on a body the lesson locks, until the release.
    enum class Mode { Idle, Moving, RubberBand, Rotating, Locked };

    void moveTo(const QPointF& scenePos);
    /// Starts turning `bodies`, or says why the lesson locks them.
    void beginRotation(const std::vector<int>& bodies, const QPointF& scenePos);

    Mode m_mode = Mode::Idle;
    QPointF m_pressPos; ///< m
    QPointF m_cursor; ///< m
    int m_gesture = 0;
    std::vector<int> m_moving; ///< bodies being dragged
    std::vector<BodyPose> m_startPoses;
    Selection m_selectionBefore; ///< for a Shift rubber band, which adds to it
    RotationGesture m_rotation;
    QString m_lockMessage; ///< why the body pressed on is locked (Mode::Locked)
};

} // namespace impetus::view
