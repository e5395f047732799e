#include "view/canvas_instruments.h"

#include "view/number_text.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <QPolygonF>
#include <QVector>

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <cmath>
#include <iterator>
#include <vector>

namespace impetus::view {

namespace {

/// An arrow's head takes at most this fraction of a short arrow, so that the shaft still shows.
constexpr double kMaxHeadFraction = 0.6;
/// The legend's sample arrows are this many head lengths long.
constexpr double kSwatchHeads = 3;
/// Trail points closer than this to the last point drawn are left out of the line, px.
constexpr double kTrailMinSegmentPx = 1.0;
/// The legend's paper: white, slightly see-through so the grid shows it is an overlay.
const QColor kLegendFill(255, 255, 255, 225);

QPointF toPoint(const Vec2& v) { return QPointF(v.x(), v.y()); }

/// |a − b|², px²: trails compare millions of distances a paint, with no square root needed.
double squaredDistance(const QPointF& a, const QPointF& b)
{
    const QPointF d = a - b;
    return QPointF::dotProduct(d, d);
}

/// Arrows collected by colour and drawn together: per colour one stroke call for the solid
/// shafts, one for the dashed (clipped) ones, and one fill for all the heads, instead of a pen, a
/// line, a brush and a polygon per arrow. With 2000 bodies' velocity arrows that was the largest
/// part of a paint after the bodies and trails (docs/benchmarks.md, "The frame budget").
class ArrowBatch {
public:
    /// Arrows drawn `scale` times their normal width and head (projector mode's thick lines).
    explicit ArrowBatch(double scale = 1) : m_scale(scale) {}

    /// An arrow from `from` to `to` (px) with a filled head, in `color`. Shorter than kMinArrowPx
    /// it is left out; longer than kMaxArrowPx it is cut there and drawn dashed.
    void add(QPointF from, QPointF to, const QColor& color)
    {
        QLineF line(from, to);
        const double length = line.length();
        if (length < constants::kMinArrowPx)
            return;
        bool clipped = false;
        if (length > constants::kMaxArrowPx) {
            line.setLength(constants::kMaxArrowPx);
            to = line.p2();
            clipped = true;
        }
        const double head = std::min(m_scale * constants::kArrowHeadPx, kMaxHeadFraction * line.length());
        const QPointF unit = (to - from) / line.length();
        const QPointF normal(-unit.y(), unit.x());
        const QPointF base = to - head * unit;
        Group& group = groupOf(color);
        (clipped ? group.dashed : group.solid).append(QLineF(from, base));
        group.heads.append(to);
        group.heads.append(base + 0.5 * head * normal);
        group.heads.append(base - 0.5 * head * normal);
    }

    /// Draws every arrow added, colour by colour in the order first added.
    void paint(QPainter& painter) const
    {
        for (const Group& group : m_groups) {
            painter.setBrush(Qt::NoBrush);
            if (!group.solid.isEmpty()) {
                painter.setPen(QPen(group.color, m_scale * constants::kArrowWidthPx, Qt::SolidLine, Qt::FlatCap));
                painter.drawLines(group.solid);
            }
            if (!group.dashed.isEmpty()) {
                painter.setPen(QPen(group.color, m_scale * constants::kArrowWidthPx, Qt::DashLine, Qt::FlatCap));
                painter.drawLines(group.dashed);
            }
            // Each head filled on its own: the 2000 heads of the large example as one path
            // with the winding rule took 40 ms to fill (the rasteriser works on the whole
            // canvas's edges at once), one small triangle at a time 3 ms.
            painter.setPen(Qt::NoPen);
            painter.setBrush(group.color);
            for (qsizetype i = 0; i + 2 < group.heads.size(); i += 3)
                painter.drawConvexPolygon(group.heads.constData() + i, 3);
        }
    }

private:
    struct Group {
        QColor color;
        QVector<QLineF> solid;
        QVector<QLineF> dashed;
        QVector<QPointF> heads; ///< each head's tip, left and right corner, one after another
    };

    Group& groupOf(const QColor& color)
    {
        // A handful of colours at most (one per kind of vector and force part): a linear search.
        const auto found = std::find_if(m_groups.begin(), m_groups.end(), [&](const Group& g) { return g.color == color; });
        if (found != m_groups.end())
            return *found;
        Group& group = m_groups.emplace_back();
        group.color = color;
        return group;
    }

