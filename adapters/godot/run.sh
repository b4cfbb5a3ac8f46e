#!/usr/bin/env bash
# Runs the Godot adapter (adapter.gd on Debian's godot3-server, headless). Godot's banner and
# warnings go to stderr. Without godot3-server it exits 3 at once, saying on stderr what to run
# (`bash scripts/setup.sh --engines godot`, which runs install.sh).
#
#   run.sh IN OUT    file mode: answers the scene lines of IN into OUT, one line per scene, and
#                    exits (tilesweep's --resolver-cmd "adapters/godot/run.sh {in} {out}")
#   run.sh           pipe mode: scene lines on stdin, one answer line per scene on stdout as soon
#                    as it is known. Godot 3.2 cannot read a pipe, so this copies stdin into a
#                    file that one long-lived Godot follows, and prints the file of answers as
#                    it grows: Godot starts once instead of once per batch.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ $# -ne 0 ] && [ $# -ne 2 ]; then
    echo "usage: $0 [IN OUT]   (file mode with IN OUT, else scene lines on stdin, answers on stdout)" >&2
    exit 2
fi
bash "$here/install.sh" --check || exit
if [ $# -eq 2 ]; then
    in="$(realpath -m -- "$1")"
    out="$(realpath -m -- "$2")"
    exec godot3-server --no-window --path "$here" -s adapter.gd "$in" "$out" >&2
fi

work="$(mktemp -d)"
godot=""
printer=""
cleanup() {
    [ -z "$godot" ] || kill "$godot" 2>/dev/null || true
    [ -z "$printer" ] || kill "$printer" 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 143' TERM INT
: >"$work/scenes.jsonl"
: >"$work/answers.jsonl"
godot3-server --no-window --path "$here" -s adapter.gd --follow "$work/scenes.jsonl" "$work/answers.jsonl" $$ >&2 &
godot=$!
# Prints every answer line as it is written, and stops once Godot has exited.
tail -n +1 -s 0.01 -f --pid="$godot" "$work/answers.jsonl" &
printer=$!
cat >>"$work/scenes.jsonl"
echo "tilesweep-end-of-input" >>"$work/scenes.jsonl"
wait "$godot" || true
wait "$printer" || true
godot=""
printer=""
