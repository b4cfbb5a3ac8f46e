// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/exact_sweep.h"
#include "tilesweep/oracle/exact/rational.h"
#include "tilesweep/resolve.h"
#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <vector>

// The exact reference: one frame through a map, and whole scenes, exactly as docs/contract.md
// defines them ("One frame through a map"), in rational arithmetic. It tests every solid and
// one-way tile of the map (no broadphase), so it cannot skip a tile a broadphase would wrongly
// leave out. A one-way tile blocks by its own rule (sweepOneWayTileExact) and then joins B like a
// solid one.
//
//     p = start, r = d
//     at most 2 steps:
//         B = tiles blocking the move from p by r;  none: p += r, stop
//         s = min time of impact in B;  H = tiles of B hit at s;  A = their contact axes
//         p += s*r;  record H (normal against r, frame time);  r = (1 - s)*r with A zeroed
//
// Usage:
//
//     auto parsed = tilesweep::parseScene<float>(line);
//     auto exact = tilesweep::oracle::resolveSceneExact(*parsed.scene);   // rationals
//     auto rounded = tilesweep::oracle::toFrameResults<float>(exact);     // what a float resolver returns

namespace tilesweep::oracle {

/// One tile hit during a frame, exactly.
struct ExactContact {
    Cell tile;              ///< the cell that was hit
    Normal normal;          ///< (-sign(r_x), 0) or (0, -sign(r_y)), r being the step's motion
    Rational time;          ///< fraction of the whole frame elapsed at the hit, in [0, 1)
    std::int32_t step = 1;  ///< 1 or 2: the step of the frame loop that recorded it
    bool tie = false;       ///< the two axes entered at the same time (the tie rule chose the axis)
    ExactVec2 position;     ///< the box's position at the hit, exactly
    bool movesOnX = false;  ///< the box still moves on x after the hit (a slide along it)
    bool movesOnY = false;  ///< likewise on y
};

/// One frame, exactly.
struct ExactFrame {
    ExactVec2 start;                     ///< the position the frame started from (a T value, exactly)
    bool startXIsNegativeZero = false;   ///< the start's x was -0 (a rational has no sign of zero)
    bool startYIsNegativeZero = false;   ///< likewise y; a position equal to the start keeps its bits
    ExactVec2 size;                      ///< the box's size, for the rounding rule's far edge
    ExactVec2 gridOrigin;                ///< the map's origin and tile size: the grid lines of
    ExactVec2 tileSize;                  ///< the rounding rule, on and off the map
    ExactVec2 position;                  ///< the exact final position
    std::vector<ExactContact> contacts;  ///< step by step; within a step by row, then column
    std::vector<Cell> startOverlaps;     ///< solid cells overlapped at the start, by row then column
};

/// Resolves one frame of `box` moving by `displacement` through `map`, exactly. A frame that drops
/// through every platform is resolved on `map.withoutOneWay()`.
[[nodiscard]] ExactFrame resolveFrameExact(const ExactTileMap& map, const ExactBox& box,
                                           const ExactVec2& displacement);

/// Resolves every frame of a scene exactly. Frame k > 0 starts at the position frame k - 1
/// returned under the contract's rounding (roundFrame: what a T resolver hands to the next frame).
template <class T>
[[nodiscard]] std::vector<ExactFrame> resolveSceneExact(const Scene<T>& scene);

/// One exact frame under the contract's rounding: the position rounded per axis toward the
/// frame's start (the representable value nearest the exact one between start and it), or
/// toward minus infinity where that would carry the box's far edge over a grid line the exact
/// far edge had not passed (roundFinalCoordinate); frame times rounded to nearest, ties to even.
/// A contact's position (Contact::position, resolve.h): on an axis the box still moves on after
/// the hit, its exact coordinate at the hit rounded to nearest, ties to even (the start itself
/// when that is the start); on any other axis the box does not move again in the frame, and it
/// is the frame's rounded position there. Decisions (tiles, normals, order) are unchanged.
template <class T>
[[nodiscard]] FrameResult<T> roundFrame(const ExactFrame& frame);

/// Every frame of an exact result under the contract's rounding; see roundFrame.
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> toFrameResults(const std::vector<ExactFrame>& frames);

/// resolveSceneExact followed by toFrameResults: what a T resolver must return, bit for bit.
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> resolveSceneExactRounded(const Scene<T>& scene);

extern template std::vector<ExactFrame> resolveSceneExact<float>(const Scene<float>&);
extern template std::vector<ExactFrame> resolveSceneExact<double>(const Scene<double>&);
extern template FrameResult<float> roundFrame<float>(const ExactFrame&);
extern template FrameResult<double> roundFrame<double>(const ExactFrame&);
extern template std::vector<FrameResult<float>> toFrameResults<float>(const std::vector<ExactFrame>&);
extern template std::vector<FrameResult<double>> toFrameResults<double>(const std::vector<ExactFrame>&);
extern template std::vector<FrameResult<float>> resolveSceneExactRounded<float>(const Scene<float>&);
extern template std::vector<FrameResult<double>> resolveSceneExactRounded<double>(const Scene<double>&);

}  // namespace tilesweep::oracle
