# Sourced by scripts/check-assignment.sh before anything else: SIGTERM, SIGINT and SIGHUP end
# every process the script started (each launcher, bounded_main.cpp, then kills its command's
# process group and the orphans it adopted), remove the temporary folder ($work, once
# check_toolchain has made it), and end the script by the same signal, as without the trap.
# Needs ps (procps).

# descendants PID: every process below PID, one a line, parents before their children.
descendants() {
  ps -e -o pid=,ppid= | awk -v root="$1" '
    { parent[$1] = $2; order[NR] = $1 }
    END {
      found[root] = 1
      do {
        more = 0
        for (i = 1; i <= NR; i++) {
          p = order[i]
          if (!(p in found) && (parent[p] in found)) { found[p] = 1; print p; more = 1 }
        }
      } while (more)
    }'
}

# still_running PID...: those of the PIDs that still run (not ended, not zombies).
still_running() {
  [ $# -gt 0 ] || return 0
  ps -o pid=,stat= -p "$(IFS=,; echo "$*")" 2>/dev/null | awk '$2 !~ /^Z/ { print $1 }'
}

# stop_everything SIGNAL: the trap.
stop_everything() {
  local signal=$1
  trap '' TERM INT HUP
  local -A seen=()
  local round pid pids=()
  # Twice: a job may have started a launcher while the first round was being sent.
  for round in 1 2; do
    while IFS= read -r pid; do
      [ -n "${seen[$pid]:-}" ] && continue
      seen[$pid]=1
      pids+=("$pid")
      kill -TERM "$pid" 2>/dev/null
    done < <(descendants $$)
    sleep 0.05
  done
  # Up to 5 s for them to end (a launcher first kills its command's group), then SIGKILL.
  local left=()
  for round in $(seq 50); do
    mapfile -t left < <(still_running "${pids[@]}")
    [ ${#left[@]} -gt 0 ] || break
    sleep 0.1
  done
  [ ${#left[@]} -eq 0 ] || kill -KILL "${left[@]}" 2>/dev/null
  wait 2>/dev/null
  if [ -n "${work:-}" ] && [ "${WOBBLE_CHECK_KEEP:-0}" != 1 ]; then rm -rf "$work"; fi
  trap - "$signal" EXIT
  kill -s "$signal" $$
  # A signal ignored on entry (SIGINT in a background job) cannot end the script; this does.
  exit $((128 + $(kill -l "$signal")))
}

for stop_signal in TERM INT HUP; do
  # shellcheck disable=SC2064
  trap "stop_everything $stop_signal" "$stop_signal"
done