    double m_scale = 1;
    std::vector<Group> m_groups;
};

/// The unit of each kind, as the legend writes it.
QString unitOf(VectorKind kind)
{
    switch (kind) {
    case VectorKind::Velocity:
        return CanvasInstruments::tr("m/s");
    case VectorKind::Acceleration:
        return CanvasInstruments::tr("m/s²");
    case VectorKind::NetForce:
    case VectorKind::ForceParts:
        return CanvasInstruments::tr("N");
    case VectorKind::Momentum:
        return CanvasInstruments::tr("kg·m/s");
    }
    return {};
}

/// One force part as the legend and the arrows show it.
struct ForcePart {
    QString name;
    QColor color;
    Vec2 controller::BodyForces::* member;
};

std::array<ForcePart, 6> forceParts()
{
    return {{
        {CanvasInstruments::tr("gravity"), constants::kGravityColor, &controller::BodyForces::gravity},
        {CanvasInstruments::tr("springs"), constants::kSpringForceColor, &controller::BodyForces::springs},
        {CanvasInstruments::tr("drag"), constants::kDragForceColor, &controller::BodyForces::drag},
        {CanvasInstruments::tr("contact normal"), constants::kContactNormalColor, &controller::BodyForces::contactNormal},
        {CanvasInstruments::tr("friction"), constants::kFrictionColor, &controller::BodyForces::contactFriction},
        {CanvasInstruments::tr("joints"), constants::kJointForceColor, &controller::BodyForces::joints},
    }};
}

} // namespace

CanvasInstruments::CanvasInstruments(const SimulationRunner& runner, QObject* parent)
    : QObject(parent)
    , m_runner(runner)
    , m_dotSteps(constants::kDefaultTrailDotSteps)
{
    m_scales[index(VectorKind::Velocity)] = constants::kDefaultVelocityScale;
    m_scales[index(VectorKind::Acceleration)] = constants::kDefaultAccelerationScale;
    m_scales[index(VectorKind::NetForce)] = constants::kDefaultForceScale;
    m_scales[index(VectorKind::ForceParts)] = constants::kDefaultForceScale;
    m_scales[index(VectorKind::Momentum)] = constants::kDefaultMomentumScale;
}

void CanvasInstruments::setShowVector(VectorKind kind, bool on)
{
    if (m_shown[index(kind)] == on)
        return;
    m_shown[index(kind)] = on;
    refresh();
}

bool CanvasInstruments::showsAnyVector() const
{
    return std::ranges::any_of(m_shown, [](bool on) { return on; }) || !m_bodyShown.empty();
}

bool CanvasInstruments::showsBodyVector(const std::string& name, VectorKind kind) const
{
    const auto it = m_bodyShown.find(name);
    return it != m_bodyShown.end() && it->second[index(kind)];
}

void CanvasInstruments::setBodyVector(const std::string& name, VectorKind kind, bool on)
{
    if (showsBodyVector(name, kind) == on)
        return;
    std::array<bool, kVectorKindCount>& kinds = m_bodyShown[name];
    kinds[index(kind)] = on;
    // An entry only for bodies that ask for something: painting skips the look-ups when none do.
    if (std::ranges::none_of(kinds, [](bool shown) { return shown; }))
        m_bodyShown.erase(name);
    refresh();
}

bool CanvasInstruments::drawsVector(std::size_t body, VectorKind kind) const
{
    if (m_shown[index(kind)] && drawsBody(body))
        return true;
    const model::World& world = m_runner.world();
    return !m_bodyShown.empty() && body < world.bodies.size() && showsBodyVector(world.bodies[body].name, kind);
}

bool CanvasInstruments::drawsKindAnywhere(VectorKind kind) const
{
    return m_shown[index(kind)] ||
           std::ranges::any_of(m_bodyShown, [kind](const auto& entry) { return entry.second[index(kind)]; });
}

double CanvasInstruments::vectorScale(VectorKind kind) const
{
    // The parts and the net force are compared with each other: one scale for both.
    if (kind == VectorKind::ForceParts)
        kind = VectorKind::NetForce;
    return m_scales[index(kind)];
}

void CanvasInstruments::scaleArrows(double factor)
{
    if (!(factor > 0) || !std::isfinite(factor))
        return;
    for (double& scale : m_scales)
        scale *= factor;
    emit changed();
}

void CanvasInstruments::setLineScale(double scale)
{
    if (scale == m_lineScale)
        return;
    m_lineScale = scale;
    invalidateTrailPictures();
    emit changed();
}

void CanvasInstruments::setSelectedOnly(bool on)
{
    m_selectedOnly = on;
    invalidateTrailPictures();
    emit changed();
}

void CanvasInstruments::setSelection(const Selection& selection)
{
    m_selection = selection;
    if (m_selectedOnly) {
        invalidateTrailPictures();
        emit changed();
    }
}

void CanvasInstruments::setShowTrails(bool on)
{
    if (m_trails == on)
        return;
    m_trails = on;
    m_trailPoints.clear();
    invalidateTrailPictures();
    if (on)
        startTrails();
    emit samplingChanged();
    emit changed();
}

void CanvasInstruments::setTrailDotSteps(int steps)
{
    m_dotSteps = std::max(1, steps);
    invalidateTrailPictures();
    emit changed();
}

const std::deque<TrailPoint>& CanvasInstruments::trail(std::size_t body) const
{
    static const std::deque<TrailPoint> kNone;
    return body < m_trailPoints.size() ? m_trailPoints[body] : kNone;
}

void CanvasInstruments::startTrails()
{
    followBodies();
    const model::World& world = m_runner.world();
    m_trailPoints.assign(world.bodies.size(), {});
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        m_trailPoints[i].push_back({world.stepCount, toPoint(world.bodies[i].state.position)});
    invalidateTrailPictures();
}

void CanvasInstruments::followBodies()
{
    const model::World& world = m_runner.world();
    const bool same = m_bodyNames.size() == world.bodies.size() &&
                      std::equal(m_bodyNames.begin(), m_bodyNames.end(), world.bodies.begin(),
                                 [](const std::string& name, const model::Body& body) { return name == body.name; });
    if (same)
        return;
    std::unordered_map<std::string, std::uint32_t> indexOf;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i)
        indexOf.emplace(world.bodies[i].name, i);
    // A rename: as many bodies as before, each with the same kind of shape at its index, all but
    // one under the same name, and that one's new name not there before. That body keeps its paths
    // (an edit of its name in the pane is no reason to lose them). Otherwise a new name is a new
    // body: a Reset that brings back a deleted wheel where a box was drawn since must not hand it
    // the box's trail.
    const std::unordered_set<std::string> oldNames(m_bodyNames.begin(), m_bodyNames.end());
    std::optional<std::size_t> renamed;
    if (m_bodyNames.size() == world.bodies.size() && m_bodyShapeKinds.size() == world.bodies.size()) {
        std::size_t changed = 0;
        bool sameShapes = true;
        for (std::size_t i = 0; i < m_bodyNames.size(); ++i) {
            sameShapes = sameShapes && m_bodyShapeKinds[i] == world.bodies[i].shape.index();
            if (m_bodyNames[i] != world.bodies[i].name) {
                ++changed;
                renamed = i;
            }
        }
        if (changed != 1 || !sameShapes || oldNames.contains(world.bodies[*renamed].name))
            renamed.reset();
    }
    const auto newIndex = [&](std::size_t oldIndex) -> std::optional<std::uint32_t> {
        if (oldIndex >= m_bodyNames.size())
            return std::nullopt;
        const auto it = indexOf.find(m_bodyNames[oldIndex]);
        if (it != indexOf.end())
            return it->second;
        if (renamed == oldIndex)
            return static_cast<std::uint32_t>(oldIndex);
        return std::nullopt;
    };
    // A renamed body keeps the arrows it asked for, which are kept by name.
    if (renamed) {
        const auto shown = m_bodyShown.find(m_bodyNames[*renamed]);
        if (shown != m_bodyShown.end()) {
            const std::array<bool, kVectorKindCount> kinds = shown->second;
            m_bodyShown.erase(shown);
            m_bodyShown[world.bodies[*renamed].name] = kinds;
        }
    }
    if (m_trails) {
        std::vector<std::deque<TrailPoint>> moved(world.bodies.size());
        for (std::size_t i = 0; i < m_trailPoints.size(); ++i) {
            if (const std::optional<std::uint32_t> to = newIndex(i))
                moved[*to] = std::move(m_trailPoints[i]);
        }
        for (std::size_t i = 0; i < moved.size(); ++i) {
            if (moved[i].empty())
                moved[i].push_back({world.stepCount, toPoint(world.bodies[i].state.position)});
        }
        m_trailPoints = std::move(moved);
        invalidateTrailPictures();
    }
    const bool traced = !m_traced.empty();
    std::erase_if(m_traced, [&](TracedPoint& point) {
        const std::optional<std::uint32_t> to = newIndex(point.body);
        if (to)
            point.body = *to;
        return !to;
    });
    m_bodyNames.clear();
    m_bodyShapeKinds.clear();
    for (const model::Body& body : world.bodies) {
        m_bodyNames.push_back(body.name);
        m_bodyShapeKinds.push_back(body.shape.index());
    }
    if (traced && m_traced.empty() && !m_trails)
        emit samplingChanged();
}

