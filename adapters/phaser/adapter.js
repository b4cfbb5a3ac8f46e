// SPDX-License-Identifier: MIT
// Phaser's Arcade physics (npm phaser, the browser build a Phaser game loads) behind tilesweep's
// resolver protocol, as a platformer's player collides with a tilemap layer. Written the way a
// Phaser user sets up such a game, not tuned to the contract:
//
//   - a HEADLESS Phaser.Game with Arcade physics (its defaults: 60 steps a second, TILE_BIAS 16,
//     OVERLAP_BIAS 4, no gravity here), booted under node with the page stand-ins of headless.js;
//     the game loop does not run by itself, the adapter steps the world;
//   - per scene, a tilemap made from the scene's rows (scene.make.tilemap with a 2D array of tile
//     indices), one layer at the map's origin, layer.setCollision on the solid tile's index; a
//     one-way cell ('-') is a tile of its own index on which tile.setCollision(false, false, true,
//     false) is called (collide only on top), as Phaser users make jump-through platforms;
//   - the box is an Arcade sprite's body (origin at its top-left, body.setSize(w, h, false)),
//     colliding with the layer through scene.physics.add.collider(player, layer), its maximum
//     velocity lifted (Phaser's default of 10,000 px/s would cap a frame at 166.7 px);
//   - per frame, body.reset(x, y) to the frame's start, body.setVelocity(v) with v the frame's
//     displacement d over one physics step (d * 60, or a double next to it for which Phaser's
//     v * (1/60) gives back d exactly: doubles.js) and world.singleStep(): the body moves by
//     velocity * 1/60 s, then each colliding tile around it that it overlaps is separated in
//     turn (SeparateTile: pushed back out along an axis when the overlap is at most TILE_BIAS);
//   - a contact is each tile the collider reports as separated: the normal the axis and sign of
//     that tile's push-back, t the fraction of the frame's displacement on that axis left after
//     the push-back (Phaser is discrete and has no time of impact);
//   - Phaser computes in double; the body's position after the step is brought to float32 by
//     the contract's rule for positions (doubles.js), so that the float protocol adds no error
//     of its own, and the next frame starts there;
//   - started_overlapping is computed from the map by the contract's definition (Phaser has no
//     notion of it).
//
//     node adapter.js < scenes.jsonl > answers.jsonl    (pipe mode: one answer line per scene)
//     node adapter.js IN OUT                             (file mode: reads IN, writes OUT)
'use strict';

const {installPageStandIns} = require('./headless');
const {velocityFor, roundPosition} = require('./doubles');
const {SceneError, serve, parseScene, formatFrames, formatError, overlappedTiles} = require('../rapier/scene_text');

installPageStandIns();
const Phaser = require('phaser');

/// Physics steps a second: Arcade's default. A frame is one step.
const kFps = 60;
/// Tile indices of the layer: a solid cell and a one-way cell ('-'); -1 is an empty cell.
const kSolid = 0;
const kOneWay = 1;
/// One physics step in seconds, as Arcade computes it from its fps.
const kStep = 1 / kFps;

// Boots a headless game whose one scene has Arcade physics, and resolves with that scene.
function bootScene() {
    return new Promise((resolve) => {
        class TileScene extends Phaser.Scene {
            create() {
                resolve(this);
            }
        }
        // eslint-disable-next-line no-new
        new Phaser.Game({
            type: Phaser.HEADLESS,
            width: 320,
            height: 240,
            banner: false,
            audio: {noAudio: true},
            physics: {default: 'arcade', arcade: {fps: kFps, gravity: {x: 0, y: 0}}},
            scene: TileScene,
        });
    });
}

class ArcadeResolver {
    constructor(scene) {
        this.scene = scene;
        this.world = scene.physics.world;
        this.player = scene.physics.add.sprite(0, 0, '__DEFAULT').setOrigin(0, 0);
        this.body = this.player.body;
        this.body.setMaxVelocity(Infinity, Infinity);
        this.boxSize = [0, 0];
        this.tilesets = new Map();  // tile size -> texture key
        this.frame = null;          // the frame being stepped: {move, contacts, before}
    }

