#!/usr/bin/env bash
# Sets up and builds TissueContact (see contrib/setup.sh), then builds and runs
# the whole ctest suite. Extra arguments go to ctest (e.g. -R materials).
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-"$root_dir/build"}
"$root_dir/contrib/setup.sh"
cd "$build_dir"
ctest -j "${JOBS:-$(nproc)}" --output-on-failure "$@"
