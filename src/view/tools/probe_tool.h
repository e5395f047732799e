#pragma once
/// \file probe_tool.h
/// The probe: a body's live readout (its state and energies) in a small label that follows it.

#include "controller/body_readout.h"
#include "model/body.h"
#include "view/tools/tool.h"

#include <QRectF>
#include <QString>
#include <QTransform>

#include <optional>
#include <string>

class QFont;

namespace impetus::view {

/// Probe: click a body to read it. A small label to the right of the body lists everything the engine
/// says of it (controller::readBody()): its name, position, velocity and speed, angle and ω,
/// momentum, kinetic and potential energy, and its collisions. The label follows the body as it
/// moves and is read afresh whenever the canvas is painted, so it follows every step of a run,
/// a Step, a Step Back and a scrub of the timeline; when the body leaves the view the label stays
/// at the edge nearest to it. Clicking another body probes that one instead; clicking the probed
/// body again or empty space, Esc, or another tool removes the label. Probing is not an edit.
///
/// The probe holds on to the body by name, so it keeps the body when others are added or deleted,
/// and lets go when the body itself is deleted or the scene replaced.
class ProbeTool : public Tool {
public:
    using Tool::Tool;
    ToolKind kind() const override { return ToolKind::Probe; }
    void cancel() override;
    void mousePress(const ToolEvent& event) override;
    bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(QKeyEvent* event) override;
    void paintOverlay(QPainter& painter, double pixelsPerMetre) const override;
    Qt::CursorShape cursorShape() const override { return Qt::PointingHandCursor; }

    /// The body probed, if any (and if it still exists).
    std::optional<model::BodyId> body() const;
    /// The probed body's readout in the world shown now.
    std::optional<controller::BodyReadout> readout() const;
    /// The label's text, one quantity (or a pair) per line; empty when nothing is probed.
    QString text() const;
    /// Where the label is drawn now, in viewport pixels; null when nothing is probed.
    QRectF labelRect() const;

private:
    /// The label's rectangle for `text` in `font`, the view mapping the scene to pixels by
    /// `toPixels`, beside `body`'s item and kept inside the viewport.
    QRectF placeLabel(model::BodyId body, const QTransform& toPixels, const QFont& font, const QString& text) const;

    std::string m_name; ///< the probed body's name; empty when none
};

} // namespace impetus::view