void CanvasInstruments::invalidateTrailPictures()
{
    ++m_trailRevision;
    m_trimmedSinceRevision = 0;
    m_trailCursors.clear();
}

void CanvasInstruments::addSamples(const std::vector<StepSample>& samples)
{
    // Traced points share a cap as the trails do (kMaxTrailPointsInAll among them all).
    const std::size_t mostTraced =
        std::min(constants::kMaxTrailPoints, constants::kMaxTrailPointsInAll / std::max<std::size_t>(1, m_traced.size()));
    for (TracedPoint& traced : m_traced) {
        for (const StepSample& sample : samples) {
            // Recorded before a body came or went (another scene), or along a run already recorded.
            if (sample.centres.size() != m_bodyNames.size() || sample.angles.size() != m_bodyNames.size() ||
                traced.body >= m_bodyNames.size() || (!traced.trail.empty() && traced.trail.back().step >= sample.step))
                continue;
            const Vec2 at = sample.centres[traced.body] + rotate(traced.local, sample.angles[traced.body]);
            traced.trail.push_back({sample.step, toPoint(at)});
            if (traced.trail.size() > mostTraced)
                traced.trail.pop_front();
        }
    }
    if (!m_trails)
        return;
    const std::size_t most =
        std::min(constants::kMaxTrailPoints, constants::kMaxTrailPointsInAll / std::max<std::size_t>(1, m_trailPoints.size()));
    for (const StepSample& sample : samples) {
        if (sample.centres.size() != m_trailPoints.size())
            continue; // recorded before a body came or went: it belongs to another scene
        bool dropped = false; // some trail lost its oldest point to this step
        for (std::size_t i = 0; i < sample.centres.size(); ++i) {
            std::deque<TrailPoint>& points = m_trailPoints[i];
            // Steps along a run that is already recorded (Step after scrubbing back) add nothing.
            if (!points.empty() && points.back().step >= sample.step)
                continue;
            points.push_back({sample.step, toPoint(sample.centres[i])});
            if (points.size() > most) {
                points.pop_front();
                dropped = true;
            }
        }
        if (dropped)
            ++m_trimmedSinceRevision;
    }
    // A picture that still shows the dropped points is repainted whole only now and then
    // (constants::kTrailTrimRedrawFraction): the trails shown run a little long in between.
    if (static_cast<double>(m_trimmedSinceRevision) > constants::kTrailTrimRedrawFraction * static_cast<double>(most))
        invalidateTrailPictures();
}

