#include "view/pace_indicator.h"

#include "view/number_text.h"
#include "view/simulation_runner.h"

#include <QLocale>
#include <QStringList>

#include <algorithm>

namespace impetus::view {

namespace {

/// Real time: one simulated second per wall-clock second.
constexpr double kRealTime = 1.0;

/// Milliseconds in a second: the tool tip gives step times in ms.
constexpr double kMsPerSecond = 1000.0;

/// Significant digits of the speed reached ("0.055×") and of times in the tool tip ("298 ms"):
/// the measurement is good to a few per cent, so more digits would only flicker.
constexpr int kSpeedDigits = 2;
constexpr int kTimeDigits = 3;
/// Decimals of the seconds a step has been computing for ("1.5 s").
constexpr int kBusyDecimals = 1;

// The numbers below are in the window's number format ("0,055" in German), as the status bar's.

QString speedText(double speed) { return localeNumber(speed, 'g', kSpeedDigits); }

/// The speed asked for, as the speed box offers it ("0.25").
QString requestedSpeedText(double speed) { return QLocale().toString(speed); }

QString msText(double seconds) { return localeNumber(seconds * kMsPerSecond, 'g', kTimeDigits); }

QString busyText(double seconds) { return QLocale().toString(seconds, 'f', kBusyDecimals); }

} // namespace

PaceIndicator::PaceIndicator(const SimulationRunner& runner, QWidget* parent)
    : QLabel(parent)
    , m_runner(runner)
{
    setObjectName(QStringLiteral("paceStatus"));
    setAccessibleName(tr("Speed against real time"));
    hide();
    connect(&runner, &SimulationRunner::paceChanged, this, &PaceIndicator::refresh);
    connect(&runner, &SimulationRunner::computingStepChanged, this, &PaceIndicator::refresh);
    connect(&runner, &SimulationRunner::runningChanged, this, &PaceIndicator::refresh);
}

void PaceIndicator::refresh()
{
    const RunPace pace = m_runner.pace();
    const bool running = m_runner.isRunning();
    if (m_runner.isComputingStep()) {
        setText(tr("Computing a step…"));
    } else if (running && pace.behind) {
        const QString reached = speedText(pace.achievedSpeed);
        // The speed box offers 1× exactly, so this compares with the value it set.
        setText(pace.requestedSpeed == kRealTime
                    ? tr("Running at %1× real time").arg(reached)
                    : tr("Running at %1× real time (speed set to %2×)")
                          .arg(reached, requestedSpeedText(pace.requestedSpeed)));
    } else {
        hide();
        return;
    }
    const QString why = reason(pace, running);
    setToolTip(why);
    setAccessibleDescription(why);
    show();
}

QString PaceIndicator::reason(const RunPace& pace, bool running) const
{
    QStringList lines;
    // The wall time real time allows one step: its simulated duration at the speed asked for.
    const double budget = pace.timeStep / pace.requestedSpeed;
    if (running) {
        lines << tr("Simulated time runs at %1× real time, slower than the %2× asked for.")
                     .arg(speedText(pace.achievedSpeed), requestedSpeedText(pace.requestedSpeed));
    } else {
        lines << tr("Step (→) is computing one time step in the background. The canvas shows it when it is "
                    "done; the window keeps working meanwhile.");
    }
    if (!pace.costKnown) {
        lines << tr("No step has been computed yet; the first one has taken %1 s so far.")
                     .arg(busyText(pace.busySeconds));
    } else {
        if (running) {
            lines << tr("One step (%1 ms of simulated time) takes %2 ms to compute; at %3× it may take at most %4 ms.")
                         .arg(msText(pace.timeStep), msText(pace.wallSecondsPerStep),
                              requestedSpeedText(pace.requestedSpeed), msText(budget));
        } else {
            lines << tr("The last step took %1 ms to compute.").arg(msText(pace.wallSecondsPerStep));
        }
        if (pace.busySeconds > std::max(pace.wallSecondsPerStep, budget)) {
            lines << tr("The steps being computed now have taken %1 s so far.").arg(busyText(pace.busySeconds));
        }
        lines << tr("The last step — bodies: %1, contacts: %2, impacts: %3. Solving the contacts and joints took "
                    "%4 ms of its %5 ms.")
                     .arg(m_runner.world().bodies.size())
                     .arg(pace.profile.contacts)
                     .arg(pace.profile.impacts)
                     .arg(localeNumber(pace.profile.solveMs, 'g', kTimeDigits),
                          localeNumber(pace.profile.totalMs, 'g', kTimeDigits));
        if (pace.stability.substeps > 1) {
            lines << tr("Soft bodies split each step into %1 substeps. %2")
                         .arg(pace.stability.substeps)
                         .arg(QString::fromStdString(pace.stability.message));
        }
    }
    if (!running) {
        lines << tr("To make steps faster: use fewer bodies, or give soft bodies fewer ellipses per m².");
    } else if (pace.costKnown && std::max(pace.wallSecondsPerStep, pace.busySeconds) <= budget) {
        lines << tr("The steps themselves are fast enough: the computer was busy with something else for a moment.");
    } else {
        lines << tr("To keep up: use fewer bodies, give soft bodies fewer ellipses per m², make the time step "
                    "larger, or choose a lower speed.");
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace impetus::view
