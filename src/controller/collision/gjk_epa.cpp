// Contact between any two convex shapes through their support functions: GJK for the distance when
// they are apart, EPA for the penetration when they overlap, then a 1-D refinement of the normal.
//
// Both GJK and EPA work on the Minkowski difference D = A − B, whose support point along d is
// S(d) = supportA(d) − supportB(−d). The signed distance between A and B is the maximum over unit
// directions n (from A to B) of the separation along n,
//     g(n) = n·supportB(−n) − n·supportA(n) = −n·S(n),
// positive when apart (the distance) and negative when overlapping (minus the penetration depth);
// GJK and EPA find that maximum from outside and inside D respectively.

#include "controller/collision/narrow_phase.h"

#include "model/constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

namespace impetus::controller {

namespace {

/// A shape's support mapping, in coordinates relative to `origin`. Working near the shapes rather
/// than near the world origin keeps the subtractions in g(n) from losing digits when a scene is
/// built far from (0, 0).
class Support {
public:
    Support(const ConvexShape& shape, const Vec2& origin) : m_shape(shape), m_origin(origin) {}

    /// The point of the shape farthest along `direction` (any length), relative to the origin, m.
    /// Ties between polygon vertices go to the lower index, for determinism.
    Vec2 operator()(const Vec2& direction) const
    {
        if (const auto* polygon = std::get_if<PolygonShape>(&m_shape)) {
            std::size_t best = 0;
            Scalar bestDot = -std::numeric_limits<Scalar>::infinity();
            for (std::size_t i = 0; i < polygon->vertices.size(); ++i) {
                const Scalar d = direction.dot(polygon->vertices[i]);
                if (d > bestDot) {
                    bestDot = d;
                    best = i;
                }
            }
            return polygon->vertices[best] - m_origin;
        }
        const Scalar length = direction.norm();
        // A zero or non-finite direction has no farthest point; the centre keeps everything finite.
        const bool usable = length > 0 && std::isfinite(length);
        if (const auto* circle = std::get_if<CircleShape>(&m_shape))
            return usable ? Vec2(circle->center - m_origin + circle->radius / length * direction)
                          : Vec2(circle->center - m_origin);
        const auto& e = std::get<EllipseShape>(m_shape);
        if (!usable)
            return e.center - m_origin;
        // In the ellipse's frame, x²/a² + y²/b² = 1 is farthest along d' where its normal
        // (x/a², y/b²) is parallel to d': x = a²d'x/k, y = b²d'y/k with k = √(a²d'x² + b²d'y²).
        const Vec2 d = direction / length;
        const Scalar dx = e.c * d.x() + e.s * d.y();
        const Scalar dy = -e.s * d.x() + e.c * d.y();
        const Scalar qx = e.radiusX * e.radiusX * dx;
        const Scalar qy = e.radiusY * e.radiusY * dy;
        const Scalar k = std::sqrt(qx * dx + qy * dy);
        if (!(k > 0))
            return e.center - m_origin;
        const Scalar px = qx / k;
        const Scalar py = qy / k;
        return Vec2(e.center.x() - m_origin.x() + e.c * px - e.s * py,
                    e.center.y() - m_origin.y() + e.s * px + e.c * py);
    }

    /// True for circles and ellipses, whose support point is unique in every direction.
    bool curved() const { return !std::holds_alternative<PolygonShape>(m_shape); }

    /// True for a polygon without vertices, which has no support point at all.
    bool empty() const
    {
        const auto* polygon = std::get_if<PolygonShape>(&m_shape);
        return polygon != nullptr && polygon->vertices.empty();
    }

    /// The largest distance from the origin to a point of the shape, m: the length scale of the
    /// GJK/EPA tolerances.
    Scalar extent() const
    {
        if (const auto* polygon = std::get_if<PolygonShape>(&m_shape)) {
            Scalar r = 0;
            for (const Vec2& v : polygon->vertices)
                r = std::max(r, (v - m_origin).norm());
            return r;
        }
        if (const auto* circle = std::get_if<CircleShape>(&m_shape))
            return (circle->center - m_origin).norm() + circle->radius;
        const auto& e = std::get<EllipseShape>(m_shape);
        return (e.center - m_origin).norm() + std::max(e.radiusX, e.radiusY);
    }

