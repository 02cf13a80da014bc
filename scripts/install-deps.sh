#!/usr/bin/env bash
# Installs, from Debian 12's archive, whatever the build needs and the machine lacks.
# Idempotent: does nothing (and asks no network) when everything is already there.
set -euo pipefail
packages=(
  build-essential cmake pkg-config python3
  libeigen3-dev libboost-dev libboost-iostreams-dev libyaml-cpp-dev libceres-dev
  libmuparser-dev libcli11-dev libstb-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # Levels: meshes (assimp), Quake III .pk3 archives (libzip), triangle queries (Embree 3),
  # navigation meshes for walks (Recast/Detour), and the corpus of 50 real maps.
  libassimp-dev libzip-dev libembree-dev librecast-dev
  openarena-088-data openarena-085-data
  # WCSP: toulbar2's JSON .cfn files, and toulbar2 itself as a reference solver.
  nlohmann-json3-dev toulbar2
  # Clusters: Open MPI for `mpirun ... sightline run` (optional at build time).
  openmpi-bin libopenmpi-dev
  # The report's 3D replay (three.js, inlined) and its check in a real headless browser.
  libjs-three chromium
  # The Python module (pybind11), its tests (pytest) and examples (numpy, matplotlib).
  python3-dev pybind11-dev python3-pytest python3-numpy python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
