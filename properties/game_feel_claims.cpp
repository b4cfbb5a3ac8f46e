// SPDX-License-Identifier: MIT
// The game-feel claims (claims.h): a box resting on a floor or a platform stays put, one sliding
// along a floor never snags on the seams between its tiles, and a platform stops only a box
// coming down onto its top.
#include "claim_support.h"
#include "claims.h"

#include <cstdint>

namespace tilesweep::properties {

using namespace claim_support;

/// What a box may stand on: a floor (the top face of a solid or a one-way tile), or a platform
/// (a one-way tile's top only).
enum class Support : std::uint8_t { Floor, Platform };

/// Whether the box at `pos` stands on the map: the top of a tile of the kind `support` names
/// exactly at its bottom, under its open x span.
template <class T>
bool standsOn(const oracle::ExactTileMap& map, const Scene<T>& scene, Vec2<T> pos, Support support) {
    const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{pos, scene.box.size}));
    for (std::int32_t j = 0; j < map.rows; ++j)
        for (std::int32_t i = 0; i < map.columns; ++i) {
            const CellKind kind = scene.map.kind(i, j);
            if (kind == CellKind::Empty || (support == Support::Platform && kind != CellKind::OneWay))
                continue;
            const oracle::ExactRect t = map.tileRect(i, j);
            if (t.min.y == box.max.y && t.min.x < box.max.x && t.max.x > box.min.x) return true;
        }
    return false;
}

/// Every frame that starts standing on `support` and moves down lands at once (a contact on y
/// at time 0) and keeps its height bit for bit, and its x too when it does not walk; empty when
/// that holds.
template <class T>
std::string keepsStanding(const Scene<T>& scene, SceneResolver& resolver, Support support) {
    const std::vector<FrameResult<T>> frames = framesFrom(resolver, scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    const char* what = support == Support::Platform ? "a platform" : "a floor";
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Vec2<T> m = scene.moves[f];
        if (!(m.y > 0) || !standsOn(map, scene, starts[f], support)) continue;
        const auto& hits = frames[f].contacts;
        const bool landed = std::any_of(hits.begin(), hits.end(),
                                        [](const Contact<T>& c) { return c.normal.y == -1 && c.time == 0; });
        if (!landed)
            return "frame " + std::to_string(f) + ": standing on " + what + ", no contact on y at time 0";
        if (!sameBits(frames[f].position.y, starts[f].y) ||
            (m.x == 0 && !sameBits(frames[f].position.x, starts[f].x)))
            return "frame " + std::to_string(f) + ": box standing on " + what + " moved from (" +
                   hex(starts[f].x) + ", " + hex(starts[f].y) + ") to (" + hex(frames[f].position.x) + ", " +
                   hex(frames[f].position.y) + ")";
    }
    return {};
}

/// A box standing on a floor and pushed down by gravity lands at once and keeps its height (a
/// floor is a solid or a one-way tile's top). Every frame that starts on a floor is checked, so
/// a box that sinks into or falls through the floor fails.
template <class T>
std::string restingContactIsStable(const Scene<T>& scene, SceneResolver& resolver) {
    return keepsStanding(scene, resolver, Support::Floor);
}

/// A box standing on a one-way tile's top and moving down, at any speed, lands on it at once
/// and keeps its height: it never falls through a platform it stood on.
template <class T>
std::string neverFallsThroughAPlatformItStoodOn(const Scene<T>& scene, SceneResolver& resolver) {
    return keepsStanding(scene, resolver, Support::Platform);
}

/// A platform stops a box only on its top face, and only a box whose bottom is at or above that
/// top: no frame reports a hit on a one-way tile whose top lies above the box's bottom at the
/// frame's start (the box is inside it or below it, jumping through), nor a hit on one with
/// another normal than (0, -1). The frame's start is enough: a second step moves down only if
/// the first did, so the bottom at a second step's start is no higher than at the frame's.
template <class T>
std::string neverBlockedByAPlatformFromBelow(const Scene<T>& scene, SceneResolver& resolver) {
    const std::vector<FrameResult<T>> frames = framesFrom(resolver, scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{starts[f], scene.box.size}));
        for (const Contact<T>& c : frames[f].contacts) {
            if (scene.map.kind(c.tile.i, c.tile.j) != CellKind::OneWay) continue;
            const std::string at = "frame " + std::to_string(f) + ": platform " + cellText(c.tile);
            if (c.normal.x != 0 || c.normal.y != -1) return at + " hit on another face than its top";
            if (map.tileRect(c.tile.i, c.tile.j).min.y < box.max.y)
                return at + " blocked a box whose bottom started below its top (jumping through it)";
        }
    }
    return {};
}

