// SPDX-License-Identifier: MIT
// What Phaser's browser build needs from a page to load and boot a HEADLESS game under node, and
// nothing more: no jsdom, no canvas package. Phaser runs its arcade physics and tilemaps without
// drawing anything; what it reads from the page at load and boot is
//
//   - navigator.userAgent and a `window` (device detection), and `importScripts` defined, which
//     makes Phaser take its Web Worker path and skip probing canvas blend modes;
//   - a `document` that is already loaded, whose elements measure 320 x 240 (the scale manager
//     sizes the game from its parent) and accept listeners;
//   - `screen`, `innerWidth`/`innerHeight`, window listeners (the scale manager's);
//   - `Image`: the texture manager decodes three built-in base64 images at boot and waits for
//     them; each stand-in image "loads" at once as a 32 x 32 picture with no pixels;
//   - HTMLCanvasElement and friends, which Phaser only tests sources against with instanceof;
//   - requestAnimationFrame, which never calls back: the game loop does not run by itself, the
//     adapter steps the physics world by hand.
//
// Phaser prints through console.log and console.warn; the adapter's standard output carries
// answers only, so both go to standard error.
'use strict';

function element() {
    return {
        style: {},
        getContext: () => null,
        addEventListener() {},
        removeEventListener() {},
        setAttribute() {},
        appendChild() {},
        removeChild() {},
        getBoundingClientRect: () => ({left: 0, top: 0, right: 320, bottom: 240, width: 320, height: 240}),
    };
}

function installPageStandIns() {
    const g = globalThis;
    g.window = g;
    g.navigator = {userAgent: 'node', platform: 'node', maxTouchPoints: 0};
    g.importScripts = function importScripts() {};
    g.document = {
        readyState: 'complete',
        createElement: element,
        documentElement: {style: {}, clientWidth: 320, clientHeight: 240},
        body: element(),
        addEventListener() {},
        removeEventListener() {},
    };
    g.screen = {orientation: {addEventListener() {}, removeEventListener() {}}, addEventListener() {}, removeEventListener() {}};
    g.innerWidth = 320;
    g.innerHeight = 240;
    g.addEventListener = () => {};
    g.removeEventListener = () => {};
    g.Image = class StandInImage {
        constructor() {
            this.width = this.naturalWidth = 32;
            this.height = this.naturalHeight = 32;
        }
        set src(_) {
            setImmediate(() => this.onload && this.onload());
        }
    };
    g.HTMLCanvasElement = class HTMLCanvasElement {};
    g.HTMLImageElement = class HTMLImageElement {};
    g.HTMLVideoElement = class HTMLVideoElement {};
    g.requestAnimationFrame = () => 0;
    g.cancelAnimationFrame = () => {};
    const toStderr = (...args) => process.stderr.write(args.map(String).join(' ') + '\n');
    console.log = console.info = console.warn = toStderr;
}

module.exports = {installPageStandIns};
