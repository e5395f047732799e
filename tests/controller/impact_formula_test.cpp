// The collision inspector's numbers: the engine's impact record and the impulse formula filled in
// from it, against an impact worked by hand.

#include "controller/impact_formula.h"
#include "controller/simulation.h"

#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impetus::controller {
namespace {

constexpr Scalar kExact = 1e-12; ///< hand-worked results, up to rounding

/// A 2 m × 1 m box of 2 kg turned by θ (cos θ = 0.8, sin θ = 0.6), its lowest corner touching a
/// fixed ground's top face (y = 0), falling at 2 m/s without turning, in zero gravity.
///
/// Worked by hand. The corner (−1, −0.5) of the box turned by θ lies at
/// r_B = (−0.8 + 0.3, −0.6 − 0.4) = (−0.5, −1) from the centre; the other corners are higher, so
/// one point strikes. The ground is A, the box B, n = (0, 1), t = (n_y, −n_x) = (1, 0).
///   m_B = 2 kg, I_B = m(w² + h²)/12 = 2·5/12 = 5/6 kg·m², 1/I_B = 1.2; the ground: 1/m = 1/I = 0.
///   r_B × n = (−0.5)(1) − (−1)(0) = −0.5;  K = 1/m_B + (r_B×n)²/I_B = 0.5 + 0.25·1.2 = 0.8 1/kg.
///   v_n = −2 m/s, e = max(0.5, 0) = 0.5:  j = −(1 + e)·v_n / K = 3 / 0.8 = 3.75 N·s.
///   After: v_B = (0, −2 + 3.75/2) = (0, −0.125), ω_B = 1.2·(r_B × j n) = 1.2·(−0.5·3.75) = −2.25,
///   and the point's normal speed −0.125 + (ω×r)_y = −0.125 + (−2.25)(−0.5) = 1 = −e·v_n.
/// Friction: the point now slides at v_t = v_x + (ω×r)_x = 0 + (−2.25)(−(−1)) = −2.25 m/s.
///   r_B × t = (−0.5)(0) − (−1)(1) = 1, K_t = 0.5 + 1.2·1 = 1.7; stopping it needs 2.25/1.7 N·s.
///   μ = √(0.2·0.2) = 0.2, μj = 0.75 < 1.3235…: it slides, j_t = 0.75 N·s.
///   After: v_B = (0.375, −0.125), ω_B = −2.25 + 1.2·(1·0.75) = −1.35 rad/s.
/// Momentum (0, −4) → (0.75, −0.25) kg·m/s: the ground's impulse (0.75, 3.75).
/// Energy ½·2·4 = 4 J → ½·2·(0.375² + 0.125²) + ½·(5/6)·1.35² = 0.15625 + 0.759375 = 0.915625 J.
model::World handWorkedWorld(Scalar friction)
{
    model::World world = testing::makeEmptyWorld(model::IntegratorKind::SemiImplicitEuler, 1.0 / 240);
    world.bodies.push_back(testing::withMaterial(testing::makeGround("ground", 10, 1), 0.0, friction));
    const Scalar angle = std::atan2(0.6, 0.8);
    model::Body box = testing::withMaterial(testing::makeBox("box", 2.0, 2.0, 1.0, Vec2(0.5, 1.0), angle), 0.5, friction);
    box.state.velocity = Vec2(0, -2);
    world.bodies.push_back(box);
    return world;
}

TEST(ImpactFormula, ReproducesTheHandWorkedImpactAndTheEnginesImpulse)
{
    model::World world = handWorkedWorld(0.2);
    Simulation simulation;
    std::vector<ImpactRecord> log;
    simulation.setImpactLog(&log);
    simulation.step(world);

    ASSERT_EQ(log.size(), 1U);
    const ImpactRecord& record = log[0];
    EXPECT_EQ(record.ownerA, 0U);
    EXPECT_EQ(record.ownerB, 1U);
    ASSERT_EQ(record.count, 1);
    EXPECT_NEAR((record.normal - Vec2(0, 1)).norm(), 0.0, kExact);

    const ImpactFormula f = impactFormula(record);
    EXPECT_TRUE(std::isinf(f.massA));
    EXPECT_NEAR(f.massB, 2.0, kExact);
    EXPECT_NEAR(f.invInertiaB, 1.2, kExact);
    EXPECT_EQ(f.invInertiaA, 0.0);
    EXPECT_EQ(f.restitution, 0.5);
    EXPECT_NEAR(f.friction, 0.2, kExact);
    const ImpactFormulaPoint& p = f.points[0];
    EXPECT_NEAR(p.rnB, -0.5, kExact);
    EXPECT_NEAR(p.denominator, 0.8, kExact);
    EXPECT_NEAR(p.approachSpeed, -2.0, kExact);
    EXPECT_TRUE(p.bounces);
    EXPECT_NEAR(p.formulaImpulse, 3.75, kExact);
    // The formula on the recorded state gives the engine's own impulse.
    EXPECT_NEAR(p.formulaImpulse, p.engineImpulse, kExact);
    EXPECT_NEAR(p.speedAfter, 1.0, kExact);
    EXPECT_NEAR(p.tangentSpeed, -2.25, kExact);
    EXPECT_NEAR(p.tangentDenominator, 1.7, kExact);
    EXPECT_NEAR(p.frictionNeeded, 2.25 / 1.7, kExact);
    EXPECT_NEAR(p.frictionLimit, 0.75, kExact);
    EXPECT_TRUE(p.slid);
    EXPECT_NEAR(p.frictionImpulse, 0.75, kExact);
    EXPECT_NEAR(record.points[0].frictionImpulse, p.frictionImpulse, kExact);

    EXPECT_NEAR((record.afterB.velocity - Vec2(0.375, -0.125)).norm(), 0.0, kExact);
    EXPECT_NEAR(record.afterB.angularVelocity, -1.35, kExact);
    EXPECT_NEAR((f.before.momentum - Vec2(0, -4)).norm(), 0.0, kExact);
    EXPECT_NEAR((f.after.momentum - Vec2(0.75, -0.25)).norm(), 0.0, kExact);
    EXPECT_NEAR(f.before.energy, 4.0, kExact);
    EXPECT_NEAR(f.after.energy, 0.915625, kExact);

    // The collision log's entry for the step carries the same impulse (the contact forces add
    // nothing to a point already leaving).
    ASSERT_EQ(simulation.events().size(), 1U);
    EXPECT_NEAR(simulation.events()[0].normalImpulse, p.engineImpulse, kExact);
}

TEST(ImpactFormula, HighFrictionSticks)
{
    // μ = 0.5: μj = 1.875 > 2.25/1.7, so friction stops the sliding: the point sticks.
    model::World world = handWorkedWorld(0.5);
    Simulation simulation;
    std::vector<ImpactRecord> log;
    simulation.setImpactLog(&log);
    simulation.step(world);
    ASSERT_EQ(log.size(), 1U);
    const ImpactFormula f = impactFormula(log[0]);
    EXPECT_FALSE(f.points[0].slid);
    EXPECT_NEAR(f.points[0].frictionImpulse, 2.25 / 1.7, kExact);
    EXPECT_NEAR(log[0].points[0].frictionImpulse, 2.25 / 1.7, kExact);
}

TEST(ImpactFormula, NoLogRecordsNothingAndChangesNothing)
{
    model::World logged = handWorkedWorld(0.2);
    model::World plain = logged;
    Simulation withLog;
    std::vector<ImpactRecord> log;
    withLog.setImpactLog(&log);
    Simulation without;
    for (int i = 0; i < 10; ++i) {
        withLog.step(logged);
        without.step(plain);
    }
    EXPECT_EQ(logged.bodies[1].state.position, plain.bodies[1].state.position);
    EXPECT_EQ(logged.bodies[1].state.velocity, plain.bodies[1].state.velocity);
    withLog.setImpactLog(nullptr);
    const std::size_t recorded = log.size();
    withLog.step(logged);
    EXPECT_EQ(log.size(), recorded);
}

} // namespace
} // namespace impetus::controller