    /// The part of a polygon's boundary farthest along the unit direction `n`: one vertex, or a
    /// whole edge when an edge is perpendicular to n within kParallelAngleTolerance. Relative to
    /// the origin. Only called for polygons.
    std::array<Vec2, 2> polygonFeature(const Vec2& n) const
    {
        const auto& polygon = std::get<PolygonShape>(m_shape);
        const std::size_t count = polygon.vertices.size();
        std::size_t best = 0;
        for (std::size_t i = 1; i < count; ++i)
            if (n.dot(polygon.vertices[i]) > n.dot(polygon.vertices[best]))
                best = i;
        const Vec2& v = polygon.vertices[best];
        for (const std::size_t other : {best + 1 == count ? 0 : best + 1, best == 0 ? count - 1 : best - 1}) {
            const Vec2 edge = polygon.vertices[other] - v;
            if (other != best && std::abs(n.dot(edge)) <= constants::kParallelAngleTolerance * edge.norm())
                return {v - m_origin, polygon.vertices[other] - m_origin};
        }
        return {v - m_origin, v - m_origin};
    }

private:
    const ConvexShape& m_shape;
    Vec2 m_origin;
};

/// The two supports together: the Minkowski difference D = A − B and the separation along a normal.
class Pair {
public:
    Pair(const Support& a, const Support& b) : m_a(a), m_b(b) {}

    /// S(d), the point of D farthest along d.
    Vec2 difference(const Vec2& d) const { return m_a(d) - m_b(-d); }

    /// g(n) = n·(supportB(−n) − supportA(n)), m: the gap between the shapes along the unit normal n.
    Scalar separation(const Vec2& n) const { return -n.dot(difference(n)); }

private:
    const Support& m_a;
    const Support& m_b;
};

/// The closest point to the origin of segment pq, and which ends it depends on.
struct SegmentClosest {
    Vec2 point;
    bool usesP;
    bool usesQ;
};

SegmentClosest closestOnSegment(const Vec2& p, const Vec2& q)
{
    const Vec2 e = q - p;
    const Scalar ee = e.dot(e);
    const Scalar t = ee > 0 ? -p.dot(e) / ee : 0;
    if (t <= 0)
        return {p, true, false};
    if (t >= 1)
        return {q, false, true};
    return {p + t * e, true, true};
}

/// GJK's simplex: up to three points of D.
struct Simplex {
    std::array<Vec2, 3> points{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()}; // Eigen leaves Vec2() unset
    int count = 0;

