#!/usr/bin/env bash
# The main job: install what is missing, build, and run gridcar's report on the embedded
# campus map (written to ./gridcar-out). Extra arguments go to `gridcar demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/gridcar demo --out gridcar-out "$@"
