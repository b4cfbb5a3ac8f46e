// SPDX-License-Identifier: MIT
#pragma once

// The contract's rounding of a final coordinate ("Positions", CONTRACT.md), written once for
// every arithmetic of the frame loop (frame_loop.h): toward the start, except on an axis that
// moved toward minus infinity when that would carry the far edge (x + w) over a grid line the
// exact far edge had not passed; then toward minus infinity. Rounding down never carries the
// near edge over a tile edge (edges are representable), and the far edge then stays short of
// every line the exact one had not reached, so the rounded box overlaps no tile the exact one
// does not. When nothing finite lies at or below the exact value, the rounding toward the start
// stands.
//
// Every final coordinate lies between the start and the start plus the displacement (the box moves
// monotonically on each axis), so an end that is not representable lies on the side of the start
// the axis moved to: its direction alone says which way "toward the start" is.
//
// The arithmetic provides start(a), axis(a).dir, compareWithStart(exact, a) (the sign of exact -
// start), isRepresentable(exact), roundToward(exact, down) (exact rounded toward minus infinity
// when `down`, plus infinity otherwise: without a branch on `down`, which is the data's),
// roundNearest(exact) (the value itself when representable; and the deliberate fault
// ROUND_NEAREST), and gridLineAhead(exact, a, needed): whether a grid line
// lies in [exact + size, up + size), up being exact rounded toward plus infinity, as LineTest. Its
// answer is read only when `needed`; it must then be No, Yes or Undecided (which sends the frame
// to the lattice), and otherwise No.

#include "exact_double.h"
#include "fault_injection.h"

#include <cmath>

namespace tilesweep::detail {

/// The answer of a grid-line test that may be filtered.
enum class LineTest { No, Yes, Undecided };

/// The exact final coordinate `exact` on axis `a`, rounded as the contract asks, into `out`;
/// false when the arithmetic could not decide the grid-line test.
///
/// A representable end takes one branch out first: one a game predicts (a box at rest on an axis,
/// or moving by whole pixels, stays so from frame to frame, and ends of arbitrary fractions are
/// nearly all inexact). Any other end is rounded without a branch on the data: the direction of
/// the move and where the grid lines are are the data's, and a branch on either would mispredict
/// at random on a game's frames. The grid-line test is asked on every such axis (cheap, with its
/// exact part behind a rare branch inside the arithmetic).
template <class Arith, class Coord, class T>
[[nodiscard, gnu::always_inline]] inline bool roundFinal(const Arith& m, const Coord& exact, int a,
                                                         T& out) noexcept {
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
    out = m.roundNearest(exact);  // deliberate fault: to nearest, not toward the start
    static_cast<void>(a);
    return true;
#else
    // A representable end is its own rounding (at the start, the start itself, its sign of zero too).
    if (m.isRepresentable(exact)) {
        out = m.compareWithStart(exact, a) == 0 ? m.start(a) : m.roundNearest(exact);
        return true;
    }
    // Not representable, so not the start: it lies on the side the axis moved to.
    const int dir = m.axis(a).dir;
#if defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)
    const bool down = dir > 0;  // the fault keeps the rule before the amendment
#else
    // Toward the start: down when the axis moved up, up when it moved down; the amended rule
    // applies on an axis that moved toward minus infinity.
    const bool ruleApplies = dir < 0;
    const LineTest line = m.gridLineAhead(exact, a, ruleApplies);
    if (line == LineTest::Undecided) return false;
    const bool down = (dir > 0) | (ruleApplies & (line == LineTest::Yes));
#endif
    T rounded = m.roundToward(exact, down);
    // Nothing finite at or below the exact value: the rounding toward the start (up) stands.
    if (!std::isfinite(rounded)) rounded = m.roundToward(exact, false);
    out = rounded;
    return true;
#endif
}

}  // namespace tilesweep::detail
