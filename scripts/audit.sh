#!/usr/bin/env bash
# The tolerance audit with its charts: builds the CLI (the plain Release build), runs
# `tilesweep audit` into DIR (default build/audit), then draws DIR/error_vs_magnitude.svg and
# failures_per_family.svg from DIR/report.json with scripts/plots.py (Debian's
# python3-matplotlib, installed when missing). With --docs it then replaces docs/audit whole with
# what a reader uses: report.md and the two charts (report.json and worst/, every figure and the
# worst scene of every cell, stay in DIR).
#
#   bash scripts/audit.sh [--out DIR] [--docs] [tilesweep audit options...]   # e.g. --cases 500 --seed 7
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/build/audit
docs=0
args=()
while (($#)); do
    case "$1" in
        --out) out=${2:?--out needs a directory}; shift 2 ;;
        --out=*) out=${1#*=}; shift ;;
        --docs) docs=1; shift ;;
        *) args+=("$1"); shift ;;
    esac
done
export TILESWEEP_PRESET=${TILESWEEP_PRESET:-plain}
export TILESWEEP_EXTRA_PACKAGES=python3-matplotlib
bash "$root/scripts/setup.sh"
TILESWEEP_TARGETS=tilesweep_cli bash "$root/scripts/build.sh" >/dev/null
cd "$root"
# The stamp describes the sources the audit runs on, so it is taken before docs/audit is replaced.
commit=$(git -C "$root" rev-parse --short HEAD)
dirty=$(git -C "$root" status --porcelain --untracked-files=no | grep -q . && echo " (with uncommitted changes)" || true)
"${TILESWEEP_BUILD_DIR:-$root/build/$TILESWEEP_PRESET}/cli/tilesweep" audit --out "$out" "${args[@]}" || status=$?
/usr/bin/python3 "$root/scripts/plots.py" audit "$out"
if ((docs)) && [ "${status:-0}" -le 1 ]; then
    rm -rf "$root/docs/audit"
    mkdir -p "$root/docs/audit"
    cp "$out/error_vs_magnitude.svg" "$out/failures_per_family.svg" "$root/docs/audit/"
    stamp="Made on $(date -u '+%Y-%m-%d %H:%M UTC') on commit $commit$dirty by \`bash scripts/audit.sh --docs${args[*]:+ ${args[*]}}\`; regenerate it whole that way, never by hand."
    awk -v stamp="$stamp" 'NR == 1 { print; print ""; print stamp; next } { print }' "$out/report.md" > "$root/docs/audit/report.md"
    echo "audit: docs/audit replaced (report.md and the charts; every figure in $out/report.json)"
fi
exit "${status:-0}"
