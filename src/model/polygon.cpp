#include "model/polygon.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <utility>

namespace impetus::model {

namespace {

/// A polygon has at least three vertices; this is geometry, not a tuning constant.
constexpr std::size_t kMinVertices = 3;

/// Vertex indices of one triangle of a triangulation, counter-clockwise.
using IndexTriangle = std::array<std::size_t, 3>;

/// Diagonal of the axis-aligned bounding box, m: the polygon's size, to which tolerances are relative.
Scalar boundingDiagonal(std::span<const Vec2> vertices)
{
    if (vertices.empty())
        return 0;
    Vec2 lo = vertices.front();
    Vec2 hi = vertices.front();
    for (const Vec2& v : vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    // hypot rather than norm(): a huge but finite polygon must not overflow to an infinite tolerance.
    return std::hypot(hi.x() - lo.x(), hi.y() - lo.y());
}

/// Distance below which two points of this polygon count as the same point, m.
Scalar pointTolerance(std::span<const Vec2> vertices)
{
    return constants::kRelativePointTolerance * boundingDiagonal(vertices);
}

/// Distance from point p to the segment ab, m.
Scalar pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const Scalar lengthSquared = ab.squaredNorm();
    if (lengthSquared == 0)
        return (p - a).norm();
    const Scalar t = std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

/// Relative error bound of the orientation determinant below: Shewchuk's ccwerrboundA,
/// (3 + 16ε)ε with ε = 2⁻⁵³ the unit roundoff. A derived bound, not a tuning constant.
constexpr Scalar kOrientationErrorBound =
    (3 + 16 * (std::numeric_limits<Scalar>::epsilon() / 2)) * (std::numeric_limits<Scalar>::epsilon() / 2);

/// Which side of the line a→b the point c is on: +1 left, −1 right, 0 on it or too close to tell.
/// The determinant is computed in doubles; its sign is trusted only when it is larger than its
/// worst rounding error (Shewchuk's static filter). Points on a common line otherwise come out on
/// random sides, and two collinear edges with a gap between them look like a crossing.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c)
{
    const Scalar left = (a.x() - c.x()) * (b.y() - c.y());
    const Scalar right = (a.y() - c.y()) * (b.x() - c.x());
    const Scalar det = left - right;
    const Scalar bound = kOrientationErrorBound * (std::abs(left) + std::abs(right));
    if (det > bound)
        return 1;
    if (det < -bound)
        return -1;
    return 0;
}

/// True when segments p1p2 and q1q2 cross, touch or come within `tolerance` (m) of each other.
bool segmentsTouch(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2, Scalar tolerance)
{
    // A proper crossing has each segment's endpoints certainly on opposite sides of the other's
    // line.
    if (orientation(p1, p2, q1) * orientation(p1, p2, q2) < 0 && orientation(q1, q2, p1) * orientation(q1, q2, p2) < 0)
        return true;
    // Otherwise they do not cross, or an endpoint lies on the other segment's line (to rounding)
    // and is where they meet; either way the closest approach is at one of the four endpoints.
    const Scalar gap = std::min({pointSegmentDistance(q1, p1, p2), pointSegmentDistance(q2, p1, p2),
        pointSegmentDistance(p1, q1, q2), pointSegmentDistance(p2, q1, q2)});
    return gap <= tolerance;
}

/// True when the edges a→b and b→c, which share b, overlap along a stretch (fold back on each
/// other) rather than meeting at b alone.
bool edgesFoldBack(const Vec2& a, const Vec2& b, const Vec2& c, Scalar tolerance)
{
    const Vec2 toA = a - b;
    const Vec2 toC = c - b;
    // Edges leaving b in opposite half-planes (angle ≥ 90°) cannot overlap beyond b.
    if (toA.dot(toC) <= 0)
        return false;
    // They overlap when the far end of the shorter edge lies on the longer one.
    if (toA.squaredNorm() <= toC.squaredNorm())
        return pointSegmentDistance(a, b, c) <= tolerance;
    return pointSegmentDistance(c, b, a) <= tolerance;
}

/// Area of the convex hull of the points, m² (Andrew's monotone chain). It is the largest area any
/// ordering of the points could enclose, so it is zero exactly when they all lie on one line, even
/// when the polygon's own signed area is zero for another reason (the two lobes of a bowtie cancel).
Scalar convexHullArea(std::span<const Vec2> points)
{
    std::vector<Vec2> sorted(points.begin(), points.end());
    std::sort(sorted.begin(), sorted.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    if (sorted.size() < kMinVertices)
        return 0;
    // Lower chain left to right, then upper chain right to left; a point that does not turn left
    // pops the previous one.
    std::vector<Vec2> hull;
    const auto addPoint = [&hull](const Vec2& p, std::size_t chainStart) {
        while (hull.size() >= chainStart + 2
            && cross(Vec2(hull[hull.size() - 1] - hull[hull.size() - 2]), Vec2(p - hull[hull.size() - 1])) <= 0)
            hull.pop_back();
        hull.push_back(p);
    };
    for (const Vec2& p : sorted)
        addPoint(p, 0);
    const std::size_t upperStart = hull.size() - 1;
    for (std::size_t i = sorted.size() - 1; i-- > 0;)
        addPoint(sorted[i], upperStart);
    hull.pop_back(); // the first point, reached again
    return std::abs(signedArea(hull));
}

/// How a polygon turns at a vertex b between its neighbours a and c (counter-clockwise order).
enum class Turn { Convex, Straight, Reflex };

/// Classifies vertex b by its signed distance from the line a→c: a left turn further than
/// `tolerance` (m) is convex, a right turn further than it reflex, anything closer straight.
/// Measuring a distance (not an angle or a raw cross product) makes the tolerance the same
/// length as the one that decides when two points are equal.
Turn classifyTurn(const Vec2& a, const Vec2& b, const Vec2& c, Scalar tolerance)
{
    const Vec2 chord = c - a;
    const Scalar chordLength = chord.norm();
    const Scalar twiceArea = cross(Vec2(b - a), Vec2(c - b));
    if (chordLength > 0) {
        const Scalar distance = twiceArea / chordLength;
        if (distance > tolerance)
            return Turn::Convex;
        if (distance < -tolerance)
            return Turn::Reflex;
    }
    // On the line a–c: straight only when b lies between a and c. Otherwise the boundary doubles
    // back on itself (a zero-width spike), which no convexity or ear test may treat as harmless.
    const bool between = (b - a).dot(chord) > 0 && (b - c).dot(Vec2(a - c)) > 0;
    return between ? Turn::Straight : Turn::Reflex;
}

/// The vertices counter-clockwise. A clockwise list is reversed about its first vertex, so the
/// user's vertex 0 stays first.
std::vector<Vec2> counterClockwiseCopy(std::span<const Vec2> vertices)
{
    std::vector<Vec2> out(vertices.begin(), vertices.end());
    if (signedArea(vertices) < 0 && out.size() > 1)
        std::reverse(out.begin() + 1, out.end());
    return out;
}

/// Removes every vertex that lies on the straight line between its neighbours from a
/// counter-clockwise polygon, keeping the others in their order.
std::vector<Vec2> dropStraightVertices(const std::vector<Vec2>& ccw, Scalar tolerance)
{
    const std::size_t n = ccw.size();
    if (n < kMinVertices)
        return ccw;
    const auto turnAt = [&](std::size_t prev, std::size_t i, std::size_t next) {
        return classifyTurn(ccw[prev], ccw[i], ccw[next], tolerance);
    };
    // Start the walk at a true corner: it is kept whatever happens to the others, so it can anchor
    // the run that follows it.
    std::size_t start = n;
    for (std::size_t i = 0; i < n && start == n; ++i) {
        if (turnAt((i + n - 1) % n, i, (i + 1) % n) != Turn::Straight)
            start = i;
    }
    if (start == n)
        return ccw;
    // Judge each vertex against the last vertex kept rather than its original predecessor, so a
    // whole collinear run collapses to its two ends, and a gentle curve made of tiny steps does not
    // vanish step by step (its deviation from the chord grows until a vertex is kept).
    std::vector<bool> keep(n, false);
    keep[start] = true;
    std::size_t lastKept = start;
    for (std::size_t k = 1; k < n; ++k) {
        const std::size_t i = (start + k) % n;
        if (turnAt(lastKept, i, (i + 1) % n) != Turn::Straight) {
            keep[i] = true;
            lastKept = i;
        }
    }
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < n; ++i) {
        if (keep[i])
            out.push_back(ccw[i]);
    }
    return out;
}

/// True when the counter-clockwise polygon has no reflex vertex.
bool ccwIsConvex(const std::vector<Vec2>& ccw, Scalar tolerance)
{
    const std::size_t n = ccw.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (classifyTurn(ccw[(i + n - 1) % n], ccw[i], ccw[(i + 1) % n], tolerance) == Turn::Reflex)
            return false;
    }
    return true;
}

/// The smallest signed distance (m) from p to the three edge lines of the counter-clockwise
/// triangle abc, positive inside: p is inside when it is positive, on the boundary when zero.
Scalar insideDistance(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c)
{
    const auto edgeDistance = [&p](const Vec2& from, const Vec2& to) {
        const Vec2 edge = to - from;
        const Scalar length = edge.norm();
        return length > 0 ? cross(edge, Vec2(p - from)) / length : (p - from).norm();
    };
    return std::min({edgeDistance(a, b), edgeDistance(b, c), edgeDistance(c, a)});
}

/// How strictly an ear candidate is judged.
enum class EarRule {
    /// Tip convex beyond the tolerance; no vertex inside the triangle, on its boundary (above all on
    /// the new diagonal, where a vertex would make the rest of the polygon touch itself) or within
    /// the tolerance of it. The normal rule.
    Careful,
    /// Tip convex by any amount; no vertex strictly inside. Only when no careful ear exists, which
    /// takes vertices that sit within rounding of a diagonal.
    Lenient,
};

/// Ear clipping over a counter-clockwise polygon without straight vertices. Returns n−2 triangles.
/// Each step clips the best-shaped ear (largest area over the sum of squared sides, so slivers
/// come last); ear status is cached and only the two neighbours of a clipped tip are re-judged,
/// since removing a tip changes no other candidate's triangle and only removes possible blockers.
/// O(n²) overall.
std::vector<IndexTriangle> earClip(const std::vector<Vec2>& p, Scalar tolerance)
{
    const std::size_t n = p.size();
    std::vector<IndexTriangle> triangles;
    if (n < kMinVertices)
        return triangles;
    triangles.reserve(n - 2);

    std::vector<std::size_t> prev(n);
    std::vector<std::size_t> next(n);
    std::vector<bool> alive(n, true);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }

    // Shape quality of the ear at b, or nullopt when b is not an ear under `rule`.
    const auto judgeEar = [&](std::size_t b, EarRule rule) -> std::optional<Scalar> {
        const std::size_t a = prev[b];
        const std::size_t c = next[b];
        const Vec2& pa = p[a];
        const Vec2& pb = p[b];
        const Vec2& pc = p[c];
        const Scalar twiceArea = cross(Vec2(pb - pa), Vec2(pc - pb));
        if (rule == EarRule::Careful ? classifyTurn(pa, pb, pc, tolerance) != Turn::Convex : twiceArea <= 0)
            return std::nullopt;
        for (std::size_t j = next[c]; j != a; j = next[j]) {
            const Scalar depth = insideDistance(p[j], pa, pb, pc);
            if (rule == EarRule::Careful ? depth >= -tolerance : depth > 0)
                return std::nullopt;
        }
        return twiceArea / ((pb - pa).squaredNorm() + (pc - pb).squaredNorm() + (pa - pc).squaredNorm());
    };
    const auto bestEar = [&](const std::vector<std::optional<Scalar>>& quality) -> std::optional<std::size_t> {
        std::optional<std::size_t> best;
        for (std::size_t i = 0; i < n; ++i) {
            // Strictly greater: ties go to the lowest index, which keeps the output deterministic.
            if (alive[i] && quality[i] && (!best || *quality[i] > *quality[*best]))
                best = i;
        }
        return best;
    };