    const Vec2& operator[](int i) const { return points[static_cast<std::size_t>(i)]; }
    void add(const Vec2& w) { points[static_cast<std::size_t>(count++)] = w; }
};

/// Replaces the simplex by the sub-simplex nearest the origin and returns the nearest point, or
/// sets `containsOrigin` when the origin lies inside a (non-degenerate) triangle.
Vec2 reduceSimplex(Simplex& simplex, bool& containsOrigin)
{
    containsOrigin = false;
    if (simplex.count == 1)
        return simplex[0];
    if (simplex.count == 2) {
        const SegmentClosest c = closestOnSegment(simplex[0], simplex[1]);
        if (!c.usesP || !c.usesQ) {
            const Vec2 kept = c.usesP ? simplex[0] : simplex[1];
            simplex = Simplex{};
            simplex.add(kept);
        }
        return c.point;
    }
    const Vec2 p = simplex[0];
    const Vec2 q = simplex[1];
    const Vec2 r = simplex[2];
    const Scalar area2 = cross(q - p, r - p);
    if (area2 != 0) {
        // Inside when the origin is on the inner side of all three edges (sign of the winding).
        const Scalar sign = area2 > 0 ? 1.0 : -1.0;
        if (sign * cross(q - p, -p) >= 0 && sign * cross(r - q, -q) >= 0 && sign * cross(p - r, -r) >= 0) {
            containsOrigin = true;
            return Vec2::Zero();
        }
    }
    // Outside (or a flat triangle): the nearest of the three edges. In 2D this is as cheap as the
    // Voronoi-region bookkeeping and plainly correct.
    const std::array<std::array<Vec2, 2>, 3> edges{{{p, q}, {q, r}, {r, p}}};
    std::size_t best = 0;
    SegmentClosest bestClosest = closestOnSegment(p, q);
    for (std::size_t i = 1; i < 3; ++i) {
        const SegmentClosest c = closestOnSegment(edges[i][0], edges[i][1]);
        if (c.point.squaredNorm() < bestClosest.point.squaredNorm()) {
            best = i;
            bestClosest = c;
        }
    }
    Simplex reduced;
    if (bestClosest.usesP)
        reduced.add(edges[best][0]);
    if (bestClosest.usesQ)
        reduced.add(edges[best][1]);
    simplex = reduced;
    return bestClosest.point;
}

enum class GjkOutcome {
    Apart, ///< `normal` is the direction of closest approach
    BeyondMargin, ///< proven farther apart than the speculative distance
    Overlapping, ///< the origin is in D (or within the tolerance of it); `simplex` seeds EPA
};

struct GjkResult {
    GjkOutcome outcome = GjkOutcome::Apart;
    Vec2 normal = Vec2(0, 1);
    Simplex simplex;
};

GjkResult gjk(const Pair& pair, const Vec2& initialDirection, Scalar speculativeDistance, Scalar tolerance)
{
    GjkResult result;
    result.simplex.add(pair.difference(initialDirection));
    Vec2 v = result.simplex[0];
    for (int iteration = 0; iteration < constants::kGjkMaxIterations; ++iteration) {
        const Scalar vv = v.squaredNorm();
        if (vv <= tolerance * tolerance) {
            result.outcome = GjkOutcome::Overlapping;
            return result;
        }
        const Scalar length = std::sqrt(vv);
        result.normal = -v / length;
        const Vec2 w = pair.difference(-v);
        // Every point x of D has v·x ≥ v·w, so v·w/|v| is a lower bound on the distance.
        const Scalar lowerBound = v.dot(w) / length;
        if (lowerBound > speculativeDistance) {
            result.outcome = GjkOutcome::BeyondMargin;
            return result;
        }
        if (length - lowerBound <= tolerance) // upper and lower bounds agree
            return result;
        result.simplex.add(w);
        bool containsOrigin = false;
        const Vec2 next = reduceSimplex(result.simplex, containsOrigin);
        if (containsOrigin) {
            result.outcome = GjkOutcome::Overlapping;
            return result;
        }
        if (next.squaredNorm() >= vv) // no progress: rounding has the last word
            return result;
        v = next;
    }
    if (v.squaredNorm() <= tolerance * tolerance)
        result.outcome = GjkOutcome::Overlapping;
    else
        result.normal = -v.normalized();
    return result;
}

/// EPA's starting polygon: counter-clockwise points of D around the origin, grown from GJK's
/// simplex when GJK stopped on a point or a segment through the origin (shapes just touching).
/// Returns fewer than 3 points when D itself is flat (both shapes degenerate and aligned).
std::vector<Vec2> initialPolytope(const Pair& pair, const Simplex& simplex, Scalar tolerance)
{
    std::vector<Vec2> points(simplex.points.begin(), simplex.points.begin() + simplex.count);
    if (points.size() == 3) {
        const Scalar area2 = cross(points[1] - points[0], points[2] - points[0]);
        if (std::abs(area2) > tolerance * tolerance) {
            if (area2 < 0)
                std::swap(points[1], points[2]);
            return points;
        }
        // Flat: keep the two points farthest apart.
        std::size_t drop = 0;
        Scalar longest = -1;
        for (std::size_t i = 0; i < 3; ++i) {
            const Scalar l = (points[(i + 1) % 3] - points[(i + 2) % 3]).squaredNorm();
            if (l > longest) {
                longest = l;
                drop = i;
            }
        }
        points.erase(points.begin() + static_cast<std::ptrdiff_t>(drop));
    }
    if (points.size() == 1) {
        for (const Vec2& d : {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)}) {
            const Vec2 w = pair.difference(d);
            if ((w - points[0]).norm() > tolerance) {
                points.push_back(w);
                break;
            }
        }
        if (points.size() == 1)
            return points;
    }
    // A segment p→q with the origin on or near it: add D's extreme points on either side.
    const Vec2 p = points[0];
    const Vec2 q = points[1];
    const Vec2 left = Vec2(-(q - p).y(), (q - p).x()).normalized();
    const Vec2 wLeft = pair.difference(left);
    const Vec2 wRight = pair.difference(-left);
    std::vector<Vec2> polygon{p};
    if (-left.dot(wRight - p) > tolerance)
        polygon.push_back(wRight);
    polygon.push_back(q);
    if (left.dot(wLeft - p) > tolerance)
        polygon.push_back(wLeft);
    return polygon;
}

/// EPA: grows a polygon inside D towards D's boundary nearest the origin. Returns the outward
/// normal of the nearest edge, which is the contact normal from A to B.
Vec2 epa(const Pair& pair, const Simplex& simplex, Scalar tolerance)
{
    std::vector<Vec2> polygon = initialPolytope(pair, simplex, tolerance);
    if (polygon.size() < 2)
        return Vec2(0, 1); // D is a point: every normal is as good, pick a fixed one
    if (polygon.size() == 2) {
        // D is a segment through the origin: its perpendicular is the only sensible normal.
        const Vec2 e = polygon[1] - polygon[0];
        return Vec2(e.y(), -e.x()).normalized();
    }
    Vec2 bestNormal(0, 1);
    for (int iteration = 0; iteration < constants::kEpaMaxIterations; ++iteration) {
        std::size_t bestEdge = polygon.size();
        Scalar bestDistance = std::numeric_limits<Scalar>::infinity();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const Vec2 e = polygon[i + 1 == polygon.size() ? 0 : i + 1] - polygon[i];
            const Scalar length = e.norm();
            if (!(length > 0))
                continue;
            const Vec2 n(e.y() / length, -e.x() / length); // outward for a CCW polygon
            const Scalar distance = n.dot(polygon[i]);
            if (distance < bestDistance) {
                bestDistance = distance;
                bestEdge = i;
                bestNormal = n;
            }
        }
        if (bestEdge == polygon.size())
            break;
        const Vec2 w = pair.difference(bestNormal);
        // Stop when D reaches no farther than this edge along its normal: the edge is on D's
        // boundary (exactly for polygons, within the tolerance for curves).
        if (bestNormal.dot(w) - bestDistance <= tolerance)
            break;
        polygon.insert(polygon.begin() + static_cast<std::ptrdiff_t>(bestEdge + 1), w);
    }
    return bestNormal;
}

