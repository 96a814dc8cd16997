#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Set up, build and run fdem-slope on Debian 12 (run as root for the install).
#   bash bootstrap.sh run [case.prm]   install, build the program (Release),
#                                      run a case (default prm/paper_slope.prm)
#   bash bootstrap.sh test             install, build (Release), run ctest
#                                      (without the tests labelled heavy)
#   bash bootstrap.sh quick            the same, the tests labelled quick only
#   bash bootstrap.sh heavy            the same, then the heavy tests only
#   bash bootstrap.sh sanitize [all]   install, build with AddressSanitizer and
#                                      UndefinedBehaviorSanitizer (Debug, -O1)
#                                      in build-sanitize, run the tests
#                                      labelled quick (every kind of claim at
#                                      its smallest size); with all, the
#                                      whole ctest
# Environment: BUILD_DIR (default build, build-sanitize for sanitize),
#   JOBS (default nproc), CMAKE_ARGS (extra configure flags).
set -euo pipefail
cd "$(dirname "$0")"

# What a run needs. libopenblas0-pthread: an optimised BLAS/LAPACK for MUMPS
# and the dense mixed system, which can use threads (one unless
# OPENBLAS_NUM_THREADS asks for more: doc/theory.md, "Threads"); Debian's
# alternatives put it in place of the reference one (and of
# libopenblas0-serial if that is there). libsuitesparse-dev: CHOLMOD (Direct
# solver = CHOLMOD); deal.II depends on it. python3-numpy,
# python3-matplotlib and python3-vtk9: the run's report.html. openmpi-bin:
# mpirun for MPI runs (libdeal.ii-dev pulls in OpenMPI's libraries; named
# here so that mpirun is there for sure). ccache: CMakeLists.txt compiles
# through it where it is installed, so that a rebuild, a second clone or a
# worktree reuses what was compiled once (doc/build.md).
packages=(cmake make g++ ccache libdeal.ii-dev gmsh libgmsh-dev nlohmann-json3-dev
          libmumps-dev libsuitesparse-dev python3-vtk9 python3-numpy python3-matplotlib
          libopenblas0-pthread openmpi-bin)
# What only the tests need (about 0.5 GB that `run` does not install):
# GoogleTest, numdiff, clang-format (Debian 12: version 14) for the ctest
# format.check, and chromium, the headless browser in which the ctest
# report.paper_slope loads a run's report.html (the test is skipped only
# where it is missing).
test_packages=(libgtest-dev numdiff clang-format chromium)
if [[ ${1:-run} != run ]]; then
  packages+=("${test_packages[@]}")
fi

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

mode=${1:-run}
jobs=${JOBS:-$(nproc)}
case "$mode" in
  run)
    # Without the tests, which need the test packages (CMakeLists.txt).
    build_dir=${BUILD_DIR:-build}
    configure=(-DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF)
    ;;
  test|quick|heavy)
    build_dir=${BUILD_DIR:-build}
    configure=(-DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON)
    ;;
  sanitize)
    # deal.II knows only Debug and Release; Debug links its checked library,
    # and CMakeLists.txt adds -O1 to our code. The test environment
    # (ASAN/LSAN/UBSAN_OPTIONS, suppressions) is set by tests/CMakeLists.txt.
    build_dir=${BUILD_DIR:-build-sanitize}
    configure=(-DCMAKE_BUILD_TYPE=Debug -DFDEM_SANITIZE=ON -DBUILD_TESTING=ON)
    ;;
  *)
    echo "usage: bash bootstrap.sh run [case.prm] | test | quick | heavy | sanitize [all]" >&2
    exit 2
    ;;
esac
cmake -S . -B "$build_dir" "${configure[@]}" ${CMAKE_ARGS:-} > /dev/null
# A run needs the program only; the tests need everything.
if [[ $mode == run ]]; then
  cmake --build "$build_dir" -j "$jobs" --target fdem-slope
else
  cmake --build "$build_dir" -j "$jobs"
fi

case "$mode" in
  run)
    "$build_dir/fdem-slope" "${2:-prm/paper_slope.prm}"
    ;;
  test)
    cd "$build_dir" && ctest --output-on-failure -j "$jobs" -LE heavy
    ;;
  quick)
    cd "$build_dir" && ctest --output-on-failure -j "$jobs" -L quick
    ;;
  heavy)
    cd "$build_dir" && ctest --output-on-failure -j "$jobs" -L heavy
    ;;
  sanitize)
    if [[ ${2:-} == all ]]; then
      cd "$build_dir" && ctest --output-on-failure -j "$jobs" --timeout 3600
    else
      cd "$build_dir" && ctest --output-on-failure -j "$jobs" --timeout 3600 -L quick
    fi
    ;;
esac
