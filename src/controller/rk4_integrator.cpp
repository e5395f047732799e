#include "controller/integrator.h"

namespace impetus::controller {

namespace {

/// stage[i] = start[i] + h·k[i] for every body (a fixed body's k has no acceleration).
void advance(const std::vector<model::BodyState>& start, std::span<const BodyDerivative> k, Scalar h,
             std::vector<model::BodyState>& stage)
{
    stage = start;
    for (std::size_t i = 0; i < start.size(); ++i) {
        stage[i].position += h * k[i].velocity;
        stage[i].angle += h * k[i].angularVelocity;
        stage[i].velocity += h * k[i].acceleration;
        stage[i].angularVelocity += h * k[i].angularAcceleration;
    }
}

} // namespace

void Rk4Integrator::integrate(model::World& world, Scalar h, std::span<const BodyDerivative> k1s)
{
    gatherStates(world, m_start);

    // The four stages of the classical method, each over the whole world so that coupled bodies
    // see each other's intermediate states.
    advance(m_start, k1s, h / 2, m_stage);
    computeDerivatives(world, m_stage, m_k2);
    advance(m_start, m_k2, h / 2, m_stage);
    computeDerivatives(world, m_stage, m_k3);
    advance(m_start, m_k3, h, m_stage);
    computeDerivatives(world, m_stage, m_k4);

    const Scalar w = h / 6;
    // m_stage is free now: it collects the result.
    m_stage = m_start;
    for (std::size_t i = 0; i < m_start.size(); ++i) {
        model::BodyState& state = m_stage[i];
        const BodyDerivative& k1 = k1s[i];
        const BodyDerivative& k2 = m_k2[i];
        const BodyDerivative& k3 = m_k3[i];
        const BodyDerivative& k4 = m_k4[i];
        state.position += w * (k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity);
        state.angle += w * (k1.angularVelocity + 2 * k2.angularVelocity +
                                 2 * k3.angularVelocity + k4.angularVelocity);
        state.velocity +=
            w * (k1.acceleration + 2 * k2.acceleration + 2 * k3.acceleration + k4.acceleration);
        state.angularVelocity += w * (k1.angularAcceleration + 2 * k2.angularAcceleration +
                                           2 * k3.angularAcceleration + k4.angularAcceleration);
    }
    scatterStates(world, m_stage);
}

} // namespace impetus::controller
