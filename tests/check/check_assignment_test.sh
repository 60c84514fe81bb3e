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

# Every process this test starts carries this in its environment, and so does whatever those
# leave behind: left_behind finds them by it. The script's temporary folders go in $dir/tmp.
export WOBBLE_CHECK_TEST="$scenario-$$"
mkdir -p "$dir/tmp"
export TMPDIR="$dir/tmp"

# left_behind: "PID NAME" of each process that carries this test's marker and still runs, after
# up to 2 s for what is ending (a SIGKILL is not instant).
left_behind() {
  local tries found=""
  for tries in $(seq 20); do
    found=$(env -u WOBBLE_CHECK_TEST grep -l -z -x "WOBBLE_CHECK_TEST=$WOBBLE_CHECK_TEST" \
              /proc/[0-9]*/environ 2>/dev/null |
            while IFS= read -r file; do
              pid=${file#/proc/}
              pid=${pid%/environ}
              echo "$pid $(cat "/proc/$pid/comm" 2>/dev/null)"
            done)
    [ -n "$found" ] || return 0
    sleep 0.1
  done
  echo "$found"
}

# expect_nothing_left: no process of this test runs, and the temporary folder is empty.
expect_nothing_left() {
  local left
  left=$(left_behind)
  [ -z "$left" ] || fail "processes left running: $(echo "$left" | paste -sd ',')"
  [ -z "$(ls -A "$dir/tmp")" ] || fail "left in the temporary folder: $(ls -A "$dir/tmp" | paste -sd ' ')"
}

# measured ARGUMENT...: run_check, with the wall time (s) in $seconds and the largest resident
# size of any process it ran (KiB) in $peak_kib.
measured() {
  set +e
  python3 -c '
import resource, subprocess, sys, time
start = time.monotonic()
status = subprocess.call(sys.argv[2:], stdout=open(sys.argv[1] + "/stdout.txt", "w"),
                         stderr=open(sys.argv[1] + "/stderr.txt", "w"))
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
print(status, round(time.monotonic() - start, 1), peak)' "$dir" "$script" --cache "$cache" "$@" \
    >"$dir/measured.txt"
  set -e
  read -r status seconds peak_kib <"$dir/measured.txt"
  out=$(cat "$dir/stdout.txt")
  err=$(cat "$dir/stderr.txt")
  echo "\$ check-assignment.sh $* -> exit $status in $seconds s, at most $peak_kib KiB resident"
  [ -z "$out" ] || echo "$out"
  [ -z "$err" ] || echo "stderr: $err"
}

# compiling FOLDER: whether a compiler of this test runs on a file of the submission FOLDER
# (its command line names the folder, which Wobble's own files' compilers do not).
compiling() {
  local pid
  for pid in $(left_behind | awk '$2 == "cc1plus" { print $1 }'); do
    tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -qF -- "$1" && return 0
  done
  return 1
}

# signal_during_build SIGNAL FOLDER ARGUMENT...: starts the script with ARGUMENT..., sends
# SIGNAL once a compiler of the submission FOLDER runs, and waits for the script: its exit
# status in $status.
signal_during_build() {
  local signal=$1 folder=$2
  shift 2
  # As from a terminal: a background job of a script would ignore SIGINT.
  env --default-signal=INT "$script" --cache "$cache" "$@" >"$dir/stdout.txt" 2>"$dir/stderr.txt" &
  local pid=$! tries started=0
  for tries in $(seq 1200); do
    if compiling "$folder"; then
      started=1
      break
    fi
    sleep 0.1
  done
  kill -s "$signal" "$pid"
  set +e
  wait "$pid"
  status=$?
  set -e
  [ "$started" = 1 ] || fail "the submission's file never reached the compiler: $(cat "$dir/stderr.txt")"
  echo "\$ check-assignment.sh $* <- SIG$signal during the build -> exit $status"
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

# A submission laid out as the course's template (tests/check/course_template): its include/
# headers, and in src/ each file's includes from the template followed by the seed's function.
# With "template" instead, the template's stubs as they are.
template="$root/tests/check/course_template"
course_submission() {
  mkdir -p "$dir/submission"
  cp -r "$template/include" "$template/src" "$dir/submission/"
  [ "${1:-}" = template ] && return 0
  python3 - "$template/src" "$seed" "$dir/submission/src" <<'PYTHON'
import os, sys
template, seed, out = sys.argv[1:]
for name in sorted(os.listdir(template)):
    includes = [l for l in open(os.path.join(template, name)) if l.startswith("#include")]
    body = [l for l in open(os.path.join(seed, name)) if not l.startswith("#include")]
    open(os.path.join(out, name), "w").write("".join(includes) + "".join(body))
PYTHON
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
# Note lines (indented) are not verdicts and are left out.
expect_failures() {
  local -A wanted=()
  local entry
  for entry in "$@"; do wanted[${entry%%=*}]=${entry#*=}; done
  expect_status 1
  local verdicts
  verdicts=$(echo "$out" | grep -v '^      note: ')
  [ "$(echo "$verdicts" | wc -l)" = 6 ] || fail "expected 6 lines, got $(echo "$verdicts" | wc -l)"
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
  done <<<"$verdicts"
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
    # One iteration too many, as <= for < writes it: the hint points at the loop's bounds.
    submission
    plant fast_mass_springs_step_sparse.cpp 'iteration < 50' 'iteration <= 50'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_step_sparse=Unext (step 1 of 4) vertex|on a stiff 10-vertex chain|; hint: it matches 51 local-global iterations from Ucur, one more than the assignment's 50: look at the loop's bounds (for (int i = 0; i < 50; ++i) runs 50 times)"
    ;;
  PlantedMissingIteration)
    # One too few, as a loop that starts at 1 writes it.
    submission
    plant fast_mass_springs_step_sparse.cpp 'int iteration = 0;' 'int iteration = 1;'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_step_sparse=Unext (step 1 of 4) vertex|on a stiff 10-vertex chain|; hint: it matches 49 local-global iterations from Ucur, one fewer than the assignment's 50: look at the loop's bounds (for (int i = 0; i < 50; ++i) runs 50 times)"
    ;;
  RelativeCache)
    # A cache named relative to the working folder, and a student's file not compiled before
    # (so the prelude is linked into its folder): a plain FAIL with its hint, not an ERROR.
    submission
    plant fast_mass_springs_step_sparse.cpp 'iteration < 50' 'iteration < 48'
    # New contents each run, so that the cache holds no object of it.
    echo "// $WOBBLE_CHECK_TEST $(date +%s%N)" >>"$dir/submission/fast_mass_springs_step_sparse.cpp"
    pushd "$dir" >/dev/null
    # The later --cache wins over run_check's own.
    run_check --cache "$(realpath --relative-to=. "$cache")" "$dir/submission"
    popd >/dev/null
    expect_failures "fast_mass_springs_step_sparse=on a stiff 10-vertex chain|; hint: it matches 48 local-global iterations"
    ;;
  PlantedIterationsFarOff)
    # Further off, the hint says how many and what the assignment runs.
    submission
    plant fast_mass_springs_step_sparse.cpp 'iteration < 50' 'iteration < 60'
    run_check "$dir/submission"
    expect_failures "fast_mass_springs_step_sparse=on a stiff 10-vertex chain|; hint: it matches 60 local-global iterations from Ucur; the assignment's step runs a fixed 50"
    ;;
  PlantedDenseConversion)
    # Right values and no stored zeros (sparseView drops them): only the scale check sees it.
    submission
    plant signed_incidence_matrix_sparse.cpp '  A.resize(E.rows(), n);
  A.setFromTriplets(ijv.begin(), ijv.end());' '  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(E.rows(), n);
  for (const auto& t : ijv) dense(t.row(), t.col()) += t.value();
  A = dense.sparseView();'
    run_check "$dir/submission"
    expect_failures "signed_incidence_matrix_sparse=uses more than 2 GiB on a 30000-vertex chain: is a dense matrix built and converted"
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
  CourseTemplate)
    # The course's template as handed out: it compiles with its libigl include and is graded,
    # six FAIL lines, not refused.
    course_submission template
    run_check "$dir/submission"
    expect_status 1
    [ "$(echo "$out" | wc -l)" = 6 ] || fail "expected 6 lines"
    [ "$(echo "$out" | grep -c '^FAIL  ')" = 6 ] || fail "expected six FAIL lines"
    [ -z "$err" ] || fail "expected nothing on stderr"
    ;;
  CourseLayoutPasses)
    # Wobble's functions in the template's layout, with its includes, debug prints through every
    # form of igl::matlab_format a student uses, and Windows line endings in one file.
    course_submission
    plant src/fast_mass_springs_step_dense.cpp '  Unext = Ucur;' '  Unext = Ucur;
  std::ostringstream debug;
  debug << Ucur.format(igl::matlab_format()) << igl::matlab_format(Ucur, "Ucur")
        << igl::matlab_format_index(E, "E") << igl::matlab_format(k, "k");
  igl::matlab_format();'
    plant src/fast_mass_springs_step_sparse.cpp '  Unext = Ucur;' '  Unext = Ucur;
  const std::string debug = igl::matlab_format(A, "A") + igl::matlab_format(M);
  igl::matlab_format();'
    sed -i 's/$/\r/' "$dir/submission/src/signed_incidence_matrix_dense.cpp"
    run_check "$dir/submission"
    expect_status 0
    [ "$out" = "$(printf 'PASS  %s\n' "${functions[@]}")" ] || fail "expected six PASS lines only"
    ;;
  OtherPinWeights)
    # Any large weight used consistently passes: 1e7 in the dense pair, w/2 of 1e10 in the sparse
    # pair, each with a note saying which weight was found.
    course_submission
    plant src/fast_mass_springs_precomputation_dense.cpp 'const double w = 1e10;' 'const double w = 1e7;'
    plant src/fast_mass_springs_step_dense.cpp 'const double w = 1e10;' 'const double w = 1e7;'
    plant src/fast_mass_springs_precomputation_sparse.cpp 'const double w = 1e10;' 'const double w = 1e10 / 2;'
    plant src/fast_mass_springs_step_sparse.cpp 'const double w = 1e10;' 'const double w = 1e10 / 2;'
    run_check "$dir/submission"
    expect_status 0
    [ "$(echo "$out" | grep -c '^PASS  ')" = 6 ] || fail "expected six PASS lines"
    for function in fast_mass_springs_precomputation_dense fast_mass_springs_step_dense; do
      echo "$out" | grep -A1 "^PASS  $function\$" | grep -q "note: .*w = 1e7 " ||
        fail "expected the weight 1e7 noted for $function"
    done
    for function in fast_mass_springs_precomputation_sparse fast_mass_springs_step_sparse; do
      echo "$out" | grep -A1 "^PASS  $function\$" | grep -q "note: .*w = 5e9 " ||
        fail "expected the weight 5e9 noted for $function"
    done
    ;;
  InconsistentPinWeights)
    # Weights that differ within a pair fail, on the function whose weight is not the handout's:
    # the dense step (1e7 beside 1e10), the sparse precomputation (1e8 beside 1e10).
    submission
    plant fast_mass_springs_step_dense.cpp 'const double w = 1e10;' 'const double w = 1e7;'
    plant fast_mass_springs_precomputation_sparse.cpp 'const double w = 1e10;' 'const double w = 1e8;'
    run_check "$dir/submission"
    expect_failures \
      "fast_mass_springs_step_dense=its pins are held with w = 1e7, but fast_mass_springs_precomputation_dense holds them with w = 1e10|must use the same w" \
      "fast_mass_springs_precomputation_sparse=its pins are held with w = 1e8, but fast_mass_springs_step_sparse holds them with w = 1e10"
    ;;
  UnextReadFirst)
    # The course passes Unext equal to Ucur: a step that iterates from Unext without assigning it
    # works in the course's program, so it passes, with a note.
    course_submission
    plant src/fast_mass_springs_step_dense.cpp '  Unext = Ucur;' ''
    plant src/fast_mass_springs_step_sparse.cpp '  Unext = Ucur;' ''
    run_check "$dir/submission"
    expect_status 0
    [ "$(echo "$out" | grep -c '^PASS  ')" = 6 ] || fail "expected six PASS lines"
    [ "$(echo "$out" | grep -c 'note: reads Unext before writing it')" = 2 ] ||
      fail "expected the note on both steps"
    ;;
  CourseCallVariants)
    # Signatures that compile at the course's call site: extra defaulted arguments (declared in
    # the header, as the course's main.cpp sees it), a matrix taken by value, and a non-const
    # reference to an input.
    course_submission
    plant include/fast_mass_springs_step_sparse.h '  Eigen::MatrixXd & Unext);' '  Eigen::MatrixXd & Unext,
  const int iterations = 50);'
    plant src/fast_mass_springs_step_sparse.cpp 'Eigen::MatrixXd& Unext) {' 'Eigen::MatrixXd& Unext,
    const int iterations) {'
    plant src/fast_mass_springs_step_sparse.cpp 'iteration < 50' 'iteration < iterations'
    plant include/fast_mass_springs_step_dense.h '  const Eigen::MatrixXd & V,' '  Eigen::MatrixXd V,'
    plant src/fast_mass_springs_step_dense.cpp 'fast_mass_springs_step_dense(const Eigen::MatrixXd& V,' \
      'fast_mass_springs_step_dense(Eigen::MatrixXd V,'
    plant include/fast_mass_springs_precomputation_sparse.h '  const Eigen::VectorXi & b,' '  Eigen::VectorXi & b,'
    plant src/fast_mass_springs_precomputation_sparse.cpp '    const Eigen::VectorXi& b,' '    Eigen::VectorXi& b,'
    # The sparse incidence matrix with a defaulted argument of its own: the sparse
    # precomputation's call of it reaches the student's (Wobble's has no such signature).
    plant include/signed_incidence_matrix_sparse.h '  Eigen::SparseMatrix<double> & A);' \
      '  Eigen::SparseMatrix<double> & A,
  const double sign = 1.0);'
    plant src/signed_incidence_matrix_sparse.cpp 'Eigen::SparseMatrix<double>& A) {' \
      'Eigen::SparseMatrix<double>& A, const double sign) {'
    plant src/signed_incidence_matrix_sparse.cpp 'E(e, 0), 1.0)' 'E(e, 0), sign)'
    plant src/signed_incidence_matrix_sparse.cpp 'E(e, 1), -1.0)' 'E(e, 1), -sign)'
    run_check "$dir/submission"
    expect_status 0
    [ "$out" = "$(printf 'PASS  %s\n' "${functions[@]}")" ] || fail "expected six PASS lines only"
    ;;
  UnsuppliedHeader)
    # A libigl header the checker has no stand-in for is named on its function's line; the other
    # functions are graded as usual.
    course_submission
    plant src/signed_incidence_matrix_sparse.cpp '#include <vector>' '#include <vector>
