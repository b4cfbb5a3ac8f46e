// SPDX-License-Identifier: MIT
// Box2D v3's character mover (npm box2d3-wasm: Box2D's C API at v3.1.1-18, compiled to
// WebAssembly) behind tilesweep's resolver protocol. Written the way Box2D's docs (character.md)
// and its Mover sample put a mover together, not tuned to the contract:
//
//   - one world per scene, one static body for the level at the map's origin, one
//     b2MakeOffsetBox shape per solid or one-way cell;
//   - the mover is a capsule: Box2D's mover functions take nothing else. The box becomes the
//     capsule inscribed in it, its radius half the box's smaller side, its segment along the
//     longer one (a square box is a circle);
//   - coordinates are meters at 16 pixels per meter (a 16-pixel tile is one meter, as in the
//     Box2D 2.4 adapter), so Box2D's linear slop is 0.005 m = 0.08 px;
//   - per frame, the Mover sample's loop: at most 5 times, b2World_CollideMover gathers the
//     planes of the shapes the capsule touches, b2SolvePlanes finds the move toward the frame's
//     target that respects them, b2World_CastMover casts the capsule along that move, and the
//     mover goes the fraction it returns; it stops early once a move is under 0.01 m;
//   - a contact is each tile whose plane (from b2World_CollideMover) faces the move still to
//     make, the first time it does in the frame: the normal the dominant axis of the plane's
//     normal, t the share of the frame's displacement already covered then;
//   - one-way cells ('-'): Box2D has no one-way feature for movers, so the adapter filters as
//     users do. A one-way cell's plane is kept only when the frame moves down, the box's bottom
//     starts at or above the cell's top and the plane faces up; the cast sees one-way cells (a
//     category bit of their own) only in frames that move down;
//   - positions are float32 as Box2D's are: the mover's top-left corner in meters, moved by
//     float32 sums, is the answer times 16;
//   - started_overlapping is computed from the map by the contract's definition (Box2D has no
//     notion of it).
//
//     node adapter.js < scenes.jsonl > answers.jsonl    (pipe mode: one answer line per scene)
//     node adapter.js IN OUT                             (file mode: reads IN, writes OUT)
'use strict';

const path = require('path');
const {pathToFileURL} = require('url');
const {SceneError, serve, parseScene, formatFrames, formatError, overlappedTiles} = require('../rapier/scene_text');

/// Pixels per Box2D meter: a 16-pixel tile is one meter.
const kPixelsPerMeter = 16;
/// The Mover sample's loop: at most 5 rounds of collide, solve and cast, stopping once a round
/// moves less than 0.01 m.
const kMaxRounds = 5;
const kStopDistance = 0.01;
/// Category bits: solid cells, one-way cells, the mover.
const kSolidBit = 0x1;
const kOneWayBit = 0x2;
const kMoverBit = 0x4;
/// A plane a solid surface sets: as rigid as can be (FLT_MAX).
const kRigid = 3.4028234663852886e38;

/// The package's build without SIMD and threads, the one its entry gives a web page that is not
/// cross-origin isolated (most pages). Its entry would give node the SIMD build, which answers
/// the same here and starts a pool of 8 threads per process; the package exports only its entry,
/// so the file is loaded by its path.
const kCompatBuild = path.join(__dirname, 'node_modules/box2d3-wasm/build/dist/es/compat/Box2D.compat.mjs');

const f = Math.fround;

class MoverResolver {
    constructor(b2) {
        this.b2 = b2;
        this.worldDef = b2.b2DefaultWorldDef();
        this.bodyDef = b2.b2DefaultBodyDef();
        this.capsule = new b2.b2Capsule();
        this.point = new b2.b2Vec2(0, 0);
        this.other = new b2.b2Vec2(0, 0);
        this.collideFilter = this.queryFilter(kSolidBit | kOneWayBit);
        this.castFilters = [this.queryFilter(kSolidBit), this.queryFilter(kSolidBit | kOneWayBit)];
        this.shapeDefs = [this.shapeDef(kSolidBit), this.shapeDef(kOneWayBit)];
        this.planes = [];  // the current round's planes: {normal: [x, y], offset, cell, oneWay}
        this.onPlane = (shapeId, result) => this.addPlane(shapeId, result);
    }

