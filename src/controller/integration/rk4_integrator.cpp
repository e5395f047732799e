#include "controller/integration/integrator.h"

namespace impetus::controller {

namespace {

/// stage[i] = start[i] + h·k[i] for every body (a fixed body's k has no acceleration).
void advance(std::span<const model::BodyState> start, std::span<const BodyDerivative> k, Scalar h,
             std::vector<model::BodyState>& stage)
{
    stage.resize(start.size());
    for (std::size_t i = 0; i < start.size(); ++i) {
        stage[i].position = start[i].position + h * k[i].velocity;
        stage[i].angle = start[i].angle + h * k[i].angularVelocity;
        stage[i].velocity = start[i].velocity + h * k[i].acceleration;
        stage[i].angularVelocity = start[i].angularVelocity + h * k[i].angularAcceleration;
    }
}

} // namespace

void Rk4Integrator::step(const model::World& world, std::span<const model::BodyState> start,
                         std::span<const BodyDerivative> k1s, Scalar h, std::vector<model::BodyState>& end)
{
    // The four stages of the classical method, each over the whole world so that coupled bodies
    // see each other's intermediate states. The torque from outside on each group of bodies
    // that pull on each other is summed over them with the method's weights.
    const bool spin = m_spin.begin(world);
    if (spin)
        m_spin.addTorques(start, k1s, 1.0 / 6);
    advance(start, k1s, h / 2, m_stage);
    computeDerivatives(world, m_stage, m_k2, m_scratch);
    if (spin)
        m_spin.addTorques(m_stage, m_k2, 2.0 / 6);
    advance(start, m_k2, h / 2, m_stage);
    computeDerivatives(world, m_stage, m_k3, m_scratch);
    if (spin)
        m_spin.addTorques(m_stage, m_k3, 2.0 / 6);
    advance(start, m_k3, h, m_stage);
    computeDerivatives(world, m_stage, m_k4, m_scratch);
    if (spin)
        m_spin.addTorques(m_stage, m_k4, 1.0 / 6);

    const Scalar w = h / 6;
    end.resize(start.size());
    for (std::size_t i = 0; i < start.size(); ++i) {
        const model::BodyState& s0 = start[i];
        model::BodyState& state = end[i];
        const BodyDerivative& k1 = k1s[i];
        const BodyDerivative& k2 = m_k2[i];
        const BodyDerivative& k3 = m_k3[i];
        const BodyDerivative& k4 = m_k4[i];
        state.position = s0.position + w * (k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity);
        state.angle = s0.angle + w * (k1.angularVelocity + 2 * k2.angularVelocity + 2 * k3.angularVelocity +
                                  k4.angularVelocity);
        state.velocity =
            s0.velocity + w * (k1.acceleration + 2 * k2.acceleration + 2 * k3.acceleration + k4.acceleration);
        state.angularVelocity = s0.angularVelocity + w * (k1.angularAcceleration + 2 * k2.angularAcceleration +
                                                      2 * k3.angularAcceleration + k4.angularAcceleration);
    }
    if (spin)
        m_spin.keep(start, end, h);
}

} // namespace impetus::controller
