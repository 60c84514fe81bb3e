#!/usr/bin/env bash
# Check a student's own six assignment functions against Wobble's (src/sim/seed), each one in
# isolation: it gets the reference's inputs, and whatever it calls is the reference's, so a bug
# is blamed on the function that has it. README.md, "Checking your own six functions".
#
#   scripts/check-assignment.sh [options] DIR
#   scripts/check-assignment.sh [options] --build-step-server DIR [--output FILE]
#
# DIR holds the six .cpp files named after the functions (signed_incidence_matrix_dense.cpp,
# ...), with or without their .h files: a missing .h is taken from src/sim/seed. They are
# compiled with g++ -std=c++17 against Eigen alone (-I DIR, then src/sim/seed, then Eigen).
#
# Prints one line per function, "PASS  name" or "FAIL  name: what differs, where, by how much,
# on which input". Exit status: 0 all pass, 1 any fails, 2 bad input (no such folder, a file
# missing, a compile error, a function with another signature).
#
# Options:
#   --cache DIR          where compiled objects are kept, by content hash
#                        (default ${XDG_CACHE_HOME:-$HOME/.cache}/wobble-check)
#   --time-limit S       seconds each check may run (default 10)
#   --memory-limit MIB   address space of each check (default 2048)
#   --jobs N             compilers and checks at once (default: the number of cores)
#   --build-step-server DIR
#                        build the step server of DIR/fast_mass_springs_step_sparse.cpp (the
#                        reference for every other function) and print its path; it serves
#                        steps to the viewer (src/app/student_step.h, src/check/step_protocol.h)
#   --output FILE        with --build-step-server: copy the server to FILE and print FILE
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seed="$root/src/sim/seed"
check_sources="$root/src/check"
course="$root/assets/course"
functions=(
  signed_incidence_matrix_dense signed_incidence_matrix_sparse
  fast_mass_springs_precomputation_dense fast_mass_springs_precomputation_sparse
  fast_mass_springs_step_dense fast_mass_springs_step_sparse
)
# The checker's own sources; step_server_main.cpp is the other program's main.
checker_sources=(check_main check_scene check_incidence check_precomputation check_step compare
                 course_problem child_process)

die() {
  echo "check-assignment: $*" >&2
  exit 2
}

cache="${XDG_CACHE_HOME:-$HOME/.cache}/wobble-check"
time_limit=10
memory_mib=2048
jobs=$(nproc 2>/dev/null || echo 2)
build_server=0
output=""
folder=""
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help)
      sed -n '2,/^set -uo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'
      exit 0
      ;;
    --cache | --time-limit | --memory-limit | --jobs | --output | --build-step-server)
      [ $# -ge 2 ] || die "$1 needs a value"
      case "$1" in
        --cache) cache=$2 ;;
        --time-limit) time_limit=$2 ;;
        --memory-limit) memory_mib=$2 ;;
        --jobs) jobs=$2 ;;
        --output) output=$2 ;;
        --build-step-server) build_server=1 folder=$2 ;;
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
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "--jobs: expected a count, got '$jobs'"
[ -z "$output" ] || [ "$build_server" = 1 ] || die "--output goes with --build-step-server"

folder=${folder%/}
[ -d "$folder" ] || die "$folder: no such folder"
if [ "$build_server" = 1 ]; then wanted=(fast_mass_springs_step_sparse); else wanted=("${functions[@]}"); fi
missing=()
for function in "${wanted[@]}"; do
  [ -f "$folder/$function.cpp" ] || missing+=("$function.cpp")
