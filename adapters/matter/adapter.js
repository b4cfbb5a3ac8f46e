// SPDX-License-Identifier: MIT
// matter-js (npm matter-js, JavaScript doubles) behind tilesweep's resolver protocol, as a double
// resolver. Written the way a matter-js user writes a tile platformer's character, not tuned to
// the contract:
//
//   - one static rectangle body per solid cell (Bodies.rectangle at the cell's centre, the
//     cell's size); the character is a dynamic rectangle with inertia Infinity (it never
//     turns) and friction, frictionStatic and frictionAir 0 (so that a slide keeps its speed
//     and a free move is not slowed), in an engine without gravity (the scene's move already
//     holds it);
//   - per frame, Body.setVelocity(box, d): matter's velocity is a displacement per update of
//     its base delta (1000/60 ms), so d is the frame's displacement as it is; then one
//     Engine.update(engine, 1000/60), as Matter.Runner calls it at 60 Hz, with matter's default
//     iterations (6 position, 4 velocity); the box's new position is the body's centre less
//     half its size;
//   - coordinates are pixels, matter's own unit;
//   - a contact is each pair of the box with a tile that matter reports in the frame
//     (collisionStart and collisionActive): the tile from the body, the normal the dominant
//     axis of the collision normal turned to point from the tile to the box, and t, as matter
//     has no time of impact, the share of the frame's displacement along that axis made before
//     the box went as deep as matter found it: 1 - depth / |d on that axis|, within [0, 1]
//     (0 when the box did not move on that axis). Contacts are listed by t, then row, then
//     column;
//   - a one-way cell ('-') is a static rectangle too, in a collision category of its own; matter
//     has no one-way bodies, and its maintainer's advice (liabru/matter-js #284, #456) is to
//     switch the character's collision mask by its vertical velocity: in beforeUpdate, the box's
//     mask takes in the platforms' category while the box moves down, and leaves it out
//     otherwise;
//   - started_overlapping is computed from the map by the contract's definition (matter has no
//     notion of it).
//
//     node adapter.js < scenes.jsonl > answers.jsonl    (pipe mode: one answer line per scene)
//     node adapter.js IN OUT                             (file mode: reads IN, writes OUT)
'use strict';

const Matter = require('matter-js');
const {SceneError, serve, parseScene, formatFrames, formatDouble, formatError, overlappedTiles} =
    require('../rapier/scene_text');

const {Engine, Bodies, Body, Composite, Events} = Matter;

/// One frame: Matter.Runner's update at 60 Hz, in milliseconds (matter's base delta).
const kFrameMilliseconds = 1000 / 60;
/// The collision filter mask that lets a body meet every other one (matter's default).
const kMeetsAll = 0xFFFFFFFF;
/// The collision category of one-way platforms (matter's default category is 1).
const kPlatformCategory = 0x0002;

// The frames of one scene, from an engine of its own (so that no scene depends on the ones
// before it).
function run(scene) {
    const engine = Engine.create({gravity: {x: 0, y: 0}});
    const [tw, th] = scene.tile;
    const bodies = [];
    const cellOf = new Map();  // body id -> [i, j]
    for (let j = 0; j < scene.rows; ++j)
        for (let i = 0; i < scene.columns; ++i) {
            const k = j * scene.columns + i;
            if (!scene.solid[k] && !scene.oneWay[k]) continue;
            const tile = Bodies.rectangle(scene.xEdges[i] + tw / 2, scene.yEdges[j] + th / 2, tw, th, {isStatic: true});
            if (!scene.solid[k]) tile.collisionFilter.category = kPlatformCategory;
            bodies.push(tile);
            cellOf.set(tile.id, [i, j]);
        }

    const [x0, y0, w, h] = scene.box;
    const box = Bodies.rectangle(x0 + w / 2, y0 + h / 2, w, h, {
        inertia: Infinity,
        friction: 0,
        frictionStatic: 0,
        frictionAir: 0,
    });
    bodies.push(box);
    Composite.add(engine.world, bodies);

    // One-way platforms: the box meets them only while it moves down (y grows downward).
    Events.on(engine, 'beforeUpdate', () => {
        box.collisionFilter.mask = box.velocity.y > 0 ? kMeetsAll : kMeetsAll & ~kPlatformCategory;
    });

    // The contacts of the current frame.
    let contacts = [];
    let move = [0, 0];
    const collect = (event) => {
        for (const pair of event.pairs) {
            const {bodyA, bodyB, normal, depth} = pair.collision;
            const tileBody = bodyA === box ? bodyB : bodyB === box ? bodyA : null;
            if (tileBody === null) continue;
            const cell = cellOf.get(tileBody.id);
            if (cell === undefined) continue;
            const toBox = bodyA === box ? 1 : -1;  // matter's normal points from bodyB to bodyA
            const nx = normal.x * toBox;
            const ny = normal.y * toBox;
            const onX = Math.abs(nx) > Math.abs(ny);
            const along = Math.abs(onX ? move[0] : move[1]);
            const t = along > 0 ? Math.min(1, Math.max(0, 1 - depth / along)) : 0;
            contacts.push({tile: cell, normal: onX ? [Math.sign(nx), 0] : [0, Math.sign(ny)], t});
        }
    };
    Events.on(engine, 'collisionStart', collect);
    Events.on(engine, 'collisionActive', collect);

    let x = x0;
    let y = y0;
    const frames = [];
    for (const [dx, dy] of scene.moves) {
        const startedOverlapping = overlappedTiles(scene, x, y);
        contacts = [];
        move = [dx, dy];
        Body.setVelocity(box, {x: dx, y: dy});
        Engine.update(engine, kFrameMilliseconds);
        x = box.position.x - w / 2;
        y = box.position.y - h / 2;
        if (!Number.isFinite(x) || !Number.isFinite(y))
            throw new Error(`the box's position is not finite after frame ${frames.length} (${x}, ${y})`);
        contacts.sort((a, b) => a.t - b.t || a.tile[1] - b.tile[1] || a.tile[0] - b.tile[0]);
        frames.push({pos: [x, y], contacts, startedOverlapping});
    }
    return frames;
}

function answer(line) {
    try {
        return formatFrames(run(parseScene(line, {scalar: 'double'})), formatDouble);
    } catch (e) {
        if (e instanceof SceneError) return formatError(e.message);
        return formatError(`matter-js: ${e && e.message ? e.message : String(e)}`);
    }
}

async function main() {
    const paths = process.argv.slice(2);
    if (paths.length !== 0 && paths.length !== 2) {
        process.stderr.write('usage: node adapter.js [IN OUT]   (no IN OUT: scenes on stdin, answers on stdout)\n');
        process.exit(2);
    }
    await serve(paths, answer);
}

main().catch((e) => {
    process.stderr.write(`matter-js adapter: ${e && e.stack ? e.stack : e}\n`);
    process.exit(1);
});
