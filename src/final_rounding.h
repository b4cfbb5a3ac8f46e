// SPDX-License-Identifier: MIT
#pragma once

// The contract's rounding of a final coordinate ("Positions", docs/contract.md), written once for
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
#include <cstdint>

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
#include <emmintrin.h>
#define TILESWEEP_FINAL_ROUNDING_SSE2 1
#endif

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

/// roundFinal for both ends of a float frame at once, on two lanes: `endX` and `endY` exact
/// doubles; `linesClear()` gives, in bit a, whether no grid line can fall where the amended rule
/// would look on axis a (FastFrame::linesClearBits), and is asked only when an end is inexact.
/// Each end is rounded toward its start, or is the start itself when equal to it (its sign of
/// zero too), as roundFinal does without the amendment. False, writing nothing, when an inexact
/// end lies below its start on an axis whose lines are not clear (the amendment may apply):
/// roundFinal then runs on each axis. One branch besides, which a game predicts: whether both
/// ends are representable (moves by whole pixels, or none); which ends round up and which down
/// is the data's, and takes none.
///
/// Why it holds. Ends lie between the start and the start plus the displacement, so an inexact
/// end is not its start, and "toward the start" is down for an end above it and up for one below
/// (roundFinal reads the same from the direction of the move). The nearest float, converted
/// back, says on which side of the end it lies; when that is away from the start, one step of
/// its bits toward the start is the directed rounding (a float's bits grow with its magnitude,
/// and the step from an infinity is the largest float). The result is finite: it lies between
/// the end and a finite start (roundFinal's fallback for an infinite result serves the amended
/// rule, which rounds away from the start, and is not taken here). No step starts from a zero:
/// every float frame's end is a multiple of 2^-149, and those below 2^-125 in magnitude are
/// floats. Without SSE2, and in the portable build, false: roundFinal does it all.
template <class LinesClear>
[[nodiscard, gnu::always_inline]] inline bool roundFloatEndsTogether(
    [[maybe_unused]] double endX, [[maybe_unused]] double endY, [[maybe_unused]] float startX,
    [[maybe_unused]] float startY, [[maybe_unused]] const LinesClear& linesClear,
    [[maybe_unused]] float& outX, [[maybe_unused]] float& outY) noexcept {
#if defined(TILESWEEP_FINAL_ROUNDING_SSE2) && !defined(TILESWEEP_FAULT_ROUND_NEAREST) && \
    !defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)
    const __m128d end =
        _mm_add_pd(_mm_set_pd(endY, endX), _mm_setzero_pd());  // a zero reads +0, as in roundFinal
    const __m128 nearest = _mm_cvtpd_ps(end);                  // to nearest, the library's rounding mode
    const __m128d nearestWide = _mm_cvtps_pd(nearest);
    const __m128 start = _mm_setr_ps(startX, startY, 0.0F, 0.0F);
    __m128 result = nearest;  // both ends representable: the ends themselves
    if (_mm_movemask_pd(_mm_cmpeq_pd(nearestWide, end)) != 3) {
        const __m128d startWide = _mm_cvtps_pd(start);
        const __m128d above = _mm_cmplt_pd(end, nearestWide);  // the nearest float lies above the end
        const __m128d below = _mm_cmplt_pd(nearestWide, end);
        const __m128d roundsUp = _mm_cmplt_pd(end, startWide);    // an end below its start
        const __m128d roundsDown = _mm_cmplt_pd(startWide, end);  // an end above its start
        // The amendment may apply: an inexact end below its start, on an axis whose lines are
        // not clear.
        const int inexactBelow = _mm_movemask_pd(_mm_and_pd(roundsUp, _mm_or_pd(above, below)));
        if ((inexactBelow & ~linesClear()) != 0) return false;
        // Steps toward plus infinity, per lane: -1 (all ones) or +1, as 64-bit integers, then
        // their low halves in lanes 0 and 1.
        const __m128i stepsWide = _mm_sub_epi64(_mm_castpd_si128(_mm_and_pd(roundsDown, above)),
                                                _mm_castpd_si128(_mm_and_pd(roundsUp, below)));
        const __m128i steps = _mm_shuffle_epi32(stepsWide, _MM_SHUFFLE(3, 3, 2, 0));
        const __m128i bits = _mm_castps_si128(nearest);
#if defined(TILESWEEP_FAULT_FINAL_STEP_SIGN_IGNORED)
        result = _mm_castsi128_ps(
            _mm_add_epi32(bits, steps));  // deliberate fault: negative floats step the wrong way
#else
        const __m128i negative = _mm_srai_epi32(bits, 31);  // all ones for a negative float
        result =
            _mm_castsi128_ps(_mm_add_epi32(bits, _mm_sub_epi32(_mm_xor_si128(steps, negative), negative)));
#endif
    }
    const __m128 atStart = _mm_cmpeq_ps(result, start);
    const __m128 out = _mm_or_ps(_mm_and_ps(atStart, start), _mm_andnot_ps(atStart, result));
    outX = _mm_cvtss_f32(out);
    outY = _mm_cvtss_f32(_mm_shuffle_ps(out, out, _MM_SHUFFLE(1, 1, 1, 1)));
    return true;
