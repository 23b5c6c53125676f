#!/usr/bin/env bash
# Configures (once) and builds gridcar in ./build (Release, 2 parallel jobs).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${GRIDCAR_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD_DIR" -j"${GRIDCAR_JOBS:-2}"
