// The app's frame-rate budget (issue 13, item 7): the real canvas showing the 2000-body scene
// (model::makeRotatingBoxWithCircles, its container turning) as it runs in real time, with the
// velocity arrows and the trails on, once with the canvas's paint caches off (everything painted
// afresh, as before them) and once on (CanvasView::setPaintCaches).
//
// Two measures for each. "Live" is what a user sees: the runner plays in real time with its own
// timer and event loop, so the worker thread computes the next batch of steps while the GUI
// thread paints the last one; the frame period is the wall time between paints that show a new
// state. "Parts" takes the same frame apart, one after the other on an idle event loop: the fixed
// steps of 1/60 s of simulated time (stepBy, on the worker), the canvas following them (items
// moved, trail points taken, arrows' forces) and one paint, each in wall time and the paint also
// in the GUI thread's CPU time (which a shared machine inflates less), then the step's phases
// (the engine's StepProfile) and what each instrument adds to a paint.
// Run: build/bench/bench/impetus-bench-frame-budget [--frames N] [--warm-up N] [--bodies N]
//      [--size WxH] [--seconds S] [--caches on|off|both]
// Offscreen by default; under Xvfb, QT_QPA_PLATFORM=xcb paints through the X server instead.

#include "model/example_scenes.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/simulation_runner.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace {

using namespace impetus;

/// The budget of one frame at 60 frames per second, ms.
constexpr double kBudgetMs = 1000.0 / 60.0;
/// Simulated time one frame shows in a real-time run, s.
constexpr double kFrameSeconds = 1.0 / 60.0;

struct Options {
    int frames = 300; ///< frames measured (5 s of a real-time run)
    int warmUp = 60; ///< frames run first, unpainted and unmeasured: the circles fall, trails grow
    int bodies = 2000; ///< circles in the turning box
    int width = 1000; ///< canvas size, px: the canvas of a default 1200 × 720 window
    int height = 600;
    int paintSamples = 40; ///< paints per configuration in the breakdown
    double seconds = 5; ///< wall time of the live measure, after `warmUp` frames' worth of play
    std::vector<bool> caches{false, true}; ///< the canvas's paint caches off (before), on (after)
};

bool parse(int argc, char** argv, Options& options)
{
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--frames" && hasValue)
            options.frames = std::atoi(argv[++i]);
        else if (arg == "--warm-up" && hasValue)
            options.warmUp = std::atoi(argv[++i]);
        else if (arg == "--caches" && hasValue) {
            const std::string which = argv[++i];
            if (which == "on")
                options.caches = {true};
            else if (which == "off")
                options.caches = {false};
            else if (which != "both")
                return false;
        } else if (arg == "--seconds" && hasValue)
            options.seconds = std::atof(argv[++i]);
        else if (arg == "--bodies" && hasValue)
            options.bodies = std::atoi(argv[++i]);
        else if (arg == "--size" && hasValue) {
            if (std::sscanf(argv[++i], "%dx%d", &options.width, &options.height) != 2)
                return false;
        } else
            return false;
    }
    return options.frames > 0 && options.seconds > 0 && options.warmUp >= 0 && options.bodies >= 0 && options.width > 0 &&
           options.height > 0;
}

/// Mean, median and 95th percentile of a series, ms.
struct Summary {
    double mean = 0;
    double median = 0;
    double p95 = 0;
};

Summary summarise(std::vector<double> values)
{
    Summary s;
    if (values.empty())
        return s;
    std::ranges::sort(values);
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
    s.median = values[values.size() / 2];
    s.p95 = values[std::min(values.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(values.size()))) - 1)];
    return s;
}

void printRow(const char* name, const std::vector<double>& values)
{
    const Summary s = summarise(values);
    std::printf("  %-28s %8.2f %8.2f %8.2f\n", name, s.mean, s.median, s.p95);
}

double elapsedMs(const QElapsedTimer& timer) { return static_cast<double>(timer.nsecsElapsed()) / 1e6; }

/// CPU time this thread has used, ms.
double threadCpuMs()
{
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) / 1e6;
}

/// Counts the paint events a widget gets (one per frame, as in the app, where the moves of a
/// step's items ask for one repaint of the viewport) and notes, for the live measure, when a
/// paint shows a state that the last one did not.
class PaintCounter : public QObject {
public:
    explicit PaintCounter(const view::SimulationRunner& runner)
        : m_runner(runner)
    {
        clock.start();
    }
    int paints = 0;
    QElapsedTimer clock;
    std::vector<double> newStateAtMs; ///< clock time of each paint showing a new state
    std::int64_t lastStep = -1;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Paint) {
            ++paints;
            const std::int64_t step = m_runner.world().stepCount;
            if (step != lastStep) {
                lastStep = step;
                newStateAtMs.push_back(elapsedMs(clock));
            }
        }
        return QObject::eventFilter(watched, event);
    }

private:
    const view::SimulationRunner& m_runner;
};