    std::vector<std::optional<Scalar>> earQuality(n);
    for (std::size_t i = 0; i < n; ++i)
        earQuality[i] = judgeEar(i, EarRule::Careful);

    for (std::size_t remaining = n; remaining > kMinVertices; --remaining) {
        std::optional<std::size_t> tip = bestEar(earQuality);
        if (!tip) {
            // The cache only errs towards "not an ear"; re-judge everything before relaxing.
            for (std::size_t i = 0; i < n; ++i)
                earQuality[i] = alive[i] ? judgeEar(i, EarRule::Careful) : std::nullopt;
            tip = bestEar(earQuality);
        }
        if (!tip) {
            std::vector<std::optional<Scalar>> lenient(n);
            for (std::size_t i = 0; i < n; ++i)
                lenient[i] = alive[i] ? judgeEar(i, EarRule::Lenient) : std::nullopt;
            tip = bestEar(lenient);
        }
        if (!tip) {
            // Unreachable for a valid polygon (the two-ears theorem); still finish with n−2
            // triangles rather than loop, by clipping the most convex vertex.
            Scalar mostConvex = 0;
            for (std::size_t i = 0; i < n; ++i) {
                if (!alive[i])
                    continue;
                const Scalar turn = cross(Vec2(p[i] - p[prev[i]]), Vec2(p[next[i]] - p[i]));
                if (!tip || turn > mostConvex) {
                    tip = i;
                    mostConvex = turn;
                }
            }
        }
        const std::size_t b = *tip;
        const std::size_t a = prev[b];
        const std::size_t c = next[b];
        triangles.push_back({a, b, c});
        alive[b] = false;
        earQuality[b] = std::nullopt;
        next[a] = c;
        prev[c] = a;
        earQuality[a] = judgeEar(a, EarRule::Careful);
        earQuality[c] = judgeEar(c, EarRule::Careful);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (alive[i]) {
            triangles.push_back({i, next[i], next[next[i]]});
            break;
        }
    }
    return triangles;
}

/// Hertel–Mehlhorn over a triangulation of the counter-clockwise polygon p: each diagonal is
/// removed when the piece the two sides would form stays convex at both ends of the diagonal
/// (everywhere else each side was convex already). Returns pieces as vertex-index cycles.
std::vector<std::vector<std::size_t>> mergeConvex(
    const std::vector<Vec2>& p, const std::vector<IndexTriangle>& triangles, Scalar tolerance)
{
    const std::size_t n = p.size();
    const std::size_t triangleCount = triangles.size();

    // Which triangle holds each directed edge (ordered map: the engine uses no unordered
    // containers, so nothing can come to depend on hash order).
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> triangleOfEdge;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        for (std::size_t k = 0; k < 3; ++k)
            triangleOfEdge[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;
    }
    struct Diagonal {
        std::size_t u; ///< the diagonal runs u→v in triangle `left`
        std::size_t v;
        std::size_t left;
        std::size_t right; ///< the triangle holding v→u
    };
    // Diagonals in triangulation order: the ears clipped first are the best-shaped ones, so their
    // diagonals are tried first.
    std::vector<Diagonal> diagonals;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t u = triangles[t][k];
            const std::size_t v = triangles[t][(k + 1) % 3];
            if (v == (u + 1) % n || u == (v + 1) % n)
                continue; // a polygon edge
            const auto other = triangleOfEdge.find({v, u});
            if (other != triangleOfEdge.end() && t < other->second)
                diagonals.push_back({u, v, t, other->second});
        }
    }

    // Union–find over triangles; the piece of a set lives at its root, the set's lowest triangle.
    std::vector<std::size_t> root(triangleCount);
    std::iota(root.begin(), root.end(), std::size_t{0});
    const auto find = [&root](std::size_t t) {
        while (root[t] != t) {
            root[t] = root[root[t]];
            t = root[t];
        }
        return t;
    };
    std::vector<std::vector<std::size_t>> pieces(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t)
        pieces[t].assign(triangles[t].begin(), triangles[t].end());

    const auto positionOfEdge = [](const std::vector<std::size_t>& piece, std::size_t u, std::size_t v) {
        for (std::size_t i = 0; i < piece.size(); ++i) {
            if (piece[i] == u && piece[(i + 1) % piece.size()] == v)
                return i;
        }
        return piece.size();
    };

    for (const Diagonal& d : diagonals) {
        const std::size_t left = find(d.left);
        const std::size_t right = find(d.right);
        if (left == right)
            continue;
        const std::vector<std::size_t>& first = pieces[left];
        const std::vector<std::size_t>& second = pieces[right];
        const std::size_t iu = positionOfEdge(first, d.u, d.v);
        const std::size_t jv = positionOfEdge(second, d.v, d.u);
        if (iu == first.size() || jv == second.size())
            continue;
        // Merged cycle: the first piece from v round to u, then the second from just after u round
        // to just before v.
        std::vector<std::size_t> merged;
        merged.reserve(first.size() + second.size() - 2);
        for (std::size_t k = 1; k <= first.size(); ++k)
            merged.push_back(first[(iu + k) % first.size()]);
        for (std::size_t k = 2; k < second.size(); ++k)
            merged.push_back(second[(jv + k) % second.size()]);
        const std::size_t m = merged.size();
        const std::size_t at = first.size() - 1; // position of u; v is at 0
        if (classifyTurn(p[merged[at - 1]], p[merged[at]], p[merged[at + 1]], tolerance) == Turn::Reflex
            || classifyTurn(p[merged[m - 1]], p[merged[0]], p[merged[1]], tolerance) == Turn::Reflex)
            continue;
        const std::size_t keep = std::min(left, right);
        const std::size_t gone = std::max(left, right);
        pieces[keep] = std::move(merged);
        pieces[gone].clear();
        root[gone] = keep;
    }

    std::vector<std::vector<std::size_t>> out;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        if (find(t) == t)
            out.push_back(std::move(pieces[t]));
    }
    return out;
}