/// Refines the normal to the maximum of g near `normal`. GJK and EPA bound the distance to within
/// their tolerance, but on a curved surface the normal (and so the contact point) is then only
/// known to the square root of it. The slope of g along the angle φ of n is
///     g'(φ) = t·(supportB(−n) − supportA(n)),  t = dn/dφ,
/// because the support points move along the surfaces, perpendicular to n. So the maximum is the
/// sign change of that slope from + to −, found by bisection. Bisecting on the slope, rather than
/// comparing values of g, keeps full precision: g is flat at its maximum and its values stop
/// telling neighbouring angles apart near √ε, its slope does not. At a polygon face the slope
/// jumps through zero and bisection lands on the face normal. The answer is kept only when g is
/// no worse (within `tolerance`) than at the starting normal, so meeting a second maximum in the
/// bracket can never make things worse.
Vec2 refineNormal(const Pair& pair, const Support& a, const Support& b, const Vec2& normal, Scalar tolerance)
{
    const auto direction = [](Scalar angle) { return Vec2(std::cos(angle), std::sin(angle)); };
    const auto slope = [&](Scalar angle) {
        const Vec2 n = direction(angle);
        return Vec2(-n.y(), n.x()).dot(b(-n) - a(n));
    };
    const Scalar centre = std::atan2(normal.y(), normal.x());
    Scalar lo = centre - constants::kContactNormalSearchHalfAngle;
    Scalar hi = centre + constants::kContactNormalSearchHalfAngle;
    if (!(slope(lo) > 0 && slope(hi) < 0)) // no maximum bracketed: keep GJK/EPA's answer
        return normal;
    for (int iteration = 0;
         iteration < constants::kContactNormalSearchMaxIterations && hi - lo > constants::kContactNormalSearchTolerance;
         ++iteration) {
        const Scalar mid = 0.5 * (lo + hi);
        const Scalar s = slope(mid);
        if (s > 0)
            lo = mid;
        else if (s < 0)
            hi = mid;
        else
            lo = hi = mid;
    }
    const Vec2 refined = direction(0.5 * (lo + hi));
    return pair.separation(refined) + tolerance >= pair.separation(normal) ? refined : normal;
}

