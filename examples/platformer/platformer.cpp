// SPDX-License-Identifier: MIT
// A small platformer loop on tilesweep's game-loop API (tilesweep/mover.h): gravity, jumps,
// walls, a one-tile pit, a fast dash and a one-way platform to jump up through, land on and drop
// through. The player is steered by a tiny controller (walk right, jump at a wall, dash once past
// the low wall, drop through the platform once), so the run is the same every time.
//
//     platformer                 prints the trajectory, one line per frame; exit 1 if a check fails
//     platformer --svg FILE      also draws it with the scene renderer (tilesweep/scene/render.h)
//     platformer --love-style    prints the frames of examples/love_style/main.lua's scenario
//                                (a box falls, lands and slides), for that script to compare
//
// The checks: the player lands, never ends a frame overlapping a solid tile, falls into the pit
// and climbs out, the dash (two tiles a frame) stops touching the wall instead of passing it, the
// player jumps up through the platform and lands exactly on its top, and drops through it to the
// floor on the frame it asks to.
// README.md quotes the game loop below between the [readme:game-loop] markers; ctest checks the
// quote is still the code (examples/platformer/check_readme_snippet.cmake).
#include "tilesweep/mover.h"
#include "tilesweep/scene/render.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

using tilesweep::Box;
using tilesweep::MoveResult;
using tilesweep::Vec2;

constexpr double kDt = 1.0 / 60;  // seconds per frame
constexpr float kGravity = 1200;  // px/s^2, y down
constexpr float kWalk = 90;       // px/s
constexpr float kJump = -380;     // px/s: a 60 px apex clears the 32 px low wall
constexpr float kDash = 1800;     // px/s: 30 px a frame, almost two tiles
constexpr int kDashFrames = 10;
constexpr float kFallLimit = 600;  // px/s
constexpr int kFrames = 300;

// 16-pixel tiles. A one-tile pit in the floor at column 5 (x in [80, 96]), a low wall of two
// tiles at column 10 (x in [160, 176]), a wall from floor to ceiling at column 19 (x in [304,
// 320]), and before it a one-way platform ('-') over columns 15 to 18, its top at y = 96: three
// tiles above the floor, within the jump's reach.
const char* const kLevel[] = {
    "##############################", "#..................#.........#", "#..................#.........#",
    "#..................#.........#", "#..................#.........#", "#..................#.........#",
    "#..............----#.........#", "#.........#........#.........#", "#.........#........#.........#",
    "#####.########################", "##############################",
};
constexpr float kTile = 16;
constexpr float kPitLeft = 80, kPitRight = 96, kPitFloor = 160;
constexpr float kTallWall = 304;
constexpr float kPlatformLeft = 240, kPlatformTop = 96, kFloor = 144;
constexpr int kStandBeforeDrop = 20;  // frames on the platform before the player drops through

struct Level {
    tilesweep::TileMap<float> map;
    Level() {
        map.tileSize = {kTile, kTile};
        map.columns = static_cast<std::int32_t>(std::strlen(kLevel[0]));
        map.rows = static_cast<std::int32_t>(sizeof kLevel / sizeof kLevel[0]);
        for (const char* row : kLevel)
            for (const char* c = row; *c != 0; ++c) {
                map.solid.push_back(*c == '#' ? 1 : 0);
                map.oneWay.push_back(*c == '-' ? 1 : 0);
            }
    }
    [[nodiscard]] tilesweep::TileMapView<float> view() const { return map.view(); }
};

struct Player {
    Box<float> box{{24, 20}, {12, 14}};
    Vec2<float> velocity{0, 0};
    int dashLeft = 0;
    bool dashed = false;
    int onPlatform = 0;  ///< frames stood on the platform so far
    bool down = false;   ///< the down key: this frame drops through one-way platforms
    bool dropped = false;
};

struct Frame {
    Player player;             ///< at the start of the frame, with the velocity it moved by
    MoveResult<float> result;  ///< what moveAndSlide returned
};

/// Whether the box stands on the platform's top (within its columns).
bool standsOnPlatform(const Box<float>& b) {
    return b.pos.y + b.size.y == kPlatformTop && b.pos.x + b.size.x > kPlatformLeft && b.pos.x < kTallWall;
}