/// The viewport painted `samples` times as it is, ms each (median).
double paintMs(view::CanvasView& canvas, int samples)
{
    std::vector<double> times;
    for (int i = 0; i < samples; ++i) {
        QElapsedTimer timer;
        timer.start();
        canvas.viewport()->repaint();
        times.push_back(elapsedMs(timer));
    }
    return summarise(times).median;
}

/// A fresh runner and canvas on the scene, instruments on, caches as `caches`.
struct Setup {
    view::SimulationRunner runner;
    std::unique_ptr<view::CanvasView> canvas;
    std::int64_t stepsPerFrame = 1;

    Setup(const Options& options, bool caches)
    {
        // The container turns as in the engine comparison: its walls get their velocity before each step.
        runner.setStepFunction([](controller::Simulation& simulation, model::World& world) {
            model::spinFixedBodies(world, Vec2::Zero(), model::kRotatingContainerAngularVelocity);
            simulation.step(world);
        });
        runner.setWorld(model::makeRotatingBoxWithCircles(options.bodies));
        canvas = std::make_unique<view::CanvasView>(runner);
        canvas->setPaintCaches(caches);
        canvas->resize(options.width, options.height);
        canvas->show();
        QApplication::processEvents();
        view::CanvasInstruments& instruments = canvas->instruments();
        instruments.setShowVector(view::VectorKind::Velocity, true);
        instruments.setShowTrails(true);
        // What the window asks of the runner when trails are on (MainWindow::updateSampling).
        view::SampleRequest request;
        request.centres = instruments.needsCentres();
        runner.setSampleRequest(request);
        const double timeStep = runner.world().settings.timeStep;
        stepsPerFrame = std::max<std::int64_t>(1, std::llround(kFrameSeconds / timeStep));
    }
};

