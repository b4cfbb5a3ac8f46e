#!/usr/bin/env python3
"""Replays every counterexample of the conformance report (docs/conformance/*/*.jsonl) against the
answer its engine gave, recorded in the file (scripts/recorded_answer.py), so that no engine is
needed: each must still fail. Its own failure must come back word for word, unless the claim asks
about a scene the file does not record (the metamorphic claims' transformed scenes), in which case
the replay fails for want of that answer and says so.

    conformance_replay_test.py TILESWEEP RECORDED_ANSWER_PY DIR

Exit status: 0 every file failed as recorded; 1 one did not (named); 77 DIR holds no
counterexample (ctest's skip code here)."""
import glob
import json
import os
import subprocess
import sys


def main(tool, recorder, directory):
    files = sorted(glob.glob(os.path.join(directory, "*", "*.jsonl")))
    if not files:
        print(f"skipped: no counterexample under {directory}")
        return 77
    verbatim = unrecorded = 0
    wrong = []
    for path in files:
        with open(path, encoding="utf-8") as f:
            failure = json.loads(f.readline())["failure"].split("\n")[0]
        command = f"python3 {recorder} {path}"
        run = subprocess.run([tool, "replay", "--resolver-cmd", command, path], capture_output=True, text=True,
                             timeout=120)
        messages = [line.split(": ", 2)[-1] for line in run.stdout.splitlines() if line.startswith("FAILED ")]
        if run.returncode != 1:
            wrong.append(f"{path}: replay exited {run.returncode}, not 1 (the claim failing):\n{run.stdout}{run.stderr}")
        elif failure in messages:
            verbatim += 1
        elif any("no answer recorded for this scene" in m for m in messages):
            unrecorded += 1
        else:
            wrong.append(f"{path}: its failure '{failure}' did not come back; the replay said:\n{run.stdout}")
    print(f"{len(files)} counterexamples replayed: {verbatim} failed word for word as recorded, "
          f"{unrecorded} for want of a scene the file does not record, {len(wrong)} otherwise")
    for w in wrong:
        print(w)
    # Most counterexamples are of claims about one scene: a replay that reproduced few of them
    # would be checking nothing.
    if verbatim * 2 < len(files):
        print(f"only {verbatim} of {len(files)} reproduced their failure word for word")
        return 1
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