void CanvasInstruments::discardAfter(std::int64_t step)
{
    for (std::deque<TrailPoint>& points : m_trailPoints) {
        while (!points.empty() && points.back().step > step)
            points.pop_back();
    }
    for (TracedPoint& traced : m_traced) {
        while (!traced.trail.empty() && traced.trail.back().step > step)
            traced.trail.pop_back();
    }
    invalidateTrailPictures();
    emit changed();
}

void CanvasInstruments::refresh()
{
    const model::World& world = m_runner.world();
    if (m_trails || !m_traced.empty() || !m_bodyShown.empty())
        followBodies(); // a body came, went or was renamed: the others keep their paths and arrows
    const bool forces = drawsKindAnywhere(VectorKind::Acceleration) || drawsKindAnywhere(VectorKind::NetForce) ||
                        drawsKindAnywhere(VectorKind::ForceParts);
    if (forces)
        m_forces = controller::reportForces(world);
    else
        m_forces.clear();
    emit changed();
}

void CanvasInstruments::clear()
{
    clearTracedPoints();
    m_bodyShown.clear();
    m_trailPoints.clear();
    invalidateTrailPictures();
    if (m_trails)
        startTrails();
    m_selection = {};
    refresh();
}

bool CanvasInstruments::drawsBody(std::size_t i) const
{
    return !m_selectedOnly || std::ranges::find(m_selection.bodies, static_cast<int>(i)) != m_selection.bodies.end();
}

