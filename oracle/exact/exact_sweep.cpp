// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/exact/exact_sweep.h"

#include <utility>

namespace tilesweep::oracle {

bool operator<(const ExtendedTime& a, const ExtendedTime& b) {
    using Kind = ExtendedTime::Kind;
    if (a.kind != b.kind) {
        return static_cast<int>(a.kind) < static_cast<int>(b.kind);
    }
    return a.kind == Kind::Finite && a.value < b.value;
}

bool operator==(const ExtendedTime& a, const ExtendedTime& b) {
    return a.kind == b.kind && (a.kind != ExtendedTime::Kind::Finite || a.value == b.value);
}

bool operator<(const ExtendedTime& a, const Rational& t) {
    return a.kind == ExtendedTime::Kind::NegativeInfinity ||
           (a.kind == ExtendedTime::Kind::Finite && a.value < t);
}

bool operator<(const Rational& t, const ExtendedTime& a) {
    return a.kind == ExtendedTime::Kind::PositiveInfinity ||
           (a.kind == ExtendedTime::Kind::Finite && t < a.value);
}

namespace {

// Shared constants: a Rational costs an allocation to make, and these are compared with often.
// Read-only after their (thread-safe) initialisation.
const Rational& zero() {
    static const Rational value(0);
    return value;
}

const Rational& one() {
    static const Rational value(1);
    return value;
}

}  // namespace

TimeInterval TimeInterval::open(ExtendedTime low, ExtendedTime high) {
    if (!(low < high)) {
        return none();
    }
    return {false, std::move(low), std::move(high)};
}

bool TimeInterval::contains(const Rational& t) const { return !empty && low < t && t < high; }

bool TimeInterval::meetsOpenUnitInterval() const {
    // (low, high) and (0, 1) share a time exactly when max(low, 0) < min(high, 1); as
    // low < high already, that is low < 1 and 0 < high.
    return !empty && low < one() && zero() < high;
}

TimeInterval intersect(const TimeInterval& a, const TimeInterval& b) {
    if (a.empty || b.empty) {
        return TimeInterval::none();
    }
    return TimeInterval::open(a.low < b.low ? b.low : a.low, a.high < b.high ? a.high : b.high);
}

TimeInterval axisOverlapTimes(const Rational& boxMin, const Rational& boxSize, const Rational& d,
                              const Rational& tileMin, const Rational& tileMax) {
    const Rational boxMax = boxMin + boxSize;
    if (d == 0) {
        // Not moving: overlapping at every time or at none.
        const bool overlapping = boxMin < tileMax && boxMax > tileMin;
        return overlapping ? TimeInterval::all() : TimeInterval::none();
    }
    // At time t the projection is [boxMin + t*d, boxMax + t*d]; it overlaps the tile when
    // boxMin + t*d < tileMax and boxMax + t*d > tileMin. Dividing by d (reversing both
    // inequalities when d < 0) gives the open interval between the two roots below.
    const Rational leadingEdgeMeets = (tileMin - boxMax) / d;   // box's max edge reaches the tile's min edge
    const Rational trailingEdgeMeets = (tileMax - boxMin) / d;  // box's min edge reaches the tile's max edge
    if (d > 0) {
        return TimeInterval::open(ExtendedTime::finite(leadingEdgeMeets),
                                  ExtendedTime::finite(trailingEdgeMeets));
    }
    return TimeInterval::open(ExtendedTime::finite(trailingEdgeMeets),
                              ExtendedTime::finite(leadingEdgeMeets));
}

ExactSweepOutput sweepTileExact(const ExactSweepInput& input) {
    ExactSweepOutput out;
    out.xTimes = axisOverlapTimes(input.box.pos.x, input.box.size.x, input.displacement.x, input.tile.min.x,
                                  input.tile.max.x);
    out.yTimes = axisOverlapTimes(input.box.pos.y, input.box.size.y, input.displacement.y, input.tile.min.y,
                                  input.tile.max.y);
    out.overlap = intersect(out.xTimes, out.yTimes);

    if (out.overlap.contains(zero())) {
        out.state = ExactSweepState::StartsOverlapping;
        return out;
    }
    if (!out.overlap.meetsOpenUnitInterval()) {
        out.state = ExactSweepState::Misses;
        return out;
    }
#if defined(TILESWEEP_FAULT_ORACLE_SKIPS_TOUCH_AT_0)
    // Deliberate fault in the reference, not the resolver: a tile touched at t = 0 never blocks.
    if (out.overlap.low.isFinite() && out.overlap.low.value == 0) {
        out.state = ExactSweepState::Misses;
        return out;
    }
#endif
    // I is an open interval that meets (0, 1) but does not contain 0, so inf I is finite and in
    // [0, 1): at least one axis moves, and the later entry is that of a moving axis.
    out.state = ExactSweepState::Blocks;
    out.time = out.overlap.low.value;

    const ExtendedTime& entryX = out.xTimes.low;
    const ExtendedTime& entryY = out.yTimes.low;
    if (entryY < entryX) {
        out.axis = Axis::X;
    } else if (entryX < entryY) {
        out.axis = Axis::Y;
    } else {
        // Both axes enter at the same finite time: an exact corner hit.
        out.tie = true;
        out.axis = (input.xFaceExposed && !input.yFaceExposed) ? Axis::X : Axis::Y;
    }
    return out;
}

ExactSweepOutput sweepOneWayTileExact(const ExactSweepInput& input) {
    ExactSweepOutput out;
    out.xTimes = axisOverlapTimes(input.box.pos.x, input.box.size.x, input.displacement.x, input.tile.min.x,
                                  input.tile.max.x);
    out.yTimes = axisOverlapTimes(input.box.pos.y, input.box.size.y, input.displacement.y, input.tile.min.y,
                                  input.tile.max.y);
    out.overlap = intersect(out.xTimes, out.yTimes);
    out.state = ExactSweepState::Misses;

    // Only a move down, from a bottom edge at or above the top edge. Then y moves, so yTimes is
    // empty or an open interval whose entry (top - bottom) / d_y is finite and >= 0: the box does
    // not overlap the tile at t = 0.
    const bool movesDown = input.displacement.y > 0;
    if (!movesDown || input.box.pos.y + input.box.size.y > input.tile.min.y) {
        return out;
    }
    if (!out.overlap.meetsOpenUnitInterval()) {
        return out;  // a corner miss, or no contact within the move
    }
    const ExtendedTime& entryX = out.xTimes.low;
    const ExtendedTime& entryY = out.yTimes.low;
    if (entryY < entryX) {
        return out;  // it enters through a side: it passes
    }
    // entry_y >= entry_x, so inf I = entry_y, which lies in [0, 1) because I meets (0, 1).
    out.state = ExactSweepState::Blocks;
    out.time = entryY.value;
    out.axis = Axis::Y;
    out.tie = entryX == entryY;
    return out;
}

}  // namespace tilesweep::oracle
