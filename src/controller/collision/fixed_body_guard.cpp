// The fixed-body guard: no centre of a moving body passes into a fixed body (fixed_body_guard.h).

#include "controller/collision/fixed_body_guard.h"

#include "controller/transform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

namespace impetus::controller {

namespace {

/// How far outside the surface a centre that was put back is left, m: a hair, so that the next
/// substep does not find it inside (rounding) and leave it there.
constexpr Scalar kBackOff = 1e-6;

/// Where the segment p(t) = from + t·d, t in [0, 1], first enters the convex polygon `piece`
/// (counter-clockwise, with outward edge normals `normals`): Cyrus–Beck clipping. Negative when
/// `from` is inside or on the piece, or the segment misses it.
Scalar convexEntry(const std::vector<Vec2>& piece, const std::vector<Vec2>& normals, const Vec2& from, const Vec2& d)
{
    Scalar enter = 0;
    Scalar exit = 1;
    bool outside = false;
    for (std::size_t i = 0; i < piece.size(); ++i) {
        // Inside the edge's half plane where n·(p − v) ≤ 0.
        const Scalar a = normals[i].dot(from - piece[i]);
        const Scalar b = normals[i].dot(d);
        if (a > 0)
            outside = true;
        if (b == 0) {
            if (a > 0)
                return -1; // parallel to the edge, on its outer side
            continue;
        }
        const Scalar t = -a / b;
        if (b < 0)
            enter = std::max(enter, t);
        else
            exit = std::min(exit, t);
        if (enter > exit)
            return -1;
    }
    return outside ? enter : -1;
}

/// True when `p` lies in the convex polygon `piece` or on its edge.
bool insideConvex(const std::vector<Vec2>& piece, const std::vector<Vec2>& normals, const Vec2& p)
{
    for (std::size_t i = 0; i < piece.size(); ++i) {
        if (normals[i].dot(p - piece[i]) > 0)
            return false;
    }
    return true;
}

/// Where the segment from + t·d, t in [0, 1], first enters the unit disc; negative when `from`
/// is inside or on it, or the segment misses it.
Scalar unitDiscEntry(const Vec2& from, const Vec2& d)
{
    const Scalar c = from.squaredNorm() - 1;
    if (!(c > 0))
        return -1;
    const Scalar a = d.squaredNorm();
    const Scalar b = from.dot(d); // half the linear coefficient
    const Scalar discriminant = b * b - a * c;
    if (a == 0 || discriminant < 0 || b >= 0)
        return -1; // standing still, passing by, or moving away
    // The smaller root of a·t² + 2b·t + c = 0, written without cancellation (b < 0): c / (−b + √D).
    const Scalar t = c / (-b + std::sqrt(discriminant));
    return t <= 1 ? t : -1;
}

/// Up to this many fixed bodies, each path is tested against each; beyond, the broad phase pairs
/// them.
constexpr std::size_t kFewFixedBodies = 16;

/// How many bodies ahead keepOut's walk over the bodies asks for their lines.
constexpr std::size_t kBodyPrefetchAhead = 8;

/// A pose with finite numbers: a path with a NaN in it is no path (and the step's NaN check names
/// the body; the guard must not hide it, nor spread it to the bodies it would put back).
bool finite(const model::BodyState& state) { return state.position.allFinite() && std::isfinite(state.angle); }

/// The box around a body's shape at pose `pose`, m.
Aabb boxAt(const model::Body& body, const Transform& pose)
{
    return std::visit(
        [&](const auto& shape) -> Aabb {
            using S = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<S, model::Circle>) {
                return Aabb{pose.position - Vec2::Constant(shape.radius), pose.position + Vec2::Constant(shape.radius)};
            } else if constexpr (std::is_same_v<S, model::Ellipse>) {
                // The extent of R·diag(a, b)·(cos u, sin u) along x and y.
                const Vec2 half(std::hypot(shape.radiusX * pose.c, shape.radiusY * pose.s),
                                std::hypot(shape.radiusX * pose.s, shape.radiusY * pose.c));
                return Aabb{pose.position - half, pose.position + half};
            } else {
                Aabb box{Vec2::Constant(std::numeric_limits<Scalar>::infinity()),
                         Vec2::Constant(-std::numeric_limits<Scalar>::infinity())};
                for (const Vec2& v : body.geometry.outline) {
                    const Vec2 w = pose.apply(v);
                    box.lower = box.lower.cwiseMin(w);
                    box.upper = box.upper.cwiseMax(w);
                }
                return box;
            }
        },
        body.shape);
}

} // namespace

