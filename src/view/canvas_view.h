#pragma once
/// \file canvas_view.h
/// The canvas: the world drawn in metres with y up.

#include "model/body.h"

#include <QGraphicsView>
#include <QRectF>

#include <vector>

class QGraphicsScene;

namespace impetus::view {

class BodyItem;
class SimulationRunner;
class SpringItem;

/// Shows the world of a SimulationRunner. The scene is in metres with y up; the view transform
/// scales by (s, −s) with s in pixels per metre, so the world's y axis points up on screen.
///
/// One BodyItem per body and one SpringItem per spring, rebuilt on the runner's worldChanged()
/// and moved on its stepped(). The view only reads the world; it never changes it.
///
/// A new world is framed to fit its bodies (and spring anchors) with a margin, keeping the aspect
/// ratio. While auto-framing is on, resizing the canvas frames that same region again.
class CanvasView : public QGraphicsView {
    Q_OBJECT

public:
    /// A canvas showing `runner`'s world. The runner must outlive the canvas.
    explicit CanvasView(const SimulationRunner& runner, QWidget* parent = nullptr);

    /// The body items, in the order of World::bodies.
    const std::vector<BodyItem*>& bodyItems() const { return m_bodyItems; }

    /// The item of body `id`, or nullptr.
    BodyItem* bodyItem(model::BodyId id) const;

    /// The spring items, in the order of World::springs.
    const std::vector<SpringItem*>& springItems() const { return m_springItems; }

    /// The region (scene coordinates, m) the canvas frames: the bodies' bounding box at the last
    /// worldChanged(), with a margin.
    QRectF frameRect() const { return m_frameRect; }

    /// Scale of the view, pixels per metre.
    double pixelsPerMetre() const;

    /// Whether resizing the canvas frames frameRect() again (on by default; a later zoom or pan by
    /// the user turns it off).
    bool autoFrame() const { return m_autoFrame; }
    /// Turns auto-framing on resize on or off.
    void setAutoFrame(bool on) { m_autoFrame = on; }

public slots:
    /// Fits frameRect() into the viewport, keeping the aspect ratio, with y up.
    void frameWorld();

    /// Recreates every item from the runner's world and frames it.
    void rebuildItems();

    /// Moves every item to the runner's current body states.
    void syncItems();

protected:
    /// Paper and a grid in metres: lines 1, 2 or 5 × 10ⁿ m apart, whichever is the first at least
    /// constants::kMinimumGridSpacingPx apart on screen, darker every whole decade, darkest on the
    /// axes x = 0 and y = 0.
    void drawBackground(QPainter* painter, const QRectF& rect) override;
    /// Frames frameRect() again while autoFrame() is on.
    void resizeEvent(QResizeEvent* event) override;

private:
    QRectF computeFrameRect() const;

    const SimulationRunner& m_runner;
    QGraphicsScene* m_scene;
    std::vector<BodyItem*> m_bodyItems;
    std::vector<SpringItem*> m_springItems;
    QRectF m_frameRect;
    bool m_autoFrame = true;
};

} // namespace impetus::view
