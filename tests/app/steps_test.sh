#!/bin/bash
# scripts/steps.sh (used by ./run, ./test and CI): a passing step shows its output and goes on; a failing one is
# named with its first error and the last lines of its log, and the script exits with the step's status.
set -u
SRC=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cat >"$T/script" <<EOS
set -euo pipefail
ROLLVIZ_LOGS="$T/logs"
source "$SRC/scripts/steps.sh"
step "say hello" echo hello
step "build (demo preset)" bash -c 'for i in \$(seq 1 40); do echo "line \$i"; done; echo "foo.cpp:3: error: no cross here" >&2; echo "[9/9] linking"; exit 7'
echo "not reached"
EOS
bash "$T/script" >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 7 ] || fail "exit status $rc, want the step's 7"
grep -q '^hello$' "$T/out" || fail "the passing step's output is not shown"
grep -q 'not reached' "$T/out" && fail "the script went on after a failed step"
grep -q 'FAILED at step "build (demo preset)" (exit status 7)' "$T/err" || fail "the failed step is not named"
grep -q '  foo.cpp:3: error: no cross here' "$T/err" || fail "the first error is not quoted"
grep -q '  \[9/9\] linking' "$T/err" || fail "the log's last lines are not shown"
grep -q "line 1$" "$T/logs/build-demo-preset.log" || fail "the whole log is not kept"
echo "steps: 6 passed, 0 failed"