    queryFilter(mask) {
        const filter = this.b2.b2DefaultQueryFilter();
        filter.categoryBits = kMoverBit;
        filter.maskBits = mask;
        return filter;
    }

    shapeDef(category) {
        const def = this.b2.b2DefaultShapeDef();
        const filter = def.filter;
        filter.categoryBits = category;
        filter.maskBits = kMoverBit;
        def.filter = filter;
        filter.delete();
        return def;
    }

    // A world holding the scene's map: one static body at the origin, a box per cell.
    buildWorld(scene) {
        const b2 = this.b2;
        const worldId = b2.b2CreateWorld(this.worldDef);
        this.point.x = f(scene.origin[0] / kPixelsPerMeter);
        this.point.y = f(scene.origin[1] / kPixelsPerMeter);
        this.bodyDef.position = this.point;
        const bodyId = b2.b2CreateBody(worldId, this.bodyDef);
        const hx = f(scene.tile[0] / 2 / kPixelsPerMeter);
        const hy = f(scene.tile[1] / 2 / kPixelsPerMeter);
        this.cells = new Map();  // shape index -> {cell, oneWay}
        for (let j = 0; j < scene.rows; ++j)
            for (let i = 0; i < scene.columns; ++i) {
                const k = j * scene.columns + i;
                if (!scene.solid[k] && !scene.oneWay[k]) continue;
                this.point.x = f((i + 0.5) * scene.tile[0] / kPixelsPerMeter);
                this.point.y = f((j + 0.5) * scene.tile[1] / kPixelsPerMeter);
                const box = b2.b2MakeOffsetBox(hx, hy, this.point, b2.b2Rot_identity);
                const oneWay = !scene.solid[k];
                const shapeId = b2.b2CreatePolygonShape(bodyId, this.shapeDefs[oneWay ? 1 : 0], box);
                box.delete();
                this.cells.set(shapeId.index1, {cell: [i, j], oneWay});
            }
        return worldId;
    }

    addPlane(shapeId, result) {
        const plane = result.plane;
        const normal = plane.normal;
        const tile = this.cells.get(shapeId.index1);
        if (result.hit && tile !== undefined)
            this.planes.push({normal: [normal.x, normal.y], offset: plane.offset, cell: tile.cell, oneWay: tile.oneWay});
        normal.delete();
        plane.delete();
        return true;
    }

    // Places the capsule inscribed in the box whose top-left corner is (x, y) meters, w x h.
    placeCapsule(x, y, w, h) {
        const r = f(Math.min(w, h) / 2);
        if (h >= w) {
            this.point.x = this.other.x = f(x + r);
            this.point.y = f(y + r);
            this.other.y = f(y + f(h - r));
        } else {
            this.point.y = this.other.y = f(y + r);
            this.point.x = f(x + r);
            this.other.x = f(x + f(w - r));
        }
        this.capsule.center1 = this.point;
        this.capsule.center2 = this.other;
        this.capsule.radius = r;
    }

