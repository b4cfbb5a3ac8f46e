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
// The arithmetic provides start(a) and compareWithStart(exact, a) (the sign of exact - start),
// roundDirected(exact, up) and roundNearest(exact) to the scalar type, isExactly(exact, v), and
// gridLineAhead(exact, rounded, a): whether a grid line lies in [exact + size, rounded + size),
// as LineTest (Undecided sends the frame to the lattice).

#include "fault_injection.h"

#include <cmath>

namespace tilesweep::detail {

/// The answer of a grid-line test that may be filtered.
enum class LineTest { No, Yes, Undecided };

/// The exact final coordinate `exact` on axis `a`, rounded as the contract asks, into `out`;
/// false when the arithmetic could not decide the grid-line test.
template <class Arith, class Coord, class T>
[[nodiscard, gnu::always_inline]] inline bool roundFinal(const Arith& m, const Coord& exact, int a,
                                                         T& out) noexcept {
    const int side = m.compareWithStart(exact, a);
    if (side == 0) {
        out = m.start(a);
        return true;
    }
#if defined(TILESWEEP_FAULT_ROUND_NEAREST)
    const T towardStart = m.roundNearest(exact);  // deliberate fault: to nearest, not toward the start
#else
    const T towardStart = m.roundDirected(exact, side < 0);
#endif
    out = towardStart;
#if !defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)  // the fault keeps the rule before the amendment
    if (side > 0 || m.isExactly(exact, towardStart)) return true;  // not toward -inf, or exact
    switch (m.gridLineAhead(exact, towardStart, a)) {
        case LineTest::No:
            return true;
        case LineTest::Undecided:
            return false;
        case LineTest::Yes:
            break;
    }
    const T down = m.roundDirected(exact, false);
    if (std::isfinite(down)) out = down;
#endif
    return true;
}

}  // namespace tilesweep::detail
