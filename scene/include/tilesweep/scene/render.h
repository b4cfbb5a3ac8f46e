// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/scene/scene.h"

#include <string>
#include <vector>

// A picture of a scene and its resolved frames, so that a person can look at a counterexample
// instead of reading numbers. Part of the `tilesweep_scene` target (scene/), like scene.h.
//
// The picture is one self-contained SVG document (no scripts, fonts, images or other external
// resources; valid XML, starting with `<svg`). Its y axis grows downward, as the contract's does,
// and one SVG unit is one pixel: every coordinate is translated to the map origin in long double
// and scaled so that the map and the whole motion fit the drawing, so a far origin (1e6, 2^40)
// renders as well as (0, 0). It shows:
//
//   - the map: solid tiles filled (`class="tile-solid"`, one rect per solid tile), one-way tiles
//     in green as a slab along their top face (`class="tile-one-way"`, one rect per one-way tile)
//     over a dashed outline of the cell (`class="one-way-outline"`), empty cells as a light grid,
//     column and row indices along the top and left edges;
//   - the box at the start (outline) and at the end of every frame (filled, semi-transparent, the
//     last frame's end emphasised; past 8 frames the ends in between are small dots, and only the
//     first and last ends are drawn as boxes); every frame end carries `class="frame-end ..."`;
//   - the path of the box's centre in each frame (`class="path"`): start, the position at each
//     contact, end; the requested motion (start + move) as a dashed line;
//   - the contacts: hit tiles outlined (`class="hit-tile"`), each normal as a short arrow leaving
//     the face that was hit (`class="normal-arrow"`), the box where it touched as a dashed outline;
//   - the cells listed in started_overlapping, hatched (`class="overlap-tile"`);
//   - the scene's name as title, a caption with scalar type, tile size, origin and map size, a
//     legend (with a one-way tile when the map has one), and a short per-frame listing (numbers
//     in %.6g-like form).
//
// Usage, with the production resolver:
//
//     tilesweep::SceneParse<float> parsed = tilesweep::parseScene<float>(line);
//     if (parsed.scene) {
//         std::string svg = tilesweep::renderSceneSvg(*parsed.scene, tilesweep::runScene(*parsed.scene));
//         // write svg to a file, or open it in a browser
//     }

namespace tilesweep {

/// Draws `scene` and its `frames` (frame k starts where frame k-1 ended, as runScene produces
/// them) as an SVG document. Frames from another resolver are drawn as given, including contacts
/// on cells outside the map; a non-finite position is listed but not drawn. Throws
/// std::invalid_argument when `frames` does not hold one frame per move, or when the map's
/// `solid` does not hold columns*rows cells, or its `oneWay` is neither empty nor as long.
template <class T>
[[nodiscard]] std::string renderSceneSvg(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames);

}  // namespace tilesweep
