#!/usr/bin/env bash
# Install what is missing, build the test programs of Wobble's own logic with AddressSanitizer,
# LeakSanitizer and UndefinedBehaviorSanitizer into build-sanitize/, and run them under them
# (what is covered and what is left to the plain pass: below).
# Any finding, a leak included, fails the test it happens in (a child wobble's finding fails
# the test that ran it), and so this script.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
source scripts/ensure-packages.sh
# GCC's sanitizer runtimes (libasan8, libubsan1) come with g++: libgcc-12-dev depends on them.
ensure_packages test

# -O2 -g1: fast enough for the suite, with line numbers in every report (-g1 is line tables and
# function names: -g's full debug information took a fifth of the build's time).
flags="-O2 -g1 -DNDEBUG"
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWOBBLE_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$flags" \
  -DWOBBLE_BUILD_TESTS=ON >/dev/null

# Set before the build too: gtest_discover_tests runs each test program while building.
# - exitcode=99 on any finding, so a sanitizer failure is never taken for wobble's own exit codes
#   (1 and 2, which tests check). UBSan reads its own: without it a UBSan finding exits with 1.
# - intercept_tls_get_addr=0: GCC 12's runtime guesses the bounds of each dynamic TLS block (the
#   thread-locals of dlopen'ed libraries: Mesa's driver, LLVM) from a glibc 2.19 block header.
#   Glibc 2.36 has no such header, so now and then a block gets bounds like 0x1059-0x18000215b
#   and LeakSanitizer dies scanning them ("Tracer caught signal 11"). Without the guess those
#   blocks are ordinary heap blocks to LeakSanitizer (glibc allocates them with malloc), and the
#   suite reports no leak from them.
export ASAN_OPTIONS="detect_leaks=1:exitcode=99:abort_on_error=0:halt_on_error=1:\
strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:\
strict_init_order=1:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=99"
# Leaks inside system libraries that Wobble cannot fix may be suppressed there, by library name
# only, each with its reason. (Mesa unloading its driver is handled at link time instead: see
# tests/sanitizers/keep_libraries_loaded.cpp.)
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp"

# What the sanitizers cover: Wobble's own code where memory and undefined behaviour can go wrong
# on bad or large input: the simulation (wobble_sim_tests, its allocation test), the readers of
# every file format (wobble_io_tests), the checker's sandbox and the student's step in its child
# process (wobble_bounded_tests, wobble_student_*), the command line, outputs and viewer logic
# driven through the real executable (wobble_app_tests, wobble_video_tests,
# wobble_added_setting_test), picking and the panel's logic and the camera's math
# (wobble_interaction_tests, wobble_ui_tests, wobble_render_tests). Left to the plain pass of
# scripts/test.sh, which runs them all: the golden images (their time is Mesa's software
# rasterizer, whose code is not Wobble's; the app tests still render through it under the
# sanitizers), the tests that simulate or render a scene for
# many steps (tests/sanitizers/long_tests.txt: shorter tests run the same code here), the course
# checker's scenarios
# (CheckAssignment.*, labelled checker_scenario: scripts/check-assignment.sh compiles the
# student's and the checker's code itself, without these flags, so under this build they would
# repeat the plain pass's work exactly; SeedPasses and BuildStepServers stay, since the student
# tests need the cache and the step servers they build), seed_standalone (the same six functions
# are in wobble_sim, instrumented here and run by its tests), the docs checks, and the benchmarks,
# which no test runs.
targets=(wobble_sim_tests wobble_sim_allocation_tests wobble_io_tests wobble_bounded_tests
  wobble_student_step_tests wobble_student_view_tests wobble_student_build_tests wobble_app_tests
  wobble_video_tests
  wobble_added_setting_test wobble_interaction_tests wobble_ui_tests wobble_render_tests)
cmake --build build-sanitize --parallel "$(nproc)" --target "${targets[@]}"
# The long tests' names, anchored, as one regular expression (their only special character is
# the dot).
long_tests=$(grep -v '^#' tests/sanitizers/long_tests.txt | sed 's/[.]/[.]/g' | paste -sd '|' -)
seed_test_costs build-sanitize tests/sanitizers/test_costs.txt
ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" \
  --label-exclude checker_scenario \
  --exclude-regex "_NOT_BUILT|^docs/|^SeedFunctions[.]|^ShippedClothPile[.]|^($long_tests)\$"

