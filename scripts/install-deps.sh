#!/usr/bin/env bash
# Installs the Debian packages gridcar needs, only those that are missing, without prompting.
# Usable on a fresh Debian 12 (bookworm) machine; needs root or sudo for apt-get.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libompl-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  libboost-program-options-dev
  libfcl-dev libeigen3-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libstb-dev
  libgtest-dev libbenchmark-dev
  ompl-demos python3 python3-matplotlib
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
  clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "[gridcar] all ${#PACKAGES[@]} Debian packages already installed"
  exit 0
fi

echo "[gridcar] installing missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "[gridcar] error: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
