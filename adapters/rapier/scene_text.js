// SPDX-License-Identifier: MIT
// Scene lines in, result lines out, for float32 resolvers and, with parseScene(line, {scalar:
// 'double'}) and formatFrames(frames, formatDouble), double ones (docs/contract.md,
// "Scene files" and "`tilesweep resolve`"): numbers are read exactly (a hexfloat string is
// rounded once, straight to the scalar type) and printed so that they read back to the same bits.
'use strict';

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);

class SceneError extends Error {}

function fail(field, problem) {
    throw new SceneError(`${field}: ${problem}`);
}

// The binary format of float32 and of double: significant bits, the lowest subnormal bit's
// exponent, and the power of two from which a value is past the largest finite one.
const kFloat32Format = {precision: 24, lowestExponent: -149, overflow: 2 ** 128};
const kDoubleFormat = {precision: 53, lowestExponent: -1074, overflow: Infinity};

// The value of the format nearest m * 2^e (m a non-negative BigInt), ties to even, or Infinity
// past its largest finite value. Rounds once: the bits below the kept ones decide, with nothing
// in between.
function roundToFormat(m, e, format) {
    if (m === 0n) return 0;
    const bits = m.toString(2).length;
    // The lowest kept bit: all significant bits, but never below the lowest subnormal one.
    const lowest = Math.max(bits + e - format.precision, format.lowestExponent);
    let kept = m;
    if (lowest > e) {
        const shift = BigInt(lowest - e);
        kept = m >> shift;
        const rest = m - (kept << shift);
        const half = 1n << (shift - 1n);
        if (rest > half || (rest === half && (kept & 1n) === 1n)) kept += 1n;
    } else {
        kept = m << BigInt(e - lowest);
    }
    // Exact: kept has at most precision + 1 bits, and lowest is a double's exponent (past the
    // largest double, powerOfTwo or the product is Infinity).
    const value = Number(kept) * powerOfTwo(lowest);
    return value >= format.overflow ? Infinity : value;
}

// The float32 nearest m * 2^e, as roundToFormat.
function roundToFloat32(m, e) {
    return roundToFormat(m, e, kFloat32Format);
}

// 2^e, exactly, for the e of a normal double.
const kPowersOfTwo = new Map();
function powerOfTwo(e) {
    let value = kPowersOfTwo.get(e);
    if (value === undefined) {
        value = 1;
        for (let k = 0; k < Math.abs(e); ++k) value = e > 0 ? value * 2 : value / 2;
        kPowersOfTwo.set(e, value);
    }
    return value;
}

// "0x1.8p+3", "-0x0p+0", "0xAp-2": C99's hexadecimal floating constants, as printf("%a") writes.
const kHexfloat = /^(-?)0[xX]([0-9a-fA-F]*)(?:\.([0-9a-fA-F]*))?[pP]([+-]?[0-9]+)$/;

function readHexfloat(text, field, double = false) {
    const match = kHexfloat.exec(text);
    if (!match || match[2].length + (match[3] || '').length === 0)
        fail(field, `expected a number or a hexfloat string like "0x1.8p+3", got '${text.slice(0, 40)}'`);
    const fraction = match[3] || '';
    const significant = (match[2] + fraction).replace(/^0+/, '');
    const digits = significant.replace(/0+$/, '');
    const trailing = significant.length - digits.length;
    const exponent = Number(match[4]) - 4 * fraction.length + 4 * trailing;
    if (!Number.isFinite(exponent) || Math.abs(exponent) > 100000) fail(field, `exponent out of range in '${text}'`);
    // Up to 13 hex digits the mantissa is an exact double and so is mantissa * 2^exponent
    // while it stays a normal double: Math.fround then rounds once (a double needs no rounding).
    // Longer ones take BigInt.
    const short = digits.length <= 13 && exponent > -1000 && exponent < 900;
    let magnitude;
    if (digits.length === 0) magnitude = 0;
    else if (short) {
        const exact = parseInt(digits, 16) * powerOfTwo(exponent);
        magnitude = double ? exact : Math.fround(exact);
    } else {
        magnitude = roundToFormat(BigInt('0x' + digits), exponent, double ? kDoubleFormat : kFloat32Format);
    }
    return match[1] === '-' ? -magnitude : magnitude;
}

