#pragma once
/// \file timeline_bar.h
/// The strip under the canvas that shows and moves along the run's timeline.

#include <QWidget>

class QLabel;
class QSlider;
class QToolButton;

namespace impetus::view {

class SimulationRunner;
class Timeline;

/// A Step Back button, a slider over the run's steps (from Timeline::firstStep() to lastStep())
/// and a label "t = 1.250 s of 3.000 s". Dragging the slider (or clicking in its groove, or the
/// arrow keys on it) pauses and shows that step; it follows the run as it grows and as it plays.
/// Object names: "timelineSlider", "timelineLabel", "stepBackButton".
class TimelineBar : public QWidget {
    Q_OBJECT

public:
    /// A bar for `timeline` of `runner`'s runs; both outlive the bar.
    TimelineBar(Timeline& timeline, const SimulationRunner& runner, QWidget* parent = nullptr);

    /// The slider: its value is a World::stepCount.
    QSlider* slider() const { return m_slider; }
    /// The label with the time shown and the run's length.
    QLabel* label() const { return m_label; }
    /// Sets the button's action (the window's Step Back, with its shortcut).
    void setStepBackAction(class QAction* action);

private:
    void update();

    Timeline& m_timeline;
    const SimulationRunner& m_runner;
    QToolButton* m_stepBack;
    QSlider* m_slider;
    QLabel* m_label;
};

} // namespace impetus::view
