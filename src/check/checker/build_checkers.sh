# Sourced by scripts/check-assignment.sh after its options are read (it sets root, cache,
# time_limit, memory_mib, compile_limit, jobs, timing_file): compiles a submission's files and
# Wobble's side, and builds the step server of the viewer's --student view
# (build_step_server). check_submission.sh links and runs the checkers.

seed="$root/src/sim/seed"
# The checker's own sources; the sandbox every compiler and checker runs in (the launcher, the
# child processes); the step server of the viewer's --student view.
check_sources="$root/src/check/checker"
sandbox_sources="$root/src/check/sandbox"
server_sources="$root/src/check/step_server"
course_headers="$check_sources/course_headers"
course="$root/assets/course"
# The checker's own sources (course_call.cpp is compiled with each student file), and those of
# the sandbox it links.
checker_sources=(check_main check_scene check_incidence check_precomputation check_step compare
                 course_problem pin_weight step_hints course_call_unlinked)
sandbox_linked=(child_process bounded_process)
cxx=g++
eigen=/usr/include/eigen3
# A student's file compiles (and links) within these, besides --compile-limit seconds of wall
# clock and of CPU time, so a file that includes /dev/zero or a pipe, or instantiates templates
# without end, stops with an ERROR instead of taking the machine. Memory is the compiler's
# address space (RLIMIT_AS): the seed's six files, as a submission, each compile within 256 to
# 320 MiB with the precompiled prelude and 256 to 384 MiB without it (the smallest limits that
# worked, 64 MiB apart), so 2 GiB is 5 times the most; /dev/zero reaches it in about 1.5 s.
# Files (the object, the assembler's): 128 MiB, 400 times a submission's object. The compiler's
# messages: the first 64 KiB are kept.
compile_memory_mib=2048
compile_file_mib=128
compile_messages_kib=64
# A checker runs a student's static initializers before its own checks: the whole run is held to
# 20 times --time-limit plus 30 s and its checks' memory plus 256 MiB; what it writes to 64 MiB.
checker_file_mib=64

check_toolchain() {
  command -v "$cxx" >/dev/null || die "g++ not found (apt-get install g++)"
  command -v ps >/dev/null || die "ps not found (apt-get install procps)"
  [ -f "$eigen/Eigen/Core" ] || die "Eigen not found in $eigen (apt-get install libeigen3-dev)"
  [ -f /usr/include/nlohmann/json.hpp ] ||
    die "nlohmann-json not found (apt-get install nlohmann-json3-dev)"
  if ! mkdir -p "$cache/obj" "$cache/lib" "$cache/bin" 2>/dev/null; then
    # The default comes from XDG_CACHE_HOME (or HOME): say which, and what is in the way.
    local from="--cache"
    [ -n "${cache_from:-}" ] && from=$cache_from
    local blocker=$cache
    while [ "$blocker" != / ] && [ "$blocker" != . ] && [ ! -e "$blocker" ]; do
      blocker=$(dirname "$blocker")
    done
    if [ -e "$blocker" ] && [ ! -d "$blocker" ]; then
      die "$cache: cannot create the cache folder: $blocker is a file, not a folder (from $from)"
    fi
    die "$cache: cannot create the cache folder (from $from; is it writable?)"
  fi
  work=$(mktemp -d) || die "cannot create a temporary folder"
  # The compilers' own temporary files (g++'s .s) too, so that one killed at a limit or by a
  # signal leaves nothing outside the folder, which goes at the end whatever happens.
  mkdir "$work/tmp" || die "cannot create a temporary folder in $work"
  export TMPDIR="$work/tmp"
  # WOBBLE_CHECK_KEEP=1 keeps it (the linked checkers, the compilers' logs) and says where.
  if [ "${WOBBLE_CHECK_KEEP:-0}" = 1 ]; then
    echo "check-assignment: keeping $work" >&2
  else
    trap 'rm -rf "$work"' EXIT
  fi
  # What a compiled object depends on besides its source and headers: the compiler, the
  # versions of Eigen and nlohmann-json, and the checker's stand-ins for libigl's headers.
  toolchain_id=$({
    "$cxx" --version | head -n 1
    cat "$eigen/Eigen/src/Core/util/Macros.h" /usr/include/nlohmann/json.hpp
    find "$course_headers" -type f | LC_ALL=C sort | xargs cat
  } | sha256sum | cut -c1-16)
  build_launcher
}

