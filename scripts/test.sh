#!/usr/bin/env bash
# The test job: install what is missing, build, and run the whole test suite through CTest;
# then build the library, the program and the tests again under AddressSanitizer +
# UndefinedBehaviorSanitizer (./build-asan, leaks detected, no recovery from undefined
# behaviour) and run the suite there too, except the wall-clock time-limit and slow-checker tests and one
# property test that needs Release speed; then build the
# libFuzzer targets with clang (./build-fuzz) and replay each one's regression inputs and seed
# corpus under the sanitizers (scripts/fuzz.sh 0: the same inputs every run; a timed fuzzing
# run's mutations differ from run to run even with a fixed seed, so its verdict would be
# chance. GRIDCAR_FUZZ_SECONDS=N fuzzes N s per target instead).
# Then the ThreadSanitizer run of the multi-threaded tests (scripts/tsan.sh, ./build-tsan).
# GRIDCAR_SKIP_SANITIZERS=1 skips the second run, GRIDCAR_SKIP_FUZZ=1 the fuzzing,
# GRIDCAR_SKIP_TSAN=1 the ThreadSanitizer run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 1200
if [ "${GRIDCAR_SKIP_FUZZ:-0}" = "1" ]; then
  echo "[gridcar] fuzzing skipped (GRIDCAR_SKIP_FUZZ=1)"
else
  bash scripts/fuzz.sh "${GRIDCAR_FUZZ_SECONDS:-0}"
fi
if [ "${GRIDCAR_SKIP_TSAN:-0}" = "1" ]; then
  echo "[gridcar] ThreadSanitizer run skipped (GRIDCAR_SKIP_TSAN=1)"
else
  echo "[gridcar] ThreadSanitizer build of the multi-threaded tests in ./build-tsan"
  bash scripts/tsan.sh
fi
if [ "${GRIDCAR_SKIP_SANITIZERS:-0}" = "1" ]; then
  echo "[gridcar] sanitizer run skipped (GRIDCAR_SKIP_SANITIZERS=1)"
  exit 0
fi
echo "[gridcar] sanitizer build (address, undefined) in ./build-asan"
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIDCAR_SANITIZE=address,undefined \
    -DGRIDCAR_BUILD_BENCHMARKS=OFF
fi
cmake --build build-asan -j"${GRIDCAR_JOBS:-2}"
# leaks are errors; the only suppressions are upstream leaks named in tests/sanitizers/lsan.supp
# (full unwinding, so that a suppression can name the frame inside OMPL)
export ASAN_OPTIONS="detect_leaks=1:fast_unwind_on_malloc=0:abort_on_error=0"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# the time-limit and slow-checker tests measure wall-clock lateness, which the sanitizers' slow
# allocation (full unwinding on every malloc) distorts: building a car-lattice path of a
# thousand OMPL states after the stop takes some 55 ms here, 1 ms with fast unwinding; the
# smoothed-path property test plans 18 campus queries under 5 s limits that the sanitizers'
# slowdown would mostly turn into timeouts: they run in the normal build above, not here
# the curve comparisons with OMPL draw 10^5 pairs here, not 10^6 (the Release run above does
# the million; the sanitizers look at the same code paths at a tenth of the 2.5 CPU-minutes)
# the goal-kind suite takes its 0.5 m scenes alone here (its 0.2 m scenes cost the sanitizers
# some 15 minutes of test time for the same code paths; the Release run above takes both)
GRIDCAR_CURVE_PAIRS=100000 GRIDCAR_GOAL_KINDS_CELLS=0.5 ctest --test-dir build-asan --output-on-failure -j2 --timeout 1800 \
  -E 'TimeLimitIsHonoured|NoSmoothedPathThatIsNotDrivable|ASlowValidityCheckerIsStillStoppedPromptly'
