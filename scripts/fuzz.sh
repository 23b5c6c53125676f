#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang in ./build-fuzz (AddressSanitizer +
# UndefinedBehaviorSanitizer) and runs each for SECONDS (default 300), starting from the seed
# corpus in tests/fuzz/corpus plus small files of ../shared/maps when present. The corpus grows
# in ./build-fuzz/corpus; a crash stops the script with the target's report and the input in
# ./build-fuzz/crashes. Prints the executions of each target.
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]
# The corpus also holds tests/fuzz/replay/TARGET.tar.gz: the inputs of earlier fuzzing runs
# merged (libFuzzer's -merge=1) to those that reach distinct coverage; docs/reliability.md says
# how they were made and how to refresh them.
# SECONDS=0 replays instead: every regression input and every corpus input once, no mutation
# (what scripts/test.sh and CI run: the same inputs every time, so the verdict cannot change
# by chance; libFuzzer's mutations are not reproducible even with a fixed seed). Fuzzing for
# new findings is this script with SECONDS > 0; each finding becomes a file in
# tests/fuzz/regressions/TARGET/ and a test. GRIDCAR_FUZZ_SEED=N fixes libFuzzer's seed.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-300}
shift || true
TARGETS=("$@")
if [ ${#TARGETS[@]} -eq 0 ]; then
  TARGETS=(fuzz_ros_map fuzz_image fuzz_movingai_map fuzz_movingai_scen fuzz_vehicle_yaml fuzz_problem_yaml
           fuzz_scenario_yaml fuzz_cli_args fuzz_path_file)
fi
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  CXX=clang++ CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIDCAR_FUZZ=ON \
    -DGRIDCAR_BUILD_TESTS=OFF -DGRIDCAR_BUILD_BENCHMARKS=OFF
fi
cmake --build build-fuzz -j"${GRIDCAR_JOBS:-2}" --target fuzz_targets
mkdir -p build-fuzz/crashes
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in "${TARGETS[@]}"; do
  corpus=build-fuzz/corpus/$t
  mkdir -p "$corpus"
  cp -n tests/fuzz/corpus/"$t"/* "$corpus"/ 2>/dev/null || true
  # inputs of earlier fuzzing runs, merged to those that reach distinct coverage
  if [ -f tests/fuzz/replay/"$t".tar.gz ]; then tar -xzf tests/fuzz/replay/"$t".tar.gz -C "$corpus"; fi
  if [ -d ../shared/maps ]; then  # real files as seeds, the small ones (libFuzzer's inputs stay <= 64 KB)
    case $t in
      fuzz_movingai_map) find ../shared/maps -name '*.map' -size -64k -exec cp -n {} "$corpus"/ \; ;;
      fuzz_movingai_scen) find ../shared/maps -name '*.scen' -size -64k -exec cp -n {} "$corpus"/ \; ;;
      fuzz_image) for f in $(find ../shared/maps \( -name '*.pgm' -o -name '*.ppm' -o -name '*.png' \) -size -64k); do
                    case $f in *.pgm) b='\x00';; *.ppm) b='\x01';; *) b='\x02';; esac
                    { printf "$b"; cat "$f"; } > "$corpus/shared-$(basename "$f")"; done ;;
    esac
  fi
  log=build-fuzz/$t.log
  # every input that once found a problem runs first (tests/fuzz/regressions/TARGET/)
  if compgen -G "tests/fuzz/regressions/$t/*" > /dev/null; then
    ./build-fuzz/tests/fuzz/$t tests/fuzz/regressions/"$t"/* > "$log" 2>&1 || { tail -n 60 "$log"; \
      echo "[fuzz] $t: a regression input fails again" >&2; exit 1; }
    echo "[fuzz] $t: $(ls tests/fuzz/regressions/"$t" | wc -l) regression input(s) pass"
  fi
  seed=()
  if [ -n "${GRIDCAR_FUZZ_SEED:-}" ]; then seed=(-seed="$GRIDCAR_FUZZ_SEED"); fi
  if [ "$SECONDS_EACH" = "0" ]; then
    echo "[fuzz] $t: replaying its corpus ($(ls "$corpus" | wc -l) inputs)"
    limit=(-runs=0)
  else
    echo "[fuzz] $t for ${SECONDS_EACH} s"
    limit=(-max_total_time="$SECONDS_EACH")
  fi
  if ! ./build-fuzz/tests/fuzz/$t "$corpus" "${seed[@]}" "${limit[@]}" -max_len=65536 -timeout=10 \
      -rss_limit_mb=2048 -malloc_limit_mb=1024 -artifact_prefix=build-fuzz/crashes/$t- -print_final_stats=1 \
      > "$log" 2>&1; then
    tail -n 60 "$log"
    echo "[fuzz] $t FOUND A PROBLEM: the input is in build-fuzz/crashes/" >&2
    exit 1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  echo "[fuzz] $t: $runs executions, no finding (corpus: $(ls "$corpus" | wc -l) inputs)"
done
