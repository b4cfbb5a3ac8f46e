#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes N random scene lines (docs/contract.md, "Scene files") for timing an engine
adapter alone: small maps of 16-pixel tiles placed at a spread of distances from the origin
(0, 2^10, 2^16, 2^20, 2^24), boxes and moves of platformer sizes, one to four frames, every
number a float32 written as a hexfloat string, as `tilesweep check` writes them.

    python3 adapters/engine_scenes.py 5000 > /tmp/scenes.jsonl
    time adapters/rapier/run.sh /tmp/scenes.jsonl /tmp/answers.jsonl
"""
import json
import random
import struct
import sys


def float32(value):
    return struct.unpack("f", struct.pack("f", value))[0]


def hexfloat(value):
    return float.hex(float32(value))


def scene(rng):
    columns, rows = rng.randint(4, 12), rng.randint(3, 8)
    density = rng.choice([0.15, 0.3, 0.5])
    cells = [["#" if rng.random() < density else "." for _ in range(columns)] for _ in range(rows)]
    cells[-1] = ["#"] * columns  # a floor
    far = rng.choice([0, 2**10, 2**16, 2**20, 2**24])
    origin = [far * rng.choice([-1, 1]), far * rng.choice([-1, 1])]
    size = [rng.choice([4, 8, 12, 14, 16, 20]), rng.choice([4, 8, 12, 16, 24])]
    box = [origin[0] + rng.uniform(0, 16 * columns - size[0]), origin[1] + rng.uniform(0, 16 * (rows - 1) - size[1])]
    scale = rng.choice([1, 4, 16, 64])
    moves = [[rng.uniform(-scale, scale), rng.uniform(-scale, scale)] for _ in range(rng.randint(1, 4))]
    return {
        "map": {"origin": [hexfloat(v) for v in origin], "tile": ["0x1p+4", "0x1p+4"],
                "rows": ["".join(row) for row in cells]},
        "box": [hexfloat(v) for v in box + size],
        "moves": [[hexfloat(dx), hexfloat(dy)] for dx, dy in moves],
    }


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    rng = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 17)
    for _ in range(count):
        print(json.dumps(scene(rng)))


if __name__ == "__main__":
    main()
