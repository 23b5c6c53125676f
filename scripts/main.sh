#!/usr/bin/env bash
# The main job: install what is missing, build, then on the embedded campus map write the map
# pictures (gridcar demo) and run two benchmarks, all in ./gridcar-out:
#  1. the fair race (benchmarks/problems/campus-reeds-shepp.yaml): every planner on OMPL's
#     Reeds-Shepp space with the car's footprint checked along the curves, at 1, 5 and 10 s:
#     gridcar-out/report.md (summary table first), campus-rs.db, .log files and plots;
#  2. the plain SE(2) reference (benchmarks/problems/campus.yaml, straight motions: the car may
#     slide sideways): gridcar-out/se2-reference/report.md.
# Extra arguments go to both `gridcar bench` runs (e.g. --time-limit 2 --runs 1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/gridcar demo --out gridcar-out
./build/gridcar bench benchmarks/problems/campus-reeds-shepp.yaml --out gridcar-out \
  --report-note "Every planner on Reeds-Shepp curves at the car's minimum turning radius, the footprint checked along every motion. The plain SE(2) race (straight motions, not drivable by construction) is the labelled reference in [se2-reference/report.md](se2-reference/report.md)." "$@"
./build/gridcar bench benchmarks/problems/campus.yaml --out gridcar-out/se2-reference \
  --report-note "Reference only: plain SE(2) space, OMPL's straight motions let the car slide sideways; the fair race on Reeds-Shepp curves is [../report.md](../report.md)." "$@"
# the parking suite (generated scenes, both cars, reversing): gridcar's planners and OMPL's on
# the Reeds-Shepp space at 2 s per run; pictures of corner-astar's paths beside the report
mkdir -p gridcar-out/parking
./build/benchmarks/bench_parking --ompl-seconds 2 --png-dir gridcar-out/parking > gridcar-out/parking/report.md
echo "[gridcar] parking suite: gridcar-out/parking/report.md"
