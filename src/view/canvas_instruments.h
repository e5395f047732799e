#pragma once
/// \file canvas_instruments.h
/// What the canvas draws over the bodies to measure them: vector arrows (velocity, acceleration,
/// forces, momentum) with their legend, and trails of the bodies' centres of mass.

#include "controller/force_report.h"
#include "model/world.h"
#include "view/selection.h"
#include "view/step_sample.h"

#include <QColor>
#include <QCoreApplication>
#include <QObject>
#include <QPolygonF>
#include <QRectF>
#include <QString>

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

class QPainter;

namespace impetus::view {

class SimulationRunner;

/// The quantities drawn as arrows from a body's centre of mass.
enum class VectorKind : std::uint8_t {
    Velocity, ///< v, m/s
    Acceleration, ///< a = F/m, m/s²
    NetForce, ///< ΣF, N
    ForceParts, ///< gravity, springs, drag, contact normal and friction, joints, each its own arrow, N
    Momentum, ///< p = m·v, kg·m/s
};
inline constexpr std::size_t kVectorKindCount = 5;

/// One point of a trail: where a body's centre of mass was after a step.
struct TrailPoint {
    std::int64_t step = 0; ///< World::stepCount
    QPointF position; ///< m
};

/// A point fixed on a body, whose path is drawn as a trail of its own (the Trace Point tool): a
/// wheel's rim point draws a cycloid where its centre draws a line.
struct TracedPoint {
    std::uint32_t body = 0; ///< index into World::bodies
    Vec2 local = Vec2::Zero(); ///< the point in the body's frame (from its centre of mass, unturned), m
    std::deque<TrailPoint> trail; ///< where it was after each step, oldest first
};

/// The canvas's measuring overlays for one SimulationRunner's world.
///
/// Arrows: each kind shown (setShowVector(), the View menu) is drawn for every dynamic body (or only
/// the selected ones, see setSelectedOnly()), and each kind a body asks for (setBodyVector(), the
/// attribute pane) for that body as well, from its centre of mass, with a length of value × scale metres on the
/// canvas, so that they grow and shrink with the zoom like the bodies; their width and heads stay
/// the same on screen, and an arrow shorter than constants::kMinArrowPx is left out. Forces come
/// from the engine (controller::reportForces), computed once per state shown. A legend in the
/// top-left corner gives each kind's colour and scale ("velocity: 1 m/s = 0.25 m").
///
/// Trails: with trails on, the runner records every body's centre after every step; each body's
/// trail is the line through them, with a dot every trailDotSteps() steps (steps that are
/// multiples of it), up to the step shown: scrubbing back shortens the trail, and the timeline's
/// futureDiscarded() forgets what follows.
class CanvasInstruments : public QObject {
    Q_OBJECT

public:
    /// Instruments for `runner`'s world; the runner outlives them.
    explicit CanvasInstruments(const SimulationRunner& runner, QObject* parent = nullptr);

    bool showsVector(VectorKind kind) const { return m_shown[index(kind)]; }
    void setShowVector(VectorKind kind, bool on);
    /// True when any vector kind is shown, for every body or for some.
    bool showsAnyVector() const;

    /// Whether body `name` shows arrows of `kind` whatever setShowVector() says (false by default).
    /// Kept by name, so that it survives other bodies coming and going; a new scene forgets it.
    bool showsBodyVector(const std::string& name, VectorKind kind) const;
    void setBodyVector(const std::string& name, VectorKind kind, bool on);
    /// True when body i of the world shown gets arrows of `kind` (shown for all or for it).
    bool drawsVector(std::size_t body, VectorKind kind) const;

    /// Metres of arrow per unit of `kind` (m per m/s, per m/s², per N, per kg·m/s); force parts
    /// share the net force's scale.
    double vectorScale(VectorKind kind) const;
    /// Multiplies every kind's scale by `factor` (> 0): longer or shorter arrows.
    void scaleArrows(double factor);

    /// Arrows, their legend's samples, trails and trail dots drawn `scale` times their normal width
    /// (CanvasLook::lineScale: projector mode's thick lines).
    void setLineScale(double scale);
    double lineScale() const { return m_lineScale; }

    /// Draws arrows and trails for the selected bodies only (true) or for every body (false).
    bool selectedOnly() const { return m_selectedOnly; }
    void setSelectedOnly(bool on);
    /// The selection, for selectedOnly().
    void setSelection(const Selection& selection);

    bool showsTrails() const { return m_trails; }
    /// Turns trails on (starting from the bodies' centres now) or off (forgetting them).
    void setShowTrails(bool on);
    /// Steps between the dots of a trail (constants::kDefaultTrailDotSteps), ≥ 1.
    int trailDotSteps() const { return m_dotSteps; }
    void setTrailDotSteps(int steps);
    /// Body i's trail, oldest first (empty when trails are off or i is out of range).
    const std::deque<TrailPoint>& trail(std::size_t body) const;

    /// Traces the point `local` (in the body's frame, m) of body `body`: its path is drawn from
    /// where it is now, with dots as the trails have, whether trails are on or not. A body has one
    /// traced point at most: a new one replaces the old. Not an edit (as trails are not); a new
    /// scene, or a body added or deleted, forgets every traced point.
    void setTracedPoint(std::uint32_t body, const Vec2& local);
    /// Stops tracing body `body`'s point; false when it had none.
    bool clearTracedPoint(std::uint32_t body);
    /// Stops tracing every point.
    void clearTracedPoints();
    /// The traced points, in the order they were set.
    const std::vector<TracedPoint>& tracedPoints() const { return m_traced; }
    /// Where body `body`'s point `local` is in the world shown now, m.
    Vec2 worldPoint(std::uint32_t body, const Vec2& local) const;
    /// Paints the traced points' paths and a ring on each point; `painter` is in scene coordinates.
    void paintTracedPoints(QPainter& painter);

