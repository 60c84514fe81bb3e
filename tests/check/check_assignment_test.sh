#!/usr/bin/env bash
# Tests of scripts/check-assignment.sh, one scenario per ctest test (tests/CMakeLists.txt):
#
#   tests/check/check_assignment_test.sh SCENARIO WORK_FOLDER
#
# Planted bugs are made at test time by copying src/sim/seed and editing one line of one file,
# so they follow the seed as it changes; an edit whose text is no longer in the seed fails the
# test instead of planting nothing. All scenarios share one object cache in WORK_FOLDER/cache:
# the first (SeedPasses, the fixture) compiles Wobble's side, the others only what they change.
set -euo pipefail

scenario=$1
work=$2
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
script="$root/scripts/check-assignment.sh"
seed="$root/src/sim/seed"
cache="$work/cache"
dir="$work/$scenario"
rm -rf "$dir"
mkdir -p "$dir"

fail() {
  echo "FAILED: $*" >&2
  exit 1
}

# run_check ARGUMENT...: run the script; its stdout in $out, stderr in $err, exit in $status.
run_check() {
  set +e
  "$script" --cache "$cache" "$@" >"$dir/stdout.txt" 2>"$dir/stderr.txt"
  status=$?
  set -e
  out=$(cat "$dir/stdout.txt")
  err=$(cat "$dir/stderr.txt")
  echo "\$ check-assignment.sh $* -> exit $status"
  [ -z "$out" ] || echo "$out"
  [ -z "$err" ] || echo "stderr: $err"
}

expect_status() {
  [ "$status" = "$1" ] || fail "expected exit $1, got $status"
}

