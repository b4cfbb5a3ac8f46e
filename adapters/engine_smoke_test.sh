#!/usr/bin/env bash
# Smoke test of an engine adapter (adapters/godot, adapters/rapier): runs it on a few scenes and
# checks that it answers one line per scene, in order, with as many frames as tilesweep's own
# answer, and an error exactly where tilesweep gives one; that it answers the same through a pipe
# as from a file; then that tilesweep reads back every answer to a valid scene through
# --resolver-cmd (file mode for Godot, pipe mode for Rapier). Exits 77 (ctest's skip code here) with
# "skipped: ..." when the engine's runtime is not installed (adapters/ENGINE/install.sh --check);
# `bash scripts/setup.sh --engines` installs it, a test does not.
#
#   engine_smoke_test.sh ENGINE TILESWEEP SCENES...     # ENGINE: a directory adapters/ENGINE with install.sh and run.sh
set -euo pipefail
engine=$1
tilesweep=$2
shift 2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ ! -f "$here/$engine/install.sh" ] || [ ! -x "$here/$engine/run.sh" ]; then
    echo "unknown engine '$engine' (adapters/*/install.sh: $(cd "$here" && echo */install.sh | sed 's|/install.sh||g'))" >&2
    exit 2
fi
# The engine's arithmetic: adapters/ENGINE/scalar holds "double" for a double engine (planck).
scalar=float
if [ -f "$here/$engine/scalar" ]; then scalar=$(tr -d '[:space:]' < "$here/$engine/scalar"); fi
status=0
missing=$(bash "$here/$engine/install.sh" --check 2>&1) || status=$?
if [ "$status" -eq 3 ]; then
    echo "skipped: $missing"
    exit 77
elif [ "$status" -ne 0 ]; then
    echo "adapters/$engine/install.sh --check failed (status $status): $missing"
    exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat "$@" | grep -v '^[[:space:]]*$' > "$work/scenes.jsonl"
"$tilesweep" resolve --scalar "$scalar" "$work/scenes.jsonl" > "$work/expected.jsonl" || true
"$here/$engine/run.sh" "$work/scenes.jsonl" "$work/answers.jsonl" 2> "$work/stderr" || {
    echo "the $engine adapter failed; its stderr ends with:"
    tail -n 20 "$work/stderr"
    exit 1
}

# Pipe mode (scene lines on stdin) answers exactly as file mode does.
if ! "$here/$engine/run.sh" < "$work/scenes.jsonl" > "$work/piped.jsonl" 2>> "$work/stderr" ||
    ! cmp -s "$work/answers.jsonl" "$work/piped.jsonl"; then
    echo "the $engine adapter answers differently through a pipe than from a file:"
    diff "$work/answers.jsonl" "$work/piped.jsonl" | head -n 6
    exit 1
fi

# Per line: "error", or the number of frames (one "pos" per frame).
shape() { awk '{ if ($0 ~ /^\{"error": ?"/) print "error"; else if ($0 ~ /^\{"frames": \[/) print gsub(/"pos": \[/, "&") " frames"; else print "not an answer: " substr($0, 1, 60) }' "$1"; }
shape "$work/expected.jsonl" > "$work/expected.shape"
shape "$work/answers.jsonl" > "$work/answers.shape"
if ! diff "$work/expected.shape" "$work/answers.shape" > "$work/diff"; then
    echo "the $engine adapter's answers do not have the expected shape (< tilesweep, > $engine):"
    cat "$work/diff"
    exit 1
fi
# Every answer to a valid scene, read back by tilesweep exactly as check and audit read it.
paste -d '\n' "$work/expected.shape" "$work/scenes.jsonl" | awk 'NR % 2 == 1 { keep = ($0 != "error") } NR % 2 == 0 && keep' \
    > "$work/valid.jsonl"
case $engine in
    godot) command="$here/godot/run.sh {in} {out}" ;;  # Godot starts once a batch: file mode
    *) command="$here/$engine/run.sh" ;;
esac
if ! "$tilesweep" resolve --scalar "$scalar" --resolver-cmd "$command" "$work/valid.jsonl" > "$work/read-back.jsonl" 2>&1; then
    echo "tilesweep could not read every answer of the $engine adapter:"
    grep '"error"' "$work/read-back.jsonl" | head -n 5
    exit 1
fi
echo "$engine: $(wc -l < "$work/answers.jsonl") answers, one per scene, with the expected frames and errors," \
    "$(wc -l < "$work/valid.jsonl") of them read back by tilesweep resolve --resolver-cmd"