# The launcher every compiler and checker runs under (bounded_main.cpp): in the cache by
# content, its path in $launcher. Compiled in the background and waited for, so that a signal's
# trap (stop_on_signal.sh) can end the compiler.
build_launcher() {
  local sources=("$sandbox_sources/bounded_main.cpp" "$sandbox_sources/bounded_run.cpp"
                 "$sandbox_sources/bounded_process.cpp")
  local key
  key=$(cat "${sources[@]}" "$sandbox_sources/bounded_run.h" "$sandbox_sources/bounded_process.h" |
        { cat; printf '%s\n' "$toolchain_id"; } | sha256sum | cut -c1-32)
  launcher="$cache/bin/bounded-$key"
  [ -x "$launcher" ] && return 0
  "$cxx" -std=c++17 -O2 -I "$sandbox_sources" "${sources[@]}" -o "$launcher.tmp.$$" \
    >"$work/launcher.log" 2>&1 &
  if wait $!; then
    mv -f "$launcher.tmp.$$" "$launcher" || die "cannot write $launcher"
  else
    rm -f "$launcher.tmp.$$"
    die "cannot compile Wobble's launcher: $(first_error "$work/launcher.log")"
  fi
}

# -O2: the checks and the scale check run in a second; Eigen's assertions stay on (no NDEBUG),
# so an index out of range in a student's code stops with a message instead of corrupting
# memory. -w: a student's warnings are not this script's business.
flags=(-std=c++17 -O2 -w)

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
# so runs sharing a cache (tests in parallel, a class) never see half a file.
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

# bounded NAME COMMAND...: COMMAND within the compile limits (a student's file is untrusted
# input), through the launcher; past a limit it says so in one line, "bounded: NAME passed its
# memory limit of 2 GiB", and fails.
bounded() {
  local name=$1
  shift
  "$launcher" --name "$name" --seconds "$compile_limit" --memory-mib "$compile_memory_mib" \
    --file-mib "$compile_file_mib" --messages-kib "$compile_messages_kib" -- "$@"
}

# grouped COMMAND...: Wobble's own compiles, without limits but through the launcher all the
# same, so that a signal to the script ends them.
grouped() {
  "$launcher" --name "the compiler" -- "$@"
}

# wobble_side_key: one hash of everything Wobble's side is compiled from (the seed, the checker,
# the sandbox and the step server, sources and headers), the toolchain and the flags, in
# $wobble_side_id. Wobble's objects are keyed by it and their name, so a run hashes these
# files once instead of once per object; a change to any of them compiles Wobble's side again.
wobble_side_key() {
  [ -z "${wobble_side_id:-}" ] || return 0
  local file
  wobble_side_id=$({
    printf '%s\n' "$toolchain_id" "${flags[*]}"
    while IFS= read -r file; do
      printf '\n--- %s\n' "${file#"$root/"}"
      cat "$file"
    done < <(find "$seed" "$check_sources" "$sandbox_sources" "$server_sources" -maxdepth 1 \
               -type f \( -name '*.cpp' -o -name '*.h' \) | LC_ALL=C sort)
  } | sha256sum | cut -c1-32)
}

# compile NAME SOURCE TAG INCLUDE_DIR... -- EXTRA_FLAG...: compile what is not cached yet. A
# student's file is keyed by its contents and the headers it can see (key_of); Wobble's own by
# $wobble_side_id, and with the precompiled prelude when $wobble_prelude is set.
declare -A object
compile() {
  local name=$1 source=$2 tag=$3
  shift 3
  local dirs=()
  while [ "$1" != "--" ]; do dirs+=("$1"); shift; done
  shift
  local key runner=(grouped) prelude=()
  if [[ "$name" == student.* ]]; then
    key=$(key_of "$source" "$tag ${flags[*]} $*" "${dirs[@]}")
    runner=(bounded "the compiler")
  else
    wobble_side_key
    [ -z "${wobble_prelude:-}" ] || prelude=(-include "$wobble_prelude")
    key=$(printf '%s\n' "$wobble_side_id" "$name ${source#"$root/"}" "$tag $*" "${#prelude[@]}" |
          sha256sum | cut -c1-32)
  fi
  object[$name]="$cache/obj/$key.o"
  local includes=()
  for dir in "${dirs[@]}"; do includes+=(-I "$dir"); done
  start_job "${object[$name]}" "$work/$name.log" \
    "${runner[@]}" "$cxx" "${flags[@]}" "${prelude[@]}" "$@" "${includes[@]}" -I "$eigen" \
    -c "$source"
}

