#!/usr/bin/env bash
# Install what is missing, build, and open the viewer on a built-in scene.
# Usage: scripts/run.sh [wobble arguments]   (default: the cloth scene in a window)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages run
build_wobble -DWOBBLE_BUILD_TESTS=OFF
[ $# -eq 0 ] && set -- cloth
exec build/src/app/wobble "$@"
