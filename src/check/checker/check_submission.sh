# Sourced by scripts/check-assignment.sh after build_checkers.sh: check_submission FOLDER
# compiles a submission (build_checkers.sh), links one checker per function, runs them, compares
# the pin weights within each pair, and prints a verdict line for every function.

now() {
  date +%s.%N
}

# check_submission FOLDER: every function's verdict, in the assignment's order.
check_submission() {
  local folder=$1
  local started compiled checked
  started=$(now)
  declare -gA verdict=() detail=() source_of=() header_used=()
  local function source
  for function in "${functions[@]}"; do
    source=$(function_source "$folder" "$function")
    if [ -z "$source" ]; then
      verdict[$function]=MISSING
      detail[$function]="no $function.cpp in $(printable "$folder") (looked in it, in src/ and below)"
      continue
    fi
    source_of[$function]=$source
  done

  compile_wobble_side
  for function in "${!source_of[@]}"; do
    compile_student "$function" "${source_of[$function]}" "$folder"
  done
  finish_jobs
  rename_wobble_side

  local name
  for name in "${!object[@]}"; do
    case "$name" in
      student.*) ;;
      *)
        [ -f "${object[$name]}" ] ||
          die "cannot compile Wobble's own ${name#*.}.cpp: $(first_error "$work/$name.log")"
        ;;
    esac
  done
  local student_objects=()
  for function in "${!source_of[@]}"; do
    if [ ! -f "${object[student.$function]}" ]; then
      verdict[$function]=ERROR
      detail[$function]=$(student_compile_error "$function" "$folder")
    else
      student_objects+=("${object[student.$function]}")
      local problem
      problem=$(call_error "$function" "$folder")
      if [ -n "$problem" ]; then
        verdict[$function]=ERROR
        detail[$function]=$problem
      fi
    fi
  done

  # Wobble's plain functions in an archive: the linker takes from it only what a program still
  # lacks, so the student's function wins and everything it calls is the reference's. The
  # student's other objects come last, for a call to another of their functions whose own
  # header changed its signature (the reference's cannot answer it).
  local plain_objects=()
  for function in "${functions[@]}"; do plain_objects+=("${object[plain.$function]}"); done
  make_archive "${plain_objects[@]}"
  local plain_archive=$archive_path student_archive=()
  if [ ${#student_objects[@]} -gt 0 ]; then
    student_archive=("$work/student.a")
    ar rcs "${student_archive[0]}" "${student_objects[@]}" || die "cannot write ${student_archive[0]}"
  fi
  local checker_objects=() renamed_objects=()
  for source in "${checker_sources[@]}" "${sandbox_linked[@]}"; do
    checker_objects+=("${object[checker.$source]}")
  done
  for function in "${functions[@]}"; do renamed_objects+=("${object[renamed.$function]}"); done
  declare -A checker=()
  local inputs
  for function in "${!source_of[@]}"; do
    [ -z "${verdict[$function]:-}" ] || continue
    inputs=("${checker_objects[@]}" "${object[student.$function]}" "${renamed_objects[@]}"
            "$plain_archive" "${student_archive[@]}")
    # Linked for this run only: a link takes a fraction of a second, and a class's checkers
    # would fill the cache.
    checker[$function]="$work/check-$function"
    start_job "${checker[$function]}" "$work/link.$function.log" bounded "the linker" "$cxx" "${inputs[@]}"
  done
  finish_jobs
  for function in "${!checker[@]}"; do
    if [ ! -f "${checker[$function]}" ]; then
      verdict[$function]=ERROR
      detail[$function]="cannot link its checker: $(compile_error "$function" "$work/link.$function.log" "$folder")"
      unset "checker[$function]"
    fi
  done
  compiled=$(now)

  # Run the checkers, $jobs at once, each through the launcher: the student's static initializers
  # run in it before any check does, and whatever they start ends with it.
  local checker_seconds
  checker_seconds=$(awk -v t="$time_limit" 'BEGIN { print 20 * t + 30 }')
  for function in "${functions[@]}"; do
    [ -n "${checker[$function]:-}" ] || continue
    if [ "$running" -ge "$jobs" ]; then
      wait -n
      running=$((running - 1))
    fi
    (
      "$launcher" --name "the checker of $function" --seconds "$checker_seconds" \
        --memory-mib $((memory_mib + 256)) --file-mib "$checker_file_mib" -- \
        "${checker[$function]}" --function "$function" --course-dir "$course" \
        --time-limit "$time_limit" --memory-limit "$memory_mib" --facts "$work/$function.facts" \
        >"$work/$function.out" 2>"$work/$function.err"
      echo $? >"$work/$function.status"
    ) &
    running=$((running + 1))
  done
  finish_jobs
  checked=$(now)

  local code
  for function in "${!checker[@]}"; do
    code=$(cat "$work/$function.status" 2>/dev/null || echo missing)
    case "$code" in
      0 | 1) verdict[$function]=checked ;;
      124)
        verdict[$function]=ERROR
        detail[$function]=$(grep -m 1 '^bounded: ' "$work/$function.err" | sed 's/^bounded: //')
        ;;
      *) die "the checker of $function could not run (status $code): $(head -n 1 "$work/$function.err")" ;;
    esac
  done
  weigh_pairs fast_mass_springs_precomputation_dense fast_mass_springs_step_dense
  weigh_pairs fast_mass_springs_precomputation_sparse fast_mass_springs_step_sparse

  local status=0
  for function in "${functions[@]}"; do
    if [ "${verdict[$function]}" = checked ]; then
      cat "$work/$function.out"
      grep -q '^PASS ' "$work/$function.out" || status=1
    else
      printf '%s  %s: %s\n' "${verdict[$function]}" "$function" "${detail[$function]}"
      status=1
    fi
  done
  if [ -n "$timing_file" ]; then
    awk -v a="$started" -v b="$compiled" -v c="$checked" \
      'BEGIN { printf "compile %.2f\ncheck %.2f\n", b - a, c - b }' >"$timing_file"
  fi
  return "$status"
}

