# Sourced by ./run, ./test and .ci/run. Each step's output is shown as it comes and kept in build/logs/; when a step
# fails, the script says which step, its first error lines and the last lines of its log, then exits with the step's
# status -- a failure reads "step X failed", not only as the compiler's wall of text.
ROLLVIZ_LOGS=${ROLLVIZ_LOGS:-$PWD/build/logs}
ROLLVIZ_STEP_TIMES=()

# step_summary: every step run so far with its time (./test prints it when it ends, passed or failed)
step_summary() {
  [ ${#ROLLVIZ_STEP_TIMES[@]} -eq 0 ] && return 0
  echo "== steps and their times"
  printf '  %s\n' "${ROLLVIZ_STEP_TIMES[@]}"
  echo "  total: $((SECONDS / 60)) min $((SECONDS % 60)) s"
}

# step "NAME" CMD...: runs CMD (stdout and stderr together, to stdout and the log) as the step NAME
step() {
  local name=$1
  shift
  local log rc=0 started=$SECONDS
  log="$ROLLVIZ_LOGS/$(printf '%s' "$name" | tr -cs 'A-Za-z0-9' '-' | sed 's/-$//').log"
  mkdir -p "$ROLLVIZ_LOGS"
  echo "== $name"
  # errexit is off inside an || list, so rc is read even under set -e -o pipefail
  { "$@" 2>&1 | tee "$log"; rc=${PIPESTATUS[0]}; } || true
  ROLLVIZ_STEP_TIMES+=("$(printf '%5d s  %s%s' $((SECONDS - started)) "$name" "$([ "$rc" -eq 0 ] || echo "  (FAILED)")")")
  [ "$rc" -eq 0 ] && return 0
  {
    echo
    echo "rollviz: FAILED at step \"$name\" (exit status $rc): $*"
    local errors
    errors=$(grep -E -m 12 ' error[: ]|Error [0-9]|undefined reference|FAILED|\*\*\*Failed|CMake Error|E: ' "$log" || true)
    if [ -n "$errors" ]; then
      echo "first errors:"
      printf '%s\n' "$errors" | cut -c1-300 | sed 's/^/  /'
    fi
    echo "last lines of $log:"
    tail -n 20 "$log" | cut -c1-300 | sed 's/^/  /'
  } >&2
  exit "$rc"
}
