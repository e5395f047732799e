// The app's frame-rate budget (issue 13, item 7): the real canvas showing the 2000-body scene
// (model::makeRotatingBoxWithCircles, its container turning) as it runs in real time, with the
// velocity arrows and the trails on. Each frame is what one 1/60 s tick of a real-time run costs:
// the fixed steps of 1/60 s of simulated time (SimulationRunner::stepBy, on its worker thread),
// the canvas following them (items moved, trail points taken, arrows' forces), and one paint of
// the viewport. Prints mean, median and 95th percentile per frame against 16.7 ms, split into
// physics, view update and paint, then what each instrument adds to a paint.
// Run: build/bench/bench/impetus-bench-frame-budget [--frames N] [--warm-up N] [--bodies N] [--size WxH]
// Offscreen by default; under Xvfb, QT_QPA_PLATFORM=xcb paints through the X server instead.

#include "model/example_scenes.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/simulation_runner.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEvent>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
        else if (arg == "--bodies" && hasValue)
            options.bodies = std::atoi(argv[++i]);
        else if (arg == "--size" && hasValue) {
            if (std::sscanf(argv[++i], "%dx%d", &options.width, &options.height) != 2)
                return false;
        } else
            return false;
    }
    return options.frames > 0 && options.warmUp >= 0 && options.bodies >= 0 && options.width > 0 &&
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

/// Counts the paint events a widget gets: one per frame, as in the app, where the moves of a
/// step's items ask for one repaint of the viewport.
class PaintCounter : public QObject {
public:
    int paints = 0;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Paint)
            ++paints;
        return QObject::eventFilter(watched, event);
    }
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

} // namespace

int main(int argc, char** argv)
{
    Options options;
    if (!parse(argc, argv, options)) {
        std::fprintf(stderr, "usage: %s [--frames N] [--warm-up N] [--bodies N] [--size WxH]\n", argv[0]);
        return 2;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    view::SimulationRunner runner;
    // The container turns as in the engine comparison: its walls get their velocity before each step.
    runner.setStepFunction([](controller::Simulation& simulation, model::World& world) {
        model::spinFixedBodies(world, Vec2::Zero(), model::kRotatingContainerAngularVelocity);
        simulation.step(world);
    });
    runner.setWorld(model::makeRotatingBoxWithCircles(options.bodies));
    view::CanvasView canvas(runner);
    canvas.resize(options.width, options.height);
    canvas.show();
    QApplication::processEvents();
    view::CanvasInstruments& instruments = canvas.instruments();
    instruments.setShowVector(view::VectorKind::Velocity, true);
    instruments.setShowTrails(true);
    // What the window asks of the runner when trails are on (MainWindow::updateSampling).
    view::SampleRequest request;
    request.centres = instruments.needsCentres();
    runner.setSampleRequest(request);

    const double timeStep = runner.world().settings.timeStep;
    const auto stepsPerFrame = std::max<std::int64_t>(1, std::llround(kFrameSeconds / timeStep));
    std::printf("Frame budget: %zu bodies (%d circles in a turning box), canvas %d x %d px on \"%s\",\n"
                "velocity arrows and trails on; %lld steps of %.6g s per frame, %d frames after %d of warm-up.\n",
                runner.world().bodies.size(), options.bodies, options.width, options.height,
                qPrintable(QApplication::platformName()), static_cast<long long>(stepsPerFrame), timeStep,
                options.frames, options.warmUp);

    PaintCounter counter;
    canvas.viewport()->installEventFilter(&counter);
    std::vector<double> total;
    std::vector<double> physics;
    std::vector<double> update;
    std::vector<double> paint;
    int paints = 0;
    for (int frame = 0; frame < options.warmUp + options.frames; ++frame) {
        QElapsedTimer timer;
        timer.start();
        runner.stepBy(stepsPerFrame);
        const double stepped = elapsedMs(timer);
        if (frame < options.warmUp)
            continue; // unpainted: the warm-up only brings the scene and the trails to a running state
        // The event loop's turn: the viewport paints the moved items once, as the app does.
        counter.paints = 0;
        QApplication::processEvents();
        const double all = elapsedMs(timer);
        paints += counter.paints;
        // The worker's wall time for the batch; the rest of stepBy is the view following it.
        const double worker = 1000.0 * runner.pace().wallSecondsPerStep * static_cast<double>(stepsPerFrame);
        total.push_back(all);
        physics.push_back(worker);
        update.push_back(std::max(0.0, stepped - worker));
        paint.push_back(all - stepped);
    }

    std::printf("\nPer frame, ms                    mean   median      p95   (budget %.1f ms)\n", kBudgetMs);
    printRow("frame (physics + view)", total);
    printRow("  physics (worker thread)", physics);
    printRow("  view update (items, trails)", update);
    printRow("  paint", paint);
    std::printf("%.2f paints per frame.\n", static_cast<double>(paints) / options.frames);
    const auto over = std::ranges::count_if(total, [](double ms) { return ms > kBudgetMs; });
    const Summary frames = summarise(total);
    std::printf("%s: median %.1f ms = %.0f fps; %lld of %d frames over budget.\n",
                frames.median <= kBudgetMs ? "Within budget" : "Over budget", frames.median, 1000.0 / frames.median,
                static_cast<long long>(over), options.frames);
    const Summary ph = summarise(physics);
    const Summary up = summarise(update);
    const Summary pa = summarise(paint);
    const char* largest = ph.mean >= up.mean && ph.mean >= pa.mean ? "physics" : pa.mean >= up.mean ? "paint" : "view update";
    std::printf("Largest part: %s (%.0f%% of the mean frame).\n", largest,
                100.0 * std::max({ph.mean, up.mean, pa.mean}) / frames.mean);

    // What a paint costs with each instrument, on the last state (trails as long as they got).
    std::printf("\nOne paint of the last state, median of %d, ms:\n", options.paintSamples);
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
    return 0;
}