#include <igl/cotmatrix.h>'
    run_check "$dir/submission"
    expect_status 1
    echo "$out" | grep -q '^ERROR  signed_incidence_matrix_sparse: includes <igl/cotmatrix.h>, which the checker cannot supply (it supplies .*<igl/matlab_format.h>' ||
      fail "expected the header named"
    [ "$(echo "$out" | grep -c '^PASS  ')" = 5 ] || fail "expected the other five to pass"
    ;;
  NegatedIncidence)
    submission
    plant signed_incidence_matrix_dense.cpp 'A(e, E(e, 0)) += 1.0;' 'A(e, E(e, 0)) -= 1.0;'
    plant signed_incidence_matrix_dense.cpp 'A(e, E(e, 1)) -= 1.0;' 'A(e, E(e, 1)) += 1.0;'
    run_check "$dir/submission"
    expect_failures "signed_incidence_matrix_dense=A is exactly the negative of the handout's, a consistent opposite orientation"
    ;;
  ClassAtOnce)
    # --class: a folder of three submissions (course layout and correct; flat with a planted
    # bug; empty), graded in parallel into a CSV, a summary and one report each.
    mkdir -p "$dir/class/carol"
    course_submission
    mv "$dir/submission" "$dir/class/alice"
    submission
    plant fast_mass_springs_step_dense.cpp 'iteration < 50' 'iteration < 51'
    mv "$dir/submission" "$dir/class/bob"
    run_check --jobs 2 --class "$dir/class" --output "$dir/grades"
    expect_status 0
    [[ "$err" == *"[3/3]"* ]] || fail "expected a progress line for each submission"
    csv="$dir/grades/grades.csv"
    [ "$(head -n 1 "$csv")" = "student,$(IFS=,; echo "${functions[*]}"),passed,notes,report" ] ||
      fail "expected the CSV's header"
    [ "$(wc -l <"$csv")" = 4 ] || fail "expected one row a student"
    grep -qx '"alice",PASS,PASS,PASS,PASS,PASS,PASS,6,"","reports/alice.txt"' "$csv" ||
      fail "expected alice to pass all six"
    grep -q '^"bob",PASS,PASS,PASS,PASS,FAIL,PASS,5,' "$csv" || fail "expected bob's dense step to fail"
    grep -q '^"carol",MISSING,MISSING,MISSING,MISSING,MISSING,MISSING,0,' "$csv" ||
      fail "expected carol's six functions missing"
    grep -q '^FAIL  fast_mass_springs_step_dense: .*hint: it matches 51 local-global iterations' \
      "$dir/grades/reports/bob.txt" || fail "expected bob's report to say why"
    summary="$dir/grades/summary.txt"
    grep -q '^Graded 3 submissions in [0-9]* s, 2 at a time' "$summary" || fail "expected the count"
    grep -q '^[0-9]* s compiling and linking, [0-9]* s checking' "$summary" ||
      fail "expected the time split"
    grep -Eq '^fast_mass_springs_step_dense +1 +1 +0 +1$' "$summary" || fail "expected the counts"
    grep -Eq '^bob +P P P P F P +5/6$' "$summary" || fail "expected bob's row"
    # A second run replaces the first's reports.
    rm -rf "$dir/class/carol"
    run_check --class "$dir/class" --output "$dir/grades"
    expect_status 0
    [ ! -e "$dir/grades/reports/carol.txt" ] || fail "expected the earlier run's report gone"
    [ "$(wc -l <"$dir/grades/grades.csv")" = 3 ] || fail "expected two rows"
    ;;
  MissingFolder)
    run_check "$dir/no-such-folder"
    expect_status 2
    [[ "$err" == *"no-such-folder: no such folder"* ]] || fail "expected the folder named"
    [ -z "$out" ] || fail "expected no PASS/FAIL lines"
    ;;
  NotAFolder)
    touch "$dir/a-file"
    run_check "$dir/a-file"
    expect_status 2
    [[ "$err" == *"a-file: not a folder"* ]] || fail "expected the path named"
    [ -z "$out" ] || fail "expected no verdict lines"
    ;;
  EveryFunctionHasALine)
    # A missing file, a compile error and a signature that is not the assignment's (with the
    # header unchanged, so the course's call cannot reach it): each gets its own line, and the
    # other three functions are still checked.
    submission
    rm "$dir/submission/fast_mass_springs_step_dense.cpp"
    plant signed_incidence_matrix_dense.cpp 'A = Eigen::MatrixXd::Zero(E.rows(), n);' \
      'A = Eigen::MatrixXd::Zero(E.rows(), n) + no_such_thing;'
    # Would link against the reference's function from the archive and pass, if not refused.
    plant fast_mass_springs_precomputation_sparse.cpp 'const double k,' 'const float k,'
    run_check "$dir/submission"
    expect_status 1
    [ "$(echo "$out" | wc -l)" = 6 ] || fail "expected 6 lines"
    line_of() { echo "$out" | grep -F " $1" | head -n 1; }
    [[ "$(line_of signed_incidence_matrix_dense)" == "ERROR  signed_incidence_matrix_dense: signed_incidence_matrix_dense.cpp:"*"error: "*"no_such_thing"*"not declared"* ]] ||
      fail "expected the compiler's first error line, its path from the submission"
    [ "$(line_of signed_incidence_matrix_sparse)" = "PASS  signed_incidence_matrix_sparse" ] ||
      fail "expected the sparse incidence to pass"
    [ "$(line_of fast_mass_springs_precomputation_dense)" = "PASS  fast_mass_springs_precomputation_dense" ] ||
      fail "expected the dense precomputation to pass"
    [[ "$(line_of fast_mass_springs_precomputation_sparse)" == "ERROR  fast_mass_springs_precomputation_sparse: the course calls fast_mass_springs_precomputation_sparse("*"double"*"but fast_mass_springs_precomputation_sparse.cpp defines fast_mass_springs_precomputation_sparse("*"float"* ]] ||
      fail "expected the signature named"
    [[ "$(line_of fast_mass_springs_step_dense)" == "MISSING  fast_mass_springs_step_dense: no fast_mass_springs_step_dense.cpp in "* ]] ||
      fail "expected the file missing"
    [ "$(line_of fast_mass_springs_step_sparse)" = "PASS  fast_mass_springs_step_sparse" ] ||
      fail "expected the sparse step to pass"
    [ -z "$err" ] || fail "expected nothing on stderr"
    rm "$dir/submission/fast_mass_springs_step_sparse.cpp"
    run_check --build-step-server "$dir/submission"
    expect_status 2
    [[ "$err" == *"missing fast_mass_springs_step_sparse.cpp"* ]] || fail "expected the file named"
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
    rm -rf "$dir/submission"
    submission
    plant fast_mass_springs_step_sparse.cpp '#include "fast_mass_springs_step_sparse.h"' \
      '#include "fast_mass_springs_step_sparse.h"