# pin_weight FUNCTION: the weight its checker found (facts), or nothing.
pin_weight() {
  awk '$1 == "pin_weight" && $2 != "nan" { print $2 }' "$work/$1.facts" 2>/dev/null
}

# weigh_pairs PRECOMPUTATION STEP: both pass but hold the pins with different weights: the
# pinned vertices move in the course's program, so one of them fails: the one whose weight is
# not the handout's, else the step.
weigh_pairs() {
  local precomputation=$1 step=$2
  [ "${verdict[$precomputation]}" = checked ] && [ "${verdict[$step]}" = checked ] || return 0
  grep -q '^PASS ' "$work/$precomputation.out" && grep -q '^PASS ' "$work/$step.out" || return 0
  local w_precomputation w_step
  w_precomputation=$(pin_weight "$precomputation")
  w_step=$(pin_weight "$step")
  [ -n "$w_precomputation" ] && [ -n "$w_step" ] || return 0
  awk -v a="$w_precomputation" -v b="$w_step" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d > 1e-6 * a) }' ||
    return 0
  local blamed=$step other=$precomputation
  if awk -v w="$w_step" 'BEGIN { d = w - 1e10; if (d < 0) d = -d; exit !(d <= 1e-6 * 1e10) }'; then
    blamed=$precomputation other=$step
  fi
  local text
  text="FAIL  $blamed: its pins are held with w = $(weight_text "$(pin_weight "$blamed")"), but $other holds them with w = $(weight_text "$(pin_weight "$other")"): a precomputation and its step must use the same w (Q's w CᵀC and y's w CᵀC V), or every pinned vertex drifts"
  { echo "$text"; grep -v '^PASS ' "$work/$blamed.out"; } >"$work/$blamed.out.new"
  mv -f "$work/$blamed.out.new" "$work/$blamed.out"
}

# weight_text W: 1e10, 5e9, 2.5e7 (as the checker writes them).
weight_text() {
  printf '%.4g' "$1" | sed -E 's/e\+?(-?)0*([0-9])/e\1\2/'
}

