#!/usr/bin/env bash
# Runs `tilesweep check` on an outside resolver and holds the verdict to what is expected of it,
# claim by claim, from the run's --json file (cli/check_command.cpp, checkJson):
#
#   bash rule_breaker_test.sh TILESWEEP RESOLVER_CMD fails CLAIM[:RULE]... -- CHECK_ARGS...
#       the run fails (exit status 1), and every CLAIM named has a failing property; with :RULE,
#       one of that claim's failure messages names the safety rule ("frame 0: RULE: ...", as
#       obeysTheSafetyRules reports the first rule of checks/frame_safety.h a frame breaks)
#   bash rule_breaker_test.sh TILESWEEP RESOLVER_CMD passes -- CHECK_ARGS...
#       the run passes: exit status 0, no property failed
#
# The other claims that failed are listed, not judged: a rule broken can break what follows from
# it. Without python3 it exits 77, which ctest reports as skipped (SKIP_RETURN_CODE).
set -uo pipefail
if ! command -v python3 >/dev/null; then
    echo "python3 not found: skipped"
    exit 77
fi
tilesweep=$1
resolver=$2
expect=$3
shift 3
wanted=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do
    wanted+=("$1")
    shift
done
[ "${1:-}" = -- ] && shift
json=$(mktemp --suffix=.json)
log=$(mktemp)
trap 'rm -f "$json" "$log"' EXIT
"$tilesweep" check --resolver-cmd "$resolver" --json "$json" "$@" >"$log" 2>&1
status=$?
python3 - "$json" "$status" "$expect" "${wanted[@]}" <<'PY'
import json, sys

path, status, expect, wanted = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
try:
    rows = json.load(open(path))["rows"]
except (OSError, ValueError, KeyError) as e:
    sys.exit(f"FAIL: no check JSON (exit status {status}): {e}")
failed = {}  # claim -> failure messages of its properties
for r in rows:
    if r["failures"] > 0:
        failed.setdefault(r["claim"], []).extend(r["messages"] or [r["smallest_failure"]])
for claim, messages in sorted(failed.items()):
    print(f"failed: {claim}: {messages[0].splitlines()[0] if messages else '?'}")
problems = []
if expect == "passes":
    if status != 0 or failed:
        problems.append(f"expected to pass; exit status {status}, {len(failed)} claim(s) failed")
else:
    if status != 1:
        problems.append(f"expected exit status 1 (a claim failed), got {status}")
    for want in wanted:
        claim, _, rule = want.partition(":")
        if claim not in failed:
            problems.append(f"claim {claim} did not fail")
        elif rule and not any(f": {rule}: " in m for m in failed[claim]):
            problems.append(f"claim {claim} failed, but no message names the rule {rule}")
for p in problems:
    print("FAIL " + p)
print(f"{len(rows)} properties, {len(failed)} claim(s) failed, {len(problems)} problem(s)")
sys.exit(1 if problems else 0)
PY
verdict=$?
if [ "$verdict" -ne 0 ]; then
    echo "--- tilesweep check output ---"
    cat "$log"
fi
exit "$verdict"
