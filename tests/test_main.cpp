// The test program's main: OMPL's random seed fixed before any test runs, so that every test
// that runs an OMPL planner (RRT, PRM, BIT*, the path simplifier) draws the same samples on
// every run. CTest runs each test in a process of its own, so each test sees the same sequence
// whichever tests run before it. GRIDCAR_TEST_SEED=N runs them with another seed (what holds
// for every seed must hold there too).
#include <gtest/gtest.h>

#include <ompl/util/RandomNumbers.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char **argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    const char *env = std::getenv("GRIDCAR_TEST_SEED");
    const unsigned long seed = env ? std::strtoul(env, nullptr, 10) : 20261201ul;
    ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));
    std::printf("[gridcar] OMPL random seed %lu (GRIDCAR_TEST_SEED)\n", seed);
    return RUN_ALL_TESTS();
}
