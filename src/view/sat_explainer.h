#pragma once
/// \file sat_explainer.h
/// Explain › Separating Axes: the narrow phase's own work on two selected bodies, drawn on the
/// canvas axis by axis (docs/explainers.md, "Separating axes").

#include "controller/collision/pair_trace.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <cstddef>
#include <vector>

class QGraphicsItem;
class QLabel;

namespace impetus::view {

class CanvasView;
class SceneDocument;

/// Shows, for the two bodies selected, every candidate axis of every pair of their convex pieces
/// that the narrow phase tested (controller::traceBodyPair): both pieces' projections on the axis
/// as intervals, the overlap in mm, the axis of least overlap, the minimum translation vector, the
/// reference and incident faces and the clipped contact points; or the separating axis found.
/// One axis at a time: N (next) and P (previous) step through them, Esc closes. The pieces are
/// traced again whenever the world changes (a Step, a seek), so a paused collision can be stepped.
class SatExplainer : public QObject {
    Q_OBJECT

public:
    /// An explainer for `canvas`, which shows `document`'s world. Both must outlive it.
    SatExplainer(CanvasView& canvas, SceneDocument& document, QObject* parent = nullptr);
    ~SatExplainer() override;

    /// Opens on the two bodies selected; false (and nothing opens) unless exactly two are.
    bool open();
    /// Removes the drawing and the panel.
    void close();
    bool isOpen() const { return m_open; }

    /// The traces of the pairs of pieces, as the narrow phase recorded them.
    const std::vector<controller::PiecePairTrace>& traces() const { return m_traces; }
    /// The pair of pieces shown (index into traces()).
    std::size_t currentPair() const { return m_pair; }
    /// The axis shown (index into the pair's trace axes); equal to the axis count for the
    /// pair's summary (least overlap, MTV, faces and points), which ends each pair's axes.
    std::size_t currentAxis() const { return m_axis; }
    /// Next and previous axis, across pairs.
    void next();
    void previous();
    /// The text panel's contents (plain text), what the panel says about the axis shown.
    QString panelText() const;

    /// The current pair's trace, or nullptr when there is none.
    const controller::PiecePairTrace* current() const;

signals:
    /// The axis or pair shown, or the traces, changed; or the explainer opened or closed.
    void changed();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void retrace();
    void updateView();
    QString describe() const;

    CanvasView& m_canvas;
    /// Null once the canvas is gone (the window deletes it before this explainer): the drawing and
    /// the panel went with it, and there is nothing left to close.
    QPointer<QObject> m_canvasAlive;
    SceneDocument& m_document;
    bool m_open = false;
    int m_bodyA = 0;
    int m_bodyB = 0;
    std::vector<controller::PiecePairTrace> m_traces;
    std::size_t m_pair = 0;
    std::size_t m_axis = 0;
    QGraphicsItem* m_item = nullptr; ///< owned by the canvas's scene while open
    QLabel* m_panel = nullptr; ///< child of the canvas's viewport
};

} // namespace impetus::view
