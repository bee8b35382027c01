#!/usr/bin/env bash
# Sets up and builds TissueContact (see contrib/setup.sh), then runs the
# program. Without arguments it runs the small built-in default scene.
#
#   contrib/run.sh                  # built-in default scene
#   contrib/run.sh prm/beam.prm     # a scene file
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root_dir/contrib/setup.sh"
exec "${BUILD_DIR:-$root_dir/build}/tissue-contact" "$@"