    // A texture for a tileset of the two tile kinds at this tile size (nothing is drawn).
    textureFor(tw, th) {
        const size = `${tw}x${th}`;
        let key = this.tilesets.get(size);
        if (key === undefined) {
            key = `tiles-${size}`;
            this.scene.textures.addImage(key, {width: 2 * tw, height: th, naturalWidth: 2 * tw, naturalHeight: th});
            this.tilesets.set(size, key);
        }
        return key;
    }

    // The scene's map as a tilemap layer with collision set, or null for a map with no cells.
    makeLayer(scene) {
        if (scene.rows === 0 || scene.columns === 0) return null;
        const data = [];
        for (let j = 0; j < scene.rows; ++j) {
            const row = new Array(scene.columns);
            for (let i = 0; i < scene.columns; ++i) {
                const k = j * scene.columns + i;
                row[i] = scene.solid[k] ? kSolid : scene.oneWay[k] ? kOneWay : -1;
            }
            data.push(row);
        }
        const [tw, th] = scene.tile;
        const map = this.scene.make.tilemap({data, tileWidth: tw, tileHeight: th});
        const tileset = map.addTilesetImage('tiles', this.textureFor(tw, th), tw, th);
        const layer = map.createLayer(0, tileset, scene.origin[0], scene.origin[1]);
        layer.setCollision(kSolid);
        layer.forEachTile((tile) => {
            if (tile.index === kOneWay) tile.setCollision(false, false, true, false);
        });
        return {map, layer};
    }

    // Before a tile is separated: where the body is.
    onProcess() {
        this.frame.before = [this.body.position.x, this.body.position.y];
        return true;
    }

    // After a tile was separated: the push-back gives the contact.
    onCollide(_, tile) {
        const frame = this.frame;
        const px = this.body.position.x - frame.before[0];
        const py = this.body.position.y - frame.before[1];
        const onX = Math.abs(px) > Math.abs(py);
        const push = onX ? px : py;
        const move = onX ? frame.move[0] : frame.move[1];
        const t = move !== 0 ? Math.min(1, Math.max(0, 1 + push / move)) : 0;
        frame.contacts.push({
            tile: [tile.x, tile.y],
            normal: onX ? [Math.sign(px), 0] : [0, Math.sign(py)],
            t: Math.fround(t),
        });
    }

    // The frames of one scene.
    run(scene) {
        const [, , w, h] = scene.box;
        if (this.boxSize[0] !== w || this.boxSize[1] !== h) {
            this.body.setSize(w, h, false);
            this.boxSize = [w, h];
        }
        const made = this.makeLayer(scene);
        const collider = made === null ? null
            : this.scene.physics.add.collider(this.player, made.layer, this.onCollide, this.onProcess, this);
        try {
            let x = scene.box[0];
            let y = scene.box[1];
            const frames = [];
            for (const move of scene.moves) {
                const startedOverlapping = overlappedTiles(scene, x, y);
                this.frame = {move, contacts: [], before: [x, y]};
                this.body.reset(x, y);
                this.body.setVelocity(velocityFor(move[0], kStep), velocityFor(move[1], kStep));
                this.world.singleStep();
                const end = this.body.position;
                x = roundPosition(x, end.x, w, scene.origin[0], scene.tile[0]);
                y = roundPosition(y, end.y, h, scene.origin[1], scene.tile[1]);
                frames.push({pos: [x, y], contacts: this.frame.contacts, startedOverlapping});
            }
            return frames;
        } finally {
            this.frame = null;
            if (collider !== null) collider.destroy();
            if (made !== null) made.map.destroy();
        }
    }
}

function answer(resolver, line) {
    try {
        return formatFrames(resolver.run(parseScene(line)));
    } catch (e) {
        if (e instanceof SceneError) return formatError(e.message);
        return formatError(`phaser: ${e && e.message ? e.message : String(e)}`);
    }
}

async function main() {
    const args = process.argv.slice(2);
    if (args.length !== 0 && args.length !== 2) {
        process.stderr.write('usage: node adapter.js [IN OUT]   (no IN OUT: scenes on stdin, answers on stdout)\n');
        process.exit(2);
    }
    const resolver = new ArcadeResolver(await bootScene());
    await serve(args, (line) => answer(resolver, line));
    process.exitCode = 0;
    process.stdout.end(() => process.exit(0));
}

main().catch((e) => {
    process.stderr.write(`phaser adapter: ${e && e.stack ? e.stack : e}\n`);
    process.exit(1);
});