void CanvasInstruments::paintTrails(QPainter& painter)
{
    m_trailCursors.assign(m_trailPoints.size(), TrailCursor{});
    paintTrailGrowth(painter);
}

void CanvasInstruments::paintTrailGrowth(QPainter& painter)
{
    if (!m_trails)
        return;
    if (m_trailCursors.size() != m_trailPoints.size())
        m_trailCursors.assign(m_trailPoints.size(), TrailCursor{});
    const model::World& world = m_runner.world();
    const QTransform toPixels = painter.worldTransform();
    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    for (std::size_t i = 0; i < m_trailPoints.size() && i < world.bodies.size(); ++i) {
        if (world.bodies[i].fixed || !drawsBody(i))
            continue;
        drawTrail(painter, toPixels, i, m_trailCursors[i]);
    }
    painter.restore();
}

void CanvasInstruments::drawTrail(QPainter& painter, const QTransform& toPixels, std::size_t i, TrailCursor& cursor)
{
    const model::World& world = m_runner.world();
    const std::int64_t shown = world.stepCount;
    const std::deque<TrailPoint>& points = m_trailPoints[i];
    // The points not drawn yet: only the newest few while running, so look from the back.
    auto from = points.end();
    while (from != points.begin() && std::prev(from)->step > cursor.lastStep)
        --from;
    if (from == points.end() || from->step > shown)
        return;
    QPolygonF& line = m_lineBuffer;
    std::vector<QPointF>& dots = m_dotBuffer;
    line.clear();
    dots.clear();
    if (cursor.hasLine)
        line << cursor.lineEnd;
    QPointF skipped; // the last point left out of the line, px
    bool pending = false;
    const double dotRadius = m_lineScale * constants::kTrailDotRadiusPx;
    for (auto it = from; it != points.end(); ++it) {
        const TrailPoint& point = *it;
        if (point.step > shown)
            break; // scrubbed back: the trail ends where the body is
        cursor.lastStep = point.step;
        const QPointF px = toPixels.map(point.position);
        // A point within a pixel of the last one drawn adds nothing to see and costs a joint
        // to stroke: a body at rest would pile up thousands in one place.
        if (!line.isEmpty() && squaredDistance(line.back(), px) < kTrailMinSegmentPx * kTrailMinSegmentPx) {
            skipped = px;
            pending = true;
        } else {
            line << px;
            pending = false;
        }
        // A dot that would overlap the last one drawn adds nothing: a body at rest would
        // stack a dot every 0.1 s on one spot.
        const QPointF* lastDot = !dots.empty() ? &dots.back() : cursor.hasDot ? &cursor.lastDot : nullptr;
        if (point.step % m_dotSteps == 0 &&
            (!lastDot || squaredDistance(*lastDot, px) >= 4 * dotRadius * dotRadius))
            dots.push_back(px);
    }
    // A whole trail is drawn even as a single point, as it always was; growth only when it grew.
    const qsizetype carried = cursor.hasLine ? 1 : 0;
    if (!line.isEmpty()) {
        cursor.hasLine = true;
        cursor.lineEnd = line.back();
    }
    if (!dots.empty()) {
        cursor.hasDot = true;
        cursor.lastDot = dots.back();
    }
    if (pending)
        line << skipped; // the trail still ends at the body
    const model::Color c = world.bodies[i].color;
    const QColor colour(c.r, c.g, c.b, constants::kTrailAlpha);
    if (line.size() > carried) {
        // One pixel whatever the look: a wider line leaves Qt's fast path (a 30,000-point path
        // took 3.7 ms at 1 px, 234 ms at 1.5 px); projector mode makes the dots larger instead.
        painter.setPen(QPen(colour, constants::kTrailWidthPx));
        painter.setBrush(Qt::NoBrush);
        painter.drawPolyline(line);
    }
    if (!dots.empty()) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(colour.darker());
        for (const QPointF& dot : dots)
            painter.drawEllipse(dot, dotRadius, dotRadius);
    }
}

