#!/usr/bin/env bash
# ThreadSanitizer run of what gridcar runs in several threads: builds the libraries and the
# concurrency / planner-lifecycle tests (one map, distance field and checker shared by planners
# in four threads; progress properties read while a planner solves; ompl::tools::Benchmark with
# progress sampling) with -fsanitize=thread in ./build-tsan, and runs them; any report fails.
# OMPL itself is not instrumented; the suppressions in tests/sanitizers/tsan.supp name only
# frames inside it. Called by scripts/test.sh (GRIDCAR_SKIP_TSAN=1 skips it there).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build-tsan/CMakeCache.txt ]; then
  cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIDCAR_SANITIZE=thread -DGRIDCAR_BUILD_BENCHMARKS=OFF
fi
cmake --build build-tsan -j"${GRIDCAR_JOBS:-2}" --target gridcar_thread_tests
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tests/sanitizers/tsan.supp"
ctest --test-dir build-tsan --output-on-failure -j1 --timeout 900
