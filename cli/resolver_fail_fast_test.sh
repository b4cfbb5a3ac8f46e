#!/usr/bin/env bash
# A broken or hung outside resolver is named, in time, by `tilesweep check`:
#
#   resolver_fail_fast_test.sh TILESWEEP cannot-start | exits-at-once | hangs | hangs-after-3
#
# cannot-start, exits-at-once and hangs fail the known scene sent before any worker starts: exit
# status 2, "resolver unusable", the reason (exit status and standard error, or the timeout),
# within 5 s. hangs-after-3 answers three scenes per process, then hangs: the run goes on, shows
# each hang as it happens, and ends by --seconds plus one --resolver-timeout with status 1. In
# every case no process of the resolver is left running.
set -uo pipefail
tilesweep=$1
case=$2
marker="tilesweep_fail_fast_$$"  # in each command line, to find what it leaves behind
case $case in
cannot-start)
    command="/nonexistent/$marker/adapter"
    seconds=10 timeout=10 limit=5 status=2
    expect=("resolver unusable" "status 127" "not found")
    ;;
exits-at-once)
    command="sh -c 'echo broken adapter $marker >&2; exit 100'"
    seconds=10 timeout=10 limit=5 status=2
    expect=("resolver unusable" "exited with status 100" "broken adapter")
    ;;
hangs)
    command="sh -c ': $marker; exec sleep 1000'"
    seconds=10 timeout=2 limit=5 status=2
    expect=("resolver unusable" "no answer within 2 s" "answering 0 of the 1 scenes")
    ;;
hangs-after-3)
    # tilesweep's own answers, three a process, then silence with the pipe held open.
    command="sh -c '$tilesweep resolve --scalar float | { n=0; while IFS= read -r l; do printf \"%s\\n\" \"\$l\"; n=\$((n+1)); [ \$n -ge 3 ] && break; done; : $marker; sleep 1000; }'"
    seconds=3 timeout=2 limit=8 status=1
    expect=("resolver failure: no answer within 2 s" "after answering 3 of the" "stopping the workers")
    ;;
*)
    echo "unknown case $case" >&2
    exit 2
    ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"; pkill -KILL -f "$marker" 2>/dev/null' EXIT
start=$(date +%s%N)
"$tilesweep" check --resolver-cmd "$command" --scalar float --seconds "$seconds" \
    --resolver-timeout "$timeout" --corpus "$work/corpus" >"$work/out" 2>&1
got=$?
elapsed_ms=$((($(date +%s%N) - start) / 1000000))
elapsed=$(printf "%d.%03d" $((elapsed_ms / 1000)) $((elapsed_ms % 1000)))
fail=0
if [ "$got" -ne "$status" ]; then
    echo "FAIL: exit status $got, expected $status"
    fail=1
fi
if [ "$elapsed_ms" -gt $((limit * 1000)) ]; then
    echo "FAIL: took $elapsed s, more than $limit s"
    fail=1
fi
for text in "${expect[@]}"; do
    if ! grep -qF -- "$text" "$work/out"; then
        echo "FAIL: the output does not say '$text'"
        fail=1
    fi
done
sleep 0.2
if pgrep -f "$marker" >/dev/null; then
    echo "FAIL: the resolver was left running:"
    pgrep -af "$marker"
    fail=1
fi
if [ "$fail" -ne 0 ]; then
    echo "--- output of: tilesweep check --resolver-cmd \"$command\" (${elapsed} s)"
    cut -c1-300 "$work/out" | tail -40
    exit 1
fi
echo "ok: $case named in ${elapsed} s (status $got)"