# first_error LOG: the line of LOG that says why it failed: a limit the launcher enforced, else
# the first error.
first_error() {
  grep -m 1 '^bounded: ' "$1" ||
    grep -m 1 -E 'undefined reference|multiple definition|(fatal )?error|out of memory|memory exhausted' "$1" ||
    grep -m 1 . "$1"
}

# The headers the checker supplies in place of the course's libigl, as a student would write
# them: <igl/matlab_format.h>, ...
supplied_headers() {
  (cd "$course_headers" && find . -type f -name '*.h' | sed 's|^\./||' | LC_ALL=C sort |
    sed 's/.*/<&>/' | paste -sd ' ')
}

# compile_error FUNCTION LOG FOLDER: the ERROR text of a file that did not compile: a header
# the checker cannot supply, by name; else the compiler's first error line, its paths written
# from the submission's folder.
compile_error() {
  local function=$1 log=$2 folder=$3
  local line
  line=$(first_error "$log")
  local header
  header=$(printf '%s\n' "$line" | sed -n 's/.*fatal error: \(.*\): No such file or directory.*/\1/p')
  if [ -n "$header" ]; then
    echo "includes <$header>, which the checker cannot supply (it supplies $(supplied_headers) and the standard library and Eigen)"
    return
  fi
  case "$line" in
    "bounded: "*"memory limit"*)
      echo "${line#bounded: } (does the file include something that never ends, such as /dev/zero?)"
      return
      ;;
    "bounded: "*"file larger"*)
      echo "${line#bounded: } (does the file define a huge array with initial values?)"
      return
      ;;
    "bounded: "*)
      echo "${line#bounded: } (does the file include something that never ends, such as a pipe, or make the compiler compute without end?)"
      return
      ;;
  esac
  line=${line//"$folder/"/}
  printable "$line"
  echo
}

# The precompiled prelude (check_prelude.h) every student file starts with, in the cache by
# content: its folder in $prelude_folder. A student file compiled before it is ready reads the
# plain header instead, which gives the same object, only slower.
start_prelude() {
  local key
  key=$(cat "$check_sources/check_prelude.h" | { cat; printf '%s\n' "$toolchain_id" "${flags[*]}"; } |
        sha256sum | cut -c1-32)
  prelude_folder="$cache/prelude/$key"
  mkdir -p "$prelude_folder" || die "$prelude_folder: cannot create the folder"
  # Absolute: compile_student links to it from a folder of its own, and a link to a relative
  # path (a relative --cache) would point nowhere, which read as the student's file including a
  # check_prelude.h the checker cannot supply.
  prelude_folder=$(cd "$prelude_folder" && pwd) || die "$prelude_folder: cannot enter the folder"
  if [ ! -f "$prelude_folder/check_prelude.h" ]; then
    cp "$check_sources/check_prelude.h" "$prelude_folder/check_prelude.h.tmp.$$" &&
      mv -f "$prelude_folder/check_prelude.h.tmp.$$" "$prelude_folder/check_prelude.h" ||
      die "cannot write $prelude_folder"
  fi
  start_job "$prelude_folder/check_prelude.h.gch" "$work/prelude.log" \
    grouped "$cxx" "${flags[@]}" -I "$eigen" -x c++-header "$prelude_folder/check_prelude.h"
}

# Wobble's side: its six functions plain (into an archive the linker takes what it lacks from),
# the checker's own objects and the step server's; compiled once, then cached. The oracle, the
# six renamed, is made from the plain objects afterwards (rename_wobble_side).
compile_wobble_side() {
  local function source
  wobble_prelude=""
  start_prelude
  # The launcher's code first, which needs no Eigen; then, once the prelude is ready, the rest
  # starts from it (-include), as a student's file does: Eigen's headers are parsed once.
  for source in "${sandbox_linked[@]}"; do
    compile "checker.$source" "$sandbox_sources/$source.cpp" checker "$sandbox_sources" --
  done
  finish_jobs
  wobble_prelude=$prelude_folder/check_prelude.h
  for function in "${functions[@]}"; do
    compile "plain.$function" "$seed/$function.cpp" plain "$seed" --
  done
  for source in "${checker_sources[@]}"; do
    compile "checker.$source" "$check_sources/$source.cpp" checker "$check_sources" \
      "$sandbox_sources" "$seed" --
  done
  compile server "$server_sources/step_server_main.cpp" checker "$server_sources" \
    "$check_sources" "$seed" --
}

