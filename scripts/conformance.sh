#!/usr/bin/env bash
# The conformance report, regenerated whole: every engine of adapters/ (and tilesweep's own
# resolver and its inexact twin, for scale) held to the contract by `tilesweep audit
# --resolver-cmd`, float engines in one run and double engines in another, on the same seed.
# Writes OUT/conformance.md, stamped with the commit and date it was made on, with the smallest
# counterexample of each engine and failed claim (its picture and its regression file, which
# carries the engine's answer) and the tolerance chart in OUT/conformance/{float,double}/. The
# rates files the charts are drawn from (every figure of the rates tables) stay in
# build/conformance-rates/, for `tilesweep merge` and plots.py.
#
#   bash scripts/conformance.sh                       # into build/conformance (default)
#   bash scripts/conformance.sh --out docs            # the committed report: docs/conformance.md
#   bash scripts/conformance.sh --seconds 5 --rates-cases 200 --engines "godot planck"
#
# Options: --seconds S, the check budget per engine (default 20); --rates-cases N, scenes per
# family for the rates (default 2000); --engines "NAME...", only those adapters (default: every
# one whose runtime is installed; `bash scripts/setup.sh --engines` installs them all). An engine
# whose runtime is missing is left out and named in the report. Builds the CLI and the C++ adapters
# (the plain Release build) first.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/build/conformance
seconds=20
rates_cases=2000
only=""
while (($#)); do
    case $1 in
        --out) out=${2:?--out needs a directory}; shift 2 ;;
        --seconds) seconds=${2:?}; shift 2 ;;
        --rates-cases) rates_cases=${2:?}; shift 2 ;;
        --engines) only=${2:?}; shift 2 ;;
        *) echo "conformance: unknown option $1 (--out DIR, --seconds S, --rates-cases N, --engines \"NAME...\")" >&2; exit 2 ;;
    esac
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
export TILESWEEP_PRESET=${TILESWEEP_PRESET:-plain}
export TILESWEEP_EXTRA_PACKAGES=python3-matplotlib
bash "$root/scripts/setup.sh"
TILESWEEP_TARGETS="tilesweep_cli tilesweep_twin_adapter tilesweep_box2d_adapter" bash "$root/scripts/build.sh" >/dev/null
build=${TILESWEEP_BUILD_DIR:-$root/build/$TILESWEEP_PRESET}
cd "$root"
# Paths inside the checkout are written relative to it (the commands run from its root), so that
# the report quotes the command any clone can run, not this machine's directories.
relative() { if [[ $1 == "$root"/* ]]; then echo "${1#"$root"/}"; else echo "$1"; fi; }
build=$(relative "$build")
out=$(relative "$out")
tool=$build/cli/tilesweep

version_of() {  # version_of COMMAND...: the first line it prints, or "?" (godot exits non-zero after --version)
    local line
    line=$("$@" 2>/dev/null | tr -d '\r' | head -n 1) || true
    echo "${line:-?}"
}

# name | scalar | command | documented tolerance (px, then what it is) | version and configuration
engines=(
    "tilesweep|float|$tool resolve --scalar float||tilesweep's own resolver (this commit), as an outside process"
    "twin|float|$build/adapters/tilesweep_twin_adapter||the game-style swept-AABB twin (bench/), as a game would write it"
    "box2d|float|$build/adapters/tilesweep_box2d_adapter|0.08 linear slop (0.005 m at 16 px a meter)|Box2D $(version_of dpkg-query -W -f '${Version}' libbox2d-dev) (Debian), b2TimeOfImpact per tile"
    "godot|float|adapters/godot/run.sh|0.08 safe margin|Godot $(version_of godot3-server --version) (Debian godot3-server), KinematicBody2D motion tests, two slides"
    "rapier|float|adapters/rapier/run.sh|0.0001 normal nudge (offset 0)|@dimforge/rapier2d-compat @RAPIER@, KinematicCharacterController"
    "rapier-deterministic|float|adapters/rapier-deterministic/run.sh|0.0001 normal nudge (offset 0)|@dimforge/rapier2d-deterministic-compat @RAPIERDET@, the same controller"
    "phaser|float|adapters/phaser/run.sh|16 TILE_BIAS|phaser @PHASER@, Arcade physics against a tilemap layer, one step at 60 Hz"
    "box2d3|float|adapters/box2d3/run.sh|0.08 linear slop (0.005 m at 16 px a meter)|box2d3-wasm @BOX2D3@, Box2D v3's capsule mover (cast, collide, solve planes)"
    "tilesweep|double|$tool resolve --scalar double||tilesweep's own resolver (this commit), as an outside process"
    "planck|double|adapters/planck/run.sh|0.08 linear slop (0.005 m at 16 px a meter)|planck @PLANCK@, a dynamic box body, one world step at 60 Hz"
    "matter|double|adapters/matter/run.sh|0.05 slop|matter-js @MATTER@, a dynamic body with infinite inertia, one Engine.update at 60 Hz"
)
npm_version() {  # npm_version ADAPTER PACKAGE: the locked version of PACKAGE in adapters/ADAPTER
    node -e 'const l = require(process.argv[1]); const p = l.packages["node_modules/" + process.argv[2]]; console.log(p ? p.version : "?")' \
        "$root/adapters/$1/package-lock.json" "$2" 2>/dev/null || echo "?"
}
describe() {
    local text=$1
    text=${text//@RAPIER@/$(npm_version rapier @dimforge/rapier2d-compat)}
    text=${text//@RAPIERDET@/$(npm_version rapier-deterministic @dimforge/rapier2d-deterministic-compat)}
    text=${text//@PHASER@/$(npm_version phaser phaser)}
    text=${text//@BOX2D3@/$(npm_version box2d3 box2d3-wasm)}
    text=${text//@PLANCK@/$(npm_version planck planck)}
    text=${text//@MATTER@/$(npm_version matter matter-js)}
    echo "$text"
}

# Which engines run: an adapter whose runtime is missing is said, not run.
declare -A missing=()
for row in "${engines[@]}"; do
    IFS='|' read -r name scalar command tolerance about <<<"$row"
    if [ -n "$only" ] && [[ " $only " != *" $name "* ]] && [ "$name" != tilesweep ]; then
        missing[$name]="not asked for (--engines)"
        continue
    fi
    if [[ $command == adapters/* ]]; then
        adapter=${command#adapters/}
        adapter=${adapter%%/*}
        if ! why=$(bash "adapters/$adapter/install.sh" --check 2>&1); then missing[$name]=$why; fi
    elif [ ! -x "${command%% *}" ]; then
        missing[$name]="${command%% *} was not built"
    fi
done

commit=$(git -C "$root" rev-parse --short HEAD)
dirty=$(git -C "$root" status --porcelain --untracked-files=no | grep -q . && echo " (with uncommitted changes)" || true)
date=$(date -u '+%Y-%m-%d %H:%M UTC')
parts=()
for scalar in float double; do
    args=()
    names=()
    for row in "${engines[@]}"; do
        IFS='|' read -r name s command tolerance about <<<"$row"
        [ "$s" = "$scalar" ] && [ -z "${missing[$name]:-}" ] || continue
        names+=("$name")
        args+=(--resolver-cmd "$command" --resolver-name "$name")
        [ -n "$tolerance" ] && args+=(--resolver-tolerance "$name=$tolerance")
    done
    ((${#args[@]})) || continue
    rm -rf "$out/conformance/$scalar" "$out/conformance-$scalar.md"
    echo "conformance: the $scalar engines (${names[*]}): checks of ${seconds} s each, $rates_cases scenes a family" >&2
    status=0
    rates=build/conformance-rates/$scalar/rates.json
    rm -rf "$(dirname "$rates")"
    "$tool" audit "${args[@]}" --scalar "$scalar" --compare "" --seconds "$seconds" --rates-cases "$rates_cases" \
        --report "$out/conformance-$scalar.md" --pictures "$out/conformance/$scalar" --rates-json "$rates" >&2 ||
        status=$?
    # 1: some engine broke some claim, which is what the report is for; anything else is a failure.
    if [ "$status" -gt 1 ]; then
        echo "conformance: tilesweep audit failed (status $status) on the $scalar engines" >&2
        exit "$status"
    fi
    /usr/bin/python3 "$root/scripts/plots.py" rates "$rates" >&2
    mv "$(dirname "$rates")/tolerance_vs_distance.svg" "$out/conformance/$scalar/"
    parts+=("$scalar")
done

# One page: the stamp, the engines, then each run's report with its headings one level down.
report=$out/conformance.md
{
    echo "# Conformance: engines held to the contract"
    echo
    echo "Made on $date on commit $commit$dirty, on a machine of $(nproc) cores, by"
    echo '`bash scripts/conformance.sh'"$( [ "$out" = docs ] && echo ' --out docs')"' --seconds '"$seconds"' --rates-cases '"$rates_cases"'`.'
    echo "Regenerate it whole with that command; never edit it by hand. The contract is"
    echo "[contract.md](contract.md); how each engine is driven, and where it deviates by design, is in"
    echo "[adapters/README.md](../adapters/README.md)."
    echo
    echo "| engine | scalar | documented tolerance | version and configuration |"
    echo "|---|---|---|---|"
    for row in "${engines[@]}"; do
        IFS='|' read -r name scalar command tolerance about <<<"$row"
        if [ -n "${missing[$name]:-}" ]; then
            echo "| $name | $scalar | ${tolerance:-none} | not measured: ${missing[$name]//|/ } |"
        else
            echo "| $name | $scalar | ${tolerance:-none} | $(describe "$about") |"
        fi
    done
    for scalar in "${parts[@]}"; do
        echo
        echo "# The $scalar engines"
        echo
        echo "![The tolerance each claim would need, against the distance from the origin](conformance/$scalar/tolerance_vs_distance.svg)"
        sed -e '1{/^# /d}' "$out/conformance-$scalar.md"
    done
} > "$report.tmp"
mv "$report.tmp" "$report"
for scalar in "${parts[@]}"; do rm -f "$out/conformance-$scalar.md"; done
echo "conformance: $report"