namespace detail {

Scalar pathEntry(const model::Body& body, const Vec2& from, const Vec2& to)
{
    const Vec2 d = to - from;
    return std::visit(
        [&](const auto& shape) -> Scalar {
            using S = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<S, model::Circle>) {
                return unitDiscEntry(from / shape.radius, d / shape.radius);
            } else if constexpr (std::is_same_v<S, model::Ellipse>) {
                const Vec2 scale(1 / shape.radiusX, 1 / shape.radiusY);
                return unitDiscEntry(from.cwiseProduct(scale), d.cwiseProduct(scale));
            } else {
                // A concave polygon's pieces share edges: a centre in one piece on its way into
                // the next is inside the body already. So a path that starts in any piece is left
                // alone, and otherwise the first piece it enters counts.
                const model::BodyGeometry& g = body.geometry;
                for (std::size_t k = 0; k < g.convexPieces.size(); ++k) {
                    if (insideConvex(g.convexPieces[k], g.pieceNormals[k], from))
                        return -1;
                }
                Scalar first = std::numeric_limits<Scalar>::infinity();
                for (std::size_t k = 0; k < g.convexPieces.size(); ++k) {
                    const Scalar t = convexEntry(g.convexPieces[k], g.pieceNormals[k], from, d);
                    if (t >= 0)
                        first = std::min(first, t);
                }
                return first <= 1 ? first : -1;
            }
        },
        body.shape);
}

} // namespace detail