# A copy of the seed (with its headers unless told "no-headers") to plant a bug in.
submission() {
  mkdir -p "$dir/submission"
  cp "$seed"/*.cpp "$dir/submission/"
  [ "${1:-}" = no-headers ] || cp "$seed"/*.h "$dir/submission/"
}

# plant FILE OLD NEW: replace the one occurrence of OLD in the submission's FILE by NEW.
plant() {
  python3 - "$dir/submission/$1" "$2" "$3" <<'PYTHON'
import sys
path, old, new = sys.argv[1:]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(f"plant: {old!r} occurs {text.count(old)} times in {path}, expected once")
open(path, "w").write(text.replace(old, new))
PYTHON
}

functions=(signed_incidence_matrix_dense signed_incidence_matrix_sparse
           fast_mass_springs_precomputation_dense fast_mass_springs_precomputation_sparse
           fast_mass_springs_step_dense fast_mass_springs_step_sparse)

# expect_failures NAME=PHRASE|PHRASE... : exactly the named functions fail, each line holding
# every |-separated phrase; every other function passes, in the assignment's order; exit 1.
expect_failures() {
  local -A wanted=()
  local entry
  for entry in "$@"; do wanted[${entry%%=*}]=${entry#*=}; done
  expect_status 1
  [ "$(echo "$out" | wc -l)" = 6 ] || fail "expected 6 lines, got $(echo "$out" | wc -l)"
  local index=0 line function phrase
  while IFS= read -r line; do
    function=${functions[$index]}
    index=$((index + 1))
    if [ -n "${wanted[$function]:-}" ]; then
      [[ "$line" == "FAIL  $function: "* ]] || fail "expected $function to fail: $line"
      IFS='|' read -ra phrases <<<"${wanted[$function]}"
      for phrase in "${phrases[@]}"; do
        [[ "$line" == *"$phrase"* ]] || fail "expected '$phrase' in: $line"
      done
    else
      [ "$line" = "PASS  $function" ] || fail "expected $function to pass: $line"
    fi
  done <<<"$out"
}

case "$scenario" in
  SeedPasses)
    run_check "$seed"
    expect_status 0
    expected=$(printf 'PASS  %s\n' "${functions[@]}")
    [ "$out" = "$expected" ] || fail "expected six PASS lines"
    ;;
  HeadersOptionalAndOutputIgnored)
    # Only the .cpp files; one of them prints (as a student's debugging would): the output of a
    # student's code must not reach the checker's lines.
    submission no-headers
    plant signed_incidence_matrix_dense.cpp '#include "signed_incidence_matrix_dense.h"' \
      '#include "signed_incidence_matrix_dense.h"
#include <cstdio>'
    plant signed_incidence_matrix_dense.cpp 'A = Eigen::MatrixXd::Zero(E.rows(), n);' \
      'A = Eigen::MatrixXd::Zero(E.rows(), n); std::printf("debug output\n");'
    run_check "$dir/submission"
    expect_status 0
    [ "$out" = "$(printf 'PASS  %s\n' "${functions[@]}")" ] || fail "expected six PASS lines only"
    ;;
  PlantedIncidenceSign)
    submission
    plant signed_incidence_matrix_sparse.cpp 'E(e, 0), 1.0)' 'E(e, 0), -1.0)'
    plant signed_incidence_matrix_sparse.cpp 'E(e, 1), -1.0)' 'E(e, 1), 1.0)'
    run_check "$dir/submission"
    expect_failures "signed_incidence_matrix_sparse=A(0,0) is -1, expected 1|on a 2-vertex spring E = [0 1]"
    ;;
  PlantedMissingPinTerm)
    submission
    plant fast_mass_springs_precomputation_dense.cpp ' + w * C.transpose() * C;' ';'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_precomputation_dense=prefactorization.solve|w CᵀC|on a 2-vertex spring written E = [1 0], vertex 0 pinned"
    ;;
  PlantedExtraIteration)
    submission
    plant fast_mass_springs_step_sparse.cpp 'iteration < 50' 'iteration < 51'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_step_sparse=Unext (step 1 of 4) vertex|on a stiff 10-vertex chain"
    ;;
  PlantedDenseConversion)
    # Right values and no stored zeros (sparseView drops them): only the scale check sees it.
    submission
    plant signed_incidence_matrix_sparse.cpp '  A.resize(E.rows(), n);
  A.setFromTriplets(ijv.begin(), ijv.end());' '  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(E.rows(), n);
  for (const auto& t : ijv) dense(t.row(), t.col()) += t.value();
  A = dense.sparseView();'
    run_check "$dir/submission"
    expect_failures "signed_incidence_matrix_sparse=uses more than 2 GiB on a 100000-vertex chain: is a dense matrix built and converted"
    ;;
  PlantedMassNotDivided)
    submission
    plant fast_mass_springs_precomputation_sparse.cpp 'M / (delta_t * delta_t)' 'M'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_precomputation_sparse=prefactorization.solve(Q·Ucur) vertex|on a 2-vertex spring E = [0 1], no pins"
    ;;
  PlantedStepWithoutForce)
    submission
    plant fast_mass_springs_step_dense.cpp ' + fext + ' ' + '
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_step_dense=Unext (step 1 of 3) vertex|on a 2-vertex spring E = [0 1], no pins"
    ;;
  PlantedStoredZero)
    submission
    plant fast_mass_springs_precomputation_sparse.cpp '  M.setFromTriplets(ijv.begin(), ijv.end());' \
      '  M.setFromTriplets(ijv.begin(), ijv.end());
  M.coeffRef(0, n - 1) += 0.0;'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_precomputation_sparse=M stores an explicit zero at (0,1)|on a 2-vertex spring E = [0 1], no pins"
    ;;
  MissingFolder)
    run_check "$dir/no-such-folder"
    expect_status 2
    [[ "$err" == *"no-such-folder: no such folder"* ]] || fail "expected the folder named"
    [ -z "$out" ] || fail "expected no PASS/FAIL lines"
    ;;
  MissingFile)
    submission
    rm "$dir/submission/fast_mass_springs_step_dense.cpp"
    run_check "$dir/submission"
    expect_status 2
    [[ "$err" == *"missing fast_mass_springs_step_dense.cpp"* ]] || fail "expected the file named"
    rm "$dir/submission/fast_mass_springs_step_sparse.cpp"
    run_check --build-step-server "$dir/submission"
    expect_status 2
    [[ "$err" == *"missing fast_mass_springs_step_sparse.cpp"* ]] || fail "expected the file named"
    ;;
  CompileError)
    submission
    plant signed_incidence_matrix_dense.cpp 'A = Eigen::MatrixXd::Zero(E.rows(), n);' \
      'A = Eigen::MatrixXd::Zero(E.rows(), n) + no_such_thing;'
    run_check "$dir/submission"
    expect_status 2
    [[ "$err" == "check-assignment: cannot compile $dir/submission/signed_incidence_matrix_dense.cpp: "*"error: "*"no_such_thing"*"not declared"* ]] ||
      fail "expected the compiler's first error line"
    [ "$(echo "$err" | wc -l)" = 1 ] || fail "expected one line"
    ;;
  WrongSignature)
    # Would link against the reference's function from the archive and pass, if not refused.
    submission
    plant fast_mass_springs_step_dense.cpp 'const double k, const Eigen::VectorXi& /*b*/' \
      'const float k, const Eigen::VectorXi& /*b*/'
    run_check "$dir/submission"
    expect_status 2
    [[ "$err" == *"fast_mass_springs_step_dense.cpp: fast_mass_springs_step_dense has another signature"*"float"* ]] ||
      fail "expected the signature refused"
    ;;
  CrashAndHang)
    submission
    plant signed_incidence_matrix_sparse.cpp '  A.resize(E.rows(), n);' \
      '  int* volatile nowhere = nullptr;
  *nowhere = 1;
  A.resize(E.rows(), n);'
    # An index out of range: Eigen's assertion aborts, and its message is quoted.
    plant fast_mass_springs_precomputation_dense.cpp 'C(c, b(c)) = 1.0;' 'C(c, b(c) + n) = 1.0;'
    plant fast_mass_springs_step_sparse.cpp '++iteration' 'iteration *= 1'
    run_check --time-limit 3 "$dir/submission"
    expect_failures \
      "signed_incidence_matrix_sparse=crashed with SIGSEGV on a 2-vertex spring E = [0 1], no pins" \
      "fast_mass_springs_precomputation_dense=crashed with SIGABRT on a 2-vertex spring written E = [1 0], vertex 0 pinned|(its last output: \"Assertion \`" \
      "fast_mass_springs_step_sparse=did not finish within 3 s on a 2-vertex spring E = [0 1], no pins"
    ;;
  BuildStepServers)
    # The step servers wobble_student_step_tests drives, into WORK_FOLDER/servers/.
    mkdir -p "$work/servers"
    run_check --build-step-server "$seed" --output "$work/servers/reference"
    expect_status 0
    [ "$out" = "$work/servers/reference" ] && [ -x "$out" ] || fail "expected the server's path"
    submission
    plant fast_mass_springs_step_sparse.cpp '  Unext = Ucur;' '  int* volatile nowhere = nullptr;
  if (Ucur(0, 1) < -0.05) *nowhere = 1;
  Unext = Ucur;'
    run_check --build-step-server "$dir/submission" --output "$work/servers/crashing"
    expect_status 0
    rm -rf "$dir/submission"
    submission
    plant fast_mass_springs_step_sparse.cpp '++iteration' 'iteration *= 1'
    run_check --build-step-server "$dir/submission" --output "$work/servers/hanging"
    expect_status 0
    rm -rf "$dir/submission"
    submission
    plant fast_mass_springs_step_sparse.cpp '#include "fast_mass_springs_step_sparse.h"' \
      '#include "fast_mass_springs_step_sparse.h"
#include <iostream>'
    plant fast_mass_springs_step_sparse.cpp '  Unext = Ucur;' \
      '  std::cout << "debug output from the step" << std::endl;
  Unext = Ucur;'
    run_check --build-step-server "$dir/submission" --output "$work/servers/printing"
    expect_status 0
    ;;
  *)
    fail "unknown scenario $scenario"
    ;;
esac
echo "ok: $scenario"
