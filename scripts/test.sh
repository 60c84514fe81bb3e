#!/usr/bin/env bash
# Install what is missing, build everything, and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages test
build_wobble -DWOBBLE_BUILD_TESTS=ON
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