done
[ ${#missing[@]} -eq 0 ] || die "$folder: missing ${missing[*]} (each function in a .cpp named after it)"

cxx=g++
command -v "$cxx" >/dev/null || die "g++ not found (apt-get install g++)"
eigen=/usr/include/eigen3
[ -f "$eigen/Eigen/Core" ] || die "Eigen not found in $eigen (apt-get install libeigen3-dev)"
[ -f /usr/include/nlohmann/json.hpp ] || die "nlohmann-json not found (apt-get install nlohmann-json3-dev)"

mkdir -p "$cache/obj" "$cache/lib" "$cache/bin" || die "$cache: cannot create the cache folder"
work=$(mktemp -d) || die "cannot create a temporary folder"
trap 'rm -rf "$work"' EXIT

# -O2: the checks and the scale check run in a second; Eigen's assertions stay on (no NDEBUG),
# so an index out of range in a student's code stops with a message instead of corrupting
# memory. -w: a student's warnings are not this script's business.
flags=(-std=c++17 -O2 -w)
renames=()
for function in "${functions[@]}"; do renames+=("-D$function=reference_$function"); done

# What a compiled object depends on besides its source and headers: the compiler and the
# versions of Eigen and nlohmann-json.
toolchain_id=$({
  "$cxx" --version | head -n 1
  cat "$eigen/Eigen/src/Core/util/Macros.h" /usr/include/nlohmann/json.hpp
} | sha256sum | cut -c1-16)

# key_of SOURCE TAG INCLUDE_DIR...: the cache key of compiling SOURCE with the flags named by
# TAG: a hash of the source, and of every header the include folders offer, each name taken
# from the first folder that has it. Include paths are left out, so the same files compiled
# from two folders (the seed as a student's submission) share one object.
key_of() {
  local source=$1 tag=$2
  shift 2
  local -A chosen=()
  local dir header name
  for dir in "$@"; do
    for header in "$dir"/*.h "$dir"/*.hpp; do
      [ -f "$header" ] || continue
      name=${header##*/}
      [ -n "${chosen[$name]:-}" ] || chosen[$name]=$header
    done
  done
  {
    printf '%s\n%s\n' "$toolchain_id" "$tag"
    cat "$source"
    while IFS= read -r name; do
      printf '\n--- %s\n' "$name"
      cat "${chosen[$name]}"
    done < <(printf '%s\n' "${!chosen[@]}" | LC_ALL=C sort)
  } | sha256sum | cut -c1-32
}

# start_job OUTPUT LOG COMMAND...: run COMMAND -o OUTPUT in the background, at most $jobs at
# once, unless OUTPUT is already cached. The result is renamed into place only when complete,
# so runs sharing a cache (tests in parallel) never see half a file.
running=0
start_job() {
  local target=$1 log=$2
  shift 2
  [ -f "$target" ] && return 0
  if [ "$running" -ge "$jobs" ]; then
    wait -n
    running=$((running - 1))
  fi
  (
    temporary="$target.tmp.$BASHPID"
    if "$@" -o "$temporary" >"$log" 2>&1; then mv -f "$temporary" "$target"; else rm -f "$temporary"; fi
  ) &
  running=$((running + 1))
}
finish_jobs() {
  wait
  running=0
}

first_error() {
  grep -m 1 -E '(fatal )?error' "$1" || head -n 1 "$1"
}

# Compile everything that is not cached yet.
declare -A object
compile() {  # NAME SOURCE TAG INCLUDE_DIR... -- EXTRA_FLAG...
  local name=$1 source=$2 tag=$3
  shift 3
  local dirs=()
  while [ "$1" != "--" ]; do dirs+=("$1"); shift; done
  shift
  local key
  key=$(key_of "$source" "$tag ${flags[*]} $*" "${dirs[@]}")
  object[$name]="$cache/obj/$key.o"
  local includes=()
  for dir in "${dirs[@]}"; do includes+=(-I "$dir"); done
  start_job "${object[$name]}" "$work/$name.log" \
    "$cxx" "${flags[@]}" "$@" "${includes[@]}" -I "$eigen" -c "$source"
}
for function in "${wanted[@]}"; do
  compile "student.$function" "$folder/$function.cpp" student "$folder" "$seed" --
done
for function in "${functions[@]}"; do
  compile "plain.$function" "$seed/$function.cpp" student "$seed" --
  [ "$build_server" = 1 ] || compile "renamed.$function" "$seed/$function.cpp" renamed "$seed" -- "${renames[@]}"
done
if [ "$build_server" = 1 ]; then
  compile server "$check_sources/step_server_main.cpp" checker "$check_sources" "$seed" --
else
  for source in "${checker_sources[@]}"; do
    compile "checker.$source" "$check_sources/$source.cpp" checker "$check_sources" "$seed" --
  done
fi
finish_jobs

errors=0
for name in "${!object[@]}"; do
  [ -f "${object[$name]}" ] && continue
  case "$name" in
    student.*) echo "check-assignment: cannot compile $folder/${name#student.}.cpp: $(first_error "$work/$name.log")" >&2 ;;
    *) echo "check-assignment: cannot compile Wobble's own ${name#*.}.cpp: $(first_error "$work/$name.log")" >&2 ;;
  esac
  errors=1
