// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"
#include "tilesweep/scene/scene.h"

#include <vector>

// The seed article's algorithm as written (shared/seed/swept-aabb-tile-collision.txt), in T,
// kept only as a measured baseline: what a straightforward implementation gets wrong. Usable as
// `--resolver seed`. NOT a reference: do not hold anything to it.
//
// One frame: previousRect is the box at the frame's start, currentRect starts at start + d. The
// solid tiles that strictly overlap the swept bounds (the union of the two rectangles, computed
// once, in T) are tested in row-major order, each test taking the current, already responded,
// currentRect. Per tile, exactly as the article says, in T:
//
//     velocity  = currentRect.xy - previousRect.xy
//     distanceX = velocity.x > 0 ? tile.left - prev.right : tile.right - prev.left   (same for y)
//     disjointX = velocity.x > 0 ? tile.right - prev.left : tile.left - prev.right   (same for y)
//     timeX = distanceX / velocity.x;  timeY = distanceY / velocity.y
//     time = max(timeX, timeY);  disjoint = min(disjointX, disjointY)
//     collided = !(time > disjoint)
//     if ((timeX < 0 && timeY < 0) || timeX > 1 || timeY > 1) collided = false
//     if (collided) position -= (1 - time) * velocity
//
// Its flaws are reproduced, not fixed:
//   - the disjoint "times" are distances, not times, so the test compares a fraction with a
//     length: moving left or up, the disjoint distance is negative and no tile is ever hit
//     (the box passes through walls);
//   - a zero velocity component divides by zero: time = +-inf, or NaN for 0/0. The velocity is
//     a difference, so a zero component is +0: the else branch then gives a positive distance for
//     any tile the box overlaps on that axis, timeX = +inf > 1, and the tile is never hit (a box
//     falling straight down falls through the floor);
//   - the response moves the box back along the whole velocity: no sliding;
//   - max/min follow std::max/std::min, so a NaN time can be picked, and then the position
//     becomes NaN. NaN (or infinite) positions are a possible output; they never crash it: tiles
//     are found by comparing coordinates, never by indexing with them, and every later frame of
//     such a box just moves on in NaN.
//
// Reported per frame: the final position; one contact per collided tile, in test order, with
// time = that test's `time` (a fraction of that test's velocity, which after an earlier response
// is shorter than the frame's displacement) and a normal against the velocity on the axis that
// max() picked (timeX unless timeX < timeY), which is (0, 0) when that velocity component is 0;
// no start overlaps (the article has no such notion, so the list is always empty).
//
// `epsilon` (default 0: the article exactly) is a tolerance, in fractions of the move, added to
// the time comparisons the way a game would patch them: collided = !(time > disjoint + epsilon),
// and a tile is rejected when (timeX < -epsilon && timeY < -epsilon) || timeX > 1 + epsilon ||
// timeY > 1 + epsilon. A positive epsilon accepts near misses, a negative one rejects near hits.
// The audit (audit/) searches it to show which of the flaws a tolerance can and cannot fix. With
// epsilon = 0 every comparison gives what the article's does (x + 0 compares like x).

namespace tilesweep::oracle {

/// One frame of the seed algorithm: `box` moving by `displacement` through `map`, in T.
template <class T>
[[nodiscard]] FrameResult<T> resolveFrameSeed(const TileMap<T>& map, const Box<T>& box, Vec2<T> displacement,
                                              T epsilon = T(0));

/// Every frame of a scene through the seed algorithm, each frame starting where the last ended.
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> resolveSceneSeed(const Scene<T>& scene, T epsilon = T(0));

extern template FrameResult<float> resolveFrameSeed<float>(const TileMap<float>&, const Box<float>&,
                                                           Vec2<float>, float);
extern template FrameResult<double> resolveFrameSeed<double>(const TileMap<double>&, const Box<double>&,
                                                             Vec2<double>, double);
extern template std::vector<FrameResult<float>> resolveSceneSeed<float>(const Scene<float>&, float);
extern template std::vector<FrameResult<double>> resolveSceneSeed<double>(const Scene<double>&, double);

}  // namespace tilesweep::oracle
