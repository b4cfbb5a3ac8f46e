// SPDX-License-Identifier: MIT
// Move-and-slide over the tiles on Box2D (v2.4, Debian's libbox2d-dev), behind the resolver
// protocol: scene lines in on standard input, one result line per scene out, flushed per line.
// Written the way a Box2D user writes a kinematic character controller, not tuned to the
// contract:
//
//   - lengths go to Box2D in meters, one meter per 16 pixels (a 16-pixel tile is 1 m, inside
//     Box2D's recommended 0.1 m to 10 m), and come back multiplied by 16 (both exact in float);
//   - per step, every solid tile under the swept bounds (grown by one cell for the polygon skin)
//     is a candidate; b2TimeOfImpact sweeps the box against each; the smallest time wins, and
//     every tile with exactly that time is a contact;
//   - the normal comes from b2Distance at the time of impact (the b2_time_of_impact.h note); a
//     tile the box is moving away from does not stop it; a tile the box is already inside
//     (cores overlapping) is ignored;
//   - the box moves to the time of impact (Box2D stops it b2_linearSlop short: its target
//     separation), the rest of the motion loses its component along the normal (slide), and
//     the loop runs at most two steps;
//   - a one-way cell ('-') is a tile like a solid one, taken as a candidate the way Box2D's
//     one-sided platform example (testbed, PreSolve) enables its contact: only while the box
//     moves down and its bottom is above the tile's top less 3 b2_linearSlop;
//   - start overlaps are the tiles b2TestOverlap reports (which counts the skin, so touching
//     tiles are listed); reported normals are the dominant axis of Box2D's normal.
//
//     tilesweep_box2d_adapter < scenes.jsonl        (float only: Box2D is float)
#include "tilesweep/scene/scene.h"

#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_time_of_impact.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace tilesweep;

/// Pixels per Box2D meter: a 16-pixel tile is one meter.
constexpr float kPixelsPerMeter = 16.0f;

b2Vec2 meters(float x, float y) { return {x / kPixelsPerMeter, y / kPixelsPerMeter}; }

struct Hit {
    Cell tile;
    b2Vec2 normal;  ///< from the tile toward the box, unit length
};

/// The cell range [lo, hi] on one axis covering [a, b] plus one cell on each side.
void cellRange(float origin, float tile, std::int32_t count, float a, float b, std::int32_t& lo,
               std::int32_t& hi) {
    const float first = std::floor((a - origin) / tile) - 1;
    const float last = std::floor((b - origin) / tile) + 1;
    lo = static_cast<std::int32_t>(std::max(first, 0.0f));
    hi = static_cast<std::int32_t>(std::min(last, static_cast<float>(count - 1)));
}

