// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/rational.h"

#include <cstdint>

// One box against one tile, in exact arithmetic, straight from docs/contract.md ("One box against
// one tile"). The box moves by d: at time t it is at pos + t*d. On each axis the times at which
// the projections overlap (strictly: touching is not overlapping) form
//
//   - the open interval (entry, exit) when d_a != 0,
//   - every time, (-inf, +inf), when d_a == 0 and the projections overlap,
//   - no time when d_a == 0 and they do not.
//
// I is the intersection of the two axes' sets. The tile blocks when 0 is not in I and I meets
// (0, 1); its time of impact is inf I, in [0, 1). An empty I is a corner miss, including a path
// through a corner point exactly (entry == exit on the meeting axes). A box overlapping the tile
// at t = 0 never blocks.
//
// A one-way tile ("One-way tiles") has the same rectangle and the same I, but blocks only a move
// down (d_y > 0) whose box bottom starts at or above the tile's top (pos_y + size_y <= top), and
// then only when I meets (0, 1) and entry_y >= entry_x: the box reaches the top face while it
// overlaps the tile on x, or exactly as it starts to. Its time is entry_y (which is then inf I),
// its axis y; an exact corner hit blocks on y, since the top is its only face.

namespace tilesweep::oracle {

/// A time on the extended line: -inf, a finite rational, or +inf.
struct ExtendedTime {
    enum class Kind : std::uint8_t { NegativeInfinity, Finite, PositiveInfinity };
    Kind kind = Kind::Finite;
    Rational value;  ///< meaningful only when kind is Finite

    [[nodiscard]] static ExtendedTime negativeInfinity() { return {Kind::NegativeInfinity, Rational(0)}; }
    [[nodiscard]] static ExtendedTime positiveInfinity() { return {Kind::PositiveInfinity, Rational(0)}; }
    [[nodiscard]] static ExtendedTime finite(Rational t) { return {Kind::Finite, std::move(t)}; }
    [[nodiscard]] bool isFinite() const { return kind == Kind::Finite; }
};

/// a < b on the extended line.
[[nodiscard]] bool operator<(const ExtendedTime& a, const ExtendedTime& b);
/// a == b on the extended line (two infinities of the same sign are equal).
[[nodiscard]] bool operator==(const ExtendedTime& a, const ExtendedTime& b);
/// a < t for a finite time t.
[[nodiscard]] bool operator<(const ExtendedTime& a, const Rational& t);
/// t < a for a finite time t.
[[nodiscard]] bool operator<(const Rational& t, const ExtendedTime& a);

/// A set of times: empty, or the open interval (low, high) with low < high.
struct TimeInterval {
    bool empty = true;
    ExtendedTime low;   ///< the infimum (the entry), when not empty
    ExtendedTime high;  ///< the supremum (the exit), when not empty

    [[nodiscard]] static TimeInterval none() { return {}; }
    [[nodiscard]] static TimeInterval all() {
        return {false, ExtendedTime::negativeInfinity(), ExtendedTime::positiveInfinity()};
    }
    /// The open interval (low, high); empty when low >= high.
    [[nodiscard]] static TimeInterval open(ExtendedTime low, ExtendedTime high);

    /// True when t lies strictly inside.
    [[nodiscard]] bool contains(const Rational& t) const;
    /// True when the interval and the open unit interval (0, 1) share a time.
    [[nodiscard]] bool meetsOpenUnitInterval() const;
};

/// The intersection of two sets of times.
[[nodiscard]] TimeInterval intersect(const TimeInterval& a, const TimeInterval& b);

/// The times at which the projection [boxMin, boxMin + boxSize] moving by d overlaps
/// [tileMin, tileMax] on one axis, strictly.
[[nodiscard]] TimeInterval axisOverlapTimes(const Rational& boxMin, const Rational& boxSize,
                                            const Rational& d, const Rational& tileMin,
                                            const Rational& tileMax);

/// What a box does against one tile over one move.
enum class ExactSweepState : std::uint8_t {
    Misses,             ///< I does not meet (0, 1): no contact (corner misses included)
    Blocks,             ///< first contact at `time`, on `axis`
    StartsOverlapping,  ///< 0 is in I: the box overlaps the tile at t = 0; it never blocks
};

/// A box moving by `displacement` against one tile.
struct ExactSweepInput {
    ExactBox box;
    ExactVec2 displacement;
    ExactRect tile;
    bool xFaceExposed = true;  ///< the cell across the tile face the motion on x approaches is empty
    bool yFaceExposed = true;  ///< likewise on y; these two settle an exact corner tie
};

/// The decision for one tile, with the intervals it came from.
struct ExactSweepOutput {
    ExactSweepState state = ExactSweepState::Misses;
    TimeInterval xTimes;   ///< the times the x projections overlap
    TimeInterval yTimes;   ///< the times the y projections overlap
    TimeInterval overlap;  ///< I = xTimes intersected with yTimes
    Rational time;         ///< inf I, in [0, 1), when Blocks
    Axis axis = Axis::Y;   ///< the contact axis, when Blocks
    bool tie = false;      ///< both axes enter at `time` exactly (an exact corner hit), when Blocks
};

/// Decides one tile. The contact axis is the one whose entry is later; on an exact tie, the axis
/// whose face is exposed when exactly one is, otherwise y.
[[nodiscard]] ExactSweepOutput sweepTileExact(const ExactSweepInput& input);

/// Decides one one-way tile: Blocks (on y, at entry_y; `tie` when entry_x == entry_y) or Misses,
/// never StartsOverlapping: a box that could be blocked starts with its bottom at or above the
/// top, so it does not overlap the tile at t = 0, and one it overlaps at t = 0 never blocks. The
/// exposure flags of the input play no part.
[[nodiscard]] ExactSweepOutput sweepOneWayTileExact(const ExactSweepInput& input);

}  // namespace tilesweep::oracle