#include <unistd.h>
static const int forked_at_start = [] {
  if (fork() == 0) {
    sleep(300);
    _exit(0);
  }
  return 0;
}();'
    plant fast_mass_springs_step_sparse.cpp '  Unext = Ucur;' '  if (fork() == 0) {
    sleep(300);
    _exit(0);
  }
  Unext = Ucur;'
    run_check --build-step-server "$dir/submission" --output "$work/servers/forking"
    expect_status 0
    ;;
  IncludesDevZero)
    # A file that includes /dev/zero: its compiler stops at the 2 GiB memory limit, within
    # seconds and that memory, said on its function's line while the others are graded; for the
    # step server, in one line on stderr with exit 2. Nothing is left behind.
    submission
    plant signed_incidence_matrix_dense.cpp '#include "signed_incidence_matrix_dense.h"' \
      '#include "/dev/zero"
#include "signed_incidence_matrix_dense.h"'
    measured "$dir/submission"
    expect_status 1
    [ "$(echo "$out" | head -n 1)" = "ERROR  signed_incidence_matrix_dense: the compiler passed its memory limit of 2 GiB (does the file include something that never ends, such as /dev/zero?)" ] ||
      fail "expected the memory limit named on the function's line"
    [ "$(echo "$out" | grep -c '^PASS  ')" = 5 ] || fail "expected the other five to pass"
    [ "$peak_kib" -lt $((2 << 20)) ] || fail "a process took $peak_kib KiB, more than 2 GiB"
    # Without the limit the compiler took 5 GB in 16 s and went on; with it, 1.5 s.
    awk -v s="$seconds" 'BEGIN { exit !(s < 120) }' || fail "took $seconds s"
    expect_nothing_left
    plant fast_mass_springs_step_sparse.cpp '#include "fast_mass_springs_step_sparse.h"' \
      '#include "/dev/zero"