# rename_wobble_side: the oracle, once the plain objects are compiled: each of them with every
# symbol of the six functions renamed, signed_incidence_matrix_dense to
# reference_signed_incidence_matrix_dense and so on (in C++'s mangled names the name is preceded
# by its length: _Z29signed_incidence_matrix_dense... becomes _Z39reference_signed_...), what
# compiling them with -Dsigned_incidence_matrix_dense=reference_signed_incidence_matrix_dense
# gave, without compiling them twice. In the cache beside the plain objects.
rename_wobble_side() {
  local function names="$work/renames.txt"
  # A plain object that did not compile is said by the caller, as any of Wobble's own.
  for function in "${functions[@]}"; do
    [ -f "${object[plain.$function]}" ] || return 0
  done
  [ -f "$names" ] || {
    # "OLD NEW" a line, for every symbol (defined or used) of the six functions.
    for function in "${functions[@]}"; do nm -P "${object[plain.$function]}"; done |
      awk -v names="${functions[*]}" '
        BEGIN {
          n = split(names, f, " ")
          for (i = 1; i <= n; i++) prefix[i] = "_Z" length(f[i]) f[i]
        }
        {
          for (i = 1; i <= n; i++)
            if (index($1, prefix[i]) == 1 && !seen[$1]++)
              print $1, "_Z" (length(f[i]) + 10) "reference_" f[i] substr($1, length(prefix[i]) + 1)
        }' >"$names"
  }
  for function in "${functions[@]}"; do
    object[renamed.$function]="$cache/obj/$(printf '%s\n' "${object[plain.$function]}" renamed |
                                            sha256sum | cut -c1-32).o"
    [ -f "${object[renamed.$function]}" ] && continue
    objcopy --redefine-syms="$names" "${object[plain.$function]}" \
      "${object[renamed.$function]}.tmp.$$" >>"$work/renamed.$function.log" 2>&1 &&
      mv -f "${object[renamed.$function]}.tmp.$$" "${object[renamed.$function]}"
  done
}

# compile_student FUNCTION SOURCE FOLDER: the student's file for FUNCTION with the course's call
# site of it (course_call.cpp) appended, one translation unit, so Eigen is parsed once; the
# submission's include folders first. Eigen comes in before the student's file (the precompiled
# check_prelude.h, then course_call.h), so a macro of theirs cannot break it. The file is included through a link in a folder of its
# own, and its name put back in the compiler's messages.
compile_student() {
  local function=$1 source=$2 folder=$3
  local dirs=()
  mapfile -t dirs < <(include_folders "$source" "$folder")
  local unity="$work/unity.$function"
  mkdir -p "$unity"
  ln -sf "$(cd "$(dirname "$source")" && pwd)/$(basename "$source")" "$unity/submitted.cpp"
  ln -sf "$check_sources/course_call.cpp" "$check_sources/course_call.h" "$unity/"
  ln -sf "$prelude_folder/check_prelude.h" "$prelude_folder/check_prelude.h.gch" "$unity/"
  printf '#include "%s"\n' check_prelude.h course_call.h submitted.cpp >"$unity/$function.cpp"
  printf '#define WOBBLE_COURSE_CALL_%s\n#include "course_call.cpp"\n' "$function" >>"$unity/$function.cpp"
  local contents
  contents=$(cat "$source" "$check_sources/course_call.cpp" "$check_sources/course_call.h" \
               "$check_sources/check_prelude.h" | sha256sum | cut -c1-32)
  compile "student.$function" "$unity/$function.cpp" "unity $function $contents" \
    "${dirs[@]}" "$course_headers" "$seed" --
  header_used[$function]=$(
    for dir in "${dirs[@]}" "$seed"; do
      [ -f "$dir/$function.h" ] && { printf '%s\n' "$dir/$function.h"; break; }
    done
  )
}