// A JSON number, or a string holding a hexfloat, as a float32 value (double: as a double). JSON
// numbers are JavaScript's doubles, read once by JSON.parse, then rounded to float32 (every
// number the tool writes is a hexfloat string, read exactly).
function readScalar(value, field, double = false) {
    let result;
    if (typeof value === 'number') result = double ? value : Math.fround(value);
    else if (typeof value === 'string') result = readHexfloat(value, field, double);
    else fail(field, `expected a number or a hexfloat string, got ${JSON.stringify(value)}`);
    if (!Number.isFinite(result)) fail(field, `non-finite value (or past the largest ${double ? 'double' : 'float'})`);
    return result;
}

function readPair(value, field, double = false) {
    if (!Array.isArray(value) || value.length !== 2) fail(field, 'expected [a, b]');
    return [readScalar(value[0], `${field}[0]`, double), readScalar(value[1], `${field}[1]`, double)];
}

// The exact value of a double as m * 2^e (m a BigInt, negative for a negative value).
const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);
function exactParts(v) {
    f64[0] = v;
    const bits = u64[0];
    const biased = Number((bits >> 52n) & 0x7ffn);
    const fraction = bits & ((1n << 52n) - 1n);
    const m = biased === 0 ? fraction : fraction | (1n << 52n);
    return {m: (bits >> 63n) === 1n ? -m : m, e: (biased === 0 ? 1 : biased) - 1075};
}

// origin + k * tile (k a non-negative integer) when that exact value is a double, else NaN.
function exactEdge(origin, k, tile) {
    // A tile of 24 significant bits or fewer times k < 2^29 is an exact double: the sum is then
    // exact when it does not round, which TwoSum's error tells.
    if (Math.fround(tile) === tile && k < 2 ** 29) {
        const product = k * tile;
        const sum = origin + product;
        const back = sum - origin;
        const err = (origin - (sum - back)) + (product - back);
        if (err === 0 && Number.isFinite(sum)) return sum;
        if (Number.isFinite(sum)) return NaN;
    }
    // Otherwise exactly, in BigInt: m * 2^e with the common lowest exponent.
    const o = exactParts(origin);
    const t = exactParts(tile);
    const e = Math.min(o.e, t.e);
    let m = (o.m << BigInt(o.e - e)) + BigInt(k) * (t.m << BigInt(t.e - e));
    if (m === 0n) return 0;
    const negative = m < 0n;
    if (negative) m = -m;
    const value = roundToFormat(m, e, kDoubleFormat);
    if (!Number.isFinite(value)) return NaN;
    const back = exactParts(value);
    const exact = back.e >= e ? (back.m << BigInt(back.e - e)) === m : back.m === (m << BigInt(e - back.e));
    return exact ? (negative ? -value : value) : NaN;
}

