// Body::updateDerived (mass modes, fixed bodies, re-centred geometry) and the body kinematics.

#include "model/body.h"

#include "model/mass_properties.h"
#include "model/polygon.h"
#include "shape_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

namespace impetus::model {
namespace {

using fixtures::reversed;
using fixtures::translated;

constexpr Scalar kTolerance = 1e-12;
constexpr Scalar pi = std::numbers::pi;

/// 1e-12, relative once the expected value is larger than 1.
Scalar tolerance(Scalar expected) { return kTolerance * std::max(1.0, std::abs(expected)); }

Body makeBody(Shape shape, MassMode mode, Scalar value, bool fixed = false)
{
    Body body;
    body.name = "body";
    body.shape = std::move(shape);
    body.massSpec = MassSpec{mode, value};
    body.fixed = fixed;
    body.updateDerived();
    return body;
}

TEST(BodyDerived, DensityModeCircle)
{
    // r = 1, ρ = 2 kg/m²: A = π, m = 2π kg, I = ½mr² = π kg·m².
    const Body body = makeBody(Circle{1.0}, MassMode::Density, 2.0);
    EXPECT_NEAR(body.area, pi, kTolerance);
    EXPECT_NEAR(body.mass, 2 * pi, kTolerance);
    EXPECT_NEAR(body.inertia, pi, kTolerance);
    EXPECT_NEAR(body.invMass, 1 / (2 * pi), kTolerance);
    EXPECT_NEAR(body.invInertia, 1 / pi, kTolerance);
    EXPECT_EQ(body.density(), 2.0);
}

TEST(BodyDerived, MassModeKeepsTheGivenMassExactly)
{
    // 0.1 kg on the L (A = 3 m²): ρ = 0.1/3 does not multiply back to 0.1 exactly, so a mass that
    // went through the density would drift in the last bit. I = ρ·J = (0.1/3)·(11/6).
    const Body body = makeBody(Polygon{fixtures::lShape()}, MassMode::Mass, 0.1);
    EXPECT_EQ(body.mass, 0.1);
    EXPECT_NEAR(body.area, 3, kTolerance);
    EXPECT_NEAR(body.density(), 0.1 / 3, kTolerance);
    EXPECT_NEAR(body.inertia, 0.1 / 3 * 11.0 / 6, kTolerance);
    EXPECT_NEAR(body.invMass, 10, tolerance(10));
}

TEST(BodyDerived, MassModeEllipse)
{
    // m = 3 kg, a = 2, b = 1: I = m(a² + b²)/4 = 3·5/4 = 3.75 kg·m², whatever the area.
    const Body body = makeBody(Ellipse{2.0, 1.0}, MassMode::Mass, 3.0);
    EXPECT_EQ(body.mass, 3.0);
    EXPECT_NEAR(body.inertia, 3.75, kTolerance);
    EXPECT_NEAR(body.density(), 3 / (2 * pi), kTolerance);
}

TEST(BodyDerived, DensityAndMassModesAgree)
{
    // ρ = 2 on a 2 × 3 box is m = 12 kg; giving 12 kg must produce the same body.
    const Body byDensity = makeBody(Box{2.0, 3.0}, MassMode::Density, 2.0);
    const Body byMass = makeBody(Box{2.0, 3.0}, MassMode::Mass, 12.0);
    EXPECT_NEAR(byDensity.mass, 12, tolerance(12));
    EXPECT_NEAR(byMass.density(), 2, kTolerance);
    EXPECT_NEAR(byDensity.inertia, byMass.inertia, tolerance(byMass.inertia));
    EXPECT_NEAR(byMass.inertia, 12 * (4 + 9) / 12.0, tolerance(13)); // m(w² + h²)/12
}

TEST(BodyDerived, FixedBodyHasZeroInverseMassButReportsItsMass)
{
    const Body body = makeBody(Box{2.0, 3.0}, MassMode::Density, 2.0, true);
    EXPECT_EQ(body.invMass, 0);
    EXPECT_EQ(body.invInertia, 0);
    EXPECT_NEAR(body.mass, 12, tolerance(12));
    EXPECT_NEAR(body.inertia, 13, tolerance(13));
}

TEST(BodyDerived, PolygonIsRecentredOnItsCentroid)
{
    const Body body = makeBody(Polygon{fixtures::lShape()}, MassMode::Density, 1.0);
    const Vec2 centroid(5.0 / 6, 5.0 / 6); // worked in mass_properties_test.cpp
    EXPECT_NEAR((body.geometry.centroidOffset - centroid).norm(), 0, kTolerance);

    // The outline is the user's polygon, counter-clockwise, moved so its centroid is the origin.
    const std::vector<Vec2>& outline = body.geometry.outline;
    ASSERT_EQ(outline.size(), 6u);
    for (std::size_t i = 0; i < outline.size(); ++i)
        EXPECT_NEAR((outline[i] - (fixtures::lShape()[i] - centroid)).norm(), 0, kTolerance);
    EXPECT_GT(signedArea(outline), 0);
    EXPECT_NEAR(polygonAreaProperties(outline).centroid.norm(), 0, kTolerance);

    // The pieces are in the same frame: their area-weighted centroids average to the origin.
    ASSERT_FALSE(body.geometry.convexPieces.empty());
    Vec2 firstMoment = Vec2::Zero();
    Scalar area = 0;
    for (const auto& piece : body.geometry.convexPieces) {
        const AreaProperties part = polygonAreaProperties(piece);
        firstMoment += part.area * part.centroid;
        area += part.area;
    }
    EXPECT_NEAR(area, 3, kTolerance);
    EXPECT_NEAR(firstMoment.norm(), 0, kTolerance);
}

TEST(BodyDerived, ClockwisePolygonFarFromTheOriginGivesTheSameBody)
{
    const Body near = makeBody(Polygon{fixtures::lShape()}, MassMode::Density, 1.0);
    const Body far = makeBody(Polygon{reversed(translated(fixtures::lShape(), Vec2(40, -25)))}, MassMode::Density, 1.0);
    EXPECT_NEAR(far.mass, near.mass, tolerance(near.mass));
    EXPECT_NEAR(far.inertia, near.inertia, tolerance(near.inertia));
    EXPECT_NEAR((far.geometry.centroidOffset - Vec2(40 + 5.0 / 6, -25 + 5.0 / 6)).norm(), 0, tolerance(50));
    EXPECT_NEAR(far.geometry.boundingRadius, near.geometry.boundingRadius, kTolerance);
    EXPECT_GT(signedArea(far.geometry.outline), 0);
}

TEST(BodyDerived, BoundingRadius)
{
    EXPECT_EQ(makeBody(Circle{0.7}, MassMode::Density, 1.0).geometry.boundingRadius, 0.7);
    EXPECT_EQ(makeBody(Ellipse{0.5, 1.5}, MassMode::Density, 1.0).geometry.boundingRadius, 1.5);
    // Box 2 × 3: the corners are √(1² + 1.5²) = √3.25 from the centre.
    EXPECT_NEAR(makeBody(Box{2.0, 3.0}, MassMode::Density, 1.0).geometry.boundingRadius, std::sqrt(3.25), kTolerance);
    // L: from the centroid (5/6, 5/6) the farthest corners are (2, 0) and (0, 2), at
    // √((7/6)² + (5/6)²) = √74/6.
    EXPECT_NEAR(makeBody(Polygon{fixtures::lShape()}, MassMode::Density, 1.0).geometry.boundingRadius,
        std::sqrt(74.0) / 6, kTolerance);
}

TEST(BodyDerived, RoundShapesHaveNoOutlineAndBoxesOnePiece)
{
    const Body circle = makeBody(Circle{1.0}, MassMode::Density, 1.0);
    EXPECT_TRUE(circle.geometry.outline.empty());
    EXPECT_TRUE(circle.geometry.convexPieces.empty());
    const Body box = makeBody(Box{2.0, 3.0}, MassMode::Density, 1.0);
    const std::vector<Vec2> corners = {Vec2(-1, -1.5), Vec2(1, -1.5), Vec2(1, 1.5), Vec2(-1, 1.5)};
    EXPECT_EQ(box.geometry.outline, corners);
    ASSERT_EQ(box.geometry.convexPieces.size(), 1u);
    EXPECT_EQ(box.geometry.convexPieces[0], corners);
}

TEST(BodyDerived, UpdatingAfterAChangeReplacesTheOldGeometry)
{
    Body body = makeBody(Polygon{fixtures::lShape()}, MassMode::Density, 1.0);
    body.shape = Circle{1.0};
    body.updateDerived();
    EXPECT_TRUE(body.geometry.outline.empty());
    EXPECT_TRUE(body.geometry.convexPieces.empty());
    EXPECT_EQ(body.geometry.centroidOffset, Vec2::Zero());
    EXPECT_EQ(body.geometry.boundingRadius, 1.0);
}

TEST(BodyKinematics, WorldPointAndVelocityAt)
{
    Body body = makeBody(Circle{1.0}, MassMode::Density, 1.0);
    body.state.position = Vec2(2, 3);
    body.state.angle = pi / 2;
    body.state.velocity = Vec2(1, 0);
    body.state.angularVelocity = 2;
    // A quarter turn takes body x to world y.
    EXPECT_NEAR((body.worldPoint(Vec2(1, 0)) - Vec2(2, 4)).norm(), 0, kTolerance);
    // r = (0, 1) from the centre: ω × r = 2·(−1, 0), plus v = (1, 0).
    EXPECT_NEAR((body.velocityAt(Vec2(2, 4)) - Vec2(-1, 0)).norm(), 0, kTolerance);
}

} // namespace
} // namespace impetus::model
