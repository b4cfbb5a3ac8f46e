// SPDX-License-Identifier: MIT
// Scene lines in, result lines out, for float32 resolvers (../../../shared/CONTRACT.md, "Scene
// files" and "`tilesweep resolve`"): numbers are read exactly (a hexfloat string is rounded
// once, straight to float32) and printed so that they read back to the same float32 bits.
'use strict';

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);

class SceneError extends Error {}

function fail(field, problem) {
    throw new SceneError(`${field}: ${problem}`);
}

// The float32 nearest m * 2^e (m a non-negative BigInt), ties to even, or Infinity past the
// largest float32. Rounds once: the bits below the kept ones decide, with nothing in between.
function roundToFloat32(m, e) {
    if (m === 0n) return 0;
    const bits = m.toString(2).length;
    // The lowest kept bit: 24 significant bits, but never below 2^-149 (subnormals).
    const lowest = Math.max(bits + e - 24, -149);
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
    const value = Number(kept) * powerOfTwo(lowest);  // exact: kept < 2^25, lowest in range
    return value >= 2 ** 128 ? Infinity : value;
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

function readHexfloat(text, field) {
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
    // while it stays a normal double: Math.fround then rounds once. Longer ones take BigInt.
    const short = digits.length <= 13 && exponent > -1000 && exponent < 900;
    const magnitude = digits.length === 0 ? 0
        : short ? Math.fround(parseInt(digits, 16) * powerOfTwo(exponent))
        : roundToFloat32(BigInt('0x' + digits), exponent);
    return match[1] === '-' ? -magnitude : magnitude;
}

// A JSON number, or a string holding a hexfloat, as a float32 value. JSON numbers go through
// JavaScript's double first (every number the tool writes is a hexfloat string).
function readScalar(value, field) {
    let result;
    if (typeof value === 'number') result = Math.fround(value);
    else if (typeof value === 'string') result = readHexfloat(value, field);
    else fail(field, `expected a number or a hexfloat string, got ${JSON.stringify(value)}`);
    if (!Number.isFinite(result)) fail(field, 'non-finite value (or past the largest float)');
    return result;
}

function readPair(value, field) {
    if (!Array.isArray(value) || value.length !== 2) fail(field, 'expected [a, b]');
    return [readScalar(value[0], `${field}[0]`), readScalar(value[1], `${field}[1]`)];
}

// The parsed scene: {origin, tile, columns, rows, solid and oneWay (row-major 0/1: '#' and '-'),
// box: [x, y, w, h], moves}.
function parseScene(line) {
    let root;
    try {
        root = JSON.parse(line);
    } catch (e) {
        fail('scene', `malformed JSON: ${e.message}`);
    }
    if (root === null || typeof root !== 'object' || Array.isArray(root)) fail('scene', 'expected a JSON object');
    const map = root.map;
    if (map === null || typeof map !== 'object') fail('map', 'expected an object with "origin", "tile" and "rows"');
    const origin = readPair(map.origin, 'map.origin');
    const tile = readPair(map.tile, 'map.tile');
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
    // Every tile edge must be a float32 (the contract refuses the map otherwise).
    for (let axis = 0; axis < 2; ++axis)
        for (let k = 0; k <= (axis === 0 ? columns : rows); ++k) {
            const edge = origin[axis] + k * tile[axis];  // exact in double: float32 inputs, k < 2^29
            if (Math.fround(edge) !== edge)
                fail('map.tile', `tile edge ${axis === 0 ? 'x' : 'y'} = origin + ${k} * tile is not a float`);
        }
    if (!Array.isArray(root.box) || root.box.length !== 4) fail('box', 'expected [x, y, w, h]');
    const box = root.box.map((v, k) => readScalar(v, `box[${k}]`));
    if (!(box[2] > 0 && box[3] > 0)) fail('box', 'width and height must be > 0');
    if (root.move !== undefined && root.moves !== undefined) fail('moves', 'give either "move" or "moves", not both');
    let moves;
    if (root.move !== undefined) moves = [readPair(root.move, 'move')];
    else if (root.moves === undefined) fail('move', 'missing field (give "move": [dx, dy] or "moves": [[dx, dy], ...])');
    else {
        if (!Array.isArray(root.moves)) fail('moves', 'expected an array of [dx, dy]');
        if (root.moves.length === 0) fail('moves', 'must not be empty');
        moves = root.moves.map((m, k) => readPair(m, `moves[${k}]`));
    }
    return {origin, tile, columns, rows, solid, oneWay, box, moves};
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

function formatFrames(frames) {
    const parts = frames.map((frame) => {
        const contacts = frame.contacts.map(
            (c) => `{"tile": [${c.tile[0]}, ${c.tile[1]}], "normal": [${c.normal[0]}, ${c.normal[1]}], ` +
                   `"t": ${formatFloat32(c.t)}}`);
        const overlaps = frame.startedOverlapping.map((cell) => `[${cell[0]}, ${cell[1]}]`);
        return `{"pos": [${formatFloat32(frame.pos[0])}, ${formatFloat32(frame.pos[1])}], ` +
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
// column: the contract's started_overlapping, computed exactly.
function overlappedTiles(scene, x, y) {
    const [ox, oy] = scene.origin;
    const [tw, th] = scene.tile;
    const [, , w, h] = scene.box;
    const cells = [];
    for (let j = 0; j < scene.rows; ++j) {
        const top = oy + j * th;
        const bottom = oy + (j + 1) * th;
        if (!(y < bottom && signOfSumMinus(y, h, top) > 0)) continue;
        for (let i = 0; i < scene.columns; ++i) {
            if (!scene.solid[j * scene.columns + i]) continue;
            const left = ox + i * tw;
            const right = ox + (i + 1) * tw;
            if (x < right && signOfSumMinus(x, w, left) > 0) cells.push([i, j]);
        }
    }
    return cells;
}

module.exports = {SceneError, parseScene, formatFrames, formatError, formatFloat32, overlappedTiles};
