#pragma once
/// \file connection_tool.h
/// What the Spring, Pin and Rod tools share: attaching to bodies at the cursor.

#include "model/body.h"
#include "view/tools/tool.h"

#include <optional>

namespace impetus::view {

/// One end of a spring or joint: a point on a body (in its own frame) or a fixed world point.
struct Attachment {
    std::optional<model::BodyId> body; ///< nullopt: a world point
    Vec2 anchor = Vec2::Zero(); ///< m, in the body's frame (origin at its centre of mass), or world
};

/// The point `world` (m) in the frame of `body`: R(−angle)·(world − position).
Vec2 bodyFramePoint(const model::Body& body, const Vec2& world);

/// A tool that joins a body to another body, or to a world point, by a drag: press on the first
/// body, release on the second (the topmost body there other than the first) or on empty space.
/// Points snap to the grid when snapping is on. Escape during the drag gives it up.
class ConnectionDragTool : public Tool {
public:
    using Tool::Tool;
    void cancel() override { m_start.reset(); }
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseRelease(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;

protected:
    /// Adds the connection from `a` at world point `from` to `b` at world point `to` (m), or shows
    /// at `to` why it cannot.
    virtual void connectEnds(const Attachment& a, const QPointF& from, const Attachment& b, const QPointF& to) = 0;
    /// The message when the press is not on a body ("Start a spring on a body").
    virtual QString startHint() const = 0;

    /// Where `point` lies on the topmost body there other than `except`, or the world point.
    Attachment attachmentAt(const QPointF& point, std::optional<model::BodyId> except) const;

private:
    std::optional<Attachment> m_start;
    QPointF m_from; ///< m
    QPointF m_cursor; ///< m
    QPointF m_pressView; ///< px
};

} // namespace impetus::view
