#pragma once
/// \file shape_fixtures.h
/// Polygons shared by the model tests: simple concave shapes with known areas, and shapes that
/// stress triangulation (collinear runs, many reflex vertices, spirals).

#include "model/scalar.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace impetus::model::fixtures {

/// The L made of a 2×1 rectangle [0,2]×[0,1] and a 1×1 square [0,1]×[1,2], counter-clockwise.
inline std::vector<Vec2> lShape()
{
    return {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};
}

/// The L with extra vertices in the middle of its edges (collinear runs), counter-clockwise.
inline std::vector<Vec2> lShapeWithMidpoints()
{
    return {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 0.5), Vec2(2, 1), Vec2(1.5, 1), Vec2(1, 1),
        Vec2(1, 1.5), Vec2(1, 2), Vec2(0.5, 2), Vec2(0, 2), Vec2(0, 1)};
}

/// A U: a 3×3 square with the 1×2 slot [1,2]×[1,3] cut out, counter-clockwise. Area 7.
inline std::vector<Vec2> uShape()
{
    return {Vec2(0, 0), Vec2(3, 0), Vec2(3, 3), Vec2(2, 3), Vec2(2, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)};
}

/// A plus sign of five unit squares, counter-clockwise: four reflex corners of 270°, where a
/// merge can leave two pieces meeting in a straight line.
inline std::vector<Vec2> plusShape()
{
    return {Vec2(1, 0), Vec2(2, 0), Vec2(2, 1), Vec2(3, 1), Vec2(3, 2), Vec2(2, 2), Vec2(2, 3), Vec2(1, 3),
        Vec2(1, 2), Vec2(0, 2), Vec2(0, 1), Vec2(1, 1)};
}

/// A star with `points` tips on a circle of radius `outer` and notches on radius `inner`,
/// counter-clockwise, the first tip on the +x axis.
inline std::vector<Vec2> star(std::size_t points, Scalar outer, Scalar inner)
{
    std::vector<Vec2> out;
    const Scalar step = std::numbers::pi / static_cast<Scalar>(points);
    for (std::size_t k = 0; k < 2 * points; ++k) {
        const Scalar r = k % 2 == 0 ? outer : inner;
        const Scalar angle = step * static_cast<Scalar>(k);
        out.emplace_back(r * std::cos(angle), r * std::sin(angle));
    }
    return out;
}

/// A comb, counter-clockwise: a base [0, teeth−½]×[0,1] with `teeth` teeth ½ m wide and 2 m tall,
/// 1 m apart. The bottoms of the gaps all lie on y = 1, so a careless ear clipper can cut a
/// diagonal straight through them. With `baseMidpoints`, the bottom edge also carries a collinear
/// vertex at every whole x.
inline std::vector<Vec2> comb(std::size_t teeth, bool baseMidpoints = false)
{
    const Scalar width = static_cast<Scalar>(teeth) - 0.5;
    std::vector<Vec2> out = {Vec2(0, 0)};
    if (baseMidpoints) {
        for (std::size_t k = 1; k < teeth; ++k)
            out.emplace_back(static_cast<Scalar>(k), 0);
    }
    out.emplace_back(width, 0);
    for (std::size_t k = teeth; k-- > 0;) {
        const Scalar x = static_cast<Scalar>(k);
        out.emplace_back(x + 0.5, 3);
        out.emplace_back(x, 3);
        if (k > 0) {
            out.emplace_back(x, 1);
            out.emplace_back(x - 0.5, 1);
        }
    }
    return out;
}

/// A band 0.6 m thick wound 1½ times round the origin (the centre line an Archimedean spiral
/// gaining 1.5 m of radius per turn), counter-clockwise, sampled every 15°.
inline std::vector<Vec2> spiral()
{
    constexpr std::size_t samples = 37; // 0 … 3π in steps of π/12
    constexpr Scalar thickness = 0.6;
    constexpr Scalar growthPerTurn = 1.5;
    const Scalar step = std::numbers::pi / 12;
    std::vector<Vec2> outer;
    std::vector<Vec2> inner;
    for (std::size_t k = 0; k < samples; ++k) {
        const Scalar angle = step * static_cast<Scalar>(k);
        const Scalar r = 1 + growthPerTurn * angle / (2 * std::numbers::pi);
        const Vec2 direction(std::cos(angle), std::sin(angle));
        inner.push_back(r * direction);
        outer.push_back((r + thickness) * direction);
    }
    // Out along the outer edge (turning left, the band on the left), back along the inner one.
    std::vector<Vec2> out = outer;
    out.insert(out.end(), inner.rbegin(), inner.rend());
    return out;
}

/// A regular polygon with `sides` vertices on a circle of radius `radius`, counter-clockwise.
inline std::vector<Vec2> regularPolygon(std::size_t sides, Scalar radius)
{
    std::vector<Vec2> out;
    for (std::size_t k = 0; k < sides; ++k) {
        const Scalar angle = 2 * std::numbers::pi * static_cast<Scalar>(k) / static_cast<Scalar>(sides);
        out.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    return out;
}

/// The same vertices in the opposite order (clockwise for a counter-clockwise input).
inline std::vector<Vec2> reversed(std::vector<Vec2> vertices)
{
    std::reverse(vertices.begin(), vertices.end());
    return vertices;
}

/// The vertices moved by `offset`.
inline std::vector<Vec2> translated(std::vector<Vec2> vertices, const Vec2& offset)
{
    for (Vec2& v : vertices)
        v += offset;
    return vertices;
}

} // namespace impetus::model::fixtures
