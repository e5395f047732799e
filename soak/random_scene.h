#pragma once
/// \file random_scene.h
/// Random valid scenes for the soak (scripts/soak, docs/testing.md): bodies of every shape, springs,
/// pin and rod joints and soft bodies, with extreme but legal masses and speeds, inside a closed
/// box of four fixed walls. The same seed gives the same scene on every machine: the generator
/// draws from std::mt19937_64, whose output the standard fixes, and turns its bits into numbers
/// itself (the standard distributions differ between libraries).

#include "model/world.h"

#include <cstdint>
#include <random>

namespace impetus::soak {

/// What a random scene may hold.
struct RandomSceneOptions {
    int minBodies = 3; ///< dynamic bodies, at least
    int maxBodies = 6; ///< dynamic bodies, at most (the box has room for 25)
};

/// Uniform numbers from a seed, the same on every platform.
class SceneRandom {
public:
    /// A stream of numbers fixed by `seed`.
    explicit SceneRandom(std::uint64_t seed) : m_engine(seed) {}
    /// Uniform in [0, 1), 53 bits.
    Scalar unit();
    /// Uniform in [low, high).
    Scalar uniform(Scalar low, Scalar high) { return low + (high - low) * unit(); }
    /// Log-uniform in [low, high), low > 0: as likely in [1, 10) as in [1000, 10000).
    Scalar logUniform(Scalar low, Scalar high);
    /// Uniform integer in [low, high].
    int integer(int low, int high);
    /// True with probability p.
    bool chance(Scalar p) { return unit() < p; }

private:
    std::mt19937_64 m_engine;
};

/// The four fixed walls around the soak's box (soak_constants.h), named "wall-floor",
/// "wall-ceiling", "wall-left" and "wall-right".
void addClosedBox(model::World& world);

/// A random scene from `seed`: the closed box, then minBodies to maxBodies dynamic bodies, one to
/// a cell of the box, and maybe springs, joints, a soft body (softened until its integrator can step
/// its grid) and a fixed obstacle. The scene is saved and read back through the scene loader, as a
/// file would be, so it has everything the loader derives; it must load with no range warning.
/// Throws std::logic_error when it does not (a bug of the generator or of the loader).
model::World makeRandomScene(std::uint64_t seed, const RandomSceneOptions& options);

} // namespace impetus::soak
