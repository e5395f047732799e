// The impulse formula written out term by term, as a teacher would on the board, from the state
// the contact solver recorded just before the impulse.

#include "controller/impact_formula.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace impetus::controller {

namespace {

Scalar massOf(Scalar invMass) { return invMass > 0 ? 1 / invMass : std::numeric_limits<Scalar>::infinity(); }

void addBody(PairTotals& totals, const ImpactBodyState& body)
{
    if (body.invMass > 0) {
        totals.momentum += body.velocity / body.invMass;
        totals.energy += 0.5 * body.velocity.squaredNorm() / body.invMass;
    }
    if (body.invInertia > 0)
        totals.energy += 0.5 * body.angularVelocity * body.angularVelocity / body.invInertia;
}

} // namespace

PairTotals pairTotals(const ImpactBodyState& a, const ImpactBodyState& b)
{
    PairTotals totals;
    addBody(totals, a);
    addBody(totals, b);
    return totals;
}

ImpactFormula impactFormula(const ImpactRecord& record)
{
    ImpactFormula f;
    f.massA = massOf(record.beforeA.invMass);
    f.massB = massOf(record.beforeB.invMass);
    f.invInertiaA = record.beforeA.invInertia;
    f.invInertiaB = record.beforeB.invInertia;
    f.restitution = record.restitution;
    f.friction = record.friction;
    f.count = record.count;
    const Scalar invMasses = record.beforeA.invMass + record.beforeB.invMass;
    for (std::size_t i = 0; i < static_cast<std::size_t>(record.count); ++i) {
        const ImpactPointRecord& r = record.points[i];
        ImpactFormulaPoint& p = f.points[i];
        p.rnA = cross(r.rA, record.normal);
        p.rnB = cross(r.rB, record.normal);
        p.denominator = invMasses + f.invInertiaA * p.rnA * p.rnA + f.invInertiaB * p.rnB * p.rnB;
        p.approachSpeed = r.approachSpeed;
        // Below the threshold a bounce would be rounding noise: the impulse only stops the approach.
        p.bounces = r.approachSpeed < -constants::kRestitutionThreshold;
        const Scalar e = p.bounces ? f.restitution : 0;
        p.formulaImpulse = p.denominator > 0 ? -(1 + e) * p.approachSpeed / p.denominator : 0;
        p.engineImpulse = r.normalImpulse;

        const Scalar rtA = cross(r.rA, record.tangent);
        const Scalar rtB = cross(r.rB, record.tangent);
        p.tangentSpeed = r.tangentSpeed;
        p.tangentDenominator = invMasses + f.invInertiaA * rtA * rtA + f.invInertiaB * rtB * rtB;
        p.frictionNeeded = p.tangentDenominator > 0 ? -p.tangentSpeed / p.tangentDenominator : 0;
        p.frictionLimit = f.friction * r.normalImpulse;
        p.frictionImpulse = std::clamp(p.frictionNeeded, -p.frictionLimit, p.frictionLimit);
        p.slid = std::abs(p.frictionNeeded) > p.frictionLimit;
    }
    for (std::size_t i = 0; i < static_cast<std::size_t>(record.count); ++i) {
        ImpactFormulaPoint& p = f.points[i];
        p.speedAfter = p.approachSpeed;
        for (std::size_t j = 0; j < static_cast<std::size_t>(record.count); ++j)
            p.speedAfter += record.k[i][j] * record.points[j].normalImpulse;
    }
    f.before = pairTotals(record.beforeA, record.beforeB);
    f.after = pairTotals(record.afterA, record.afterB);
    return f;
}

} // namespace impetus::controller