std::vector<FrameResult<float>> runBox2D(const Scene<float>& scene) {
    const TileMap<float>& map = scene.map;
    b2PolygonShape boxShape;
    boxShape.SetAsBox(scene.box.size.x / 2 / kPixelsPerMeter, scene.box.size.y / 2 / kPixelsPerMeter);
    b2PolygonShape tileShape;
    tileShape.SetAsBox(map.tileSize.x / 2 / kPixelsPerMeter, map.tileSize.y / 2 / kPixelsPerMeter);
    const auto solid = [&](std::int32_t i, std::int32_t j) {
        return map.solid[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.columns) +
                         static_cast<std::size_t>(i)] != 0;
    };
    // Box2D's one-sided platform test: the box's bottom (pixels) no lower than the top plus 3
    // slops, as the testbed's PreSolve keeps a contact enabled.
    const auto oneWayBlocks = [&](std::int32_t i, std::int32_t j, b2Vec2 posPixels, b2Vec2 motion) {
        if (map.kind(i, j) != CellKind::OneWay || motion.y <= 0) return false;
        const float top = map.origin.y + static_cast<float>(j) * map.tileSize.y;
        return posPixels.y + scene.box.size.y <= top + 3.0f * b2_linearSlop * kPixelsPerMeter;
    };
    const auto tileCenter = [&](std::int32_t i, std::int32_t j) {
        return meters(map.origin.x + (static_cast<float>(i) + 0.5f) * map.tileSize.x,
                      map.origin.y + (static_cast<float>(j) + 0.5f) * map.tileSize.y);
    };
    const auto boxCenter = [&](b2Vec2 posPixels) {
        return meters(posPixels.x + scene.box.size.x / 2, posPixels.y + scene.box.size.y / 2);
    };

    std::vector<FrameResult<float>> frames;
    b2Vec2 p(scene.box.pos.x, scene.box.pos.y);  // pixels
    for (const Vec2<float>& move : scene.moves) {
        FrameResult<float> frame;
        std::int32_t i0, i1, j0, j1;
        if (map.columns > 0 && map.rows > 0) {
            cellRange(map.origin.x, map.tileSize.x, map.columns, p.x, p.x + scene.box.size.x, i0, i1);
            cellRange(map.origin.y, map.tileSize.y, map.rows, p.y, p.y + scene.box.size.y, j0, j1);
            b2Transform boxXf(boxCenter(p), b2Rot(0));
            for (std::int32_t j = j0; j <= j1; ++j)
                for (std::int32_t i = i0; i <= i1; ++i)
                    if (solid(i, j) && b2TestOverlap(&boxShape, 0, &tileShape, 0, boxXf,
                                                     b2Transform(tileCenter(i, j), b2Rot(0))))
                        frame.startOverlaps.push_back({i, j});
        }
        b2Vec2 r(move.x, move.y);  // pixels
        float elapsed = 0;         // fraction of the frame before this step
        for (int step = 0; step < 2 && (r.x != 0 || r.y != 0); ++step) {
            float best = 1;
            std::vector<Hit> hits;
            if (map.columns > 0 && map.rows > 0) {
                cellRange(map.origin.x, map.tileSize.x, map.columns, std::min(p.x, p.x + r.x),
                          std::max(p.x, p.x + r.x) + scene.box.size.x, i0, i1);
                cellRange(map.origin.y, map.tileSize.y, map.rows, std::min(p.y, p.y + r.y),
                          std::max(p.y, p.y + r.y) + scene.box.size.y, j0, j1);
            } else {
                i0 = j0 = 0;
                i1 = j1 = -1;
            }
            for (std::int32_t j = j0; j <= j1; ++j)
                for (std::int32_t i = i0; i <= i1; ++i) {
                    if (!solid(i, j) && !oneWayBlocks(i, j, p, r)) continue;
                    b2TOIInput input;
                    input.proxyA.Set(&boxShape, 0);
                    input.proxyB.Set(&tileShape, 0);
                    input.sweepA.localCenter.SetZero();
                    input.sweepA.c0 = boxCenter(p);
                    input.sweepA.c = boxCenter(p + r);
                    input.sweepA.a0 = input.sweepA.a = 0;
                    input.sweepA.alpha0 = 0;
                    input.sweepB.localCenter.SetZero();
                    input.sweepB.c0 = input.sweepB.c = tileCenter(i, j);
                    input.sweepB.a0 = input.sweepB.a = 0;
                    input.sweepB.alpha0 = 0;
                    input.tMax = 1;
                    b2TOIOutput output;
                    b2TimeOfImpact(&output, &input);
                    if (output.state != b2TOIOutput::e_touching && output.state != b2TOIOutput::e_overlapped)
                        continue;
                    const float t = output.state == b2TOIOutput::e_touching ? output.t : 0.0f;
                    if (t > best) continue;
                    // The normal at the time of impact, from b2Distance (closest points of the cores).
                    b2DistanceInput distanceInput;
                    distanceInput.proxyA = input.proxyA;
                    distanceInput.proxyB = input.proxyB;
                    distanceInput.transformA = b2Transform(boxCenter(p + t * r), b2Rot(0));
                    distanceInput.transformB = b2Transform(tileCenter(i, j), b2Rot(0));
                    distanceInput.useRadii = false;
                    b2SimplexCache cache;
                    cache.count = 0;
                    b2DistanceOutput distance;
                    b2Distance(&distance, &cache, &distanceInput);
                    if (distance.distance <= 0) continue;  // already inside it: let the box leave
                    b2Vec2 normal = distance.pointA - distance.pointB;  // from the tile toward the box
                    normal.Normalize();
                    if (b2Dot(normal, r) >= 0) continue;  // moving away from it
                    if (t < best) {
                        best = t;
                        hits.clear();
                    }
                    hits.push_back({{i, j}, normal});
                }
            if (hits.empty()) {
                p += r;
                break;
            }
            p += best * r;
            std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
                return a.tile.j != b.tile.j ? a.tile.j < b.tile.j : a.tile.i < b.tile.i;
            });
            const float frameTime = elapsed + best * (1 - elapsed);
            for (const Hit& h : hits) {
                const bool onX = std::fabs(h.normal.x) > std::fabs(h.normal.y);
                const Normal n{static_cast<std::int8_t>(onX ? (h.normal.x > 0 ? 1 : -1) : 0),
                               static_cast<std::int8_t>(onX ? 0 : (h.normal.y > 0 ? 1 : -1))};
                frame.contacts.push_back(
                    {h.tile, n, frameTime, {}});  // no position: the protocol carries none
            }
            // Slide: the rest of the motion without its component into the first hit's normal.
            r = (1 - best) * r;
            r -= b2Dot(r, hits.front().normal) * hits.front().normal;
            elapsed = frameTime;
        }
        frame.position = {p.x, p.y};
        frames.push_back(std::move(frame));
    }
    return frames;
}

}  // namespace

int main() {
    std::ios::sync_with_stdio(false);
    std::string line;
    while (std::getline(std::cin, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const SceneParse<float> parsed = parseScene<float>(line);
        try {
            std::cout << (parsed.scene ? formatFrames(runBox2D(*parsed.scene)) : formatError(parsed.error));
        } catch (const std::exception& e) {
            std::cout << formatError(std::string("box2d: ") + e.what());
        }
        std::cout << '\n' << std::flush;
    }
    return 0;
}
