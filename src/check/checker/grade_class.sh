# Sourced by scripts/check-assignment.sh for --class DIR: every submission folder under DIR
# checked as one would be alone, $jobs of them at once (each with one compiler and one check at a
# time, so the machine's cores are shared and every check keeps its own limits), then one CSV
# row a student and a summary an instructor can read.

# file_name NAME: a submission's folder name as a file name of the report.
file_name() {
  printf '%s' "$1" | tr -c 'A-Za-z0-9._-' '_'
}

# csv_field TEXT: TEXT as one CSV field, quoted.
csv_field() {
  local text=${1//\"/\"\"}
  printf '"%s"' "$text"
}

# verdict_of REPORT FUNCTION: PASS, FAIL, MISSING or ERROR from a submission's report.
verdict_of() {
  awk -v f="$2" '$2 == f || $2 == f ":" { print $1; exit }' "$1"
}

grade_class() {
  local class=$1 output=$2
  local started
  started=$(date +%s.%N)
  local submissions=() entry
  for entry in "$class"/*/; do
    [ -d "$entry" ] && submissions+=("${entry%/}")
  done
  [ ${#submissions[@]} -gt 0 ] || die "$class: no submission folders in it (one subfolder a student)"
  mkdir -p "$output" 2>/dev/null || die "$output: cannot create the report folder"
  rm -rf "$output/reports" "$output/.timing"
  mkdir -p "$output/reports" "$output/.timing" || die "$output: cannot write in it"

  # Wobble's side once, with every core, before the submissions share the cache.
  source "$root/src/check/checker/build_checkers.sh"
  check_toolchain
  compile_wobble_side
  finish_jobs
  rename_wobble_side
  local warmed
  warmed=$(date +%s.%N)

  local total=${#submissions[@]} running_students=0 index=0
  declare -A report_of=()
  local submission name
  echo "check-assignment: grading $total submissions, $jobs at a time" >&2
  for submission in "${submissions[@]}"; do
    index=$((index + 1))
    name=$(file_name "$(basename "$submission")")
    [ -z "${report_of[$name]:-}" ] || name="$name.$index"
    report_of[$submission]=$name
    if [ "$running_students" -ge "$jobs" ]; then
      wait -n
      running_students=$((running_students - 1))
    fi
    (
      bash "$root/scripts/check-assignment.sh" --jobs 1 --cache "$cache" \
        --time-limit "$time_limit" --memory-limit "$memory_mib" --compile-limit "$compile_limit" \
        --timing-file "$output/.timing/$name" "$submission" \
        >"$output/reports/$name.txt" 2>"$output/reports/$name.err" </dev/null
      echo $? >"$output/.timing/$name.status"
      local done_count passed
      done_count=$(find "$output/.timing" -name '*.status' | wc -l)
      passed=$(grep -c '^PASS ' "$output/reports/$name.txt")
      printf 'check-assignment: [%d/%d] %s: %d of 6 pass\n' "$done_count" "$total" \
        "$(printable "$(basename "$submission")")" "$passed" >&2
    ) &
    running_students=$((running_students + 1))
  done
  wait
  local finished
  finished=$(date +%s.%N)

  write_class_csv "$output" "${submissions[@]}"
  write_class_summary "$output" "$started" "$warmed" "$finished" "${submissions[@]}" |
    tee "$output/summary.txt.tmp"
  mv -f "$output/summary.txt.tmp" "$output/summary.txt"
  local ungraded=0
  for submission in "${submissions[@]}"; do
    [ -z "$(class_failure "${report_of[$submission]}")" ] || ungraded=$((ungraded + 1))
  done
  rm -rf "$output/.timing"
  echo "check-assignment: wrote $output/grades.csv, $output/summary.txt and $output/reports/" >&2
  # 0 when every submission was graded, whatever its verdicts; 1 when one could not be.
  [ "$ungraded" = 0 ]
}

# A submission whose whole check could not run: its one line of stderr, for the CSV and table.
class_failure() {
  local name=$1
  local status
  status=$(cat "$output/.timing/$name.status" 2>/dev/null || echo 2)
  [ "$status" = 2 ] || return 0
  head -n 1 "$output/reports/$name.err"
}

write_class_csv() {
  local output=$1
  shift
  {
    printf 'student'
    local function
    for function in "${functions[@]}"; do printf ',%s' "$function"; done
    printf ',passed,notes,report\n'
    local submission name verdict passed notes failure
    for submission in "$@"; do
      name=${report_of[$submission]}
      csv_field "$(basename "$submission")"
      passed=0
      failure=$(class_failure "$name")
      for function in "${functions[@]}"; do
        verdict=$(verdict_of "$output/reports/$name.txt" "$function")
        [ -n "$verdict" ] || verdict=ERROR
        [ "$verdict" = PASS ] && passed=$((passed + 1))
        printf ',%s' "$verdict"
      done
      # The notes, each after the function it is about.
      notes=$(awk '/^[A-Z]+  [a-z_]+/ { f = $2; sub(":$", "", f) }
                   /^      note: / { sub("^      note: ", ""); printf "%s%s: %s", sep, f, $0; sep = " | " }' \
                "$output/reports/$name.txt")
      [ -z "$failure" ] || notes=$failure
      printf ',%d,' "$passed"
      csv_field "$notes"
      printf ','
      csv_field "reports/$name.txt"
      printf '\n'
    done
  } >"$output/grades.csv.tmp"
  mv -f "$output/grades.csv.tmp" "$output/grades.csv"
}

write_class_summary() {
  local output=$1 started=$2 warmed=$3 finished=$4
  shift 4
  local submissions=("$@")
  local compile_sum=0 check_sum=0 submission name
  for submission in "${submissions[@]}"; do
    name=${report_of[$submission]}
    read -r compile_sum check_sum < <(awk -v c="$compile_sum" -v k="$check_sum" \
      '$1 == "compile" { c += $2 } $1 == "check" { k += $2 } END { print c, k }' \
      "$output/.timing/$name" 2>/dev/null || echo "$compile_sum $check_sum")
  done
  awk -v n="${#submissions[@]}" -v j="$jobs" -v s="$started" -v w="$warmed" -v f="$finished" \
    -v c="$compile_sum" -v k="$check_sum" 'BEGIN {
      printf "Graded %d submissions in %.0f s, %d at a time.\n", n, f - s, j
      printf "Time: %.0f s compiling Wobble'"'"'s side (cached after the first run); per submission, summed:\n", w - s
      printf "%.0f s compiling and linking, %.0f s checking (%.0f%% compiling).\n\n", c, k, (c + k > 0) ? 100 * c / (c + k) : 0
    }'
  printf '%-40s %5s %5s %5s %8s\n' function PASS FAIL ERROR MISSING
  local function verdict count
  for function in "${functions[@]}"; do
    local -A count_of=([PASS]=0 [FAIL]=0 [ERROR]=0 [MISSING]=0)
    for submission in "${submissions[@]}"; do
      verdict=$(verdict_of "$output/reports/${report_of[$submission]}.txt" "$function")
      [ -n "$verdict" ] || verdict=ERROR
      count_of[$verdict]=$((${count_of[$verdict]:-0} + 1))
    done
    printf '%-40s %5d %5d %5d %8d\n' "$function" "${count_of[PASS]}" "${count_of[FAIL]}" \
      "${count_of[ERROR]}" "${count_of[MISSING]}"
  done
  printf '\nP pass, F fail, E error, M missing; columns in the assignment'"'"'s order:\n'
  printf '  incidence dense, incidence sparse, precomputation dense, precomputation sparse,\n'
  printf '  step dense, step sparse. Each student'"'"'s report says what differs.\n\n'
  local letters
  for submission in "${submissions[@]}"; do
    name=${report_of[$submission]}
    letters=""
    for function in "${functions[@]}"; do
      verdict=$(verdict_of "$output/reports/$name.txt" "$function")
      letters+="${verdict:0:1}"
      [ -n "$verdict" ] || letters+=E
      letters+=" "
    done
    count=$(grep -c '^PASS ' "$output/reports/$name.txt")
    printf '%-40s %s %d/6' "$(printable "$(basename "$submission")" | cut -c1-40)" "$letters" "$count"
    local failure
    failure=$(class_failure "$name")
    [ -z "$failure" ] || printf '  (%s)' "$failure"
    printf '\n'
  done
}