// The parsed scene: {origin, tile, columns, rows, solid and oneWay (row-major 0/1: '#' and '-'),
// box: [x, y, w, h], moves}.
//
// options.scalar: 'float' (the default: every number rounded to float32, every tile edge a
// float32) or 'double' (every number rounded to double, every tile edge a double). The scene
// also holds the tile edges, exactly: xEdges[i] = origin[0] + i * tile[0] (i = 0..columns) and
// yEdges[j] likewise.
function parseScene(line, options = {}) {
    const double = options.scalar === 'double';
    if (!double && options.scalar !== undefined && options.scalar !== 'float')
        throw new Error(`parseScene: unknown scalar '${options.scalar}' (float or double)`);
    let root;
    try {
        root = JSON.parse(line);
    } catch (e) {
        fail('scene', `malformed JSON: ${e.message}`);
    }
    if (root === null || typeof root !== 'object' || Array.isArray(root)) fail('scene', 'expected a JSON object');
    const map = root.map;
    if (map === null || typeof map !== 'object') fail('map', 'expected an object with "origin", "tile" and "rows"');
    const origin = readPair(map.origin, 'map.origin', double);
    const tile = readPair(map.tile, 'map.tile', double);
    if (!(tile[0] > 0 && tile[1] > 0)) fail('map.tile', 'tile width and height must be > 0');
    if (!Array.isArray(map.rows)) fail('map.rows', 'expected an array of strings');
    const rows = map.rows.length;
    const columns = rows > 0 && typeof map.rows[0] === 'string' ? map.rows[0].length : 0;
    const solid = new Uint8Array(columns * rows);
    const oneWay = new Uint8Array(columns * rows);
    map.rows.forEach((row, j) => {
        if (typeof row !== 'string') fail(`map.rows[${j}]`, 'expected a string');
        if (row.length !== columns) fail('map.rows', `ragged rows (row ${j} has length ${row.length}, row 0 ${columns})`);
        for (let i = 0; i < columns; ++i) {
            const c = row[i];
            if (c === '#') solid[j * columns + i] = 1;
            else if (c === '-') oneWay[j * columns + i] = 1;
            else if (c !== '.') fail(`map.rows[${j}]`, `unknown tile character '${c}' (use '#', '-' or '.')`);
        }
    });
    // Every tile edge must be a float32 (double: a double; the contract refuses the map otherwise).
    const xEdges = new Float64Array(columns + 1);
    const yEdges = new Float64Array(rows + 1);
    for (let axis = 0; axis < 2; ++axis) {
        const edges = axis === 0 ? xEdges : yEdges;
        for (let k = 0; k < edges.length; ++k) {
            const edge = double ? exactEdge(origin[axis], k, tile[axis])
                : origin[axis] + k * tile[axis];  // exact in double: float32 inputs, k < 2^29
            if (double ? Number.isNaN(edge) : Math.fround(edge) !== edge)
                fail('map.tile', `tile edge ${axis === 0 ? 'x' : 'y'} = origin + ${k} * tile is not a ${double ? 'double' : 'float'}`);
            edges[k] = edge;
        }
    }
    if (!Array.isArray(root.box) || root.box.length !== 4) fail('box', 'expected [x, y, w, h]');
    const box = root.box.map((v, k) => readScalar(v, `box[${k}]`, double));
    if (!(box[2] > 0 && box[3] > 0)) fail('box', 'width and height must be > 0');
    if (root.move !== undefined && root.moves !== undefined) fail('moves', 'give either "move" or "moves", not both');
    let moves;
    if (root.move !== undefined) moves = [readPair(root.move, 'move', double)];
    else if (root.moves === undefined) fail('move', 'missing field (give "move": [dx, dy] or "moves": [[dx, dy], ...])');
    else {
        if (!Array.isArray(root.moves)) fail('moves', 'expected an array of [dx, dy]');
        if (root.moves.length === 0) fail('moves', 'must not be empty');
        moves = root.moves.map((m, k) => readPair(m, `moves[${k}]`, double));
    }
    return {origin, tile, columns, rows, solid, oneWay, box, moves, xEdges, yEdges};
}

// The float32 just above (dir = 1) or below (dir = -1) v.
function nextFloat32(v, dir) {
    if (v === 0) return dir * 2 ** -149;
    f32[0] = v;
    u32[0] += (v > 0) === (dir > 0) ? 1 : -1;
    return f32[0];
}

// v (a float32 value) so that reading it back as float32 gives v: the shortest decimal that
// lies strictly between v's rounding midpoints (judged on the double the text parses to, which
// is strictly inside exactly when the text is, as the midpoints are doubles), else 9 digits.
function formatFloat32(v) {
    if (!Number.isFinite(v)) throw new Error('cannot write a non-finite value');
    if (Number.isInteger(v)) return Object.is(v, -0) ? '-0' : String(v);
    const below = (v + nextFloat32(v, -1)) / 2;
    const above = (v + nextFloat32(v, 1)) / 2;
    for (let digits = 1; digits < 9; ++digits) {
        const text = v.toPrecision(digits);
        const read = Number(text);
        if (read > below && read < above) return text;
    }
    return v.toPrecision(9);
}

