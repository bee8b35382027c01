#!/usr/bin/env bash
# Installs the Debian packages TissueContact needs (when missing), then
# configures and builds it in Release mode in ./build.
#
#   contrib/setup.sh            # used by contrib/run.sh and contrib/test.sh
#
# Environment: BUILD_DIR (default: build), JOBS (default: number of cores).
set -euo pipefail

root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-"$root_dir/build"}
jobs=${JOBS:-$(nproc)}

# libopenblas0-serial: Debian's optimized BLAS and LAPACK, which take over
# libblas.so.3 and liblapack.so.3 from the reference implementation that
# libdeal.ii-dev brings (UMFPACK's and MUMPS' dense kernels: a direct solve
# of the coarse knee 2.5 times faster, doc/theory/04-solver.md sec. 4.5).
# The serial build: threaded BLAS would compete with TBB's threads.
packages=(libdeal.ii-dev libopenblas0-serial zlib1g-dev gmsh numdiff gnuplot-nox python3 cmake g++ make)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "-- installing Debian packages: ${missing[*]}"
  sudo_cmd=""
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -q
  $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S "$root_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j "$jobs"
