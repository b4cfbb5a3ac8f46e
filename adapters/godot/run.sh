#!/usr/bin/env bash
# Runs the Godot adapter in file mode: `run.sh IN OUT` answers the scene lines of IN into OUT,
# one line per scene (Godot 3.2 cannot read a pipe). Installs Debian's godot3-server through the
# project's setup on first use. Godot's banner and warnings go to stderr; OUT holds only answers.
set -euo pipefail
if [ $# -ne 2 ]; then
    echo "usage: $0 IN OUT   (scene lines in IN, one answer line per scene written to OUT)" >&2
    exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if ! command -v godot3-server >/dev/null; then
    TILESWEEP_EXTRA_PACKAGES=godot3-server bash "$here/../../scripts/setup.sh" >&2
fi
in="$(realpath -m -- "$1")"
out="$(realpath -m -- "$2")"
exec godot3-server --no-window --path "$here" -s adapter.gd "$in" "$out" >&2