// v (a double) as the shortest decimal that reads back to the same double: JavaScript's own
// Number to string, which is that (with an exponent past 1e21 or below 1e-6, as JSON allows),
// except for -0.
function formatDouble(v) {
    if (!Number.isFinite(v)) throw new Error('cannot write a non-finite value');
    return Object.is(v, -0) ? '-0' : String(v);
}

// The answer line of a scene's frames; formatNumber writes pos and t (formatFloat32 by default,
// formatDouble for a double resolver).
function formatFrames(frames, formatNumber = formatFloat32) {
    const parts = frames.map((frame) => {
        const contacts = frame.contacts.map(
            (c) => `{"tile": [${c.tile[0]}, ${c.tile[1]}], "normal": [${c.normal[0]}, ${c.normal[1]}], ` +
                   `"t": ${formatNumber(c.t)}}`);
        const overlaps = frame.startedOverlapping.map((cell) => `[${cell[0]}, ${cell[1]}]`);
        return `{"pos": [${formatNumber(frame.pos[0])}, ${formatNumber(frame.pos[1])}], ` +
               `"contacts": [${contacts.join(', ')}], "started_overlapping": [${overlaps.join(', ')}]}`;
    });
    return `{"frames": [${parts.join(', ')}]}`;
}

function formatError(message) {
    return `{"error": ${JSON.stringify(message)}}`;
}

// The exact sign of a + b - c for doubles a, b, c (TwoSum: a + b = s + err exactly).
function signOfSumMinus(a, b, c) {
    const s = a + b;
    const bb = s - a;
    const err = (a - (s - bb)) + (b - bb);
    if (s !== c) return s > c ? 1 : -1;  // |err| is at most half an ulp of s: it cannot reach c
    return err > 0 ? 1 : err < 0 ? -1 : 0;
}

// The solid tiles whose interior the box's interior meets (strictly, on both axes), by row then
// column: the contract's started_overlapping, computed exactly (from the exact tile edges).
function overlappedTiles(scene, x, y) {
    const [, , w, h] = scene.box;
    const cells = [];
    for (let j = 0; j < scene.rows; ++j) {
        const top = scene.yEdges[j];
        const bottom = scene.yEdges[j + 1];
        if (!(y < bottom && signOfSumMinus(y, h, top) > 0)) continue;
        for (let i = 0; i < scene.columns; ++i) {
            if (!scene.solid[j * scene.columns + i]) continue;
            const left = scene.xEdges[i];
            const right = scene.xEdges[i + 1];
            if (x < right && signOfSumMinus(x, w, left) > 0) cells.push([i, j]);
        }
    }
    return cells;
}

const isBlank = (line) => /^\s*$/.test(line);

/// Answers scene lines with respond(line), one answer line each: with paths [IN, OUT] the lines of
/// the file IN into OUT, each answer written as soon as it is known (a crash mid-batch leaves the
/// answers so far); with no paths the lines of standard input as they come, never waiting for the
/// end of the input. A reader that goes away ends the process quietly.
async function serve(paths, respond) {
    const fs = require('fs');
    if (paths.length === 2) {
        const out = fs.openSync(paths[1], 'w');
        for (const line of fs.readFileSync(paths[0], 'utf8').split('\n'))
            if (!isBlank(line)) fs.writeSync(out, respond(line) + '\n');
        fs.closeSync(out);
        return;
    }
    const readline = require('readline');
    process.stdout.on('error', (e) => process.exit(e.code === 'EPIPE' ? 0 : 1));  // reader gone
    const input = readline.createInterface({input: process.stdin, crlfDelay: Infinity});
    for await (const line of input)
        if (!isBlank(line)) process.stdout.write(respond(line) + '\n');
}

module.exports = {SceneError, serve, parseScene, formatFrames, formatError, formatFloat32, formatDouble, overlappedTiles};