void CanvasInstruments::setTracedPoint(std::uint32_t body, const Vec2& local)
{
    const model::World& world = m_runner.world();
    if (body >= world.bodies.size())
        return;
    followBodies();
    const bool sampling = m_traced.empty();
    std::erase_if(m_traced, [&](const TracedPoint& traced) { return traced.body == body; });
    TracedPoint& traced = m_traced.emplace_back();
    traced.body = body;
    traced.local = local;
    traced.trail.push_back({world.stepCount, toPoint(worldPoint(body, local))});
    if (sampling && !m_trails)
        emit samplingChanged();
    emit changed();
}

bool CanvasInstruments::clearTracedPoint(std::uint32_t body)
{
    if (std::erase_if(m_traced, [&](const TracedPoint& traced) { return traced.body == body; }) == 0)
        return false;
    if (m_traced.empty() && !m_trails)
        emit samplingChanged();
    emit changed();
    return true;
}

void CanvasInstruments::clearTracedPoints()
{
    if (m_traced.empty())
        return;
    m_traced.clear();
    if (!m_trails)
        emit samplingChanged();
    emit changed();
}

Vec2 CanvasInstruments::worldPoint(std::uint32_t body, const Vec2& local) const
{
    const model::BodyState& state = m_runner.world().bodies.at(body).state;
    return state.position + rotate(local, state.angle);
}

void CanvasInstruments::paintTracedPoints(QPainter& painter)
{
    const model::World& world = m_runner.world();
    if (m_traced.empty() || m_bodyNames.size() != world.bodies.size())
        return;
    const QTransform toPixels = painter.worldTransform();
    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    const double dotRadius = m_lineScale * constants::kTrailDotRadiusPx;
    for (const TracedPoint& traced : m_traced) {
        // As a trail: points within a pixel of the last one left out, a dot every trailDotSteps()
        // steps that does not overlap the last, and nothing after the step shown (a scrub back).
        QPolygonF& line = m_lineBuffer;
        std::vector<QPointF>& dots = m_dotBuffer;
        line.clear();
        dots.clear();
        for (const TrailPoint& point : traced.trail) {
            if (point.step > world.stepCount)
                break;
            const QPointF px = toPixels.map(point.position);
            if (line.isEmpty() || squaredDistance(line.back(), px) >= kTrailMinSegmentPx * kTrailMinSegmentPx)
                line << px;
            if (point.step % m_dotSteps == 0 &&
                (dots.empty() || squaredDistance(dots.back(), px) >= 4 * dotRadius * dotRadius))
                dots.push_back(px);
        }
        const QPointF now = toPixels.map(toPoint(worldPoint(traced.body, traced.local)));
        line << now;
        // One pixel, as a trail (drawn afresh every paint: a wider line would cost a hundred times
        // more on a long path); the dots and the ring grow in projector mode.
        painter.setPen(QPen(constants::kTracedPointColor, constants::kTracedPointWidthPx));
        painter.setBrush(Qt::NoBrush);
        painter.drawPolyline(line);
        painter.setPen(Qt::NoPen);
        painter.setBrush(constants::kTracedPointColor.darker());
        for (const QPointF& dot : dots)
            painter.drawEllipse(dot, dotRadius, dotRadius);
        // The point itself: a ring, so that the body under it still shows.
        painter.setPen(QPen(constants::kTracedPointColor, m_lineScale * constants::kTracedPointWidthPx));
        painter.setBrush(Qt::NoBrush);
        const double ring = m_lineScale * constants::kTracedPointRingPx;
        painter.drawEllipse(now, ring, ring);
    }
    painter.restore();
}

