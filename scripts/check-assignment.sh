#!/usr/bin/env bash
# Check a student's own six assignment functions against Wobble's (src/sim/seed), each one in
# isolation: it gets the reference's inputs, and whatever it calls is the reference's, so a bug
# is blamed on the function that has it. docs/classroom.md has the whole story.
#
#   scripts/check-assignment.sh [options] DIR
#   scripts/check-assignment.sh [options] --class DIR [--output FOLDER]
#   scripts/check-assignment.sh [options] --build-step-server DIR [--output FILE]
#
# DIR is a submission as the course hands it out and students hand it in (src/*.cpp with
# include/*.h, the course's template layout) or a folder holding the six .cpp files named after
# the functions (signed_incidence_matrix_dense.cpp, ...), with or without their .h files: a
# missing .h is taken from src/sim/seed. Each file is compiled as the course compiles it, with
# the submission's include folders first, then the checker's own stand-ins for the libigl
# headers the template includes (src/check/checker/course_headers), then src/sim/seed and Eigen.
#
# Prints a verdict line for every function, whatever happens to the others, then any notes:
#   PASS     name
#   FAIL     name: what differs, where, by how much, on which input[; hint: why]
#   MISSING  name: no name.cpp in the submission
#   ERROR    name: the compiler's first error line, a header the checker cannot supply, or a
#            course call that does not compile or link with the submission's signature
#         note: a pin weight other than the handout's, Unext read before it is written
# Exit status: 0 all pass, 1 any does not, 2 the folder itself cannot be used (or the checker
# cannot run: no compiler, no Eigen).
#
# Options:
#   --class DIR          grade every submission folder under DIR (one subfolder a student) in
#                        parallel; writes FOLDER/grades.csv, FOLDER/summary.txt and each
#                        student's report in FOLDER/reports/ (--output FOLDER, default ./grades)
#   --cache DIR          where compiled objects are kept, by content hash
#                        (default ${XDG_CACHE_HOME:-$HOME/.cache}/wobble-check)
#   --time-limit S       seconds each check may run (default 10)
#   --memory-limit MIB   address space of each check (default 2048)
#   --compile-limit S    seconds each compile of a student's file may take, wall clock and CPU
#                        (default 120; its address space is held to 2048 MiB, the files it
#                        writes to 128 MiB, its messages kept to the first 64 KiB)
#   --jobs N             compilers and checks at once, or with --class submissions at once
#                        (default: the number of cores)
#   --build-step-server DIR
#                        build the step server of DIR's fast_mass_springs_step_sparse.cpp (the
#                        reference for every other function) and print its path; it serves
#                        steps to the viewer (src/app/student/student_step.h, src/check/step_server/step_protocol.h)
#   --output FILE        with --build-step-server: copy the server to FILE and print FILE
#
# Every compiler and checker runs in a process group of its own, under a launcher
# (src/check/sandbox/bounded_main.cpp) that kills the whole group, and whatever left it, when it ends,
# passes a limit, or the script gets SIGTERM, SIGINT or SIGHUP; the script then removes its
# temporary folder and ends by that signal.
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/src/check/checker/submission_files.sh"
source "$root/src/check/checker/stop_on_signal.sh"

cache="${XDG_CACHE_HOME:-$HOME/.cache}/wobble-check"
# Where the cache folder's name came from, for a message when it cannot be made.
if [ -n "${XDG_CACHE_HOME:-}" ]; then cache_from=XDG_CACHE_HOME; else cache_from=HOME; fi
time_limit=10
memory_mib=2048
compile_limit=120
jobs=$(nproc 2>/dev/null || echo 2)
build_server=0
class_mode=0
output=""
folder=""
timing_file=""
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help)
      sed -n '2,/^set -uo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'
      exit 0
      ;;
    --cache | --time-limit | --memory-limit | --compile-limit | --jobs | --output | \
      --build-step-server | --class | --timing-file)
      [ $# -ge 2 ] || die "$1 needs a value"
      case "$1" in
        --cache) cache=$2 cache_from="--cache" ;;
        --time-limit) time_limit=$2 ;;
        --memory-limit) memory_mib=$2 ;;
        --compile-limit) compile_limit=$2 ;;
        --jobs) jobs=$2 ;;
        --output) output=$2 ;;
        --build-step-server) build_server=1 folder=$2 ;;
        --class) class_mode=1 folder=$2 ;;
        --timing-file) timing_file=$2 ;;  # for --class: where a submission's run times go
      esac
      shift 2
      ;;
    -*) die "unknown option $1 (see --help)" ;;
    *)
      [ -z "$folder" ] || die "one folder only (got '$folder' and '$1')"
      folder=$1
      shift
      ;;
  esac
done
[ -n "$folder" ] || die "usage: scripts/check-assignment.sh [options] DIR (see --help)"
[[ "$time_limit" =~ ^[0-9]+([.][0-9]+)?$ ]] || die "--time-limit: expected seconds, got '$time_limit'"
[[ "$memory_mib" =~ ^[0-9]+$ ]] || die "--memory-limit: expected MiB, got '$memory_mib'"
[[ "$compile_limit" =~ ^[1-9][0-9]*$ ]] || die "--compile-limit: expected seconds, got '$compile_limit'"
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "--jobs: expected a count, got '$jobs'"
[ "$build_server" = 0 ] || [ "$class_mode" = 0 ] || die "--class and --build-step-server do not go together"
[ -z "$output" ] || [ "$build_server" = 1 ] || [ "$class_mode" = 1 ] ||
  die "--output goes with --build-step-server or --class"

folder=${folder%/}
[ -n "$folder" ] || folder=/
[ -e "$folder" ] || die "$folder: no such folder"
[ -d "$folder" ] || die "$folder: not a folder (give the folder that holds the submission)"
[ -r "$folder" ] && [ -x "$folder" ] || die "$folder: cannot read the folder"

if [ "$class_mode" = 1 ]; then
  source "$root/src/check/checker/grade_class.sh"
  grade_class "$folder" "${output:-grades}"
  exit $?
fi

source "$root/src/check/checker/build_checkers.sh"
source "$root/src/check/checker/check_submission.sh"
check_toolchain
if [ "$build_server" = 1 ]; then
  build_step_server "$folder" "$output"
  exit $?
fi
check_submission "$folder"
exit $?
