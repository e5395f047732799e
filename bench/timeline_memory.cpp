// The memory of a long run in the real window (issue 13, item 5): the 2000-body scene (2000
// circles in a turning box) run for five minutes of simulated time in MainWindow, with the
// timeline keeping its keyframes, the velocity arrows and the trails on and a graph open, as a
// student would leave them. Prints, every 30 simulated seconds, the process's resident memory
// (VmRSS) and its peak (VmHWM) from /proc/self/status, with what the timeline's keyframes and the
// trails hold. A program, not a test: five minutes of this scene take minutes to compute.
//
//   impetus-bench-timeline-memory [--seconds S] [--bodies N]

#include "model/example_scenes.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/graph_panel.h"
#include "view/main_window.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

namespace model = impetus::model;
namespace view = impetus::view;

/// The amount on the line of /proc/self/status that starts with `key` ("VmRSS:", given in kB),
/// MB; -1 when there is none.
double statusMb(const char* key)
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly | QIODevice::Text))
        return -1;
    // /proc files report no size, so QFile::atEnd() is true at once: read it all.
    const QByteArray wanted(key);
    for (const QByteArray& line : status.readAll().split('\n')) {
        if (line.startsWith(wanted))
            return line.mid(wanted.size()).trimmed().split(' ').front().toDouble() / 1e3;
    }
    return -1;
}

double mb(double bytes) { return bytes / 1e6; }

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    double seconds = 300;
    int bodies = 2000;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--seconds") {
            seconds = std::atof(argv[i + 1]);
        } else if (option == "--bodies") {
            bodies = std::atoi(argv[i + 1]);
        } else {
            std::fprintf(stderr, "usage: %s [--seconds S] [--bodies N]\n", argv[0]);
            return 2;
        }
    }
    if (!(seconds > 0) || bodies < 1) {
        std::fprintf(stderr, "--seconds and --bodies must be positive\n");
        return 2;
    }

    const double startMb = statusMb("VmRSS:");
    view::MainWindow window;
    window.setScene(model::makeRotatingBoxWithCircles(bodies), QStringLiteral("rotating box"));
    // The container turns, as in the engine comparison and the frame budget.
    window.runner().setStepFunction([](impetus::controller::Simulation& simulation, model::World& world) {
        model::spinFixedBodies(world, impetus::Vec2::Zero(), model::kRotatingContainerAngularVelocity);
        simulation.step(world);
    });
    window.resize(1200, 800);
    window.show();
    QApplication::processEvents();
    window.trailsAction()->trigger();
    window.canvas().instruments().setShowVector(view::VectorKind::Velocity, true);
    window.addGraph(QString(), view::GraphQuantity::Speed);
    QApplication::processEvents();
    const double windowMb = statusMb("VmRSS:");
    std::printf("%d circles in a turning box, %.0f s of simulated time in the window, arrows and trails on, "
                "one graph.\nresident: %.0f MB at start, %.0f MB with the window and the scene\n",
                bodies, seconds, startMb, windowMb);
    std::printf("%8s %10s %10s %10s %12s %10s %8s\n", "sim s", "RSS MB", "peak MB", "keyframes", "keyframes MB",
                "interval", "wall s");

    const double h = window.runner().world().settings.timeStep;
    const auto steps = static_cast<std::int64_t>(std::llround(seconds / h));
    const auto report = static_cast<std::int64_t>(std::llround(30 / h));
    constexpr int kStepsPerFrame = 4;     // a 1/60 s frame at the default step
    constexpr int kFramesPerPaint = 15;   // paint now and then: the trail layer grows with the paints
    QElapsedTimer wall;
    wall.start();
    std::int64_t done = 0;
    int frames = 0;
    while (done < steps) {
        const int batch = static_cast<int>(std::min<std::int64_t>(kStepsPerFrame, steps - done));
        window.runner().stepBy(batch);
        done += batch;
        if (++frames % kFramesPerPaint == 0)
            QApplication::processEvents();
        if (done % report == 0 || done == steps) {
            const view::Timeline& timeline = window.timeline();
            std::printf("%8.0f %10.0f %10.0f %10zu %12.1f %10lld %8.0f\n", static_cast<double>(done) * h,
                        statusMb("VmRSS:"), statusMb("VmHWM:"), timeline.keyframeCount(),
                        mb(static_cast<double>(timeline.memoryUsed())),
                        static_cast<long long>(timeline.keyframeInterval()), static_cast<double>(wall.elapsed()) / 1e3);
            std::fflush(stdout);
        }
    }
    std::printf("peak resident memory over the run: %.0f MB\n", statusMb("VmHWM:"));
    return 0;
}