/// The vertices multiplied by the power of two that brings the largest coordinate into [1, 2).
std::vector<Vec2> scaledToUnitSize(std::span<const Vec2> vertices)
{
    Scalar largest = 0;
    for (const Vec2& v : vertices)
        largest = std::max({largest, std::abs(v.x()), std::abs(v.y())});
    std::vector<Vec2> out(vertices.begin(), vertices.end());
    if (largest == 0)
        return out;
    const int exponent = std::ilogb(largest);
    for (Vec2& v : out)
        v = Vec2(std::ldexp(v.x(), -exponent), std::ldexp(v.y(), -exponent));
    return out;
}

/// An axis-aligned box, m.
struct Bounds {
    Vec2 lo;
    Vec2 hi;
};

/// Every pair (i, j), i < j, of boxes that overlap once each is grown by `margin` on every side,
/// in increasing order of i then j. The boxes are binned in a uniform grid of about as many cells
/// as boxes, and only boxes that share a cell are compared, each pair in one cell only (the one
/// holding the corner where their overlap starts). A polygon's edges or vertices, spread along its
/// outline, then cost about n instead of the n² of trying every pair; only boxes that really
/// overlap many others (long edges across a fine zigzag) cost more.
std::vector<std::pair<std::size_t, std::size_t>> overlappingPairs(const std::vector<Bounds>& boxes, Scalar margin)
{
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    if (boxes.empty())
        return pairs;
    Vec2 lo = boxes.front().lo;
    Vec2 hi = boxes.front().hi;
    for (const Bounds& box : boxes) {
        lo = lo.cwiseMin(box.lo);
        hi = hi.cwiseMax(box.hi);
    }
    const Vec2 extent = (hi - lo).array() + 2 * margin;
    // Square cells, about one per box; at least one cell across each side.
    const Scalar cellsWanted = static_cast<Scalar>(boxes.size());
    const Scalar area = extent.x() * extent.y();
    Scalar cell = area > 0 ? std::sqrt(area / cellsWanted) : std::max(extent.x(), extent.y()) / cellsWanted;
    if (!(cell > 0))
        cell = 1;
    const auto cellsAlong = [&](Scalar length) {
        return static_cast<std::size_t>(std::clamp(std::ceil(length / cell), Scalar(1), cellsWanted));
    };
    const std::size_t columns = cellsAlong(extent.x());
    const std::size_t rows = cellsAlong(extent.y());
    const auto column = [&](Scalar x) {
        return static_cast<std::size_t>(std::clamp(std::floor((x - lo.x() + margin) / cell), Scalar(0),
                                                   static_cast<Scalar>(columns - 1)));
    };
    const auto row = [&](Scalar y) {
        return static_cast<std::size_t>(std::clamp(std::floor((y - lo.y() + margin) / cell), Scalar(0),
                                                   static_cast<Scalar>(rows - 1)));
    };

    std::vector<std::vector<std::size_t>> cells(columns * rows);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t r = row(boxes[i].lo.y() - margin); r <= row(boxes[i].hi.y() + margin); ++r) {
            for (std::size_t c = column(boxes[i].lo.x() - margin); c <= column(boxes[i].hi.x() + margin); ++c)
                cells[r * columns + c].push_back(i);
        }
    }
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < columns; ++c) {
            const std::vector<std::size_t>& members = cells[r * columns + c];
            for (std::size_t k = 0; k < members.size(); ++k) {
                const Bounds& a = boxes[members[k]];
                for (std::size_t m = k + 1; m < members.size(); ++m) {
                    const Bounds& b = boxes[members[m]];
                    if (a.lo.x() > b.hi.x() + 2 * margin || b.lo.x() > a.hi.x() + 2 * margin ||
                        a.lo.y() > b.hi.y() + 2 * margin || b.lo.y() > a.hi.y() + 2 * margin)
                        continue;
                    // The overlap starts at the larger of the two low corners; only its cell reports.
                    if (column(std::max(a.lo.x(), b.lo.x()) - margin) != c || row(std::max(a.lo.y(), b.lo.y()) - margin) != r)
                        continue;
                    pairs.push_back(std::minmax(members[k], members[m]));
                }
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

/// validatePolygon's geometric tests, on finite vertices (at least three).
std::vector<PolygonIssue> checkSimple(std::span<const Vec2> vertices)
{
    std::vector<PolygonIssue> issues;
    const std::size_t n = vertices.size();
    const Scalar tolerance = pointTolerance(vertices);
    std::vector<bool> repeatsEarlier(n, false);
    std::vector<Bounds> points;
    points.reserve(n);
    for (const Vec2& v : vertices)
        points.push_back({v, v});
    for (const auto& [i, j] : overlappingPairs(points, tolerance)) {
        if ((vertices[i] - vertices[j]).norm() <= tolerance) {
            issues.push_back({PolygonIssueKind::DuplicateVertex,
                "vertices " + std::to_string(i) + " and " + std::to_string(j) + " are the same point"});
            repeatsEarlier[j] = true;
        }
    }
    const bool hasDuplicates = !issues.empty();
    const auto distinct = static_cast<std::size_t>(std::count(repeatsEarlier.begin(), repeatsEarlier.end(), false));
    if (distinct < kMinVertices) {
        issues.push_back({PolygonIssueKind::TooFewVertices,
            "polygon needs at least " + std::to_string(kMinVertices) + " distinct vertices (got "
                + std::to_string(distinct) + ")"});
        return issues;
    }

    const Scalar diagonal = boundingDiagonal(vertices);
    const Scalar areaTolerance = constants::kRelativeAreaTolerance * diagonal * diagonal;
    // The hull, not the signed area: a bowtie's two lobes cancel to zero signed area, yet it is a
    // self-intersection, not a flat polygon. A polygon that passes the intersection test below has
    // its edges at least the point tolerance apart, so its own area cannot be negligible either.
    if (convexHullArea(vertices) <= areaTolerance) {
        // Flat vertices fold back on themselves everywhere; reporting that as intersections would
        // only say the same thing less helpfully.
        issues.push_back({PolygonIssueKind::ZeroArea, "polygon has zero area (its vertices are collinear)"});
        return issues;
    }
    // A repeated vertex makes the edges around it touch, and a zero-length edge touches both its
    // neighbours: every such contact would be reported again as an intersection.
    if (hasDuplicates)
        return issues;

    // Edges that cross, touch or come within the tolerance have boxes that overlap when grown by
    // it, so only those pairs need the exact test.
    std::vector<Bounds> edges;
    edges.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& a = vertices[i];
        const Vec2& b = vertices[(i + 1) % n];
        edges.push_back({a.cwiseMin(b), a.cwiseMax(b)});
    }
    for (const auto& [i, j] : overlappingPairs(edges, tolerance)) {
        bool intersects = false;
        if (j == i + 1) {
            intersects = edgesFoldBack(vertices[i], vertices[j], vertices[(j + 1) % n], tolerance);
        } else if (i == 0 && j == n - 1) {
            intersects = edgesFoldBack(vertices[n - 1], vertices[0], vertices[1], tolerance);
        } else {
            intersects = segmentsTouch(vertices[i], vertices[i + 1], vertices[j], vertices[(j + 1) % n], tolerance);
        }
        if (intersects) {
            issues.push_back({PolygonIssueKind::SelfIntersection,
                "polygon self-intersects (edges " + std::to_string(i) + " and " + std::to_string(j) + ")"});
        }
    }
    return issues;
}

} // namespace