done
[ "$errors" = 0 ] || exit 2

# Each student file must define its function with the assignment's signature, or the linker
# would quietly take the reference's from the archive below and the check would pass.
for function in "${wanted[@]}"; do
  symbol=$(nm -g --defined-only "${object[plain.$function]}" | awk '$2 == "T" { print $3; exit }')
  nm -g --defined-only "${object[student.$function]}" | awk '$2 == "T" { print $3 }' |
    grep -qxF "$symbol" && continue
  other=$(nm -g -C --defined-only "${object[student.$function]}" | grep -m 1 -F " $function(" | cut -d' ' -f3-)
  if [ -n "$other" ]; then
    die "$folder/$function.cpp: $function has another signature than the assignment's ($other; see src/sim/seed/$function.h)"
  fi
  die "$folder/$function.cpp does not define $function (as declared in src/sim/seed/$function.h)"
done

# Wobble's plain functions in an archive: the linker takes from it only what a program still
# lacks, so the student's function wins and everything it calls is the reference's.
plain_objects=()
for function in "${functions[@]}"; do plain_objects+=("${object[plain.$function]}"); done
archive="$cache/lib/$(printf '%s\n' "${plain_objects[@]}" | sha256sum | cut -c1-32).a"
if [ ! -f "$archive" ]; then
  ar rcs "$archive.tmp.$$" "${plain_objects[@]}" && mv -f "$archive.tmp.$$" "$archive" ||
    die "cannot write $archive"
fi

link_key() {
  printf '%s\n' "$@" | sha256sum | cut -c1-32
}

if [ "$build_server" = 1 ]; then
  inputs=("${object[server]}" "${object[student.fast_mass_springs_step_sparse]}" "$archive")
  server="$cache/bin/step-server-$(link_key "${inputs[@]}")"
  start_job "$server" "$work/link.log" "$cxx" "${inputs[@]}"
  finish_jobs
  [ -f "$server" ] || die "cannot link the step server: $(first_error "$work/link.log")"
  if [ -n "$output" ]; then
    cp "$server" "$output.tmp.$$" && mv -f "$output.tmp.$$" "$output" || die "cannot write $output"
    server=$output
  fi
  echo "$server"
  exit 0
fi

# One checker per function: the student's object for that function alone, the renamed oracle,
# then the plain archive.
checker_objects=()
for source in "${checker_sources[@]}"; do checker_objects+=("${object[checker.$source]}"); done
renamed_objects=()
for function in "${functions[@]}"; do renamed_objects+=("${object[renamed.$function]}"); done
declare -A checker
for function in "${functions[@]}"; do
  inputs=("${checker_objects[@]}" "${object[student.$function]}" "${renamed_objects[@]}" "$archive")
  checker[$function]="$cache/bin/check-$function-$(link_key "${inputs[@]}")"
  start_job "${checker[$function]}" "$work/link.$function.log" "$cxx" "${inputs[@]}"
done
finish_jobs
for function in "${functions[@]}"; do
  [ -f "${checker[$function]}" ] ||
    die "cannot link the checker of $function: $(first_error "$work/link.$function.log")"
done

# Run the six checkers, $jobs at once, and print their lines in the assignment's order.
for function in "${functions[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n
    running=$((running - 1))
  fi
  (
    "${checker[$function]}" --function "$function" --course-dir "$course" \
      --time-limit "$time_limit" --memory-limit "$memory_mib" \
      >"$work/$function.out" 2>"$work/$function.err"
    echo $? >"$work/$function.status"
  ) &
  running=$((running + 1))
done
finish_jobs

status=0
for function in "${functions[@]}"; do
  code=$(cat "$work/$function.status" 2>/dev/null || echo missing)
  case "$code" in
    0 | 1)
      cat "$work/$function.out"
      [ "$code" = 1 ] && [ "$status" = 0 ] && status=1
      ;;
    *)
      echo "check-assignment: the checker of $function could not run (status $code): $(head -n 1 "$work/$function.err")" >&2
      status=2
      ;;
  esac
done
exit "$status"
