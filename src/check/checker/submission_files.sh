# Sourced by scripts/check-assignment.sh: the assignment's six functions, and where a
# submission keeps them. No side effects beyond defining these.

functions=(
  signed_incidence_matrix_dense signed_incidence_matrix_sparse
  fast_mass_springs_precomputation_dense fast_mass_springs_precomputation_sparse
  fast_mass_springs_step_dense fast_mass_springs_step_sparse
)

die() {
  # One line whatever the names in it hold: a line break or a tab (a folder may be named with
  # one) is written as \n or \t, as wobble writes control characters.
  local message="check-assignment: $*"
  message=${message//$'\n'/\\n}
  message=${message//$'\r'/\\r}
  message=${message//$'\t'/\\t}
  printf '%s\n' "$message" >&2
  exit 2
}

# One line, whatever a name holds: newlines and other control characters as '?'.
printable() {
  printf '%s' "$1" | tr '\000-\037\177' '?'
}

# function_source FOLDER FUNCTION: the path of FUNCTION.cpp in the submission FOLDER, or
# nothing. The folder itself first, then src/ (the course's layout), then anywhere below up to
# four levels (a repository inside the folder, as a download or a clone leaves it), shallowest
# first and src/ folders before others. Hidden folders and build folders are not searched.
function_source() {
  local folder=$1 function=$2
  local name="$function.cpp"
  if [ -f "$folder/$name" ]; then
    printf '%s\n' "$folder/$name"
    return
  fi
  if [ -f "$folder/src/$name" ]; then
    printf '%s\n' "$folder/src/$name"
    return
  fi
  find "$folder" -mindepth 1 -maxdepth 4 \( -name '.*' -o -name 'build*' -o -name 'cmake-build*' \) \
    -prune -o -type f -name "$name" -print 2>/dev/null |
    awk -F/ '{ src = ($0 ~ /\/src\/[^\/]*$/) ? 0 : 1; print NF, src, $0 }' |
    LC_ALL=C sort -n -k1,1 -k2,2 | head -n 1 | cut -d' ' -f3-
}

# include_folders SOURCE FOLDER: the submission's own include folders for SOURCE, one a line, in
# the order the compiler searches them: the source's folder, an include/ beside it (the course's
# src/ and include/), the submission's include/, and the submission's folder.
include_folders() {
  local source_folder
  source_folder=$(cd "$(dirname "$1")" && pwd)
  local folder
  folder=$(cd "$2" && pwd)
  local candidates=("$source_folder" "$(dirname "$source_folder")/include" "$folder/include"
                    "$folder")
  local -A seen=()
  local candidate
  for candidate in "${candidates[@]}"; do
    [ -d "$candidate" ] || continue
    [ -z "${seen[$candidate]:-}" ] || continue
    seen[$candidate]=1
    printf '%s\n' "$candidate"
  done
}