/// The contact point between two polygons touching along `normal`, relative to the origin: the
/// middle of the overlap of their extreme features (vertex or edge) along the tangent, midway
/// between the surfaces along the normal.
Vec2 polygonPairPoint(const Support& a, const Support& b, const Vec2& normal)
{
    const std::array<Vec2, 2> featureA = a.polygonFeature(normal);
    const std::array<Vec2, 2> featureB = b.polygonFeature(-normal);
    const Vec2 tangent(-normal.y(), normal.x());
    // std::minmax of two values returns references to them, which must outlive the pair: the
    // initializer-list form returns copies.
    const auto [minA, maxA] = std::minmax({tangent.dot(featureA[0]), tangent.dot(featureA[1])});
    const auto [minB, maxB] = std::minmax({tangent.dot(featureB[0]), tangent.dot(featureB[1])});
    // With no overlap (vertex against vertex, apart) this is the middle of the gap between them.
    const Scalar along = 0.5 * (std::max(minA, minB) + std::min(maxA, maxB));
    const Scalar across = 0.5 * (normal.dot(featureA[0]) + normal.dot(featureB[0]));
    return along * tangent + across * normal;
}

/// A reference point of the shape: the centre, or a vertex of a polygon.
Vec2 anchor(const ConvexShape& shape)
{
    if (const auto* polygon = std::get_if<PolygonShape>(&shape))
        return polygon->vertices.empty() ? Vec2(Vec2::Zero()) : polygon->vertices[0];
    if (const auto* circle = std::get_if<CircleShape>(&shape))
        return circle->center;
    return std::get<EllipseShape>(shape).center;
}

} // namespace

Manifold collideConvexGeneral(const ConvexShape& a, const ConvexShape& b, Scalar speculativeDistance)
{
    const Vec2 origin = anchor(a);
    const Support supportA(a, origin);
    const Support supportB(b, origin);
    if (supportA.empty() || supportB.empty() || !isFinite(origin))
        return {};
    const Pair pair(supportA, supportB);

    const Scalar scale = std::max(supportA.extent(), supportB.extent());
    if (!std::isfinite(scale))
        return {};
    const Scalar tolerance = constants::kGjkEpaRelativeTolerance * std::max(scale, std::numeric_limits<Scalar>::min());

    // Start from the direction in which D is expected to face the origin: from A towards B.
    Vec2 start = anchor(b) - origin;
    if (!(start.squaredNorm() > 0))
        start = Vec2(1, 0);
    const GjkResult g = gjk(pair, start, speculativeDistance, tolerance);
    if (g.outcome == GjkOutcome::BeyondMargin)
        return {};
    Vec2 normal = g.outcome == GjkOutcome::Apart ? g.normal : epa(pair, g.simplex, tolerance);
    if (supportA.curved() || supportB.curved())
        normal = refineNormal(pair, supportA, supportB, normal, tolerance);
    if (!isFinite(normal))
        return {};

    const Vec2 pointA = supportA(normal);
    const Vec2 pointB = supportB(-normal);
    const Scalar separation = normal.dot(pointB - pointA);
    if (!std::isfinite(separation) || separation > speculativeDistance)
        return {};
    // The contact point comes from a curved surface when there is one: its support point is
    // unique, whereas a polygon's may be any point of a face.
    Vec2 point;
    if (supportB.curved())
        point = pointB - 0.5 * separation * normal;
    else if (supportA.curved())
        point = pointA + 0.5 * separation * normal;
    else
        point = polygonPairPoint(supportA, supportB, normal);

    Manifold m;
    m.normal = normal;
    m.points[0] = {point + origin, separation, 0};
    m.count = 1;
    return m;
}

} // namespace impetus::controller
