#pragma once
/// \file canvas_view.h
/// The canvas: the world drawn in metres with y up, and the editing tools that act on it.

#include "model/body.h"
#include "view/canvas_look.h"
#include "view/selection.h"
#include "view/tools/tool.h"

#include <QGraphicsView>
#include <QImage>
#include <QTimer>
#include <QTransform>
#include <QRectF>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QGraphicsScene;

namespace impetus::view {

class BodyItem;
class BodyStamps;
class CanvasInstruments;
class JointItem;
class LessonSession;
class SceneDocument;
class SimulationRunner;
class SoftDetailItem;
class SpringItem;

/// Shows the world of a SimulationRunner. The scene is in metres with y up; the view transform
/// scales by (s, −s) with s in pixels per metre, so the world's y axis points up on screen.
///
/// One BodyItem per body, one SpringItem per spring and one JointItem per joint, rebuilt on the
/// runner's worldChanged() and moved on its stepped(). The view only reads the world; edits go
/// through the SceneDocument given to setDocument(), and only its tools make them.
///
/// A new scene is framed to fit its bodies (and spring anchors) with a margin, keeping the aspect
/// ratio; edits do not move the view. While auto-framing is on, resizing the canvas frames that
/// same region again. The wheel zooms toward the cursor; a middle-button drag, or a drag while
/// Space is held, pans. Either turns auto-framing off.
class CanvasView : public QGraphicsView {
    Q_OBJECT

public:
    /// A canvas showing `runner`'s world, for viewing only (the screenshot). The runner must
    /// outlive the canvas.
    explicit CanvasView(const SimulationRunner& runner, QWidget* parent = nullptr);
    ~CanvasView() override;

    /// Makes the canvas an editor of `document` (whose runner is the one shown): creates the tools
    /// (Select is current), shows the document's selection, and frames each new scene. The
    /// document must outlive the canvas.
    void setDocument(SceneDocument& document);

    /// The runner whose world is shown.
    const SimulationRunner& runner() const { return m_runner; }

    /// The body items, in the order of World::bodies.
    const std::vector<BodyItem*>& bodyItems() const { return m_bodyItems; }

    /// The item of body `id`, or nullptr.
    BodyItem* bodyItem(model::BodyId id) const;

    /// The spring items, in the order of World::springs.
    const std::vector<SpringItem*>& springItems() const { return m_springItems; }

    /// Per body: the item that draws a soft body's ellipses and strain, or nullptr for a rigid one.
    const std::vector<SoftDetailItem*>& softItems() const { return m_softItems; }
    /// Whether soft bodies show their ellipses, and their grid springs coloured by strain.
    bool showsSoftEllipses() const { return m_showSoftEllipses; }
    bool showsSoftStrain() const { return m_showSoftStrain; }
    void setShowSoftEllipses(bool on);
    void setShowSoftStrain(bool on);

    /// The vector arrows, their legend and the trails drawn over the bodies.
    CanvasInstruments& instruments() { return *m_instruments; }
    const CanvasInstruments& instruments() const { return *m_instruments; }

    /// The joint items, in the order of World::joints.
    const std::vector<JointItem*>& jointItems() const { return m_jointItems; }

    /// The region (scene coordinates, m) the canvas frames: the bodies' bounding box when the
    /// scene was put in, with a margin.
    QRectF frameRect() const { return m_frameRect; }

    /// Scale of the view, pixels per metre.
    double pixelsPerMetre() const;

    /// Whether resizing the canvas frames frameRect() again (on by default; a zoom or pan by the
    /// user turns it off).
    bool autoFrame() const { return m_autoFrame; }
    /// Turns auto-framing on resize on or off.
    void setAutoFrame(bool on) { m_autoFrame = on; }

    /// The viewport point `viewPos` (px, fractions allowed) in scene coordinates, m.
    QPointF toScene(const QPointF& viewPos) const;
    /// The scene point `scenePos` (m) in viewport coordinates, px, unrounded.
    QPointF toView(const QPointF& scenePos) const;

    /// Multiplies the scale by `factor` (limited to constants::kMinPixelsPerMetre …
    /// kMaxPixelsPerMetre) keeping the scene point under the viewport point `viewAnchor` in place.
    void zoomBy(double factor, const QPointF& viewAnchor);

    /// Moves the view so that the scene follows the mouse by `pixels`.
    void panBy(const QPointF& pixels);

    /// Distance between neighbouring grid lines at the current zoom, m (1, 2 or 5 × 10ⁿ).
    double gridSpacing() const;

    /// Whether tools snap the points they place to the grid.
    bool snapToGrid() const { return m_snapToGrid; }
    /// `scenePos` on the nearest grid crossing when snapping is on, unchanged otherwise.
    QPointF snapped(const QPointF& scenePos) const;

    /// The current tool, or nullptr without a document.
    Tool* tool() const { return m_tool; }
    /// The kind of the current tool.
    ToolKind toolKind() const { return m_tool ? m_tool->kind() : ToolKind::Select; }

    /// Bodies whose outline contains `scenePos`, topmost first (the last drawn is on top).
    std::vector<int> bodiesAt(const QPointF& scenePos) const;
    /// The topmost body at `scenePos`, if any.
    std::optional<int> bodyAt(const QPointF& scenePos) const;
    /// The spring drawn within constants::kPickTolerancePx of `scenePos`, if any.
    std::optional<int> springAt(const QPointF& scenePos) const;
    /// The joint drawn within constants::kPickTolerancePx of `scenePos`, if any.
    std::optional<int> jointAt(const QPointF& scenePos) const;
    /// Everything lying wholly inside the scene rectangle `rect`.
    Selection itemsInside(const QRectF& rect) const;