#include "fast_mass_springs_step_sparse.h"'
    run_check --build-step-server "$dir/submission"
    expect_status 2
    [ "$err" = "check-assignment: cannot compile $dir/submission/fast_mass_springs_step_sparse.cpp: the compiler passed its memory limit of 2 GiB (does the file include something that never ends, such as /dev/zero?)" ] ||
      fail "expected one line naming the memory limit"
    [ -z "$out" ] || fail "expected no server path"
    expect_nothing_left
    ;;
  IncludesAPipe)
    # A file that includes a named pipe nobody writes: its compiler waits without end, and stops
    # at --compile-limit, named on its function's line.
    submission
    mkfifo "$dir/submission/never.h"
    plant signed_incidence_matrix_sparse.cpp '#include "signed_incidence_matrix_sparse.h"' \
      '#include "never.h"
#include "signed_incidence_matrix_sparse.h"'
    run_check --compile-limit 2 "$dir/submission"
    expect_status 1
    [ "$(echo "$out" | sed -n 2p)" = "ERROR  signed_incidence_matrix_sparse: the compiler took longer than its 2 s limit (does the file include something that never ends, such as a pipe, or make the compiler compute without end?)" ] ||
      fail "expected the time limit named on the function's line"
    [ "$(echo "$out" | grep -c '^PASS  ')" = 5 ] || fail "expected the other five to pass"
    expect_nothing_left
    ;;
  SignalDuringBuild)
    # SIGTERM, SIGINT or SIGHUP to the script while a compiler waits on a pipe (a build that
    # never ends by itself): the script ends by that signal, and no script, launcher, g++ or
    # cc1plus is left running, nor anything in the temporary folder. One submission, the step
    # server's build, and a class.
    submission
    mkfifo "$dir/submission/never.h"
    plant fast_mass_springs_step_sparse.cpp '#include "fast_mass_springs_step_sparse.h"' \
      '#include "never.h"