/// Runs the event loop for `seconds` of wall time.
void runFor(double seconds)
{
    QEventLoop loop;
    QTimer::singleShot(static_cast<int>(seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
}

/// The live measure: the runner plays in real time; prints the frame period a user sees.
void measureLive(const Options& options, bool caches)
{
    Setup setup(options, caches);
    PaintCounter counter(setup.runner);
    setup.canvas->viewport()->installEventFilter(&counter);
    setup.runner.play();
    runFor(static_cast<double>(options.warmUp) * kFrameSeconds);
    const std::int64_t firstStep = setup.runner.world().stepCount;
    counter.newStateAtMs.clear();
    QElapsedTimer wall;
    wall.start();
    runFor(options.seconds);
    const double wallMs = elapsedMs(wall);
    setup.runner.pause();
    std::vector<double> periods;
    for (std::size_t i = 1; i < counter.newStateAtMs.size(); ++i)
        periods.push_back(counter.newStateAtMs[i] - counter.newStateAtMs[i - 1]);
    const Summary s = summarise(periods);
    const double simulated = static_cast<double>(setup.runner.world().stepCount - firstStep) *
                             setup.runner.world().settings.timeStep;
    // The share of frames within the budget, with a millisecond's grace for the timer's own
    // jitter (a frame of 17 ms on a 60 Hz screen is late by a fraction of a refresh, not a frame).
    constexpr double kGraceMs = 1.0;
    const auto within = std::ranges::count_if(periods, [](double period) { return period <= kBudgetMs + kGraceMs; });
    const double withinShare = periods.empty() ? 0.0 : 100.0 * static_cast<double>(within) / static_cast<double>(periods.size());
    std::printf("  live, caches %-3s  frame period mean %7.2f  median %7.2f  p95 %7.2f ms  (%.0f fps at the median);"
                " %.0f %% of frames within %.1f ms; %zu new states in %.1f s; simulated %.2f s per wall s\n",
                caches ? "on" : "off", s.mean, s.median, s.p95, s.median > 0 ? 1000.0 / s.median : 0.0, withinShare,
                kBudgetMs + kGraceMs, counter.newStateAtMs.size(), wallMs / 1000, simulated / (wallMs / 1000));
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    if (!parse(argc, argv, options)) {
        std::fprintf(stderr, "usage: %s [--frames N] [--warm-up N] [--bodies N] [--size WxH] [--seconds S] [--caches on|off|both]\n", argv[0]);
        return 2;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    {
        Setup probe(options, true);
        std::printf("Frame budget: %zu bodies (%d circles in a turning box), canvas %d x %d px on \"%s\",\n"
                    "velocity arrows and trails on; %lld steps of %.6g s per frame; budget %.1f ms.\n",
                    probe.runner.world().bodies.size(), options.bodies, options.width, options.height,
                    qPrintable(QApplication::platformName()), static_cast<long long>(probe.stepsPerFrame),
                    probe.runner.world().settings.timeStep, kBudgetMs);
    }

    std::printf("\nLive (the runner playing in real time, %.0f frames' worth of warm-up, then %.1f s):\n",
                static_cast<double>(options.warmUp), options.seconds);
    for (const bool caches : options.caches)
        measureLive(options, caches);

    for (const bool caches : options.caches) {
        Setup setup(options, caches);
        view::SimulationRunner& runner = setup.runner;
        view::CanvasView& canvas = *setup.canvas;
        view::CanvasInstruments& instruments = canvas.instruments();
        PaintCounter counter(runner);
        canvas.viewport()->installEventFilter(&counter);
        std::vector<double> total;
        std::vector<double> physics;
        std::vector<double> update;
        std::vector<double> paint;
        std::vector<double> paintCpu;
        std::vector<controller::StepProfile> profiles;
        int paints = 0;
        for (int frame = 0; frame < options.warmUp + options.frames; ++frame) {
            QElapsedTimer timer;
            timer.start();
            runner.stepBy(setup.stepsPerFrame);
            const double stepped = elapsedMs(timer);
            if (frame < options.warmUp)
                continue; // unpainted: the warm-up only brings the scene and the trails to a running state
            // The event loop's turn: the viewport paints the moved items once, as the app does.
            counter.paints = 0;
            const double cpuBefore = threadCpuMs();
            QApplication::processEvents();
            paintCpu.push_back(threadCpuMs() - cpuBefore);
            const double all = elapsedMs(timer);
            paints += counter.paints;
            // The worker's wall time for the batch; the rest of stepBy is the view following it.
            const double worker =
                1000.0 * runner.pace().wallSecondsPerStep * static_cast<double>(setup.stepsPerFrame);
            total.push_back(all);
            physics.push_back(worker);
            update.push_back(std::max(0.0, stepped - worker));
            paint.push_back(all - stepped);
            profiles.push_back(runner.pace().profile);
        }

        std::printf("\nParts, caches %s, %d frames after %d of warm-up; per frame, ms   mean   median      p95\n",
                    caches ? "on" : "off", options.frames, options.warmUp);
        printRow("frame (physics + view)", total);
        printRow("  physics (worker thread)", physics);
        printRow("  view update (items, trails)", update);
        printRow("  paint", paint);
        printRow("  paint, GUI thread CPU", paintCpu);
        std::printf("%.2f paints per frame.\n", static_cast<double>(paints) / options.frames);
        const Summary ph = summarise(physics);
        const Summary up = summarise(update);
        const Summary pa = summarise(paint);
        const Summary frames = summarise(total);
        const char* largest = ph.mean >= up.mean && ph.mean >= pa.mean ? "physics" : pa.mean >= up.mean ? "paint" : "view update";
        std::printf("Largest part: %s (%.0f%% of the mean frame); one after the other the parts take %.1f ms at the"
                    " median, overlapped (physics on its thread) max(physics, view + paint) = %.1f ms.\n",
                    largest, 100.0 * std::max({ph.mean, up.mean, pa.mean}) / frames.mean, frames.median,
                    std::max(ph.median, up.median + pa.median));
        if (caches) {
            // The engine's own account of a step (the last of each frame), medians over the frames.
            const auto phase = [&](double controller::StepProfile::* field) {
                std::vector<double> values;
                for (const controller::StepProfile& profile : profiles)
                    values.push_back(profile.*field);
                return summarise(values).median;
            };
            std::printf("One step's phases (StepProfile, median of the frames' last steps), ms: total %.2f = broad %.2f"
                        " + narrow %.2f + integrate %.2f + solve %.2f (prepare %.2f, impacts %.2f, velocity %.2f,"
                        " position %.2f) + events %.2f; x %lld steps a frame.\n",
                        phase(&controller::StepProfile::totalMs), phase(&controller::StepProfile::broadMs),
                        phase(&controller::StepProfile::narrowMs), phase(&controller::StepProfile::integrateMs),
                        phase(&controller::StepProfile::solveMs), phase(&controller::StepProfile::prepareMs),
                        phase(&controller::StepProfile::impactsMs), phase(&controller::StepProfile::velocityMs),
                        phase(&controller::StepProfile::positionMs), phase(&controller::StepProfile::eventsMs),
                        static_cast<long long>(setup.stepsPerFrame));
        }

        // What a paint costs with each instrument, on the last state (trails as long as they got).
        std::printf("One paint of the last state, caches %s, median of %d, ms:\n", caches ? "on" : "off",
                    options.paintSamples);
        instruments.setShowVector(view::VectorKind::Velocity, false);
        // Trails are hidden by drawing them for no body rather than by turning them off, which
        // would forget them: selected-only with an empty selection.
        instruments.setSelectedOnly(true);
        std::printf("  bodies only                 %8.2f\n", paintMs(canvas, options.paintSamples));
        instruments.setSelectedOnly(false);
        std::printf("  bodies + trails             %8.2f  (%zu points per body)\n", paintMs(canvas, options.paintSamples),
                    instruments.trail(0).size());
        instruments.setShowVector(view::VectorKind::Velocity, true);
        std::printf("  bodies + trails + arrows    %8.2f\n", paintMs(canvas, options.paintSamples));
    }
    return 0;
}
