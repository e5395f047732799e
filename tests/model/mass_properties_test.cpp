// Area, centroid and polar moment of known shapes, each against values worked by hand.

#include "model/mass_properties.h"

#include "shape_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace impetus::model {
namespace {

using fixtures::reversed;
using fixtures::translated;

constexpr Scalar kTolerance = 1e-12;
constexpr Scalar pi = std::numbers::pi;

/// 1e-12, relative once the expected value is larger than 1.
Scalar tolerance(Scalar expected) { return kTolerance * std::max(1.0, std::abs(expected)); }

void expectProperties(const AreaProperties& actual, Scalar area, const Vec2& centroid, Scalar polarMoment)
{
    EXPECT_NEAR(actual.area, area, tolerance(area));
    EXPECT_NEAR(actual.centroid.x(), centroid.x(), tolerance(centroid.x()));
    EXPECT_NEAR(actual.centroid.y(), centroid.y(), tolerance(centroid.y()));
    EXPECT_NEAR(actual.polarMoment, polarMoment, tolerance(polarMoment));
}

TEST(MassProperties, Circle)
{
    // r = 2: A = πr² = 4π; J = ∫r² dA = ∫₀² r²·2πr dr = 2π·2⁴/4 = 8π (= ½·A·r²).
    expectProperties(areaProperties(Circle{2.0}), 4 * pi, Vec2::Zero(), 8 * pi);
}

TEST(MassProperties, Box)
{
    // 2 × 3: A = 6; J = Ix + Iy = w·h³/12 + h·w³/12 = 2·27/12 + 3·8/12 = 4.5 + 2 = 6.5.
    expectProperties(areaProperties(Box{2.0, 3.0}), 6, Vec2::Zero(), 6.5);
}

TEST(MassProperties, BoxAsAPolygonAgreesWithTheBox)
{
    // The same 2 × 3 rectangle as four corners, centred on (5, 7).
    const std::vector<Vec2> corners = {Vec2(4, 5.5), Vec2(6, 5.5), Vec2(6, 8.5), Vec2(4, 8.5)};
    expectProperties(polygonAreaProperties(corners), 6, Vec2(5, 7), 6.5);
}

TEST(MassProperties, Ellipse)
{
    // a = 2, b = 1: A = πab = 2π. Ix = πab³/4 = π/2, Iy = πa³b/4 = 2π, J = πab(a² + b²)/4 = 5π/2,
    // so per unit mass I/m = (a² + b²)/4 = 5/4.
    const AreaProperties props = areaProperties(Ellipse{2.0, 1.0});
    expectProperties(props, 2 * pi, Vec2::Zero(), 5 * pi / 2);
    EXPECT_NEAR(props.polarMoment / props.area, 1.25, kTolerance);
}

TEST(MassProperties, RightTriangle)
{
    // Legs 3 (along x) and 4 (along y): A = ½·3·4 = 6, centroid at a third of each leg (1, 4/3).
    // About the centroid Ix = b·h³/36 = 3·64/36 = 16/3 and Iy = h·b³/36 = 4·27/36 = 3, so
    // J = 16/3 + 3 = 25/3 (= A(a² + b²)/18 = 6·25/18).
    const std::vector<Vec2> triangle = {Vec2(0, 0), Vec2(3, 0), Vec2(0, 4)};
    expectProperties(polygonAreaProperties(triangle), 6, Vec2(1, 4.0 / 3), 25.0 / 3);
    expectProperties(areaProperties(Polygon{triangle}), 6, Vec2(1, 4.0 / 3), 25.0 / 3);
}

TEST(MassProperties, ConcaveLShape)
{
    // L = R1 [0,2]×[0,1] (A1 = 2, c1 = (1, ½)) + R2 [0,1]×[1,2] (A2 = 1, c2 = (½, 3/2)).
    // A = 3. c = (2·(1, ½) + 1·(½, 3/2))/3 = (2.5/3, 2.5/3) = (5/6, 5/6).
    // Own moments: J1 = A1(w² + h²)/12 = 2·(4 + 1)/12 = 5/6; J2 = 1·(1 + 1)/12 = 1/6.
    // Parallel axis: |c1 − c|² = (1/6)² + (−1/3)² = 5/36, times A1 = 2 gives 10/36 = 5/18;
    //                |c2 − c|² = (−1/3)² + (2/3)² = 5/9,  times A2 = 1 gives 5/9 = 10/18.
    // J = 5/6 + 1/6 + 5/18 + 10/18 = 1 + 15/18 = 11/6.
    // Check about the origin: J₀(R1) = ∫x² + ∫y² = 8/3 + 2/3 = 10/3, J₀(R2) = 1/3 + 7/3 = 8/3,
    // J₀ = 6, and J₀ − A|c|² = 6 − 3·50/36 = 6 − 25/6 = 11/6.
    expectProperties(polygonAreaProperties(fixtures::lShape()), 3, Vec2(5.0 / 6, 5.0 / 6), 11.0 / 6);
}

TEST(MassProperties, BothWindingsGiveTheSamePositiveResult)
{
    const std::vector<Vec2> triangle = {Vec2(0, 0), Vec2(3, 0), Vec2(0, 4)};
    expectProperties(polygonAreaProperties(reversed(triangle)), 6, Vec2(1, 4.0 / 3), 25.0 / 3);
    expectProperties(polygonAreaProperties(reversed(fixtures::lShape())), 3, Vec2(5.0 / 6, 5.0 / 6), 11.0 / 6);
}

TEST(MassProperties, FarFromTheOriginGivesTheSameMoment)
{
    // Moving a shape moves its centroid and changes nothing else. 1 km out is far for a classroom
    // scene but an ordinary coordinate; the moment must keep 12 digits there.
    const Vec2 offset(1000, -2000);
    const AreaProperties atOrigin = polygonAreaProperties(fixtures::lShape());
    const AreaProperties far = polygonAreaProperties(translated(fixtures::lShape(), offset));
    EXPECT_NEAR(far.area, atOrigin.area, tolerance(atOrigin.area));
    EXPECT_NEAR(far.centroid.x(), atOrigin.centroid.x() + offset.x(), tolerance(offset.x()));
    EXPECT_NEAR(far.centroid.y(), atOrigin.centroid.y() + offset.y(), tolerance(offset.y()));
    EXPECT_NEAR(far.polarMoment, 11.0 / 6, tolerance(11.0 / 6));
}

} // namespace
} // namespace impetus::model