    // One frame: the mover from its top-left corner (x, y) (meters) by (dx, dy) (meters).
    frame(worldId, scene, x, y, dx, dy, startBottomPx) {
        const b2 = this.b2;
        const w = f(scene.box[2] / kPixelsPerMeter);
        const h = f(scene.box[3] / kPixelsPerMeter);
        const targetX = f(x + dx);
        const targetY = f(y + dy);
        const length = Math.hypot(dx, dy);
        const movingDown = dy > 0;
        const contacts = [];
        const seen = new Set();
        for (let round = 0; round < kMaxRounds; ++round) {
            this.placeCapsule(x, y, w, h);
            this.planes = [];
            b2.b2World_CollideMover(worldId, this.capsule, this.collideFilter, this.onPlane);
            // One-way cells: a plane only for a box moving down from at or above the top, facing up.
            const planes = this.planes.filter((p) => !p.oneWay || (movingDown && p.normal[1] < 0 &&
                startBottomPx <= scene.origin[1] + p.cell[1] * scene.tile[1]));
            const restX = f(targetX - x);
            const restY = f(targetY - y);
            const t = length > 0 ? Math.min(1, Math.max(0, 1 - Math.hypot(restX, restY) / length)) : 0;
            const facing = planes.filter((p) => p.normal[0] * restX + p.normal[1] * restY < 0)
                .sort((a, b) => a.cell[1] - b.cell[1] || a.cell[0] - b.cell[0]);
            for (const p of facing) {
                const key = p.cell[0] + ',' + p.cell[1];
                if (seen.has(key)) continue;
                seen.add(key);
                const onX = Math.abs(p.normal[0]) > Math.abs(p.normal[1]);
                contacts.push({
                    tile: p.cell,
                    normal: onX ? [Math.sign(p.normal[0]), 0] : [0, Math.sign(p.normal[1])],
                    t: f(t),
                });
            }
            this.point.x = restX;
            this.point.y = restY;
            const solved = b2.b2SolvePlanes(this.point, planes.map((p) => ({
                plane: {normal: {x: p.normal[0], y: p.normal[1]}, offset: p.offset},
                pushLimit: kRigid, push: 0, clipVelocity: true,
            })));
            const translation = solved.translation;
            this.other.x = translation.x;
            this.other.y = translation.y;
            translation.delete();
            solved.delete();
            const fraction = b2.b2World_CastMover(worldId, this.capsule, this.other, this.castFilters[movingDown ? 1 : 0]);
            const moveX = f(fraction * this.other.x);
            const moveY = f(fraction * this.other.y);
            x = f(x + moveX);
            y = f(y + moveY);
            if (f(f(moveX * moveX) + f(moveY * moveY)) < kStopDistance * kStopDistance) break;
        }
        return {x, y, contacts};
    }

    // The frames of one scene.
    run(scene) {
        const worldId = this.buildWorld(scene);
        try {
            let x = scene.box[0];
            let y = scene.box[1];
            const frames = [];
            for (const [dx, dy] of scene.moves) {
                const startedOverlapping = overlappedTiles(scene, x, y);
                const end = this.frame(worldId, scene, f(x / kPixelsPerMeter), f(y / kPixelsPerMeter),
                    f(dx / kPixelsPerMeter), f(dy / kPixelsPerMeter), y + scene.box[3]);
                x = f(end.x * kPixelsPerMeter);
                y = f(end.y * kPixelsPerMeter);
                frames.push({pos: [x, y], contacts: end.contacts, startedOverlapping});
            }
            return frames;
        } finally {
            this.b2.b2DestroyWorld(worldId);
        }
    }
}

function answer(resolver, line) {
    try {
        return formatFrames(resolver.run(parseScene(line)));
    } catch (e) {
        if (e instanceof SceneError) return formatError(e.message);
        return formatError(`box2d3: ${e && e.message ? e.message : String(e)}`);
    }
}

async function main() {
    const args = process.argv.slice(2);
    if (args.length !== 0 && args.length !== 2) {
        process.stderr.write('usage: node adapter.js [IN OUT]   (no IN OUT: scenes on stdin, answers on stdout)\n');
        process.exit(2);
    }
    const {default: loadBox2D} = await import(pathToFileURL(kCompatBuild).href);
    const resolver = new MoverResolver(await loadBox2D());
    await serve(args, (line) => answer(resolver, line));
}

main().catch((e) => {
    process.stderr.write(`box2d3 adapter: ${e && e.stack ? e.stack : e}\n`);
    process.exit(1);
});
