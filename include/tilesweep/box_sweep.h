// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"

#include <cstdint>

// One box swept against one tile, with the exact rules of docs/contract.md: per-axis open
// time intervals, their intersection I, blocking when the box does not overlap the tile at
// t = 0 and I meets (0, 1), time of impact inf I. Touching is not overlapping, so a path through
// a corner point exactly does not block, and neither does one whose swept bounds overlap the
// tile while the path misses it.

namespace tilesweep {

/// What a box does against one tile over one move.
enum class BoxSweepStatus : std::uint8_t {
    Misses,             ///< I does not meet (0, 1): no contact
    Blocks,             ///< first contact at `time`, on `axis`
    StartsOverlapping,  ///< the box overlaps the tile at t = 0; it never blocks
    InvalidInput,       ///< a value is not finite, or a size is not > 0
};

/// A box moving by `displacement` against the closed rectangle [tileMin, tileMax].
template <class T>
struct BoxSweepInput {
    Box<T> box;
    Vec2<T> displacement;
    Vec2<T> tileMin;
    Vec2<T> tileMax;
    bool xFaceExposed = true;  ///< the cell across the tile face the box approaches on x is empty
    bool yFaceExposed = true;  ///< likewise on y; both settle an exact corner tie
};

/// The result of one sweep.
template <class T>
struct BoxSweepResult {
    BoxSweepStatus status = BoxSweepStatus::InvalidInput;  ///< (named `state` before the one scheme)
    Axis axis = Axis::Y;  ///< contact axis, when Blocks: the later entry; on an exact tie the
                          ///< exposed face if exactly one is, otherwise y
    T time = 0;           ///< time of impact, when Blocks: the exact one, in [0, 1), rounded to
                          ///< nearest (so 1 for a hit within half an ulp of the end)
};

/// Sweeps one box against one tile. Exact decisions; never NaN in the output.
template <class T>
[[nodiscard]] BoxSweepResult<T> sweepBox(const BoxSweepInput<T>& input) noexcept;

// The names before the one scheme of resolve.h, kept for one release. The result's field `state`
// is now `status`: a field cannot be aliased, so code that reads it changes with the rename.
using BoxSweepState [[deprecated("use tilesweep::BoxSweepStatus")]] = BoxSweepStatus;
template <class T>
using BoxSweepOutput [[deprecated("use tilesweep::BoxSweepResult")]] = BoxSweepResult<T>;

extern template BoxSweepResult<float> sweepBox<float>(const BoxSweepInput<float>&) noexcept;
extern template BoxSweepResult<double> sweepBox<double>(const BoxSweepInput<double>&) noexcept;

}  // namespace tilesweep
