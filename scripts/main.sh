#!/usr/bin/env bash
# The main job: install what is missing, build, then on the embedded campus map write the map
# pictures (gridcar demo) and run the benchmark of our planners against OMPL's
# (benchmarks/problems/campus.yaml): OMPL .log, SQLite database, report.md and plots, all in
# ./gridcar-out. Extra arguments go to `gridcar bench` (e.g. --time-limit 2 --runs 1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/gridcar demo --out gridcar-out
./build/gridcar bench benchmarks/problems/campus.yaml --out gridcar-out "$@"