    /// Shows `message` in a tool tip at the scene point `scenePos` (a refused polygon, a spring
    /// that starts on nothing), and keeps it as lastMessage().
    void showMessage(const QPointF& scenePos, const QString& message);
    /// The last message shown by showMessage().
    QString lastMessage() const { return m_lastMessage; }

    /// The lesson whose locks the tools obey (no drag, turn or nudge of a locked body), or nullptr.
    const LessonSession* lessonSession() const { return m_lessonSession; }
    /// Makes the tools obey `session`'s locks; the session must outlive the canvas.
    void setLessonSession(const LessonSession* session) { m_lessonSession = session; }

    /// How the canvas draws (line widths, grid colours, hatched collisions): the normal look, or
    /// projector mode's.
    const CanvasLook& look() const { return m_look; }
    /// Draws with `look` from now on, items and background alike.
    void setLook(const CanvasLook& look);

    /// Whether the canvas paints through its caches (on by default): the paper, grid and trails
    /// kept in a layer of the viewport's size, to which a run only adds the trails' new points,
    /// and round bodies stamped from pictures drawn once per colour and size (body_stamps.h).
    /// Off paints everything afresh on every paint, as the reference the caches are tested
    /// against and the benchmark's "before".
    bool paintCaches() const { return m_paintCaches; }
    void setPaintCaches(bool on);

public slots:
    /// Fits frameRect() into the viewport, keeping the aspect ratio, with y up.
    void frameWorld();

    /// Takes the bodies' bounding box as the new frameRect() and frames it, auto-framing on.
    void frameScene();

    /// Recreates every item from the runner's world. The view does not move.
    void rebuildItems();

    /// Moves every item to the runner's current body states.
    void syncItems();

    /// Makes `kind` the current tool, cancelling what the previous one was drawing. Needs a
    /// document; emits toolChanged().
    void setTool(ToolKind kind);

    /// Turns snapping to the grid on or off.
    void setSnapToGrid(bool on) { m_snapToGrid = on; }

signals:
    /// Space was pressed and released on the canvas without panning: the window toggles Play.
    void spaceTapped();

    /// The current tool changed.
    void toolChanged(ToolKind kind);

protected:
    /// Paper and a grid in metres: lines 1, 2 or 5 × 10ⁿ m apart, whichever is the first at least
    /// constants::kMinimumGridSpacingPx apart on screen, darker every whole decade, darkest on the
    /// axes x = 0 and y = 0; the darker lines are labelled in metres along the left and bottom
    /// edges.
    void drawBackground(QPainter* painter, const QRectF& rect) override;
    /// The current tool's overlay.
    void drawForeground(QPainter* painter, const QRectF& rect) override;
    /// Frames frameRect() again while autoFrame() is on.
    void resizeEvent(QResizeEvent* event) override;
    /// Takes Space and the keys the tool wants before the window's shortcuts do.
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    /// Zooms toward the cursor.
    void wheelEvent(QWheelEvent* event) override;
    /// Forgets a half-done Space press when the canvas loses the keyboard.
    void focusOutEvent(QFocusEvent* event) override;

private:
    QRectF computeFrameRect() const;
    ToolEvent toolEvent(const QMouseEvent* event) const;
    void showSelection();
    /// Draws body i as its grid now has it, if it is soft: the deformed outline, and the ellipses
    /// and strain when they are shown.
    void syncSoftBody(std::size_t i);
    void drawGridLabels(QPainter* painter, const QRectF& rect, double spacing, int linesPerMajor) const;
    /// The paper, the grid and its labels over the scene rectangle `rect`.
    void drawPaper(QPainter* painter, const QRectF& rect) const;
    /// Brings m_backgroundLayer up to date for a paint of the viewport by `viewportPainter`.
    void updateBackgroundLayer(QPainter& viewportPainter);
    /// Hands m_look's line scale and outlines to every item.
    void applyLookToItems();

    const SimulationRunner& m_runner;
    SceneDocument* m_document = nullptr;
    QGraphicsScene* m_scene;
    CanvasInstruments* m_instruments;
    std::vector<BodyItem*> m_bodyItems;
    std::vector<SpringItem*> m_springItems;
    std::vector<JointItem*> m_jointItems;
    std::vector<SoftDetailItem*> m_softItems;
    /// The fixed points of springs and rods to the world (their own items).
    std::vector<QGraphicsItem*> m_anchorItems;
    bool m_showSoftEllipses = false;
    bool m_showSoftStrain = false;
    std::vector<std::unique_ptr<Tool>> m_tools;
    Tool* m_tool = nullptr;
    QRectF m_frameRect;
    bool m_autoFrame = true;
    bool m_snapToGrid = false;
    bool m_spaceHeld = false; ///< Space is down on the canvas
    bool m_spaceUsedForPan = false; ///< a drag happened while Space was down
    bool m_panning = false;
    QPointF m_lastPanPos; ///< px
    QString m_lastMessage;
    CanvasLook m_look;
    bool m_paintCaches = true;
    /// Paper, grid and trails as the viewport shows them, device pixels (paintCaches()).
    QImage m_backgroundLayer;
    QTransform m_layerTransform; ///< scene → viewport when the layer was painted whole
    std::uint64_t m_layerRevision = 0; ///< CanvasInstruments::trailRevision() then
    bool m_layerDirty = true; ///< must be painted whole at the next paint
    bool m_layerGrown = false; ///< holds trail growth, not yet painted whole
    std::int64_t m_layerStep = -1; ///< World::stepCount the layer shows
    QTimer m_layerSettle; ///< paints the layer whole once the states stop coming
    std::unique_ptr<BodyStamps> m_stamps; ///< shared by the body items
    const LessonSession* m_lessonSession = nullptr;
};

} // namespace impetus::view
