#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages Stroma needs that are missing. Idempotent, and silent when
# everything is present. Run as root (or with sudo available).
set -euo pipefail

packages=(
  cmake ninja-build g++ ccache pkg-config
  libeigen3-dev libtinyxml2-dev libtbb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libsuitesparse-dev   # CHOLMOD, for the optional Cholmod plugin
  zlib1g-dev   # gzip/zlib-compressed NRRD and MetaImage volume images (SparseGrid)
  gnuplot-nox   # PNG plots of error against run time (framework/report/Chart)
  libmetis-dev   # automatic mesh partitions of the hybrid model (DomainDecomposition)
  libbullet-dev  # dynamic AABB trees of collision detection (Collision)
  calculix-ccx   # independent FE reference runs (share/reference/calculix/cantilever_ccx.py)
  clang libclang-rt-14-dev   # libFuzzer and LeakSanitizer for the fuzz and leak tests
  libosmesa6-dev libpng-dev   # headless rendering to PNG (stroma render, Rendering plugin)
  libglfw3-dev   # the interactive viewer (stroma view, Viewer plugin)
  xvfb xauth   # a virtual display for the viewer's tests
  python3-meshio   # an independent reader of the exported VTU files, in their test
  libassimp-dev   # meshes of every format (MeshAssimpLoader, MeshAssimp plugin)
  liburdfdom-dev   # robots from URDF files (URDFLoader, URDF plugin)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing packages: ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
