#pragma once
// The solver settings the dynamics tests run with. Those tests are built twice: as they are, and
// with IMPETUS_TEST_BATCH_EVERY_WORLD defined, which sends every world, however small, through the
// batched velocity passes that only large worlds take (controller/contact_batches.h). Both builds
// must meet the same textbook results.

#include "controller/simulation.h"

namespace impetus::controller {

inline SolverSettings settingsUnderTest()
{
    SolverSettings settings;
#ifdef IMPETUS_TEST_BATCH_EVERY_WORLD
    settings.batchMinConstraints = 0;
#endif
    return settings;
}

/// True in the build whose every world is batched.
inline constexpr bool kEveryWorldBatched =
#ifdef IMPETUS_TEST_BATCH_EVERY_WORLD
    true;
#else
    false;
#endif

} // namespace impetus::controller