std::vector<PolygonIssue> validatePolygon(std::span<const Vec2> vertices)
{
    std::vector<PolygonIssue> issues;
    const std::size_t n = vertices.size();
    if (n < kMinVertices) {
        issues.push_back({PolygonIssueKind::TooFewVertices,
            "polygon needs at least " + std::to_string(kMinVertices) + " vertices (got " + std::to_string(n) + ")"});
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!isFinite(vertices[i]))
            issues.push_back(
                {PolygonIssueKind::NonFiniteVertex, "vertex " + std::to_string(i) + " is not a finite number"});
    }
    // Every later test measures distances and areas, meaningless with NaNs or too few points.
    if (!issues.empty())
        return issues;
    // The tests below square lengths: for a polygon 1e160 m across they overflow (a triangle was
    // called collinear), for one 1e-200 m across they underflow (its vertices were "the same
    // point"). Judging a copy scaled by a power of two to about unit size gives the same answers
    // the tests give at a classroom scale, since such a scaling is exact in binary floating point.
    const std::vector<Vec2> unitScaled = scaledToUnitSize(vertices);
    return checkSimple(unitScaled);
}

Scalar signedArea(std::span<const Vec2> vertices)
{
    if (vertices.empty())
        return 0;
    // Shoelace about the first vertex instead of the origin: the same sum, but the products stay
    // the size of the polygon, so a shape far from the origin loses no digits to cancellation.
    const Vec2 origin = vertices.front();
    Scalar twiceArea = 0;
    for (std::size_t i = 1; i + 1 < vertices.size(); ++i)
        twiceArea += cross(Vec2(vertices[i] - origin), Vec2(vertices[i + 1] - origin));
    return twiceArea / 2;
}

