// SPDX-License-Identifier: MIT
// Rapier's KinematicCharacterController (npm @dimforge/rapier2d-compat) behind tilesweep's
// resolver protocol. Written the way a Rapier user writes a tile platformer's mover, not tuned
// to the contract:
//
//   - one fixed cuboid collider per solid cell, centred on the cell; the box is a cuboid
//     collider, moved by a character controller made with world.createCharacterController(0)
//     (offset 0, slide on, Rapier's other defaults: no autostep, no snap to ground), its up
//     vector set to (0, -1) because y grows downward;
//   - per frame, one computeColliderMovement(box, move) and the box's position plus
//     computedMovement(); Rapier slides as often as it likes inside that call;
//   - coordinates are pixels, with world.lengthUnit = 16 (16 pixels per meter, so a 16-pixel
//     tile is one meter, as in the Box2D adapter), which is how Rapier is told a game is in pixels;
//   - each computedCollision(i) is a contact: the tile from the collider's handle, the normal
//     the dominant axis of normal1, and t the fraction of the frame elapsed at the hit, from
//     the translation applied before it and the translation remaining;
//   - a one-way cell ('-') is a tile collider too. Rapier has no one-way collider (its character
//     controller leaves them to the user), so the adapter does what its users do: a filter
//     predicate that, each frame, leaves a one-way collider out of the controller's obstacles
//     unless the box moves down and its bottom starts at or above the collider's top;
//   - started_overlapping is computed from the map by the contract's definition (Rapier has no
//     notion of it).
//
//     node adapter.js < scenes.jsonl > answers.jsonl    (pipe mode: one answer line per scene)
//     node adapter.js IN OUT                             (file mode: reads IN, writes OUT)
//     node adapter.js --shared-world ...                 (one world for all scenes: see main)
//     node adapter.js --rapier PACKAGE ...               (another build of Rapier: see main)
'use strict';

let RAPIER = null;  // the Rapier package: main loads it
const {SceneError, serve, parseScene, formatFrames, formatError, overlappedTiles} = require('./scene_text');

/// Pixels per Rapier meter: a 16-pixel tile is one meter.
const kPixelsPerMeter = 16;

// Collision groups (membership in the high 16 bits, filter in the low 16): tiles meet the box
// and not one another, as a level's static geometry is usually set up; it also spares the
// broad phase the pairs of neighbouring tiles.
const kTileGroup = 0x0001_0002;
const kBoxGroup = 0x0002_0001;

// A world and its tiles. With --shared-world one serves every scene: tile colliders are kept in
// a pool and re-placed per scene.
class TileWorld {
    constructor() {
        this.world = new RAPIER.World({x: 0, y: 0});
        this.world.lengthUnit = kPixelsPerMeter;
        this.controller = this.world.createCharacterController(0);
        this.controller.setUp({x: 0, y: -1});
        this.controller.setSlideEnabled(true);
        this.box = this.world.createCollider(
            RAPIER.ColliderDesc.cuboid(0.5, 0.5).setCollisionGroups(kBoxGroup));
        this.boxSize = [1, 1];
        this.tiles = [];             // pooled tile colliders
        this.cellOfHandle = new Map();  // collider handle -> [i, j]
        this.oneWayHandles = new Set(); // the handles of the current scene's one-way cells
        this.active = 0;             // tiles in use by the current scene
    }

    // Places the scene's solid and one-way cells: one cuboid per cell, centred on it.
    placeMap(scene) {
        const [ox, oy] = scene.origin;
        const [tw, th] = scene.tile;
        let used = 0;
        this.oneWayHandles.clear();
        for (let j = 0; j < scene.rows; ++j)
            for (let i = 0; i < scene.columns; ++i) {
                const k = j * scene.columns + i;
                if (!scene.solid[k] && !scene.oneWay[k]) continue;
                let collider = this.tiles[used];
                if (collider === undefined) {
                    collider = this.world.createCollider(
                        RAPIER.ColliderDesc.cuboid(tw / 2, th / 2).setCollisionGroups(kTileGroup));
                    this.tiles.push(collider);
                    collider.halfExtentsSet = [tw / 2, th / 2];
                } else {
                    // setHalfExtents builds a new shape: only when the tile size changed.
                    const [hx, hy] = collider.halfExtentsSet;
                    if (hx !== tw / 2 || hy !== th / 2) {
                        collider.setHalfExtents({x: tw / 2, y: th / 2});
                        collider.halfExtentsSet = [tw / 2, th / 2];
                    }
                    if (used >= this.active) collider.setEnabled(true);
                }
                collider.setTranslation({x: ox + (i + 0.5) * tw, y: oy + (j + 0.5) * th});
                this.cellOfHandle.set(collider.handle, [i, j]);
                if (!scene.solid[k]) this.oneWayHandles.add(collider.handle);
                ++used;
            }
        for (let k = used; k < this.active; ++k) this.tiles[k].setEnabled(false);
        this.active = used;
        this.world.step();  // brings the broad phase up to date with the moved colliders
    }

