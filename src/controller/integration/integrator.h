#pragma once
/// \file integrator.h
/// Time integrators over the whole world state: every body's position, angle, velocity and
/// angular velocity advance together, so bodies joined by springs integrate as one coupled system.

#include "controller/integration/force_model.h"
#include "controller/integration/spin_keeper.h"
#include "model/scalar.h"
#include "model/world.h"

#include <memory>
#include <span>
#include <vector>

namespace impetus::controller {

/// Advances the bodies of a world by one step h under the forces of computeDerivatives().
/// Implementations keep scratch buffers, so one instance serves one simulation at a time.
class Integrator {
public:
    virtual ~Integrator() = default;

    /// Advances every body's state in `world` by h seconds. Fixed bodies move with their own
    /// constant velocity (none by default).
    void integrate(model::World& world, Scalar h);

    /// One step of the world's state list (force_model.h, stateCount) without touching the world:
    /// from `start`, whose derivative `startDerivative` the caller has already (the simulation
    /// needs it for collisions, so it is not computed again), to `end`, h seconds later. `world`
    /// supplies the forces: its bodies' masses, springs and soft grids.
    virtual void step(const model::World& world, std::span<const model::BodyState> start,
                      std::span<const BodyDerivative> startDerivative, Scalar h,
                      std::vector<model::BodyState>& end) = 0;

    /// Which method this is.
    virtual model::IntegratorKind kind() const = 0;

private:
    std::vector<model::BodyState> m_currentStates;
    std::vector<BodyDerivative> m_currentDerivatives;
    std::vector<model::BodyState> m_nextStates;
};

/// Explicit (forward) Euler: x ← x + h·v, v ← v + h·a(x, v), both from the old state. First order;
/// on a harmonic oscillator its energy grows by exactly (1 + ω²h²) every step. Each group of
/// bodies that pull on each other (a soft grid, rigid bodies on springs) then gets the angular
/// momentum that the torque from outside at the start of the step gives it (spin_keeper.h):
/// explicit Euler alone would spin it up by itself.
class ExplicitEulerIntegrator final : public Integrator {
public:
    void step(const model::World& world, std::span<const model::BodyState> start,
              std::span<const BodyDerivative> startDerivative, Scalar h, std::vector<model::BodyState>& end) override;
    model::IntegratorKind kind() const override { return model::IntegratorKind::Euler; }

private:
    SpinKeeper m_spin;
};

/// Semi-implicit (symplectic) Euler: v ← v + h·a(x, v), then x ← x + h·v with the new velocity.
/// First order, but its energy error stays bounded on conservative systems.
class SemiImplicitEulerIntegrator final : public Integrator {
public:
    void step(const model::World& world, std::span<const model::BodyState> start,
              std::span<const BodyDerivative> startDerivative, Scalar h, std::vector<model::BodyState>& end) override;
    model::IntegratorKind kind() const override { return model::IntegratorKind::SemiImplicitEuler; }

};

/// Classical fourth-order Runge–Kutta: four derivative evaluations k₁…k₄ at t, t+h/2, t+h/2 and
/// t+h, combined as y ← y + h/6·(k₁ + 2k₂ + 2k₃ + k₄). Fourth order: halving h divides the error
/// by 16. Exact for motion whose position is a polynomial of degree ≤ 4 in t (a projectile). Each
/// group of bodies that pull on each other then gets the angular momentum that the torque from
/// outside, weighted over the four stages as the method weights their accelerations, gives it
/// (spin_keeper.h).
class Rk4Integrator final : public Integrator {
public:
    void step(const model::World& world, std::span<const model::BodyState> start,
              std::span<const BodyDerivative> startDerivative, Scalar h, std::vector<model::BodyState>& end) override;
    model::IntegratorKind kind() const override { return model::IntegratorKind::Rk4; }

private:
    std::vector<model::BodyState> m_stage;
    std::vector<BodyDerivative> m_k2, m_k3, m_k4;
    ForceScratch m_scratch;
    SpinKeeper m_spin;
};

/// A new integrator of the given kind.
std::unique_ptr<Integrator> makeIntegrator(model::IntegratorKind kind);

} // namespace impetus::controller