// The controller: walk right, jump when standing against a wall, dash once on the ground past
// the low wall, drop through the platform once after standing on it a while; gravity always (a
// dash is level flight).
void steer(Player& p, const std::vector<Frame>& trace) {
    const bool grounded = !trace.empty() && trace.back().result.onGround;
    const bool walled = !trace.empty() && trace.back().result.onWall;
    p.onPlatform = grounded && standsOnPlatform(p.box) ? p.onPlatform + 1 : 0;
    p.down = !p.dropped && p.onPlatform > kStandBeforeDrop;
    p.dropped = p.dropped || p.down;
    if (p.dashLeft > 0) {
        --p.dashLeft;
        p.velocity = {kDash, 0};
        return;
    }
    p.velocity.x = kWalk;
    if (grounded && !p.dashed && p.box.pos.x > 200) {
        p.dashed = true;
        p.dashLeft = kDashFrames - 1;
        p.velocity = {kDash, 0};
        return;
    }
    if (grounded && walled && !p.down && (p.dropped || p.onPlatform == 0)) p.velocity.y = kJump;
    p.velocity.y += static_cast<float>(static_cast<double>(kGravity) * kDt);
    if (p.velocity.y > kFallLimit) p.velocity.y = kFallLimit;
}

int fail(const char* what) {
    std::fprintf(stderr, "platformer: %s\n", what);
    return 1;
}

/// True when the box's interior meets a solid tile's (touching is not overlapping). The
/// positions are small floats, so every sum below is exact in double.
bool overlapsSolid(const Level& level, const Box<float>& b) {
    const double x0 = static_cast<double>(b.pos.x), y0 = static_cast<double>(b.pos.y);
    const double x1 = x0 + static_cast<double>(b.size.x), y1 = y0 + static_cast<double>(b.size.y);
    const double tile = static_cast<double>(kTile);
    for (std::int32_t j = 0; j < level.map.rows; ++j)
        for (std::int32_t i = 0; i < level.map.columns; ++i)
            if (level.view().isSolid(i, j) && x0 < (i + 1) * tile && x1 > i * tile && y0 < (j + 1) * tile &&
                y1 > j * tile)
                return true;
    return false;
}

int runPlatformer(const char* svgPath) {
    const Level level;
    Player player;
    std::vector<Frame> trace;
    // [readme:game-loop]
    const auto map = tilesweep::prepareMap(level.view());  // once per map: validates it
    if (!map.isValid()) return fail(tilesweep::describe(map.error()));
    const auto drop = map.withoutOneWay();  // the map of frames that drop through platforms
    for (int frame = 0; frame < kFrames; ++frame) {
        steer(player, trace);  // input, gravity, jumps, the dash, the down key
        const auto r = tilesweep::moveAndSlide(player.down ? drop : map, {player.box, player.velocity * kDt});
        trace.push_back({player, r});  // the frame's start and its result
        player.box.pos = r.position;
        player.velocity = tilesweep::clipVelocity(player.velocity, r);  // floors, ceilings, walls
    }
    // [readme:end]
    std::printf("# frame x y vx vy flags (G ground, W wall, C ceiling): the position at the end\n");
    bool landed = false, inPit = false, outOfPit = false, dashStopped = false;
    bool jumpedThrough = false, landedOnPlatform = false, droppedToFloor = false;
    int drops = 0;
    for (std::size_t frame = 0; frame < trace.size(); ++frame) {
        const Frame& f = trace[frame];
        const Vec2<float> move = f.player.velocity * kDt;
        const Box<float> b{f.result.position, f.player.box.size};
        std::printf("%zu %.9g %.9g %.9g %.9g %s%s%s\n", frame, static_cast<double>(b.pos.x),
                    static_cast<double>(b.pos.y), static_cast<double>(f.player.velocity.x),
                    static_cast<double>(f.player.velocity.y), f.result.onGround ? "G" : "",
                    f.result.onWall ? "W" : "", f.result.onCeiling ? "C" : "");
        if (f.result.status != tilesweep::MoveStatus::Moved &&
            f.result.status != tilesweep::MoveStatus::Blocked)
            return fail("a frame was refused");
        if (overlapsSolid(level, b)) return fail("the player ended a frame inside a tile");
        landed = landed || f.result.onGround;
        if (f.result.onGround && b.pos.x >= kPitLeft && b.pos.x + b.size.x <= kPitRight &&
            b.pos.y + b.size.y == kPitFloor)
            inPit = true;
        if (inPit && b.pos.x > kPitRight) outOfPit = true;
        if (move.x > kTile && f.result.onWall && b.pos.x + b.size.x == kTallWall) dashStopped = true;
        if (b.pos.x + b.size.x > kTallWall) return fail("the player got past the tall wall");
        // Rising with the box's interior across the platform's top: jumping up through it.
        if (f.player.velocity.y < 0 && b.pos.y < kPlatformTop && b.pos.y + b.size.y > kPlatformTop &&
            b.pos.x + b.size.x > kPlatformLeft)
            jumpedThrough = true;
        if (f.result.onGround && standsOnPlatform(b)) {
            if (!jumpedThrough) return fail("the player stood on the platform before jumping through it");
            if (drops > 0 && !droppedToFloor) return fail("the drop through the platform landed on it");
            landedOnPlatform = true;
        }
        if (f.player.down) ++drops;
        if (drops > 0 && f.result.onGround && b.pos.y + b.size.y == kFloor) droppedToFloor = true;
    }
    if (!landed) return fail("the player never landed");
    if (!inPit || !outOfPit) return fail("the player did not fall into the one-tile pit and climb out");
    if (!dashStopped) return fail("the dash did not stop touching the wall");
    if (!jumpedThrough || !landedOnPlatform)
        return fail("the player did not jump up through the platform and land on it");
    if (drops != 1 || !droppedToFloor)
        return fail("the player did not drop through the platform to the floor");
    std::printf(
        "# checks hold: lands, never inside a tile, in and out of the pit, the dash stops at the wall, "
        "up through the platform and onto it, down through it\n");

    if (svgPath != nullptr) {
        // The same run as a scene, each frame resolved again with resolveMove on the map it used
        // (the drop frame's without its one-way cells, which a scene file cannot say), which
        // must give the very same positions.
        tilesweep::Scene<float> scene;
        scene.name = "platformer";
        scene.map = level.map;
        scene.box = Player{}.box;
        std::vector<tilesweep::FrameResult<float>> frames;
        tilesweep::Contact<float> contacts[16];
        tilesweep::Cell overlaps[16];
        for (const Frame& f : trace) {
            const Vec2<float> move = f.player.velocity * kDt;
            scene.moves.push_back(move);
            const auto view = f.player.down ? level.view().withoutOneWay() : level.view();
            const auto r =
                tilesweep::resolveMove<float>({view, f.player.box, move}, {contacts, 16, overlaps, 16});
            if (std::memcmp(&r.position, &f.result.position, sizeof r.position) != 0)
                return fail("resolveMove disagrees with moveAndSlide");
            frames.push_back({r.position,
                              {contacts, contacts + std::min(r.contactCount, 16)},
                              {overlaps, overlaps + std::min(r.startOverlapCount, 16)}});
        }
        std::ofstream out(svgPath);
        out << tilesweep::renderSceneSvg(scene, frames);
        if (!out) return fail("cannot write the SVG file");
        std::printf("# drawn to %s\n", svgPath);
    }
    return 0;
}

