// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/rational.h"
#include "tilesweep/resolve.h"
#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <vector>

// The fine-substep oracle: the "per-pixel" method of the seed article, done exactly. The box is
// placed at the exact positions pos + (k/N)*d, k = 1..N, and each is tested for plain (strict)
// overlap against every solid tile that could be reached (those meeting the swept bounds),
// leaving out the tiles it already overlaps at t = 0. It shares no formula with the sweep: it
// knows nothing of entry times, intervals or contact axes.
//
// A one-way tile ('-') is tested only on a move down (d_y > 0) whose box bottom starts at or above
// the tile's top. It stops the box at substep k when the box overlaps it there and, at substep
// k - 1, overlapped it on x with its bottom at or above the top: the box came down onto the top
// face while over the platform. A box that was beside the platform at k - 1 and inside it at k
// passes (the samples cannot tell a landing on the end of the top from an entry through the side).
// A one-way tile is never a start overlap.
//
// What it guarantees, against the exact reference's first step (the straight move from the start):
//   - No false hit: when it reports substep k, some tile blocks, and the earliest time of impact
//     s satisfies s < k/N.
//   - The bracket: when the earliest-hit tile's overlap window (s, min(exit, 1)) is longer than
//     1/N, then (k-1)/N <= s < k/N. (The contract's I is open, so an impact at exactly (k-1)/N
//     is first seen overlapping at k/N; the bracket is ((k-1)/N, k/N] for the first *overlapping*
//     moment.) For a one-way tile the box must also have been over it on x at the sample before
//     s: entry_x < 0, or s - entry_x >= 1/N.
//   - Nothing more: a window no longer than 1/N can fall between two substeps (a clipped corner),
//     and then the first report is late or missing. A landing on a platform's end within 1/N of
//     reaching it on x is missed likewise (an exact corner landing always is).

namespace tilesweep::oracle {

/// The first substep at which the moving box overlaps a solid tile or lands on a one-way one.
struct SubstepOverlap {
    std::int64_t substeps = 0;        ///< N, the number of equal substeps
    std::int64_t firstOverlap = 0;    ///< k in [1, N] of the first overlapping substep; 0 when none
    std::vector<Cell> tiles;          ///< tiles that stop the box at substep k, by row then column
    std::vector<Cell> startOverlaps;  ///< solid tiles overlapped at t = 0 (never tested), by row then column

    /// True when some substep overlapped.
    [[nodiscard]] bool found() const { return firstOverlap > 0; }
    /// (k-1)/N, the start of the bracket.
    [[nodiscard]] Rational bracketLow() const { return Rational(firstOverlap - 1) / Rational(substeps); }
    /// k/N, the first substep time seen overlapping.
    [[nodiscard]] Rational bracketHigh() const { return Rational(firstOverlap) / Rational(substeps); }
};

/// Moves `box` by `displacement` in `substeps` equal exact substeps and reports the first that
/// overlaps a solid tile not overlapped at t = 0, or lands on a one-way tile (see the header
/// note). Throws std::invalid_argument when substeps < 1. Pass `map.withoutOneWay()` to drop
/// through every platform.
[[nodiscard]] SubstepOverlap findFirstOverlapExact(const ExactTileMap& map, const ExactBox& box,
                                                   const ExactVec2& displacement, std::int64_t substeps);

/// One frame of a substep "resolver", with the substep facts behind it.
template <class T>
struct SubstepFrame {
    /// position: the last substep before the first overlap (all N substeps when none overlaps),
    /// contacts: the tiles that stop the box at the first stopping substep k, each with time k/N and
    /// a guessed normal (see resolveSceneSubstep), startOverlaps: tiles overlapped at t = 0.
    FrameResult<T> frame;
    std::int64_t substeps = 0;      ///< N
    std::int64_t firstOverlap = 0;  ///< k, or 0 when no substep overlapped
};

/// A whole-frame resolver built on findFirstOverlapExact, usable as `--resolver substep:N`. It
/// does not slide: the box stops at substep k-1 on both axes. The position is the exact one of
/// substep k-1 rounded toward the frame's start per axis (as the contract rounds); contact times
/// are k/N rounded to nearest. The normal of a contact is guessed: the axis on which the box was
/// still separated from that tile at substep k-1 when exactly one was, otherwise the dominant
/// axis of the motion (|dx| > |dy| gives x, else y), pointing against the motion on that axis.
/// A one-way tile's is always (0, -1): at k-1 the box was over it on x and above its top.
/// Frame k+1 starts from frame k's rounded position.
template <class T>
[[nodiscard]] std::vector<SubstepFrame<T>> resolveSceneSubstep(const Scene<T>& scene, std::int64_t substeps);

/// The FrameResults of substep frames, dropping the substep facts.
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> frameResults(const std::vector<SubstepFrame<T>>& frames) {
    std::vector<FrameResult<T>> results;
    results.reserve(frames.size());
    for (const SubstepFrame<T>& f : frames) {
        results.push_back(f.frame);
    }
    return results;
}

extern template std::vector<SubstepFrame<float>> resolveSceneSubstep<float>(const Scene<float>&,
                                                                            std::int64_t);
extern template std::vector<SubstepFrame<double>> resolveSceneSubstep<double>(const Scene<double>&,
                                                                              std::int64_t);

}  // namespace tilesweep::oracle
