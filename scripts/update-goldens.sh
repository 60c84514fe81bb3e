#!/usr/bin/env bash
# Re-render every golden image into tests/golden/ with the current build. Only for an intended
# visual change: look at the new images, and commit them together with the change.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages test
build_wobble -DWOBBLE_BUILD_TESTS=ON
WOBBLE_UPDATE_GOLDEN=1 ctest --test-dir build --output-on-failure -R 'golden/'
git status --short tests/golden
