// SPDX-License-Identifier: MIT
// The game-feel claims (claims.h): a box resting on a floor stays put, and one sliding along a
// floor never snags on the seams between its tiles.
#include "claim_support.h"
#include "claims.h"

#include <cstdint>

namespace tilesweep::properties {

using namespace claim_support;

/// Whether the box at `pos` stands on the map: a solid tile's top exactly at its bottom, under
/// its open x span.
template <class T>
bool standsOnFloor(const oracle::ExactTileMap& map, const Scene<T>& scene, Vec2<T> pos) {
    const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{pos, scene.box.size}));
    for (std::int32_t j = 0; j < map.rows; ++j)
        for (std::int32_t i = 0; i < map.columns; ++i) {
            if (!map.isSolid(i, j)) continue;
            const oracle::ExactRect t = map.tileRect(i, j);
            if (t.min.y == box.max.y && t.min.x < box.max.x && t.max.x > box.min.x) return true;
        }
    return false;
}

/// A box standing on a floor and pushed down by gravity lands at once (a floor contact at time
/// 0) and keeps its height bit for bit, and its x too when it does not walk. Every frame that
/// starts on a floor is checked, so a box that sinks into or falls through the floor fails.
template <class T>
std::string restingContactIsStable(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = resolveUnderTest(scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Vec2<T> m = scene.moves[f];
        if (!(m.y > 0) || !standsOnFloor(map, scene, starts[f])) continue;
        const auto& hits = frames[f].contacts;
        const bool landed = std::any_of(hits.begin(), hits.end(),
                                        [](const Contact<T>& c) { return c.normal.y == -1 && c.time == 0; });
        if (!landed)
            return "frame " + std::to_string(f) + ": standing on a floor, no floor contact at time 0";
        if (!sameBits(frames[f].position.y, starts[f].y) ||
            (m.x == 0 && !sameBits(frames[f].position.x, starts[f].x)))
            return "frame " + std::to_string(f) + ": resting box moved from (" + hex(starts[f].x) + ", " +
                   hex(starts[f].y) + ") to (" + hex(frames[f].position.x) + ", " +
                   hex(frames[f].position.y) + ")";
    }
    return {};
}

/// A box standing on a floor (a solid tile under its open x span, top exactly at its bottom)
/// and moving sideways and down is never stopped on x by a tile of that floor: no snag on seams.
template <class T>
std::string slidingAlongFloorNeverSnags(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = resolveUnderTest(scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!(scene.moves[f].y > 0)) continue;
        const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{starts[f], scene.box.size}));
        bool supported = false;
        for (std::int32_t j = 0; j < map.rows && !supported; ++j)
            for (std::int32_t i = 0; i < map.columns && !supported; ++i) {
                if (!map.isSolid(i, j)) continue;
                const oracle::ExactRect t = map.tileRect(i, j);
                supported = t.min.y == box.max.y && t.min.x < box.max.x && t.max.x > box.min.x;
            }
        if (!supported) continue;
        if (!sameBits(frames[f].position.y, starts[f].y))
            return "frame " + std::to_string(f) + ": left the floor it stood on, moving down";
        for (const Contact<T>& c : frames[f].contacts)
            if (c.normal.x != 0 && map.tileRect(c.tile.i, c.tile.j).min.y == box.max.y)
                return "frame " + std::to_string(f) + ": snagged on the side of floor tile " +
                       cellText(c.tile);
    }
    return {};
}

template std::string restingContactIsStable<float>(const Scene<float>&);
template std::string restingContactIsStable<double>(const Scene<double>&);
template std::string slidingAlongFloorNeverSnags<float>(const Scene<float>&);
template std::string slidingAlongFloorNeverSnags<double>(const Scene<double>&);

}  // namespace tilesweep::properties
