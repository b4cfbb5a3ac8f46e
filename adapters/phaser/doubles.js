// SPDX-License-Identifier: MIT
// Phaser computes in double (JavaScript numbers) and tilesweep's float protocol carries float32.
// Two conversions between them, made so that neither adds an error of its own:
//
//   - velocityFor(d, step): a velocity v with v * step === d exactly in double, when one exists
//     near d / step (Phaser moves a body by velocity * step, so the displacement it applies is
//     then the frame's own);
//   - roundPosition(s, e, size, origin, tile): Phaser's double end coordinate e brought to a
//     float32 by the contract's rule for positions (docs/contract.md, "Positions"):
//     the float32 nearest e between the start s and e, except on an axis
//     moving toward minus infinity when that would carry the far edge back over a grid line,
//     where it is the largest float32 <= e. Phaser's position stands for the exact one.
'use strict';

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);
const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);

const kLargestFloat32 = 3.4028234663852886e38;

// The float32 just above (dir = 1) or below (dir = -1) the float32 v.
function nextFloat32(v, dir) {
    if (v === 0) return dir * 2 ** -149;
    f32[0] = v;
    u32[0] += (v > 0) === (dir > 0) ? 1 : -1;
    return f32[0];
}

// The double just above (dir = 1) or below (dir = -1) the finite double v.
function nextDouble(v, dir) {
    if (v === 0) return dir * Number.MIN_VALUE;
    f64[0] = v;
    u64[0] += (v > 0) === (dir > 0) ? 1n : -1n;
    return f64[0];
}

// A velocity that moves a body by exactly d over a step of `step` seconds (v * step === d),
// searched among the doubles nearest d / step; d / step itself when none of them does.
function velocityFor(d, step) {
    const guess = d / step;
    if (!Number.isFinite(guess) || guess * step === d) return guess;
    let below = guess;
    let above = guess;
    for (let k = 0; k < 4; ++k) {
        below = nextDouble(below, -1);
        above = nextDouble(above, 1);
        if (below * step === d) return below;
        if (above * step === d) return above;
    }
    return guess;
}

// x * 2^1074 as a BigInt, exactly (every finite double is a multiple of 2^-1074).
function units(x) {
    f64[0] = x;
    const bits = u64[0];
    const negative = bits >> 63n === 1n;
    const exponent = Number((bits >> 52n) & 0x7ffn);
    const fraction = bits & 0xfffffffffffffn;
    const magnitude = exponent === 0 ? fraction : (fraction | (1n << 52n)) << BigInt(exponent - 1);
    return negative ? -magnitude : magnitude;
}

// The largest float32 <= e (minus the largest float32 when e is below every float32).
function float32Below(e) {
    let r = Math.fround(e);
    if (r === -Infinity) return -kLargestFloat32;
    if (r > e) r = nextFloat32(r, -1);
    return r === Infinity ? kLargestFloat32 : r;
}

// The smallest float32 >= e (the largest float32 when e is above every float32).
function float32Above(e) {
    let r = Math.fround(e);
    if (r === Infinity) return kLargestFloat32;
    if (r < e) r = nextFloat32(r, 1);
    return r === -Infinity ? -kLargestFloat32 : r;
}

// The float32 end coordinate for start s (a float32), exact end e (a double), the box's size
// on the axis and the map's origin and tile size on it (float32s): see the top of this file.
function roundPosition(s, e, size, origin, tile) {
    if (e === s) return s;
    if (e > s) return float32Below(e);
    const q = float32Above(e);
    if (q === e) return q;
    // Moving toward minus infinity: is there a grid line g = origin + k * tile with
    // e + size <= g < q + size? The smallest g >= e + size decides; exact, in units of 2^-1074.
    const o = units(origin);
    const t = units(tile);
    const reach = units(e) + units(size) - o;
    let k = reach / t;           // truncated toward zero: the ceiling when reach <= 0
    if (k * t < reach) k += 1n;  // the ceiling when reach > 0
    if (o + k * t < units(q) + units(size)) return float32Below(e);
    return q;
}

module.exports = {velocityFor, roundPosition};
