#!/usr/bin/env bash
# Installs everything geodex needs to build, test, fuzz and benchmark, from Debian 12 packages.
# Idempotent: when every package is already installed it does nothing (no apt-get update).
# Runs as root, or as a user with sudo; never asks questions (DEBIAN_FRONTEND=noninteractive).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build g++
  clang libclang-rt-14-dev llvm       # asan and fuzz presets; libFuzzer runtime
  libeigen3-dev                       # solver
  libgtest-dev librapidcheck-dev      # unit and property tests
  libcli11-dev                        # the geodex command-line tool
  libcgal-dev libgmp-dev libmpfr-dev  # differential oracle (CGAL Surface_mesh_shortest_path)
  libcgal-demo                        # ~150 real meshes (data.tar.gz) for tests, demo, benchmarks
  libpng-dev libstb-dev               # images (geodex render)
  python3 git
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-yaml  # the Python module (python/)
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$pkg" 2>/dev/null || true)
  [[ $status == installed ]] || missing+=("$pkg")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

if [[ $(id -u) -eq 0 ]]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  # Prompt for a password only when someone is there to type it; otherwise fail at once.
  if [[ -t 0 ]]; then SUDO=(sudo); else SUDO=(sudo -n); fi
else
  echo "install-deps: missing packages: ${missing[*]}" >&2
  echo "install-deps: run this script as root (or install sudo) to install them" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
  "${PACKAGES[@]}"