# student_compile_error FUNCTION FOLDER: the ERROR text of a student's file that did not compile
# with its course call: the call's own error says which header's signature it could not use.
student_compile_error() {
  local function=$1 folder=$2
  local log="$work/student.$function.log"
  local relative=${source_of[$function]#"$folder/"}
  local text
  text=$(compile_error "$function" "$log" "$folder")
  text=${text//"$work/unity.$function/submitted.cpp"/"$relative"}
  if [[ "$(first_error "$log")" == *course_call.cpp:* ]]; then
    local header=${header_used[$function]#"$folder/"}
    header=${header/#"$seed/"/"Wobble's src/sim/seed/"}
    text="the course's call of $function does not compile with the signature in $header: ${text#*error: }"
  fi
  printable "$text"
}

# call_error FUNCTION FOLDER: "" when the student's object defines every FUNCTION(...) its
# course call site needs, else the ERROR text. Without this the linker would quietly take the
# reference's function from the archive, and the check would pass.
call_error() {
  local function=$1 folder=$2
  local prefix="_Z${#function}${function}"
  local missing
  # The call and the file are one object: whatever it needs of FUNCTION and does not define
  # itself, the file did not define.
  missing=$(nm -u "${object[student.$function]}" | awk '{ print $2 }' | grep -m 1 "^$prefix")
  [ -n "$missing" ] || return 0
  local header=${header_used[$function]#"$folder/"}
  header=${header/#"$seed/"/"Wobble's src/sim/seed/"}
  local has
  has=$(nm -C --defined-only "${object[student.$function]}" | grep -F " $function(" |
        cut -d' ' -f3- | head -n 1)
  local text="the course calls $(printf '%s' "$missing" | c++filt) as declared in $header"
  if [ -n "$has" ]; then
    text+=", but ${source_of[$function]#"$folder/"} defines $has: give the header and the file the same signature"
  else
    text+=", but ${source_of[$function]#"$folder/"} does not define $function"
  fi
  printable "$text"
}

link_key() {
  printf '%s\n' "$@" | sha256sum | cut -c1-32
}

# make_archive OBJECT...: an archive of the objects in the cache, named by their paths (which
# name their contents); its path in $archive_path.
make_archive() {
  local objects=("$@")
  archive_path="$cache/lib/$(printf '%s\n' "${objects[@]}" | sha256sum | cut -c1-32).a"
  [ -f "$archive_path" ] && return 0
  ar rcs "$archive_path.tmp.$$" "${objects[@]}" && mv -f "$archive_path.tmp.$$" "$archive_path" ||
    die "cannot write $archive_path"
}

# build_step_server FOLDER OUTPUT: the step server of the submission's sparse step; its path on
# stdout, or exit 2 with the reason.
build_step_server() {
  local folder=$1 output=$2
  local function=fast_mass_springs_step_sparse
  declare -gA source_of=() header_used=()
  source_of[$function]=$(function_source "$folder" "$function")
  [ -n "${source_of[$function]}" ] ||
    die "$folder: missing $function.cpp (looked in it, in src/ and below)"
  compile_wobble_side
  compile_student "$function" "${source_of[$function]}" "$folder"
  finish_jobs
  local name
  for name in "${!object[@]}"; do
    [[ "$name" == student.* ]] && continue
    [ -f "${object[$name]}" ] ||
      die "cannot compile Wobble's own ${name#*.}.cpp: $(first_error "$work/$name.log")"
  done
  [ -f "${object[student.$function]}" ] ||
    die "cannot compile ${source_of[$function]}: $(student_compile_error "$function" "$folder")"
  local problem
  problem=$(call_error "$function" "$folder")
  [ -z "$problem" ] || die "$folder: $problem"

  local plain_objects=()
  for name in "${functions[@]}"; do plain_objects+=("${object[plain.$name]}"); done
  make_archive "${plain_objects[@]}"
  local inputs=("${object[server]}" "${object[checker.pin_weight]}" "${object[student.$function]}"
                "$archive_path")
  local server
  server="$cache/bin/step-server-$(link_key "${inputs[@]}")"
  start_job "$server" "$work/link.log" bounded "the linker" "$cxx" "${inputs[@]}"
  finish_jobs
  [ -f "$server" ] || die "cannot link the step server: $(first_error "$work/link.log")"
  if [ -n "$output" ]; then
    cp "$server" "$output.tmp.$$" && mv -f "$output.tmp.$$" "$output" || die "cannot write $output"
    server=$output
  fi
  echo "$server"
}