/// A box standing on a floor (a solid or one-way tile's top exactly at its bottom, under its
/// open x span) and moving sideways and down is never stopped on x by a tile of that floor, unless
/// a wall stops it on the same face at the same time: no snag on the seams between floor tiles
/// or platform tiles.
template <class T>
std::string slidingAlongFloorNeverSnags(const Scene<T>& scene, SceneResolver& resolver) {
    const std::vector<FrameResult<T>> frames = framesFrom(resolver, scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!(scene.moves[f].y > 0) || !standsOn(map, scene, starts[f], Support::Floor)) continue;
        const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{starts[f], scene.box.size}));
        if (!sameBits(frames[f].position.y, starts[f].y))
            return "frame " + std::to_string(f) + ": left the floor it stood on, moving down";
        const auto isFloorTile = [&](Cell t) { return map.tileRect(t.i, t.j).min.y == box.max.y; };
        for (const Contact<T>& c : frames[f].contacts) {
            if (c.normal.x == 0 || !isFloorTile(c.tile)) continue;
            // A wall met on the same face line at the same time stops the box there anyway (a
            // floor tile whose top a wall covers shows its side when the cell across is a
            // platform: only a solid cell hides a face).
            const bool againstAWall =
                std::any_of(frames[f].contacts.begin(), frames[f].contacts.end(), [&](const Contact<T>& w) {
                    return w.normal == c.normal && sameBits(w.time, c.time) && !isFloorTile(w.tile);
                });
            if (!againstAWall)
                return "frame " + std::to_string(f) + ": snagged on the side of floor tile " +
                       cellText(c.tile);
        }
    }
    return {};
}

template std::string restingContactIsStable<float>(const Scene<float>&, SceneResolver&);
template std::string restingContactIsStable<double>(const Scene<double>&, SceneResolver&);
template std::string slidingAlongFloorNeverSnags<float>(const Scene<float>&, SceneResolver&);
template std::string slidingAlongFloorNeverSnags<double>(const Scene<double>&, SceneResolver&);
template std::string neverFallsThroughAPlatformItStoodOn<float>(const Scene<float>&, SceneResolver&);
template std::string neverFallsThroughAPlatformItStoodOn<double>(const Scene<double>&, SceneResolver&);
template std::string neverBlockedByAPlatformFromBelow<float>(const Scene<float>&, SceneResolver&);
template std::string neverBlockedByAPlatformFromBelow<double>(const Scene<double>&, SceneResolver&);

// ---- The claims of this file, with their properties (claim.h) ----------------------------------

template <class T>
std::vector<Claim<T>> gameFeelClaims() {
    using S = ClaimScope;
    return {
        {"restingContactIsStable",
         &restingContactIsStable<T>,
         S::Safety,
         nullptr,
         {{"restingContactIsStable", Family::Resting, {{"touch-at-0", 0.3}}}}},
        {"slidingAlongFloorNeverSnags",
         &slidingAlongFloorNeverSnags<T>,
         S::Safety,
         nullptr,
         {{"slidingAlongFloorNeverSnags", Family::SeamLanding, {{"seam", 0.1}, {"touch-at-0", 0.2}}},
          {"neverSnagsOnAPlatformSeam",
           Family::PlatformWalk,
           {{"on-platform", 0.75}, {"one-way-seam", 0.1}}}}},
        {"neverFallsThroughAPlatformItStoodOn",
         &neverFallsThroughAPlatformItStoodOn<T>,
         S::Safety,
         nullptr,
         {{"neverFallsThroughAPlatformItStoodOn", Family::PlatformWalk, {{"on-platform", 0.75}}}}},
        {"neverBlockedByAPlatformFromBelow",
         &neverBlockedByAPlatformFromBelow<T>,
         S::Safety,
         nullptr,
         {{"neverBlockedByAPlatformFromBelow",
           Family::PlatformJump,
           {{"in-one-way", 0.3}, {"one-way-hit", 0.15}}}}},
    };
}

template std::vector<Claim<float>> gameFeelClaims<float>();
template std::vector<Claim<double>> gameFeelClaims<double>();

}  // namespace tilesweep::properties