#else
    return false;  // every parameter unused here ([[maybe_unused]])
#endif
}

/// roundFloatEndsTogether for a double frame: each end an exact pair (hi = fl(value), lo the
/// rest), rounded toward its start. An inexact end (lo != 0) lies on the side of its start that
/// its high part and low part say (hi is on the value's side of the start, or equal to it when
/// lo says which), and is rounded by one step of hi toward the start when lo points away from
/// the start, else hi itself, as roundFinal does through roundToward. It goes back to roundFinal
/// on the same condition: an inexact end below its start on an axis whose lines are not clear.
/// hi is zero only for a zero value, so no step starts from a zero, and the result is finite as
/// above.
template <class LinesClear>
[[nodiscard, gnu::always_inline]] inline bool roundDoubleEndsTogether(
    [[maybe_unused]] const ExactPair& endX, [[maybe_unused]] const ExactPair& endY,
    [[maybe_unused]] double startX, [[maybe_unused]] double startY,
    [[maybe_unused]] const LinesClear& linesClear, [[maybe_unused]] double& outX,
    [[maybe_unused]] double& outY) noexcept {
#if defined(TILESWEEP_FINAL_ROUNDING_SSE2) && !defined(TILESWEEP_FAULT_ROUND_NEAREST) && \
    !defined(TILESWEEP_FAULT_OLD_ROUNDING_RULE)
    const __m128d zero = _mm_setzero_pd();
    const __m128d hi = _mm_add_pd(_mm_set_pd(endY.hi, endX.hi), zero);  // a zero reads +0, as in roundFinal
    const __m128d lo = _mm_set_pd(endY.lo, endX.lo);
    const __m128d start = _mm_set_pd(startY, startX);
    __m128d result = hi;  // both ends representable (both low parts zero): the ends themselves
    if (_mm_movemask_pd(_mm_cmpeq_pd(lo, zero)) != 3) {
        const __m128d loBelow = _mm_cmplt_pd(lo, zero);  // the value lies below hi
        const __m128d loAbove = _mm_cmplt_pd(zero, lo);
        const __m128d atStartHigh = _mm_cmpeq_pd(hi, start);
        const __m128d roundsUp = _mm_or_pd(_mm_cmplt_pd(hi, start), _mm_and_pd(atStartHigh, loBelow));
        const __m128d roundsDown = _mm_or_pd(_mm_cmplt_pd(start, hi), _mm_and_pd(atStartHigh, loAbove));
        const int inexactBelow = _mm_movemask_pd(_mm_and_pd(roundsUp, _mm_or_pd(loBelow, loAbove)));
        if ((inexactBelow & ~linesClear()) != 0) return false;
        // Steps toward plus infinity: -1 (all ones) where the value lies below hi and rounds
        // down, +1 where it lies above hi and rounds up.
        const __m128i steps = _mm_sub_epi64(_mm_castpd_si128(_mm_and_pd(roundsDown, loBelow)),
                                            _mm_castpd_si128(_mm_and_pd(roundsUp, loAbove)));
        const __m128i bits = _mm_castpd_si128(hi);
#if defined(TILESWEEP_FAULT_FINAL_STEP_SIGN_IGNORED)
        result = _mm_castsi128_pd(
            _mm_add_epi64(bits, steps));  // deliberate fault: negative doubles step the wrong way
#else
        const __m128i negative = _mm_shuffle_epi32(_mm_srai_epi32(bits, 31), _MM_SHUFFLE(3, 3, 1, 1));
        result =
            _mm_castsi128_pd(_mm_add_epi64(bits, _mm_sub_epi64(_mm_xor_si128(steps, negative), negative)));
#endif
    }
    const __m128d atStart = _mm_cmpeq_pd(result, start);
    const __m128d out = _mm_or_pd(_mm_and_pd(atStart, start), _mm_andnot_pd(atStart, result));
    outX = _mm_cvtsd_f64(out);
    outY = _mm_cvtsd_f64(_mm_unpackhi_pd(out, out));
    return true;
#else
    return false;  // every parameter unused here ([[maybe_unused]])
#endif
}

}  // namespace tilesweep::detail