#include "fast_mass_springs_step_sparse.h"'
    signal_during_build TERM "$dir/submission" "$dir/submission"
    expect_status 143
    expect_nothing_left
    signal_during_build INT "$dir/submission" --build-step-server "$dir/submission"
    expect_status 130
    expect_nothing_left
    mkdir -p "$dir/class"
    mv "$dir/submission" "$dir/class/student"
    signal_during_build HUP "$dir/class/student" --class "$dir/class" --output "$dir/grades"
    expect_status 129
    expect_nothing_left
    ;;
  ForkingStudentCode)
    # A function that forks a sleeping child each time it runs, and a static initializer that
    # forks one which leaves the checker's process group (setsid, then a second fork): every
    # check still passes, and nothing of them is left running afterwards; the step server's
    # build likewise (its run: wobble_student_step_tests, StudentStep.AForkInTheStepLeaves...).
    submission
    plant signed_incidence_matrix_sparse.cpp '#include "signed_incidence_matrix_sparse.h"' \
      '#include "signed_incidence_matrix_sparse.h"
#include <unistd.h>
static const int forked_at_start = [] {
  if (fork() == 0) {
    setsid();
    if (fork() == 0) sleep(300);
    _exit(0);
  }
  return 0;
}();'
    plant signed_incidence_matrix_sparse.cpp '  A.resize(E.rows(), n);' '  if (fork() == 0) {
    sleep(300);
    _exit(0);
  }
  A.resize(E.rows(), n);'
    run_check "$dir/submission"
    expect_status 0
    [ "$out" = "$(printf 'PASS  %s\n' "${functions[@]}")" ] || fail "expected six PASS lines only"
    expect_nothing_left
    ;;
  StaticInitializerHoards)
    # A static initializer that asks for 4 GiB runs in the checker itself, before any check:
    # the launcher names the checker's memory limit (--memory-limit and 256 MiB) on the
    # function's line, and the others are graded.
    submission
    plant signed_incidence_matrix_dense.cpp '#include "signed_incidence_matrix_dense.h"' \
      '#include "signed_incidence_matrix_dense.h"
#include <vector>
static std::vector<char> hoard(std::size_t(1) << 32, 1);'
    run_check "$dir/submission"
    expect_status 1
    [ "$(echo "$out" | head -n 1)" = "ERROR  signed_incidence_matrix_dense: the checker of signed_incidence_matrix_dense passed its memory limit of 2304 MiB" ] ||
      fail "expected the checker's memory limit named on the function's line"
    [ "$(echo "$out" | grep -c '^PASS  ')" = 5 ] || fail "expected the other five to pass"
    expect_nothing_left
    ;;
  *)
    fail "unknown scenario $scenario"
    ;;
esac
echo "ok: $scenario"