    /// What the trails and traced points need recorded after each step.
    bool needsCentres() const { return m_trails || !m_traced.empty(); }

    /// The forces of the state shown (empty when no force or acceleration arrow is shown).
    const std::vector<controller::BodyForces>& forces() const { return m_forces; }

    /// Paints the trails whole; `painter` is in scene coordinates (m, y up). Remembers how far
    /// each trail was drawn, for paintTrailGrowth().
    void paintTrails(QPainter& painter);
    /// Paints only what the trails gained since the last paintTrails() or paintTrailGrowth(), onto
    /// a picture that already holds what those drew (the canvas's cached layer, canvas_view.h);
    /// `painter` is in scene coordinates with the same transform as then. Each trail goes on from
    /// the last point it drew, with the same thinning of points and dots as a whole paint, so
    /// the picture differs from a whole paint only where segments cross: a whole paint lays body
    /// i's trail over body j's for i > j, growth lays newer segments over older ones.
    void paintTrailGrowth(QPainter& painter);
    /// Changes whenever the trails stop being what was drawn plus growth: trails turned on or
    /// off, cleared or cut back, their dots or their bodies changed, or their oldest points
    /// dropped by more than constants::kTrailTrimRedrawFraction of a trail's length since the
    /// last change. A picture drawn at an older revision must be painted whole again.
    std::uint64_t trailRevision() const { return m_trailRevision; }
    /// Paints the arrows; `painter` is in scene coordinates.
    void paintVectors(QPainter& painter) const;
    /// Paints the legend into the viewport rectangle `viewport` (px); the painter's transform is
    /// reset for it.
    void paintLegend(QPainter& painter, const QRectF& viewport) const;

    /// The legend's lines, as painted (for tests and the accessibility description).
    QStringList legendLines() const;

public slots:
    /// Takes a batch's samples into the trails.
    void addSamples(const std::vector<StepSample>& samples);
    /// Forgets trail points after `step` (the timeline's futureDiscarded()).
    void discardAfter(std::int64_t step);
    /// Follows the world after a step or an edit: recomputes the forces when they are shown.
    void refresh();
    /// A new scene: forgets the trails.
    void clear();

signals:
    /// Something drawn changed: repaint.
    void changed();
    /// needsCentres() changed.
    void samplingChanged();

private:
    static std::size_t index(VectorKind kind) { return static_cast<std::size_t>(kind); }
    /// True when body i gets arrows and a trail.
    bool drawsBody(std::size_t i) const;
    /// Starts every body's trail at its centre now.
    void startTrails();
    /// When bodies came or went (or were renamed) since the trails and traced points were last
    /// told of them: each body keeps its trail and its traced points under its name at its new
    /// index, a new body's trail starts where it is, and a gone body's are dropped.
    void followBodies();
    /// True when `kind` is drawn for some body.
    bool drawsKindAnywhere(VectorKind kind) const;
    /// How far one trail has been drawn: where its line and its dots stopped, px.
    struct TrailCursor {
        std::int64_t lastStep = -1; ///< step of the last point taken; -1: nothing drawn yet
        bool hasLine = false;
        QPointF lineEnd; ///< the last point kept in the line (a point skipped after it is not)
        bool hasDot = false;
        QPointF lastDot;
    };
    /// Draws body i's trail points after `cursor` into `painter` (pixels, identity transform)
    /// mapped by `toPixels`, and moves the cursor on; a default cursor draws the whole trail.
    void drawTrail(QPainter& painter, const QTransform& toPixels, std::size_t i, TrailCursor& cursor);
    /// A new trail revision: what was drawn no longer holds.
    void invalidateTrailPictures();

    const SimulationRunner& m_runner;
    std::array<bool, kVectorKindCount> m_shown{};
    /// The kinds each body asks for on its own, by body name; bodies asking for none are absent.
    std::map<std::string, std::array<bool, kVectorKindCount>> m_bodyShown;
    std::array<double, kVectorKindCount> m_scales{};
    bool m_selectedOnly = false;
    double m_lineScale = 1; ///< × the normal widths of arrows and trails
    Selection m_selection;
    bool m_trails = false;
    int m_dotSteps;
    std::vector<std::deque<TrailPoint>> m_trailPoints;
    std::vector<TrailCursor> m_trailCursors; ///< per body: how far the last paint drew its trail
    std::uint64_t m_trailRevision = 0;
    /// Steps since the last revision in which some trail dropped its oldest point: about the
    /// points the longest trail dropped.
    std::size_t m_trimmedSinceRevision = 0;
    /// Reused by drawTrail(), so that painting allocates nothing once they have grown.
    QPolygonF m_lineBuffer;
    std::vector<QPointF> m_dotBuffer;
    std::vector<controller::BodyForces> m_forces;
    std::vector<TracedPoint> m_traced;
    /// The names of the world's bodies, in order, as m_trailPoints and m_traced index them.
    std::vector<std::string> m_bodyNames;
    /// The kinds of the bodies' shapes (circle, ellipse, box, polygon: the variant's index) when
    /// m_bodyNames was taken: a body renamed keeps its kind.
    std::vector<std::size_t> m_bodyShapeKinds;
};

} // namespace impetus::view
