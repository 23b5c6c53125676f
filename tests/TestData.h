#pragma once
// Locates test data. Real maps live in ../shared beside the repository (CI has it, a fresh
// clone may not): tests that need them skip with a message naming the missing folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace gridcar::test
{
inline std::string sharedDir() { return GRIDCAR_SHARED_DIR; }
inline std::string sharedMaps() { return sharedDir() + "/maps"; }
inline bool haveSharedMaps() { return std::filesystem::is_directory(sharedMaps()); }
inline std::string tmpDir()
{
    std::filesystem::create_directories(GRIDCAR_TEST_TMP);
    return GRIDCAR_TEST_TMP;
}
}  // namespace gridcar::test

#define GRIDCAR_REQUIRE_SHARED_MAPS()                                                                    \
    do                                                                                                   \
    {                                                                                                    \
        if (!gridcar::test::haveSharedMaps())                                                            \
            GTEST_SKIP() << "real maps not available: " << gridcar::test::sharedMaps()                   \
                         << " does not exist (a fresh clone has no ../shared; CI provides it)";          \
    } while (0)
