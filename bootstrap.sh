#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Set up, build and run fdem-slope on Debian 12 (run as root for the install).
#   bash bootstrap.sh run [case.prm]   install, build (Release), run a case
#                                      (default prm/paper_slope.prm)
#   bash bootstrap.sh test             install, build (Release), run ctest
# Environment: BUILD_DIR (default build), JOBS (default nproc),
#   CMAKE_ARGS (extra configure flags, e.g. -DFDEM_SANITIZE=ON).
set -euo pipefail
cd "$(dirname "$0")"

# libopenblas0-serial: an optimised BLAS/LAPACK for MUMPS and the dense
# mixed system; Debian's alternatives put it in place of the reference one.
packages=(cmake make g++ libdeal.ii-dev gmsh libgmsh-dev nlohmann-json3-dev
          libmumps-dev libgtest-dev numdiff python3-vtk9 python3-numpy python3-matplotlib
          libopenblas0-serial)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "Installing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
fi

build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release ${CMAKE_ARGS:-} > /dev/null
cmake --build "$build_dir" -j "${JOBS:-$(nproc)}"

case "${1:-run}" in
  run)
    "$build_dir/fdem-slope" "${2:-prm/paper_slope.prm}"
    ;;
  test)
    cd "$build_dir" && ctest --output-on-failure -j "${JOBS:-$(nproc)}"
    ;;
  *)
    echo "usage: bash bootstrap.sh run [case.prm] | test" >&2
    exit 2
    ;;
esac
