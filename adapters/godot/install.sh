#!/usr/bin/env bash
# The Godot adapter's runtime, Debian's godot3-server, installed through scripts/setup.sh (under
# its lock). `bash scripts/setup.sh --engines godot` runs this; run.sh only checks.
#
#   install.sh           installs godot3-server when it is missing
#   install.sh --check   exits 0 when it is installed, else 3 with one line on stderr saying what to run
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
command -v godot3-server >/dev/null && exit 0
if [ "${1:-}" = --check ]; then
    echo "godot3-server is not installed: run  bash scripts/setup.sh --engines godot" >&2
    exit 3
fi
bash "$here/../../scripts/setup.sh" --packages godot3-server
if ! command -v godot3-server >/dev/null; then
    echo "install: the godot3-server package is installed but godot3-server is not on PATH ($PATH)" >&2
    exit 1
fi
