// SPDX-License-Identifier: MIT
// planck (npm planck, a TypeScript port of Box2D 2.x that computes in JavaScript doubles) behind
// tilesweep's resolver protocol, as a double resolver. Written the way a planck user writes a
// tile platformer's character, not tuned to the contract:
//
//   - the level is one static body holding a Box fixture per solid cell; the character is a
//     dynamic body with fixedRotation and one Box fixture of friction 0 (so that it does not
//     stick to walls), in a world without gravity (the scene's move already holds it);
//   - per frame, the frame's displacement becomes the body's velocity (displacement / (1/60 s),
//     set with setLinearVelocity) and the world takes one step, world.step(1/60) with planck's
//     default 8 velocity and 3 position iterations; the box's new position is the body's;
//   - coordinates are meters at 16 pixels per meter (a 16-pixel tile is one meter, as in the
//     Box2D and Rapier adapters); dividing and multiplying by 16 is exact in double, so only
//     the engine rounds;
//   - a contact is each tile contact the solver pushed on (post-solve with a positive normal
//     impulse), the first time in the frame: the tile from the fixture's user data, the normal
//     the dominant axis of the contact's world normal turned to point from the tile to the box,
//     and t the fraction of the frame elapsed when the engine solved it: 0 in the step's
//     discrete phase (contacts touching as the step starts), the time of impact in its
//     continuous phase. Contacts are listed by t, then row, then column;
//   - a one-way cell ('-') is a Box fixture too, whose contact is disabled in pre-solve as
//     planck's OneSidedPlatform example does, with both of that example's tests: the contact is
//     kept only while the box moves down and its bottom is at most 3 linearSlop below the
//     platform's top;
//   - started_overlapping is computed from the map by the contract's definition (Box2D has no
//     notion of it).
//
//     node adapter.js < scenes.jsonl > answers.jsonl    (pipe mode: one answer line per scene)
//     node adapter.js IN OUT                             (file mode: reads IN, writes OUT)
'use strict';

const planck = require('planck');
const {SceneError, serve, parseScene, formatFrames, formatDouble, formatError, overlappedTiles} =
    require('../rapier/scene_text');

/// Pixels per planck meter: a 16-pixel tile is one meter. A power of two, so converting is exact.
const kPixelsPerMeter = 16;
/// One frame: planck's step at 60 Hz.
const kFrameSeconds = 1 / 60;
/// planck's linear slop (0.005 m): its collision tolerance, and the one-way test's unit.
const kLinearSlop = planck.Settings.linearSlop;

// The frames of one scene, from a world of its own (so that no scene depends on the ones
// before it).
function run(scene) {
    const world = new planck.World({gravity: {x: 0, y: 0}});
    const level = world.createBody({type: 'static'});
    const tileWidth = scene.tile[0] / kPixelsPerMeter;
    const tileHeight = scene.tile[1] / kPixelsPerMeter;
    for (let j = 0; j < scene.rows; ++j)
        for (let i = 0; i < scene.columns; ++i) {
            const k = j * scene.columns + i;
            if (!scene.solid[k] && !scene.oneWay[k]) continue;
            const center = {
                x: (scene.xEdges[i] + scene.tile[0] / 2) / kPixelsPerMeter,
                y: (scene.yEdges[j] + scene.tile[1] / 2) / kPixelsPerMeter,
            };
            level.createFixture({
                shape: new planck.Box(tileWidth / 2, tileHeight / 2, center, 0),
                userData: {cell: [i, j], oneWay: !scene.solid[k], top: scene.yEdges[j] / kPixelsPerMeter},
            });
        }

    const [x0, y0, w, h] = scene.box;
    const box = world.createBody({
        type: 'dynamic',
        fixedRotation: true,
        position: {x: (x0 + w / 2) / kPixelsPerMeter, y: (y0 + h / 2) / kPixelsPerMeter},
    });
    const boxFixture = box.createFixture({
        shape: new planck.Box(w / 2 / kPixelsPerMeter, h / 2 / kPixelsPerMeter),
        density: 1,
        friction: 0,
    });
    const halfHeight = h / 2 / kPixelsPerMeter;

    // The tile's user data of a contact between the box and a tile, else null.
    const tileOf = (contact) => {
        const a = contact.getFixtureA();
        const b = contact.getFixtureB();
        if (a === boxFixture) return b.getUserData();
        if (b === boxFixture) return a.getUserData();
        return null;
    };

    // One-way platforms: planck's OneSidedPlatform example disables the contact in pre-solve.
    world.on('pre-solve', (contact) => {
        const tile = tileOf(contact);
        if (tile === null || !tile.oneWay) return;
        const movingDown = box.getLinearVelocity().y > 0;  // y grows downward
        const bottom = box.getPosition().y + halfHeight;
        if (!(movingDown && bottom <= tile.top + 3 * kLinearSlop)) contact.setEnabled(false);
    });

    // The contacts of the current frame.
    let contacts = [];
    let seen = new Set();
    let stepStart = null;  // the box's centre of mass as the step starts
    world.on('post-solve', (contact, impulse) => {
        const tile = tileOf(contact);
        if (tile === null || seen.has(tile)) return;
        if (!impulse.normalImpulses.some((n) => n > 0)) return;
        seen.add(tile);
        // The box's sweep starts where the step started in the discrete phase; in the
        // continuous phase it starts at the time of impact, alpha0 (a fraction of the step).
        const sweep = box.m_sweep;
        const discrete = sweep.c0.x === stepStart.x && sweep.c0.y === stepStart.y;
        const t = discrete ? 0 : sweep.alpha0;
        const n = contact.getWorldManifold(null).normal;  // from fixture A to fixture B
        const toBox = contact.getFixtureA() === boxFixture ? -1 : 1;
        const nx = n.x * toBox;
        const ny = n.y * toBox;
        const onX = Math.abs(nx) > Math.abs(ny);
        contacts.push({
            tile: tile.cell,
            normal: onX ? [Math.sign(nx), 0] : [0, Math.sign(ny)],
            t,
        });
    });

    let x = x0;
    let y = y0;
    const frames = [];
    for (const [dx, dy] of scene.moves) {
        const startedOverlapping = overlappedTiles(scene, x, y);
        contacts = [];
        seen = new Set();
        box.setLinearVelocity({x: dx / kPixelsPerMeter / kFrameSeconds, y: dy / kPixelsPerMeter / kFrameSeconds});
        const c = box.getWorldCenter();
        stepStart = {x: c.x, y: c.y};
        world.step(kFrameSeconds);
        const p = box.getPosition();
        x = p.x * kPixelsPerMeter - w / 2;
        y = p.y * kPixelsPerMeter - h / 2;
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
        return formatError(`planck: ${e && e.message ? e.message : String(e)}`);
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
    process.stderr.write(`planck adapter: ${e && e.stack ? e.stack : e}\n`);
    process.exit(1);
});
