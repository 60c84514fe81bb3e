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
# One test more than the cores: some tests wait (a hang's time limit, a page's pauses between
# input events, a child's exit) and would leave a core idle. 637 s against 673 s with two on the
# 2-core development machine, the cores then busy the whole time (docs/development.md).
ctest --test-dir build --output-on-failure --parallel "$(( $(nproc) + 1 ))"
