#!/usr/bin/env bash
# clang-format (Debian's clang-format-14, installed when missing) over every tracked C and C++
# file, with the repository's .clang-format.
#
#   bash scripts/format.sh --check    # lists the files that differ and exits 1 if any does (CI)
#   bash scripts/format.sh            # rewrites them in place
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mode=apply
case "${1:-}" in
    --check) mode=check ;;
    "") ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "format.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
esac
if ! command -v clang-format-14 >/dev/null; then
    source "$root/scripts/setup.sh"
    TILESWEEP_EXTRA_PACKAGES=clang-format-14 tilesweep_setup_base
fi
cd "$root"
mapfile -t files < <(git ls-files '*.h' '*.cpp' '*.c')
if [ "$mode" = check ]; then
    bad=()
    for file in "${files[@]}"; do
        clang-format-14 --dry-run --Werror "$file" >/dev/null 2>&1 || bad+=("$file")
    done
    if ((${#bad[@]})); then
        echo "format.sh: ${#bad[@]} of ${#files[@]} files differ from .clang-format (bash scripts/format.sh fixes them):" >&2
        printf '  %s\n' "${bad[@]}" >&2
        exit 1
    fi
    echo "format.sh: all ${#files[@]} files match .clang-format"
else
    clang-format-14 -i "${files[@]}"
fi