void CanvasInstruments::paintVectors(QPainter& painter) const
{
    if (!showsAnyVector())
        return;
    const model::World& world = m_runner.world();
    const QTransform toPixels = painter.worldTransform();
    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    ArrowBatch arrows(m_lineScale);
    const auto arrow = [&](const Vec2& at, const Vec2& value, VectorKind kind, const QColor& color) {
        const Vec2 tip = at + vectorScale(kind) * value;
        arrows.add(toPixels.map(toPoint(at)), toPixels.map(toPoint(tip)), color);
    };
    const bool forces = m_forces.size() == world.bodies.size();
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (body.fixed)
            continue;
        const Vec2 at = body.state.position;
        if (forces && drawsVector(i, VectorKind::ForceParts)) {
            for (const ForcePart& part : forceParts())
                arrow(at, m_forces[i].*part.member, VectorKind::ForceParts, part.color);
        }
        if (forces && drawsVector(i, VectorKind::NetForce))
            arrow(at, m_forces[i].net(), VectorKind::NetForce, constants::kNetForceColor);
        if (forces && drawsVector(i, VectorKind::Acceleration))
            arrow(at, m_forces[i].acceleration, VectorKind::Acceleration, constants::kAccelerationColor);
        if (drawsVector(i, VectorKind::Momentum))
            arrow(at, body.mass * body.state.velocity, VectorKind::Momentum, constants::kMomentumColor);
        if (drawsVector(i, VectorKind::Velocity))
            arrow(at, body.state.velocity, VectorKind::Velocity, constants::kVelocityColor);
    }
    arrows.paint(painter);
    painter.restore();
}

QStringList CanvasInstruments::legendLines() const
{
    QStringList lines;
    const auto scaleText = [&](VectorKind kind) {
        return tr("1 %1 = %2 m").arg(unitOf(kind), localeNumber(vectorScale(kind), 'g', 3));
    };
    if (drawsKindAnywhere(VectorKind::Velocity))
        lines << tr("velocity: %1").arg(scaleText(VectorKind::Velocity));
    if (drawsKindAnywhere(VectorKind::Acceleration))
        lines << tr("acceleration: %1").arg(scaleText(VectorKind::Acceleration));
    if (drawsKindAnywhere(VectorKind::NetForce))
        lines << tr("net force: %1").arg(scaleText(VectorKind::NetForce));
    if (drawsKindAnywhere(VectorKind::ForceParts)) {
        for (const ForcePart& part : forceParts())
            lines << tr("%1: %2").arg(part.name, scaleText(VectorKind::ForceParts));
    }
    if (drawsKindAnywhere(VectorKind::Momentum))
        lines << tr("momentum: %1").arg(scaleText(VectorKind::Momentum));
    return lines;
}

void CanvasInstruments::paintLegend(QPainter& painter, const QRectF& viewport) const
{
    const QStringList lines = legendLines();
    if (lines.isEmpty())
        return;
    std::vector<QColor> colours;
    if (drawsKindAnywhere(VectorKind::Velocity))
        colours.push_back(constants::kVelocityColor);
    if (drawsKindAnywhere(VectorKind::Acceleration))
        colours.push_back(constants::kAccelerationColor);
    if (drawsKindAnywhere(VectorKind::NetForce))
        colours.push_back(constants::kNetForceColor);
    if (drawsKindAnywhere(VectorKind::ForceParts)) {
        for (const ForcePart& part : forceParts())
            colours.push_back(part.color);
    }
    if (drawsKindAnywhere(VectorKind::Momentum))
        colours.push_back(constants::kMomentumColor);

    painter.save();
    painter.resetTransform();
    painter.setRenderHint(QPainter::Antialiasing);
    const QFontMetricsF metrics(painter.font());
    const double pad = constants::kLegendPaddingPx;
    const double swatch = kSwatchHeads * m_lineScale * constants::kArrowHeadPx;
    double width = 0;
    for (const QString& line : lines)
        width = std::max(width, metrics.horizontalAdvance(line));
    const double lineHeight = metrics.height();
    const QRectF box(viewport.left() + constants::kLegendMarginPx, viewport.top() + constants::kLegendMarginPx,
                     width + swatch + 3 * pad, lineHeight * static_cast<double>(lines.size()) + 2 * pad);
    painter.setPen(QPen(constants::kMinorGridColor.darker(), 1));
    painter.setBrush(kLegendFill);
    painter.drawRect(box);
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const double y = box.top() + pad + lineHeight * (static_cast<double>(i) + 0.5);
        ArrowBatch sample(m_lineScale);
        sample.add(QPointF(box.left() + pad, y), QPointF(box.left() + pad + swatch, y), colours[static_cast<std::size_t>(i)]);
        sample.paint(painter);
        painter.setPen(constants::kMeasureColor);
        painter.drawText(QPointF(box.left() + 2 * pad + swatch, y + metrics.ascent() / 2 - metrics.descent() / 2),
                         lines[i]);
    }
    painter.restore();
}

} // namespace impetus::view
