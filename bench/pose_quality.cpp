#include "pose_quality.h"

#include "controller/collision/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>
#include <vector>

namespace impetus::bench {

namespace {

constexpr Scalar kInfinity = std::numeric_limits<Scalar>::infinity();

/// One convex piece in world coordinates: a polygon (counter-clockwise), or a circle.
struct Piece {
    std::vector<Vec2> vertices; ///< empty for a circle
    Vec2 centre = Vec2::Zero(); ///< circle only
    Scalar radius = 0; ///< circle only
};

/// The largest gap between `a` and `b` along the outward normals of `a`'s edges: positive when
/// one of them separates the polygons, otherwise minus the least overlap along them.
Scalar faceSeparation(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    Scalar best = -kInfinity;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Vec2 edge = a[(i + 1) % a.size()] - a[i];
        const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
        Scalar nearest = kInfinity;
        for (const Vec2& v : b)
            nearest = std::min(nearest, normal.dot(v - a[i]));
        best = std::max(best, nearest);
    }
    return best;
}

Scalar polygonCircleSeparation(const std::vector<Vec2>& polygon, const Vec2& centre, Scalar radius)
{
    Scalar best = -kInfinity;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
        const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
        best = std::max(best, normal.dot(centre - polygon[i]) - radius);
    }
    // A circle adds one axis to the polygon's: from the polygon's nearest vertex to the centre.
    // Without it, a circle just beyond a corner would count as overlapping.
    const Vec2 nearest = *std::min_element(polygon.begin(), polygon.end(), [&](const Vec2& p, const Vec2& q) {
        return (p - centre).squaredNorm() < (q - centre).squaredNorm();
    });
    const Vec2 offset = centre - nearest;
    if (offset.squaredNorm() > 0) {
        const Vec2 axis = offset.normalized();
        Scalar closest = kInfinity;
        for (const Vec2& v : polygon)
            closest = std::min(closest, axis.dot(centre - v));
        best = std::max(best, closest - radius);
    }
    return best;
}

/// Signed distance between two convex pieces: ≥ 0 apart or touching, < 0 overlapping by −value.
Scalar separation(const Piece& a, const Piece& b)
{
    const bool aRound = a.vertices.empty();
    const bool bRound = b.vertices.empty();
    if (aRound && bRound)
        return (a.centre - b.centre).norm() - a.radius - b.radius;
    if (aRound)
        return polygonCircleSeparation(b.vertices, a.centre, a.radius);
    if (bRound)
        return polygonCircleSeparation(a.vertices, b.centre, b.radius);
    return std::max(faceSeparation(a.vertices, b.vertices), faceSeparation(b.vertices, a.vertices));
}

} // namespace

Overlap deepestOverlap(const model::World& world, std::span<const Pose> poses)
{
    if (poses.size() != world.bodies.size())
        throw std::invalid_argument("deepestOverlap: one pose per body is needed");
    std::vector<Piece> pieces;
    std::vector<controller::BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        const Pose& pose = poses[i];
        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            Piece piece;
            piece.centre = pose.position;
            piece.radius = circle->radius;
            const Vec2 r = Vec2::Constant(circle->radius);
            proxies.push_back({{pose.position - r, pose.position + r}, i, body.fixed});
            pieces.push_back(std::move(piece));
            continue;
        }
        if (std::holds_alternative<model::Ellipse>(body.shape))
            throw std::invalid_argument("deepestOverlap: ellipses are not measured");
        for (const auto& local : body.geometry.convexPieces) {
            Piece piece;
            controller::Aabb box{Vec2::Constant(kInfinity), Vec2::Constant(-kInfinity)};
            for (const Vec2& v : local) {
                const Vec2 p = pose.position + rotate(v, pose.angle);
                piece.vertices.push_back(p);
                box.lower = box.lower.cwiseMin(p);
                box.upper = box.upper.cwiseMax(p);
            }
            proxies.push_back({box, i, body.fixed});
            pieces.push_back(std::move(piece));
        }
    }

    controller::BroadPhase broadPhase;
    std::vector<controller::ProxyPair> pairs;
    broadPhase.findPairs(proxies, pairs);
    Overlap deepest;
    for (const controller::ProxyPair& pair : pairs) {
        const Scalar depth = -separation(pieces[pair.first], pieces[pair.second]);
        if (depth > deepest.depth)
            deepest = Overlap{depth, proxies[pair.first].body, proxies[pair.second].body};
    }
    return deepest;
}

Scalar worstJointError(const model::World& world, std::span<const Pose> poses)
{
    if (poses.size() != world.bodies.size())
        throw std::invalid_argument("worstJointError: one pose per body is needed");
    const auto worldPoint = [&](model::BodyId id, const Vec2& anchor) {
        const Pose& pose = poses[id.index];
        return Vec2(pose.position + rotate(anchor, pose.angle));
    };
    Scalar worst = 0;
    for (const model::Joint& joint : world.joints) {
        const Vec2 a = worldPoint(joint.bodyA, joint.anchorA);
        // A joint to the world holds on to anchorB as a world point.
        const Vec2 b = joint.bodyB ? worldPoint(*joint.bodyB, joint.anchorB) : joint.anchorB;
        const Scalar distance = (b - a).norm();
        worst = std::max(worst, joint.type == model::JointType::Pin ? distance : std::abs(distance - joint.length));
    }
    return worst;
}

} // namespace impetus::bench
