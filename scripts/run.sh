#!/usr/bin/env bash
# Install what is missing, build, and run Wobble on a built-in scene.
# Usage: scripts/run.sh [wobble arguments]   (default: the cloth scene)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages run
build_wobble -DWOBBLE_BUILD_TESTS=OFF
if [ $# -eq 0 ]; then
  # The interactive viewer is not built yet: simulate the cloth for 2 s and write the result.
  set -- cloth --headless --frames 120 --stats --export-obj build/cloth.obj
  echo "wobble: writing the cloth after 120 frames to build/cloth.obj" >&2
fi
exec build/src/app/wobble "$@"