// The scenario of examples/love_style/main.lua: a 10x12 box dropped at (20, 10) with 75 px/s to
// the right, gravity 900 px/s^2, 240 frames of 1/60 s. Velocities and moves are computed in
// double and rounded once to float, as the Lua script does, so both feed the resolver the same
// bits. One line per frame: x y (C99 hexfloats, exact) and the flags.
constexpr const char* kLoveLevel[] = {
    "....................", "....................", "....................", "....................",
    "....................", "...............#....", "...............#....", "####################",
};

int runLoveStyle() {
    tilesweep::TileMap<float> level;
    level.tileSize = {16, 16};
    level.columns = 20;
    level.rows = 8;
    for (const char* row : kLoveLevel)
        for (const char* c = row; *c != 0; ++c) level.solid.push_back(*c == '#' ? 1 : 0);
    const auto map = tilesweep::prepareMap(level.view());
    if (!map.isValid()) return fail(tilesweep::describe(map.error()));
    Box<float> box{{20, 10}, {10, 12}};
    double vx = 75, vy = 0;
    const double gravity = 900, dt = 1.0 / 60;
    for (int frame = 0; frame < 240; ++frame) {
        vy = vy + gravity * dt;
        const Vec2<float> move{static_cast<float>(vx * dt), static_cast<float>(vy * dt)};
        const auto r = tilesweep::moveAndSlide(map, {box, move});
        box.pos = r.position;
        if (r.onGround) vy = 0;
        if (r.onWall) vx = 0;
        std::printf("%a %a %d %d\n", static_cast<double>(box.pos.x), static_cast<double>(box.pos.y),
                    r.onGround ? 1 : 0, r.onWall ? 1 : 0);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const char* svg = nullptr;
    for (int k = 1; k < argc; ++k) {
        if (std::strcmp(argv[k], "--love-style") == 0) return runLoveStyle();
        if (std::strcmp(argv[k], "--svg") == 0 && k + 1 < argc) {
            svg = argv[++k];
            continue;
        }
        std::fprintf(stderr, "usage: platformer [--svg FILE] | --love-style\n");
        return 2;
    }
    return runPlatformer(svg);
}
