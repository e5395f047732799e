#include "view/timeline_bar.h"

#include "view/simulation_runner.h"
#include "view/timeline.h"
#include "view/view_constants.h"

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>

#include <algorithm>
#include <limits>

namespace impetus::view {

namespace {

/// Space at the strip's left and right ends, px: the button sits at the edge, the label clear of it.
constexpr int kLeftMarginPx = 4;
constexpr int kRightMarginPx = 8;

/// A step count as a slider value: sliders hold ints, and a run of 2³¹ steps (over 100 days at the
/// default step) is beyond any lesson; beyond it the slider saturates.
int sliderValue(std::int64_t step)
{
    return static_cast<int>(std::clamp<std::int64_t>(step, 0, std::numeric_limits<int>::max()));
}

} // namespace

TimelineBar::TimelineBar(Timeline& timeline, const SimulationRunner& runner, QWidget* parent)
    : QWidget(parent)
    , m_timeline(timeline)
    , m_runner(runner)
    , m_stepBack(new QToolButton(this))
    , m_slider(new QSlider(Qt::Horizontal, this))
    , m_label(new QLabel(this))
{
    setObjectName(QStringLiteral("timelineBar"));
    setAccessibleName(tr("Timeline"));
    m_stepBack->setObjectName(QStringLiteral("stepBackButton"));
    m_stepBack->setAutoRaise(true);
    m_slider->setObjectName(QStringLiteral("timelineSlider"));
    m_slider->setAccessibleName(tr("Time along the run"));
    m_slider->setToolTip(tr("Drag to go back to any moment of the run; Play goes on from there"));
    m_slider->setPageStep(constants::kTimelinePageSteps);
    m_slider->setSingleStep(1);
    // The canvas keeps the keys (Space, the arrows): the slider takes the mouse only.
    m_slider->setFocusPolicy(Qt::NoFocus);
    m_label->setObjectName(QStringLiteral("timelineLabel"));
    m_label->setAccessibleName(tr("Time shown"));

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(kLeftMarginPx, 0, kRightMarginPx, 0);
    layout->addWidget(m_stepBack);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_label);

    // Only a move by the user seeks (a drag, a click in the groove): valueChanged also fires when
    // the bar follows the run. The slider position is already the new one when this fires.
    connect(m_slider, &QSlider::actionTriggered, this, [this] {
        m_timeline.seek(m_slider->sliderPosition());
    });
    connect(&m_timeline, &Timeline::rangeChanged, this, &TimelineBar::update);
    connect(&m_runner, &SimulationRunner::stepped, this, &TimelineBar::update);
    connect(&m_runner, &SimulationRunner::worldChanged, this, &TimelineBar::update);
    update();
}

void TimelineBar::setStepBackAction(QAction* action) { m_stepBack->setDefaultAction(action); }

void TimelineBar::update()
{
    const QSignalBlocker blocker(m_slider);
    m_slider->setRange(sliderValue(m_timeline.firstStep()), sliderValue(m_timeline.lastStep()));
    if (!m_slider->isSliderDown())
        m_slider->setValue(sliderValue(m_timeline.currentStep()));
    const double dt = m_runner.world().settings.timeStep;
    const double shown = m_runner.world().time;
    // The run's end in time: the step count times the step, measured from the time shown, so that
    // a time step changed along the way does not show a run that ends before now.
    const double end = shown + static_cast<double>(m_timeline.lastStep() - m_timeline.currentStep()) * dt;
    // In the window's number format ("0,500" in German), as the status bar's time.
    const QLocale locale;
    m_label->setText(tr("t = %1 s of %2 s").arg(locale.toString(shown, 'f', 3), locale.toString(end, 'f', 3)));
}

} // namespace impetus::view
