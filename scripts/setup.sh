#!/usr/bin/env bash
# Installs the Debian packages cellproj builds against, when missing. Idempotent: with everything
# present it only asks dpkg (well under a second). apt-get as root, sudo otherwise.
#   scripts/setup.sh          what the build and tests need
#   scripts/setup.sh --fuzz   and clang's libFuzzer, for bench/fuzz.sh
#   scripts/setup.sh --bench  and matplotlib, for bench/run's plots
# Xvfb runs the VTK mapper's and the ParaView plugin's tests in a real window. ParaView's Python
# (python3-paraview) conflicts with python3-vtk9, which libvtk9-dev needs: the plugin's test
# unpacks it into the build tree instead (tests/paraview/run.sh).
set -euo pipefail
packages=(
  build-essential cmake pkg-config python3 clang-format
  libvtk9-dev libcgal-dev libtet1.5-dev libglm-dev libtbb-dev libnetcdf-dev zlib1g-dev libpng-dev libopenmpi-dev openmpi-bin
  libosmesa6-dev libfreetype-dev fonts-dejavu-core libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-meshio python3-vtk9 python3-pip python3-setuptools python3-wheel
  libavcodec-dev libavformat-dev libavfilter-dev libswscale-dev ffmpeg libopenexr-dev
  libglew-dev xvfb xauth paraview paraview-dev
)
[ "${1:-}" = "--fuzz" ] && packages+=(clang libclang-rt-dev)
[ "${1:-}" = "--bench" ] && packages+=(python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q >&2
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