std::vector<Vec2> normalizedCounterClockwise(std::span<const Vec2> vertices)
{
    return dropStraightVertices(counterClockwiseCopy(vertices), pointTolerance(vertices));
}

bool isConvex(std::span<const Vec2> vertices)
{
    // Fewer than three points, or no area, have no orientation to be convex with respect to.
    if (vertices.size() < kMinVertices || signedArea(vertices) == 0)
        return false;
    const std::vector<Vec2> ccw = counterClockwiseCopy(vertices);
    if (!ccwIsConvex(ccw, pointTolerance(vertices)))
        return false;
    // Turning left everywhere is not enough: a pentagram does, but winds round twice. The exterior
    // angles of a closed polygon add up to a whole number of turns, 2π·k; one turn means convex.
    const std::size_t n = ccw.size();
    Scalar turning = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 in = ccw[i] - ccw[(i + n - 1) % n];
        const Vec2 out = ccw[(i + 1) % n] - ccw[i];
        turning += std::atan2(cross(in, out), in.dot(out));
    }
    // 3π lies halfway between one turn and two, so rounding cannot tip the decision.
    return turning < 3 * std::numbers::pi_v<Scalar>;
}

std::vector<Triangle> triangulate(std::span<const Vec2> vertices)
{
    const std::vector<Vec2> polygon = normalizedCounterClockwise(vertices);
    std::vector<Triangle> out;
    for (const IndexTriangle& t : earClip(polygon, pointTolerance(vertices)))
        out.push_back({polygon[t[0]], polygon[t[1]], polygon[t[2]]});
    return out;
}

