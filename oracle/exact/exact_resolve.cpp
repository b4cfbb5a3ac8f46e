// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/exact/exact_resolve.h"

#include "tilesweep/oracle/exact/rational_convert.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace tilesweep::oracle {
namespace {

constexpr int kMaxSteps = 2;  // docs/contract.md: "It takes at most two steps"

// -1, 0 or +1.
int signOf(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

// Whether the face of tile (i, j) that the motion on `axis` approaches is exposed: the cell
// across that face is not solid (only '#' hides a face; a one-way neighbour counts as empty).
// Motion +x approaches the left face, whose neighbour is (i-1, j); -x the right face, (i+1, j);
// +y the top face, (i, j-1); -y the bottom face, (i, j+1).
bool faceExposed(const ExactTileMap& map, std::int64_t i, std::int64_t j, Axis axis, int motionSign) {
    if (axis == Axis::X) {
        return !map.isSolid(i - motionSign, j);
    }
    return !map.isSolid(i, j - motionSign);
}

// A tile that can block (solid or one-way) and its exact rectangle, computed once per scene
// rather than once per test.
struct MapTile {
    Cell cell;
    CellKind kind = CellKind::Solid;
    ExactRect rect;
};

// Every solid and one-way tile of the map, by row then column: the contract's order within a
// step, one-way tiles among the solid ones.
std::vector<MapTile> tilesOf(const ExactTileMap& map) {
    std::vector<MapTile> tiles;
    for (std::int32_t j = 0; j < map.rows; ++j) {
        for (std::int32_t i = 0; i < map.columns; ++i) {
            const CellKind kind = map.kind(i, j);
            if (kind != CellKind::Empty) {
                tiles.push_back({{i, j}, kind, map.tileRect(i, j)});
            }
        }
    }
    return tiles;
}

struct Blocker {
    Cell cell;
    ExactSweepOutput sweep;
};

// Every tile that blocks the move of `box` by `motion`, in row-major order: a solid tile by the
// rules for one box against one tile, a one-way tile by the rules for one-way tiles. No
// broadphase: each tile of the map is tested.
std::vector<Blocker> findBlockers(const ExactTileMap& map, const std::vector<MapTile>& tiles,
                                  const ExactBox& box, const ExactVec2& motion) {
    std::vector<Blocker> blockers;
    const int signX = signOf(motion.x);
    const int signY = signOf(motion.y);
    for (const MapTile& tile : tiles) {
        const std::int64_t i = tile.cell.i;
        const std::int64_t j = tile.cell.j;
        ExactSweepInput input{box, motion, tile.rect, faceExposed(map, i, j, Axis::X, signX),
                              faceExposed(map, i, j, Axis::Y, signY)};
        ExactSweepOutput sweep =
            tile.kind == CellKind::OneWay ? sweepOneWayTileExact(input) : sweepTileExact(input);
        if (sweep.state == ExactSweepState::Blocks) {
            blockers.push_back({tile.cell, std::move(sweep)});
        }
    }
    return blockers;
}

// The frame loop of the contract, over the map's solid and one-way tiles.
ExactFrame resolveFrame(const ExactTileMap& map, const std::vector<MapTile>& tiles, const ExactBox& box,
                        const ExactVec2& displacement) {
    ExactFrame frame;
    frame.start = box.pos;
    frame.size = box.size;
    frame.gridOrigin = map.origin;
    frame.tileSize = map.tileSize;

    // started_overlapping lists solid tiles only.
    const ExactRect startRect = rectOf(box);
    for (const MapTile& tile : tiles) {
        if (tile.kind == CellKind::Solid && overlaps(startRect, tile.rect)) {
            frame.startOverlaps.push_back(tile.cell);
        }
    }

    ExactVec2 p = box.pos;
    ExactVec2 r = displacement;
    Rational elapsed(0);    // fraction of the frame elapsed when this step starts
    Rational remaining(1);  // fraction of the frame this step's time 1 stands for
    for (int step = 1; step <= kMaxSteps; ++step) {
        const std::vector<Blocker> blockers = findBlockers(map, tiles, {p, box.size}, r);
        if (blockers.empty()) {
            p = {p.x + r.x, p.y + r.y};
            break;
        }
        Rational s = blockers.front().sweep.time;
        for (const Blocker& b : blockers) {
            if (b.sweep.time < s) {
                s = b.sweep.time;
            }
        }
        const Rational frameTime = elapsed + s * remaining;
        bool zeroX = false;
        bool zeroY = false;
        for (const Blocker& b : blockers) {  // row-major already: H in the contract's order
            if (b.sweep.time != s) {
                continue;
            }
            Normal normal{0, 0};
            if (b.sweep.axis == Axis::X) {
                normal.x = static_cast<std::int8_t>(-signOf(r.x));
                zeroX = true;
            } else {
                normal.y = static_cast<std::int8_t>(-signOf(r.y));
                zeroY = true;
            }
            frame.contacts.push_back({b.cell, normal, frameTime, step, b.sweep.tie, {}});
        }
        p = {p.x + s * r.x, p.y + s * r.y};
        const Rational rest = 1 - s;
        r = {zeroX ? Rational(0) : Rational(rest * r.x), zeroY ? Rational(0) : Rational(rest * r.y)};
        // Where this step's contacts happened, and on which axes the box moves on from there
        // (there is no step after the last one).
        const bool lastStep = step == kMaxSteps;
        for (ExactContact& c : frame.contacts) {
            if (c.step != step) continue;
            c.position = p;
            c.movesOnX = !lastStep && r.x != 0;
            c.movesOnY = !lastStep && r.y != 0;
        }
        elapsed = frameTime;
        remaining *= rest;
    }
    frame.position = p;
    return frame;
}

}  // namespace

ExactFrame resolveFrameExact(const ExactTileMap& map, const ExactBox& box, const ExactVec2& displacement) {
    return resolveFrame(map, tilesOf(map), box, displacement);
}

template <class T>
std::vector<ExactFrame> resolveSceneExact(const Scene<T>& scene) {
    const ExactTileMap map = toExact(scene.map);
    const std::vector<MapTile> tiles = tilesOf(map);
    std::vector<ExactFrame> frames;
    frames.reserve(scene.moves.size());
    Vec2<T> start = scene.box.pos;
    for (const Vec2<T>& move : scene.moves) {
        const ExactBox box{toExact(start), toExact(scene.box.size)};
        frames.push_back(resolveFrame(map, tiles, box, toExact(move)));
        frames.back().startXIsNegativeZero = start.x == 0 && std::signbit(start.x);
        frames.back().startYIsNegativeZero = start.y == 0 && std::signbit(start.y);
        start = roundFrame<T>(frames.back()).position;
    }
    return frames;
}

template <class T>
FrameResult<T> roundFrame(const ExactFrame& frame) {
    FrameResult<T> result;
    // Exact: the start is a T value. A final coordinate equal to the start is the start itself,
    // bits and all, so a -0 start stays -0.
    const T startX =
        frame.startXIsNegativeZero ? -T(0) : fromRational<T>(frame.start.x, Rounding::NearestEven);
    const T startY =
        frame.startYIsNegativeZero ? -T(0) : fromRational<T>(frame.start.y, Rounding::NearestEven);
    result.position = {
        roundFinalCoordinate<T>(frame.position.x, startX, frame.size.x, frame.gridOrigin.x, frame.tileSize.x),
        roundFinalCoordinate<T>(frame.position.y, startY, frame.size.y, frame.gridOrigin.y,
                                frame.tileSize.y)};
    result.contacts.reserve(frame.contacts.size());
    // A contact's coordinate on an axis it slides on: to nearest, or the start's own bits (a -0
    // start stays -0) when it is the start.
    const auto atContact = [](const Rational& exact, const Rational& start, T startBits) {
        return exact == start ? startBits : fromRational<T>(exact, Rounding::NearestEven);
    };
    for (const ExactContact& c : frame.contacts) {
        const Vec2<T> position{
            c.movesOnX ? atContact(c.position.x, frame.start.x, startX) : result.position.x,
            c.movesOnY ? atContact(c.position.y, frame.start.y, startY) : result.position.y};
        result.contacts.push_back(
            {c.tile, c.normal, fromRational<T>(c.time, Rounding::NearestEven), position});
    }
    result.startOverlaps = frame.startOverlaps;
    return result;
}

template <class T>
std::vector<FrameResult<T>> toFrameResults(const std::vector<ExactFrame>& frames) {
    std::vector<FrameResult<T>> results;
    results.reserve(frames.size());
    for (const ExactFrame& frame : frames) {
        results.push_back(roundFrame<T>(frame));
    }
    return results;
}

template <class T>
std::vector<FrameResult<T>> resolveSceneExactRounded(const Scene<T>& scene) {
    return toFrameResults<T>(resolveSceneExact(scene));
}

template std::vector<ExactFrame> resolveSceneExact<float>(const Scene<float>&);
template std::vector<ExactFrame> resolveSceneExact<double>(const Scene<double>&);
template FrameResult<float> roundFrame<float>(const ExactFrame&);
template FrameResult<double> roundFrame<double>(const ExactFrame&);
template std::vector<FrameResult<float>> toFrameResults<float>(const std::vector<ExactFrame>&);
template std::vector<FrameResult<double>> toFrameResults<double>(const std::vector<ExactFrame>&);
template std::vector<FrameResult<float>> resolveSceneExactRounded<float>(const Scene<float>&);
template std::vector<FrameResult<double>> resolveSceneExactRounded<double>(const Scene<double>&);

}  // namespace tilesweep::oracle
