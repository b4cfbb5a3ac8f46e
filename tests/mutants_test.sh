#!/usr/bin/env bash
# Every mutant of scripts/mutants.txt still applies to today's sources, as scripts/fault-table.sh
# (TILESWEEP_MUTANTS=1) applies it: a line is "name ||| file ||| text ||| mutated text" (fields
# separated by " ||| ", nothing trimmed), the file exists, the text occurs in it exactly once, the
# mutated text differs from it, and no name repeats. Lines starting with # and blank lines are
# skipped. Each bad entry is named with its line; the test fails when there is one.
#
#   bash tests/mutants_test.sh [ROOT] [MUTANTS_FILE]   (defaults: the repository, scripts/mutants.txt)
#
# No build needed: python3's standard library only, as fault-table.sh's own mutate() uses.
# Without python3 it exits 77, which ctest reports as skipped (SKIP_RETURN_CODE).
set -euo pipefail
if ! command -v python3 >/dev/null; then
    echo "python3 not found: skipped"
    exit 77
fi
root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
list=${2:-$root/scripts/mutants.txt}
exec python3 - "$root" "$list" <<'PY'
import os, re, sys

root, listing = sys.argv[1:]
bad = []
names = {}
checked = 0
try:
    lines = open(listing, encoding="utf-8").read().split("\n")
except OSError as e:
    sys.exit(f"FAIL: cannot read {listing}: {e.strerror}")
if lines and lines[-1] == "":
    lines.pop()  # the final newline
for number, line in enumerate(lines, 1):
    if line.startswith("#") or line.strip() == "":
        continue
    where = f"{os.path.basename(listing)}:{number}"
    parts = line.split(" ||| ")
    if len(parts) != 4:
        bad.append(f"{where}: malformed: {len(parts)} field(s), not 4 (name ||| file ||| text ||| mutated text): {line[:80]}")
        continue
    name, path, text, mutated = parts
    label = f"{where} {name}"
    # fault-table.sh lists the mutants by this pattern: a name it does not match is never run.
    if not re.fullmatch(r"[A-Z][A-Z0-9_]*", name):
        bad.append(f"{label}: malformed: the name is not [A-Z][A-Z0-9_]*")
    if name in names:
        bad.append(f"{label}: the name repeats (first on line {names[name]})")
    else:
        names[name] = number
    checked += 1
    if text == mutated:
        bad.append(f"{label}: the mutated text equals the text")
    if text == "":
        bad.append(f"{label}: the text is empty")
        continue
    full = os.path.join(root, path)
    if os.path.isabs(path) or not os.path.isfile(full):
        bad.append(f"{label}: no file {path}")
        continue
    source = open(full, encoding="utf-8").read()
    # Occurrences, overlapping ones included: exactly one means str.replace changes that one.
    count, at = 0, source.find(text)
    while at >= 0:
        count += 1
        at = source.find(text, at + 1)
    if count != 1:
        bad.append(f"{label}: the text occurs {count} times in {path}, not once: {text.strip()[:80]}")
for message in bad:
    print(f"FAIL {message}")
print(f"{checked} mutant(s) checked in {listing}, {len(bad)} problem(s)")
sys.exit(1 if bad else 0)
PY