    // The frames of one scene.
    run(scene) {
        this.placeMap(scene);
        const [, , w, h] = scene.box;
        if (this.boxSize[0] !== w || this.boxSize[1] !== h) {
            this.box.setHalfExtents({x: w / 2, y: h / 2});
            this.boxSize = [w, h];
        }
        let x = scene.box[0];
        let y = scene.box[1];
        const frames = [];
        for (const [dx, dy] of scene.moves) {
            const startedOverlapping = overlappedTiles(scene, x, y);
            this.box.setTranslation({x: x + w / 2, y: y + h / 2});
            // One-way colliders block this frame only when it moves down from at or above them.
            const [, oy] = scene.origin;
            const th = scene.tile[1];
            const keep = this.oneWayHandles.size === 0 ? undefined : (collider) => {
                if (!this.oneWayHandles.has(collider.handle)) return true;
                const [, j] = this.cellOfHandle.get(collider.handle);
                return dy > 0 && y + h <= oy + j * th;
            };
            this.controller.computeColliderMovement(this.box, {x: dx, y: dy}, undefined, undefined, keep);
            const movement = this.controller.computedMovement();
            const contacts = [];
            let elapsed = 0;          // fraction of the frame before the current slide
            let appliedBefore = null; // translation applied at the previous collision
            for (let k = 0; k < this.controller.numComputedCollisions(); ++k) {
                const collision = this.controller.computedCollision(k);
                const cell = collision.collider ? this.cellOfHandle.get(collision.collider.handle) : undefined;
                if (cell === undefined) continue;
                const applied = collision.translationDeltaApplied;
                const remaining = collision.translationDeltaRemaining;
                const stepApplied = appliedBefore === null
                    ? Math.hypot(applied.x, applied.y)
                    : Math.hypot(applied.x - appliedBefore.x, applied.y - appliedBefore.y);
                const stepLength = stepApplied + Math.hypot(remaining.x, remaining.y);
                const fraction = stepLength > 0 ? stepApplied / stepLength : 0;
                const t = Math.fround(elapsed + fraction * (1 - elapsed));
                const n = collision.normal1;
                const onX = Math.abs(n.x) > Math.abs(n.y);
                contacts.push({
                    tile: cell,
                    normal: onX ? [Math.sign(n.x), 0] : [0, Math.sign(n.y)],
                    t,
                });
                elapsed = t;
                appliedBefore = {x: applied.x, y: applied.y};
            }
            x = Math.fround(x + movement.x);
            y = Math.fround(y + movement.y);
            frames.push({pos: [x, y], contacts, startedOverlapping});
        }
        return frames;
    }
}

function answer(tileWorld, line) {
    try {
        return formatFrames(tileWorld.run(parseScene(line)));
    } catch (e) {
        if (e instanceof SceneError) return formatError(e.message);
        return formatError(`rapier: ${e && e.message ? e.message : String(e)}`);
    }
}

// The answer to one line, from a world made for it alone, or from one shared world.
function answerer(sharedWorld) {
    if (sharedWorld) {
        const shared = new TileWorld();
        return (line) => answer(shared, line);
    }
    return (line) => {
        const own = new TileWorld();
        try {
            return answer(own, line);
        } finally {
            own.world.removeCharacterController(own.controller);  // world.free() alone leaks it
            own.world.free();
        }
    };
}

async function main() {
    const args = process.argv.slice(2);
    // --rapier PACKAGE loads another build of the same API instead of @dimforge/rapier2d-compat:
    // a package name or directory, as require takes it (adapters/rapier-deterministic/run.sh
    // passes the cross-platform deterministic build's directory).
    const at = args.indexOf('--rapier');
    RAPIER = require(at >= 0 ? args.splice(at, 2)[1] : '@dimforge/rapier2d-compat');
    await RAPIER.init();
    // A new world per scene, by default: Rapier's broad phase keeps a history, and in a tie (two
    // tiles equally near) which one is hit first, and so at times where the box ends, depends
    // on the scenes answered before. A world per scene answers every scene as if it came first,
    // so a scene gets the same answer in any batch (shrinking and replay rely on it).
    // --shared-world keeps one world with pooled tiles, as a game keeps its world: 1.6 times
    // faster, and about 10% of random scenes then answer differently in another order.
    const sharedWorld = args.includes('--shared-world');
    const paths = args.filter((a) => a !== '--shared-world');
    const respond = answerer(sharedWorld);
    if (paths.length !== 0 && paths.length !== 2) {
        process.stderr.write('usage: node adapter.js [--shared-world] [--rapier PACKAGE] [IN OUT]   (no IN OUT: scenes on stdin, answers on stdout)\n');
        process.exit(2);
    }
    await serve(paths, respond);
}

main().catch((e) => {
    process.stderr.write(`rapier adapter: ${e && e.stack ? e.stack : e}\n`);
    process.exit(1);
});
