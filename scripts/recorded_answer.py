#!/usr/bin/env python3
"""A resolver that answers from regression files: each scene line on stdin is looked up among the
scenes of FILE... (the lines `tilesweep check` writes for a counterexample of an outside resolver,
which carry that resolver's answer as "resolver_answer"), and answered with the recorded answer,
one line per scene, in `tilesweep resolve`'s protocol. A scene that no file holds gets an error
line. So a counterexample of an engine replays without the engine:

    tilesweep replay --resolver-cmd "python3 scripts/recorded_answer.py FILE" FILE

Scenes are compared as parsed JSON (map, box and moves), so key order and spacing do not matter;
their numbers are compared as written (hexfloats, as check writes and replay sends them)."""
import json
import sys


def scene_key(scene):
    return json.dumps({k: scene.get(k) for k in ("map", "box", "moves")}, sort_keys=True)


def main(paths):
    if not paths:
        print("usage: recorded_answer.py FILE...", file=sys.stderr)
        return 2
    answers = {}
    for path in paths:
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                if not line.strip():
                    continue
                record = json.loads(line)
                if "resolver_answer" not in record:
                    print(f"{path}:{number}: no resolver_answer to replay", file=sys.stderr)
                    return 2
                answers[scene_key(record)] = json.dumps(record["resolver_answer"], separators=(", ", ": "))
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            key = scene_key(json.loads(line))
        except (ValueError, AttributeError):
            key = None
        print(answers.get(key, '{"error": "no answer recorded for this scene"}'), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
