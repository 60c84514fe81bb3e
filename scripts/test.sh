#!/usr/bin/env bash
# Install what is missing, build everything, and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages test
# The browser build first (build-web/), for the web tests among the suite (tests/web/).
bash scripts/build-web.sh
build_wobble -DWOBBLE_BUILD_TESTS=ON -DWOBBLE_WEB_TESTS=ON
seed_test_costs build tests/test_costs.txt
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
