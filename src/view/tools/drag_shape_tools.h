#pragma once
/// \file drag_shape_tools.h
/// The tools that draw a body with one drag: Box, Circle and Ellipse.

#include "model/body.h"
#include "view/tools/tool.h"

#include <QPainterPath>

#include <optional>

namespace impetus::view {

/// A tool that draws one body per drag from the press point to the release point (both snapped
/// to the grid when snapping is on). A drag shorter than constants::kMinimumDragPx draws nothing.
/// The new body gets a unique name, the default material and density 1 kg/m², and is selected.
/// Escape during the drag gives it up: nothing is drawn.
class DragShapeTool : public Tool {
public:
    using Tool::Tool;
    void cancel() override { m_dragging = false; }
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseRelease(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;

protected:
    /// The shape and centre of the body dragged from `from` to `to`, m.
    struct Outline {
        model::Shape shape;
        QPointF centre;
        QPainterPath preview; ///< the outline in the scene, m
    };
    /// The body a drag from `from` to `to` makes, or nothing when it would have no size.
    virtual std::optional<Outline> outlineFor(const QPointF& from, const QPointF& to) const = 0;
    /// The base of the new body's name ("box" gives "box 1", "box 2", …).
    virtual QString baseName() const = 0;
    /// The undo action's name ("Draw box").
    virtual QString actionName() const = 0;

private:
    bool m_dragging = false;
    QPointF m_from; ///< m, snapped
    QPointF m_to; ///< m, snapped
    QPointF m_pressView; ///< px
};

/// Drag from one corner to the opposite one: an upright box.
class BoxTool : public DragShapeTool {
public:
    using DragShapeTool::DragShapeTool;
    ToolKind kind() const override { return ToolKind::Box; }

protected:
    std::optional<Outline> outlineFor(const QPointF& from, const QPointF& to) const override;
    QString baseName() const override { return tr("box"); }
    QString actionName() const override { return tr("Draw box"); }
};

/// Drag from the centre out: a circle through the release point.
class CircleTool : public DragShapeTool {
public:
    using DragShapeTool::DragShapeTool;
    ToolKind kind() const override { return ToolKind::Circle; }

protected:
    std::optional<Outline> outlineFor(const QPointF& from, const QPointF& to) const override;
    QString baseName() const override { return tr("circle"); }
    QString actionName() const override { return tr("Draw circle"); }
};

/// Drag from one corner of the bounding box to the opposite one: an upright ellipse inside it.
class EllipseTool : public DragShapeTool {
public:
    using DragShapeTool::DragShapeTool;
    ToolKind kind() const override { return ToolKind::Ellipse; }

protected:
    std::optional<Outline> outlineFor(const QPointF& from, const QPointF& to) const override;
    QString baseName() const override { return tr("ellipse"); }
    QString actionName() const override { return tr("Draw ellipse"); }
};

/// Paints a shape being drawn: `path` (scene, m) in the preview colour.
void paintPreview(QPainter& painter, const QPainterPath& path);

} // namespace impetus::view
