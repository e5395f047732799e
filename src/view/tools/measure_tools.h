#pragma once
/// \file measure_tools.h
/// The measuring tools: a ruler (a distance in metres) and a protractor (an angle in degrees).
/// They only read the scene: nothing they do is an edit, so nothing is undone.

#include "view/tools/tool.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QString>

#include <optional>
#include <vector>

class QFont;

namespace impetus::view {

/// The size, px, of a measuring label of `text` (one line or several) written in `font`, with its
/// padding: what drawMeasureLabel() needs for the whole text.
QSizeF measureLabelSize(const QFont& font, const QString& text);

/// Draws `text` on the measuring tools' light paper filling `box` (px, the painter untransformed),
/// with a thin dark frame; the lines are centred when `centred`, else left-aligned.
void drawMeasureLabel(QPainter& painter, const QRectF& box, const QString& text, bool centred);

/// Where a measuring tool puts a point clicked at `scenePos`: the nearest body centre of mass or
/// polygon or box corner within constants::kMeasureSnapPx on screen, else the point itself
/// (snapped to the grid when snapping is on).
QPointF measurePoint(const CanvasView& canvas, const QPointF& scenePos);

/// Ruler: click one end and then the other (or drag from one to the other). The ruler stays on
/// the canvas, with its length in metres at its middle ("1.234 m") and its run and rise
/// ("Δx = 1.2 m, Δy = 0.3 m"), until the next measurement, Esc or another tool. Its ends snap to
/// body centres and corners (measurePoint()).
class RulerTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::Ruler; }
    void cancel() override;
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    void mouseRelease(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;

    /// The distance measured, m; none before both ends are placed.
    std::optional<double> distance() const;
    /// The label drawn at the ruler's middle: "1.234 m"; empty before the ruler has two ends.
    QString text() const;

private:
    std::optional<QPointF> m_start; ///< m
    std::optional<QPointF> m_end; ///< m, the cursor's snapped point while placing
    bool m_placing = false; ///< the start is placed, the end follows the cursor
    QPointF m_pressView; ///< px, where the button went down
};

/// Protractor: click the vertex of the angle, then a point on each arm. Shows the angle between
/// the arms in degrees (0–180), drawn as an arc, until the next measurement, Esc or another tool.
/// Points snap like the ruler's.
class ProtractorTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::Protractor; }
    void cancel() override;
    void mousePress(const ToolEvent& event) override;
    void mouseMove(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;

    /// The angle measured, degrees; none before the three points are placed.
    std::optional<double> angleDegrees() const;
    /// The label: "37.5°"; empty before the three points are placed.
    QString text() const;

private:
    std::vector<QPointF> m_points; ///< vertex, first arm, second arm (m); the last follows the cursor
    bool m_done = false;
};

} // namespace impetus::view