std::vector<std::vector<Vec2>> decomposeConvex(std::span<const Vec2> vertices)
{
    const Scalar tolerance = pointTolerance(vertices);
    std::vector<Vec2> polygon = normalizedCounterClockwise(vertices);
    if (polygon.size() < kMinVertices)
        return {};
    // A convex polygon is its own decomposition; returning it as is also keeps its vertex order.
    if (ccwIsConvex(polygon, tolerance))
        return {std::move(polygon)};

    std::vector<std::vector<Vec2>> out;
    for (std::vector<std::size_t>& piece : mergeConvex(polygon, earClip(polygon, tolerance), tolerance)) {
        // Start each piece at its lowest polygon vertex, so pieces read in the polygon's own order.
        std::rotate(piece.begin(), std::min_element(piece.begin(), piece.end()), piece.end());
        std::vector<Vec2> points;
        points.reserve(piece.size());
        for (const std::size_t i : piece)
            points.push_back(polygon[i]);
        // A merge may leave a vertex at exactly 180° (two half-angles at a reflex vertex that add
        // up to a straight line). Convex shape code expects strictly convex corners, so drop it;
        // the neighbouring piece keeps that vertex, which only makes a T-junction between pieces.
        out.push_back(dropStraightVertices(points, tolerance));
    }
    return out;
}

} // namespace impetus::model
