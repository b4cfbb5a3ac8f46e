#!/usr/bin/env python3
"""Applies one mutant of scripts/mutants.txt to a source tree, or puts its file back.

    mutate.py ROOT NAME            applies NAME in ROOT (ROOT/scripts/mutants.txt says where), prints the file
    mutate.py ROOT NAME restore    puts the file back whole, newer than anything built from the fault

A line of mutants.txt is "name ||| file ||| text ||| mutated text"; the text must occur exactly
once in the file. The file as it was is kept beside it (FILE.before-mutant) until restored.
scripts/fault-table.sh and scripts/judge-faults.sh apply their faults through this."""
import os
import sys


def main(root, name, mode="apply"):
    for line in open(os.path.join(root, "scripts/mutants.txt"), encoding="utf-8"):
        parts = line.rstrip("\n").split(" ||| ")
        if line.startswith("#") or len(parts) != 4 or parts[0] != name:
            continue
        path = os.path.join(root, parts[1])
        kept = path + ".before-mutant"
        if mode == "restore":
            if os.path.exists(kept):
                os.replace(kept, path)
                os.utime(path)  # newer than the objects built with the fault: they are built again
            print(parts[1])
            return 0
        text = open(path, encoding="utf-8").read()
        if text.count(parts[2]) != 1:
            sys.exit(f"mutant {name}: the text occurs {text.count(parts[2])} times in {parts[1]}")
        os.replace(path, kept)
        open(path, "w", encoding="utf-8").write(text.replace(parts[2], parts[3]))
        print(parts[1])
        return 0
    sys.exit(f"no mutant {name}")


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