int FixedBodyGuard::keepOut(const model::World& world, std::span<const model::BodyState> start,
                            std::span<model::BodyState> end)
{
    m_proxies.clear();
    m_fixedPoses.clear();
    // The broad phase never pairs two proxies it is told are fixed. Here the paths are marked
    // fixed and the fixed bodies not, so that it pairs each path with the fixed bodies it may
    // meet and never with another path (a pile's thousands of neighbours); the few pairs of fixed
    // bodies that touch (a box's walls at its corners) are skipped below.
    m_paths.clear();
    // Each path's box is padded by its body's size, which the guard needs not but the broad
    // phase's cache does: a box of a body at rest is a point, and a point's fat box (a fraction of
    // its size larger) holds nothing that moves.
    const auto pathBox = [&](std::size_t entry, Scalar pad) {
        const Vec2& a = start[entry].position;
        const Vec2& b = end[entry].position;
        return Aabb{a.cwiseMin(b) - Vec2::Constant(pad), a.cwiseMax(b) + Vec2::Constant(pad)};
    };
    // One walk over the bodies gives the fixed bodies' boxes and the paths' (which follow them in
    // m_proxies): a body is seven cache lines, and the walk waits on the three it reads (the two
    // flags and the bounding radius), so it asks for a later body's while it works on this one.
    const std::size_t bodyCount = world.bodies.size();
    for (std::size_t i = 0; i < bodyCount; ++i) {
        if (i + kBodyPrefetchAhead < bodyCount) {
            const model::Body& later = world.bodies[i + kBodyPrefetchAhead];
            __builtin_prefetch(&later.fixed);
            // The optional's flag lies at its end, a cache line past `fixed`.
            __builtin_prefetch(reinterpret_cast<const char*>(&later.soft) + sizeof(later.soft) - 1);
            __builtin_prefetch(&later.geometry.boundingRadius);
        }
        const model::Body& body = world.bodies[i];
        if (!finite(start[i]) || !finite(end[i]))
            continue; // no place: a fixed body puts nothing back, a moving one has no path (NaN would spread)
        if (body.fixed) {
            const Transform from = Transform::of(start[i]);
            const Transform to = Transform::of(end[i]);
            m_proxies.push_back(BroadPhaseProxy{Aabb::merged(boxAt(body, from), boxAt(body, to)), static_cast<std::uint32_t>(i), false});
            m_fixedPoses.push_back({from, to});
        } else if (!body.soft) {
            m_paths.push_back(BroadPhaseProxy{pathBox(i, body.geometry.boundingRadius), static_cast<std::uint32_t>(i), true});
        }
    }
    const std::size_t fixedCount = m_proxies.size();
    m_keptOut.clear();
    if (fixedCount == 0)
        return 0;
    m_proxies.insert(m_proxies.end(), m_paths.begin(), m_paths.end());
    std::size_t entry = bodyCount;
    for (const model::SoftGrid& grid : world.softBodies) {
        const Scalar pad = grid.semiAxes().maxCoeff();
        for (std::size_t k = 0; k < grid.size(); ++k, ++entry) {
            if (finite(start[entry]) && finite(end[entry]))
                m_proxies.push_back(BroadPhaseProxy{pathBox(entry, pad), static_cast<std::uint32_t>(entry), true});
        }
    }

    // Each entry's earliest entry into any fixed body; of two at once, the lower body's, so that
    // the answer does not depend on the order the pairs come in.
    m_hits.clear();
    const auto test = [&](std::size_t fixedProxy, std::size_t pathProxy) {
        const std::uint32_t f = m_proxies[fixedProxy].body;
        const std::uint32_t e = m_proxies[pathProxy].body;
        const FixedPose& pose = m_fixedPoses[fixedProxy];
        const Vec2 from = pose.start.inverseApply(start[e].position);
        const Vec2 to = pose.end.inverseApply(end[e].position);
        const Scalar t = detail::pathEntry(world.bodies[f], from, to);
        if (!(t >= 0))
            return;
        const Hit hit{e, static_cast<std::uint32_t>(fixedProxy), t, from, to};
        const auto known = std::find_if(m_hits.begin(), m_hits.end(), [&](const Hit& h) { return h.entry == e; });
        if (known == m_hits.end())
            m_hits.push_back(hit);
        else if (t < known->fraction || (t == known->fraction && hit.fixed < known->fixed))
            *known = hit;
    };
    if (fixedCount <= kFewFixedBodies) {
        // A handful of walls: each path against each, box first. Cheaper than a sweep of every
        // path, which a world whose bodies all move (a turning drum) would sort every substep.
        for (std::size_t p = fixedCount; p < m_proxies.size(); ++p) {
            for (std::size_t f = 0; f < fixedCount; ++f) {
                if (m_proxies[f].box.overlaps(m_proxies[p].box))
                    test(f, p);
            }
        }
    } else {
        m_broadPhase.findPairs(m_proxies, m_pairs);
        for (const ProxyPair& pair : m_pairs) {
            if (pair.second < fixedCount || pair.first >= fixedCount)
                continue; // two fixed bodies, or (never) two paths
            test(pair.first, pair.second);
        }
    }

    // Each put back where its path enters, in the fixed body's frame at the substep's end.
    std::sort(m_hits.begin(), m_hits.end(), [](const Hit& a, const Hit& b) { return a.entry < b.entry; });
    m_keptOut.clear();
    std::size_t grid = 0;
    std::size_t gridEnd = bodyCount + (world.softBodies.empty() ? 0 : world.softBodies[0].size());
    for (const Hit& hit : m_hits) {
        std::uint32_t body = hit.entry;
        if (hit.entry >= bodyCount) {
            while (hit.entry >= gridEnd)
                gridEnd += world.softBodies[++grid].size();
            body = world.softBodies[grid].body.index;
        }
        const KeptOut kept{body, m_proxies[hit.fixed].body};
        if (std::find(m_keptOut.begin(), m_keptOut.end(), kept) == m_keptOut.end())
            m_keptOut.push_back(kept);
        const Vec2 d = hit.to - hit.from;
        const Scalar back = std::min(hit.fraction, kBackOff / d.norm());
        const Scalar t = hit.fraction - back;
        model::BodyState& state = end[hit.entry];
        state.position = m_fixedPoses[hit.fixed].end.apply(hit.from + t * d);
        state.angle = start[hit.entry].angle + t * (state.angle - start[hit.entry].angle);
    }
    return static_cast<int>(m_hits.size());
}

} // namespace impetus::controller
