#!/usr/bin/env bash
# The main job: builds tilesweep (installing what is missing) and resolves the example scenes
# shipped in examples/, one JSON line of frames per scene, in float.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh"
"${TILESWEEP_BUILD_DIR:-$root/build}/cli/tilesweep" resolve "${@:---scalar=float}" "$root/examples/platformer.jsonl"
