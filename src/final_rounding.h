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
// The arithmetic provides start(a), compareWithStart(exact, a) (the sign of exact - start),
// neighborOf(exact) (a Neighbor: a value next to the exact one) and, for a deliberate fault,
// roundNearest(exact), and gridLineAhead(exact, a, needed): whether a grid line lies in
// [exact + size, up + size), up being exact rounded toward plus infinity, as LineTest. Its
// answer is read only when `needed`; it must then be No, Yes or Undecided (which sends the frame
// to the lattice), and otherwise No.

#include "exact_double.h"
#include "fault_injection.h"

#include <cmath>

namespace tilesweep::detail {

/// The answer of a grid-line test that may be filtered.
enum class LineTest { No, Yes, Undecided };

/// A representable value next to an exact one: `value` is the exact value itself (side 0), or
/// one of the two values on either side of it (side +1 when above it, -1 when below), so that
/// the other one is stepFromNonzero(value, -side) (exact_double.h): then it is never zero.
template <class T>
struct Neighbor {
    T value;
    int side;
};

/// The exact final coordinate `exact` on axis `a`, rounded as the contract asks, into `out`;
/// false when the arithmetic could not decide the grid-line test.
///
/// An inexact end is rounded without a branch on the data: the side of the start, the side of
/// the exact value its neighbor lies on and where the grid lines are are the data's, and a branch
/// on each would mispredict at random on a game's frames. The grid-line test is asked on every
/// such axis (cheap, with its exact part behind a rare branch inside the arithmetic); the
/// rounding is then the neighbor moved by at most one step. A representable end takes one
/// branch out first: that one a game predicts.
template <class Arith, class Coord, class T>
[[nodiscard, gnu::always_inline]] inline bool roundFinal(const Arith& m, const Coord& exact, int a,
                                                         T& out) noexcept {
    const int side = m.compareWithStart(exact, a);
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
    const Neighbor<T> near{m.roundNearest(exact), 0};  // deliberate fault: to nearest, not toward the start
#else
    const Neighbor<T> near = m.neighborOf(exact);
#endif
    // A representable end is its own rounding (at the start, the start itself, its sign of zero
    // too). A branch, but one a game predicts: a box at rest on an axis, or moving by whole
    // pixels, stays so from frame to frame, and ends of arbitrary fractions are nearly all inexact.
    if (near.side == 0) {
        out = side == 0 ? m.start(a) : near.value;
        return true;
    }
    const int above = static_cast<int>(near.side > 0);  // down is then one step below it
    const int below = static_cast<int>(near.side < 0);  // up is then one step above it
#if defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)
    const int useDown = static_cast<int>(side > 0);  // the fault keeps the rule before the amendment
#else
    // Toward the start: down when the end lies above it, up when below; the amended rule applies
    // on an axis that moved toward minus infinity (the end, here, is not representable).
    const bool ruleApplies = side < 0;
    const LineTest line = m.gridLineAhead(exact, a, ruleApplies);
    if (line == LineTest::Undecided) return false;
    const int useDown = static_cast<int>(side > 0) |
                        (static_cast<int>(ruleApplies) & static_cast<int>(line == LineTest::Yes));
#endif
    const int steps = (-useDown & -above) | ((useDown - 1) & below);
    T rounded = stepFromNonzero(near.value, steps);  // nonzero: the end is not representable
    // Nothing finite at or below the exact value: the rounding toward the start (up) stands.
    if (!std::isfinite(rounded)) rounded = stepFromNonzero(near.value, below);
    out = rounded;
    return true;
}

}  // namespace tilesweep::detail
