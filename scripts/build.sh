#!/usr/bin/env bash
# Configures (once) and builds gridcar in ./build (Release, 2 parallel jobs), the libraries
# shared (libgridcar_*.so with a SOVERSION, as a distribution packages them); the sanitizer
# build of scripts/test.sh keeps CMake's default, static, so the test job installs and links
# both kinds (test cmake_export).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${GRIDCAR_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON
fi
cmake --build "$BUILD_DIR" -j"${GRIDCAR_JOBS:-2}"
