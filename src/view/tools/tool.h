#pragma once
/// \file tool.h
/// What every canvas tool shares: the events it gets from the canvas and its overlay.

#include "model/scalar.h"

#include <QCoreApplication>
#include <QPointF>
#include <QString>
#include <Qt>

class QKeyEvent;
class QPainter;

namespace impetus::view {

class CanvasView;
class SceneDocument;

/// The tools of the canvas, one class each.
enum class ToolKind {
    Select, ///< click, rubber band, drag to move, arrow keys to nudge; Ctrl+drag rotates
    Rotate, ///< drag to turn the body under the cursor (or the selection) about its centre
    Polygon, ///< click vertices; close on the first vertex, Enter or a double click
    Box, ///< drag out a box
    Circle, ///< drag from the centre out to the radius
    Ellipse, ///< drag out the ellipse's bounding box
    Spring, ///< drag from a body to another body or to a world point
    Pin, ///< click: a hinge between the bodies under the cursor, or a body and the world
    Rod, ///< drag from a body to another body or to a world point
    Ruler, ///< click two points (or drag): the distance between them, m
    Protractor, ///< click a vertex and a point on each arm: the angle between them, degrees
    Probe, ///< click a body: its live readout in a label that follows it
    TracePoint, ///< click a point on a body: its path is drawn as the body moves
};

/// A mouse event as a tool sees it: where it happened on the canvas and in the scene.
struct ToolEvent {
    QPointF scenePos; ///< the cursor in the scene, m (y up), not snapped
    QPointF viewPos; ///< the cursor in viewport pixels
    Qt::MouseButton button = Qt::NoButton; ///< the button that changed (press, release)
    Qt::MouseButtons buttons; ///< the buttons held
    Qt::KeyboardModifiers modifiers;
};

/// A canvas tool. The canvas forwards the mouse and the keys it does not use itself (pan, zoom,
/// Space) to its current tool, and asks it to paint an overlay (a rubber band, a shape being
/// drawn) over the scene. A tool changes the scene only through its SceneDocument, so every change
/// is one undoable command.
class Tool {
    Q_DECLARE_TR_FUNCTIONS(Tool)

public:
    /// A tool that edits `document` shown on `canvas`; both outlive the tool.
    Tool(SceneDocument& document, CanvasView& canvas)
        : m_document(document)
        , m_canvas(canvas)
    {
    }
    virtual ~Tool() = default;
    Tool(const Tool&) = delete;
    Tool& operator=(const Tool&) = delete;

    /// Which tool this is.
    virtual ToolKind kind() const = 0;

    /// The tool stops being the current one (or the scene was replaced): drop any drawing in
    /// progress.
    virtual void cancel() {}

    /// A mouse button went down on the canvas.
    virtual void mousePress(const ToolEvent&) {}
    /// The mouse moved over the canvas (with or without a button held).
    virtual void mouseMove(const ToolEvent&) {}
    /// A mouse button was released.
    virtual void mouseRelease(const ToolEvent&) {}
    /// A double click (after its press and release).
    virtual void mouseDoubleClick(const ToolEvent&) {}

    /// True when the tool uses `key` (with `modifiers`) right now, so that the canvas takes it
    /// before a shortcut does (the arrow keys nudge a selection instead of stepping).
    virtual bool wantsKey(int /*key*/, Qt::KeyboardModifiers /*modifiers*/) const { return false; }
    /// A key press; returns true when the tool used it.
    virtual bool keyPress(QKeyEvent*) { return false; }

    /// Paints the tool's overlay in scene coordinates (m, y up) over the items. `pixelsPerMetre`
    /// converts on-screen sizes.
    virtual void paintOverlay(QPainter&, double /*pixelsPerMetre*/) const {}

    /// The cursor shape over the canvas while the tool is current.
    virtual Qt::CursorShape cursorShape() const { return Qt::CrossCursor; }

protected:
    SceneDocument& m_document;
    CanvasView& m_canvas;
};

/// `p` as a Vec2.
inline Vec2 toVec2(const QPointF& p) { return Vec2(p.x(), p.y()); }

/// `v` as a QPointF.
inline QPointF toQPointF(const Vec2& v) { return QPointF(v.x(), v.y()); }

} // namespace impetus::view
