// SPDX-License-Identifier: MIT
#pragma once

// The numbers that carry the fast path's proofs, in one place, each with its derivation.
//
// None of them is a tolerance on a decision: every decision of the resolver is exact. They are
// error bounds on estimates (a cell index, a product, a grid coordinate) that only choose which
// exact comparisons to make, or range limits inside which the fast path's arithmetic is exact.
// An estimate's margin that is too large costs a few extra exact tests; one that is too small
// would skip a tile, which is why the fault FILTER_BOUND_HALVED halves two of them and the suite
// must catch it.
//
// Notation: u = 2^-53, the unit roundoff of double (rounding to nearest errs by at most u times
// the result's magnitude, away from underflow and overflow). A bound "in ulps" is a multiple of u.

namespace tilesweep::detail {

/// u = 2^-53: the relative error of one double rounding to nearest.
inline constexpr double kUnitRoundoff = 0x1p-53;

// ---- cell estimates --------------------------------------------------------------------------

/// Margin of a cell-range estimate fl(fl(v - origin) * fl(1 / tile)), in units of u times
/// M / tile, where M is the sum of the magnitudes that formed v, plus |origin| (estimateCells).
/// v is one input, or a sum of two or three inputs rounded to nearest (the far edge low + size
/// of a double frame, the swept end low + disp, high + disp): within 2u M of the exact value.
/// The difference with the origin rounds once more (u M), the rounded reciprocal and the
/// product twice (relative u each, on a value below M / tile): 5.03u M / tile in all. The margin
/// is computed as fl(fl(8u * M) * invTile), at least 8u(1 - 2u) M / tile, and subtracting or
/// adding it rounds once more (u M / tile): 6.04u < 8u(1 - 2u). So the widened range holds every
/// cell the exact coordinate lies in; a cell too many is tested exactly and rejected.
inline constexpr double kCellEstimateErrorUlps = 8;

/// Margin of the walk's secondary range, in units of u times A / tile, A = |low| + |high| +
/// |disp| + |origin| of the secondary axis. The estimate v = (low + (disp / speed) * t - origin)
/// * fl(1 / tile) takes six rounded operations. With t / speed in [0, 1] and every intermediate
/// below A(1 + 3u), their errors are at most 2.01u|disp| (the slope and its product with t),
/// + 1.01uA (sum), + 1.01uA (difference), all scaled by 1/tile (1 + 2.01u), then + 2.01uA/tile
/// (the rounded reciprocal and the product): under 6.05uA/tile in all. Adding or subtracting the
/// margin rounds once more, by at most 1.01uA/tile, and the margin itself is computed 5u low at
/// worst: 10 covers the 7.07 needed (and half of it does not). Double frames estimate the
/// distances t as well (the high part of an exact pair, within u|t|): 1.01u|disp| more; and
/// `high` is the far edge rounded to nearest: 1.01u|high| more, 9.09 in all, which 10, computed
/// at most 5u low, still covers.
inline constexpr double kSecondaryRangeErrorUlps = 10;

/// Reach of the zero move's estimates (zero_move.h): cell coordinates q = (v - origin) / tile
/// below 2^31 in magnitude, so that every cell index fits the map's int32 range and the
/// estimates' error stays under kZeroMoveBand. Larger ones take the ordinary path.
inline constexpr double kZeroMoveReach = 0x1p31;
/// Band of the zero move's cell decision (zero_move.h): a rounded cell coordinate q below
/// kZeroMoveReach is within 3.01u * 2^31 < 0.76 * 2^-20 of the exact one (ql = fl(fl(x - o) / t)
/// within (2u + u^2)|Ql|; qh = fl(fl(fl(x - o) + w) / t) within u(1 + u)^2 |Ql| + (2u + u^2)|Qh|;
/// each division adds at most 2^-1075 where it underflows), so a q more than 2^-20 from every
/// integer has the exact coordinate's floor. A q within it takes the exact settlement.
inline constexpr double kZeroMoveBand = 0x1p-20;
/// TwoProduct (exact_double.h) is exact for a tile size in (2^-900, 2^900) times a cell index
/// below 2^31: nothing overflows and the error term does not underflow.
inline constexpr double kZeroMoveProductGuard = 0x1p-900;

// ---- products and times ----------------------------------------------------------------------

/// The semi-static error bound of compareProducts on exact pairs (exact_double.h), relative to
/// S = |p| + |q|, p = fl(a.hi*s), q = fl(b.hi*t): c = (2 + 16u)u. With D = fl(p - q), the exact
/// difference X = a*s - b*t satisfies
///   |X - D| <= |a.hi*s - p| + |b.hi*t - q| + |(p - q) - D| + |a.lo*s| + |b.lo*t|
///           <= u|p| + u|q| + u|D| + u(1 + u)(|p| + |q|) = (2u + u^2)S + u|D|
/// (each rounding to nearest errs by at most u times its result; |lo| <= ulp(hi)/2 <= u|hi|, and
/// |a.hi*s| <= (1 + u)|p|). So sign(D) is sign(X) once |D|(1 - u) > (2u + u^2)S. The filter
/// decides only when |D| > fl(c * fl(S)) >= c(1 - u)^2 S, and c(1 - u)^3 >= 2u + u^2 holds for
/// c = 2u + 7u^2 + 16u^3 already: (2 + 16u)u is safe.
///
/// The bound is close to tight: the u|D| term is kept apart rather than bounded by u(1 + u)S, so
/// inside the band the error is at most about 2uS, the bound itself. Exact ties come within
/// 0.946 of it in the construction of tests/exact_primitives_test.cpp
/// (comparesExactTiesInTheFilterBandsUpperHalf), and reach its upper half wherever the two
/// rounded products land two ulps apart. Half the bound (FILTER_BOUND_HALVED) is wrong on
/// exactly those: the sign of D (two ulps of p) is not the sign of an exact tie.
inline constexpr double kPairProductErrorBound = (2.0 + 16.0 * kUnitRoundoff) * kUnitRoundoff;

/// The filter of roundTimeToDouble (time_rounding.h), in units of u times |d| + |e| + |lo|: the
/// remainder R~ = fl(fl(d - e) + lo) is within (2u + u^2)(|d| + |e| + |lo|) of the exact one;
/// the bound computed as fl(3u fl(fl(|d| + |e|) + |lo|)) is at least 3u(1 - u)^3 of that sum,
/// which exceeds 2u + u^2.
inline constexpr double kTimeRemainderErrorUlps = 3;

// ---- the grid-line test of a double frame's final position -----------------------------------

/// Reach of the filtered grid-line test of roundFinal on exact pairs (FastFrame::gridLineAhead),
/// in units of u times A / tile, A = |hi| + size + |origin|. The grid coordinate of the far edge,
/// z = fl(fl(fl(hi + size) - origin) * fl(1 / tile)), is within 4.1uA / tile of (hi + size -
/// origin) / tile (two rounded sums, the reciprocal and the product), and the pair's low part lo
/// (left out) moves the exact value by |lo| / tile more. The interval to search, [exact, up) +
/// size, up the double just above the exact value, spans at most (|up - hi| + |lo|) / tile from
/// there. With |lo| <= u|hi| <= uA and |up - hi| <= ulp(hi) <= 2u|hi| <= 2uA, the reach must be
/// at least (4.1 + 2 + 2)uA / tile = 8.1uA / tile; the test (FastFrame::lineFree) compares it
/// exactly with z's distance to the nearest integer. The code takes 20uA / tile, computed in five
/// operations (at least (1 - 5.1u) of its exact value). A larger reach only sends more frames to
/// the lattice (the test then says "may hold a line"); it never changes a result.
inline constexpr double kGridLineReachUlps = 20;
/// The same test, and the float frames' (kFloatLineReachRelative), only run for |z| < 2^40, where
/// the shift below finds the nearest integer exactly, and the doubles near z still resolve 2^-12
/// of a cell (for double frames, |origin| < 2^47 tiles by admitDoubleFrame keeps A / tile below
/// 2^48, so the reach stays below 2 cells). Any limit up to 2^51 would be as sound; a larger z
/// (or a NaN) is not filtered: double frames go to the lattice, float frames to the exact test.
inline constexpr double kGridLineReachLimit = 0x1p40;

/// 1.5 * 2^52: for |z| < 2^51, fl(z + shift) lies in [2^52, 2^53), where the doubles are the
/// integers, so it is shift + (z rounded to an integer, to nearest), and subtracting the shift is
/// exact. The grid-line filters (FastFrame::lineFree) take the integer nearest z this way, for
/// |z| < kGridLineReachLimit, without a conversion to an integer register.
inline constexpr double kNearestIntegerShift = 0x1.8p52;

/// The reach of a float frame's grid-line filter (FastFrame::gridLineAhead), in cells:
///   R = (2^-22 (|far| + size + |far - origin|) + 2^-148) / tile, computed with the reciprocal.
/// There far = exact + size and far - origin are exact doubles (range_admission.h), so the
/// estimate z = fl((far - origin) * fl(1 / tile)) is within (2u + u^2)|far - origin| / tile of
/// the exact grid coordinate Z. The interval searched, [far, up + size), is W = (up - exact) /
/// tile wide, up being the float just above an exact value no float represents, so up - exact is
/// below the float spacing there: 2^-23|exact| + 2^-149 at most (2^-149 below float's normal
/// range), with |exact| <= |far| + size. When no integer lies within
///   R' = (2u + u^2)|far - origin| / tile + W
/// of z, every integer m has |m - Z| > W, so none lies in [Z, Z + W]: no line. The code's R,
/// computed by three rounded sums and a rounded product (at least (1 - u)^4 of its exact value),
/// exceeds R' with room, term by term: 2^-22 (1 - u)^4 > 2^-23 + 2u + u^2, and
/// 2^-148 (1 - u)^4 > 2^-149. A larger reach only sends more frames to the exact test
/// (FastAxis::hasLineIn); it never changes a result.
inline constexpr double kFloatLineReachRelative = 0x1p-22;
/// The least term of the same reach, for ends below float's normal range (see above).
inline constexpr double kFloatLineReachLeast = 0x1p-148;

// ---- range admission -------------------------------------------------------------------------

/// The most bits the fast path's exact doubles may need: a double's 53.
///
/// Float frames (admitFloatFrame). Every input is a float, a multiple of its ulp, so all are
/// multiples of 2^G, G the lowest ulp exponent among the nonzero ones (G >= -149: subnormal
/// inputs are turned away). A multiple of 2^G below 2^(G+53) in magnitude is a double, so it is
/// enough that every value the solver must hold exactly is below 2^(G+53). On one axis, with x,
/// w, dx the box's position, size and displacement, o the origin, t the tile and c the cells,
/// those values are (fast_frame.h, fast_axis.h, frame_loop.h, final_rounding.h):
///   - x + w, x + dx, and the touch positions e - w, e + w (e a tile edge);
///   - tile edges e = o + k*t for -1 <= k <= c + 1 (k*t itself is exact: k < 2^25 times a
///     24-bit significand);
///   - the distances e - (x + w), x - e, e - x, (x + w) - e of the tile test;
///   - the grid-line test's ends (x + dx) + w, e (a touch position plus w) and r + w (r the float
///     the position rounds to, between the start and the exact end: the exact end itself, or a
///     float of at least 2^(G+24), so a multiple of 2^G too), their difference, and the grid
///     lines o + k*t and k*t next to them (within 2t of (x + dx) + w: FastAxis::hasLineIn).
/// Each is at most A = |x| + |w| + |dx| + |o| + (c + 2)t in magnitude (the grid lines: |x + dx
/// + w| + 2t <= A, as c + 2 >= 2). The range test bounds A by exponent fields: |x|, |w|, |dx| <
/// 2^B (B = boxTop - 126), so their sum is below 3 * 2^B < 2^(B+2); |o| + (c + 2)t < 2^E (E =
/// edgeTop - 126); so A < 2^(B+2) + 2^E <= 2^(C+1) with C = max(B + 2, E), and C + 1 - G <= 53
/// suffices. A bounds the differences as well as the coordinates, so the differences need no
/// bits of their own.
///
/// What a wider test admits. A value misses the double grid only when it is at least 2^(G+53)
/// and has a bit at 2^G, which only an input with its ulp at 2^G (below 2^(G+24)) provides; it
/// changes an answer only when it lies within 2^G of what it is compared with or rounded to (a
/// tile edge, a grid line, a float). One binade wider (G + 53 >= C) holds exactly every value
/// that decides anything: the box's sums are below 3 * 2^B < 2^(B+2), tile edges below 2^E,
/// touch positions and the grid-line test's ends among them; only distances to far tile edges
/// can pass 2^C, and the solver compares those with the speed alone, which they exceed by far
/// (monotonic rounding keeps that exact). So no answer can change, and a fault one binade wide
/// is equivalent. On a valid map every tile edge is a float, so a fine bit comes from the box
/// alone (w or dx), and a value 2^G from a float needs two fine inputs that cancel to 2^G
/// beside a coarse one: the far face x + dx + w of a box whose move dx = -(w - 2^G) leaves it
/// 2^G past the grid line x. That value is below 2^B, so it misses the grid only when G + 53 <=
/// B - 1: four binades (C + 1 - G = 57). Then it rounds onto x, the grid-line test sees x in
/// [far face, far face rounded), and the position is rounded down, one float below the contract's
/// x. That is the fault FAST_RANGE_TOO_WIDE (fault_injection.h), and the range-edge family builds
/// those scenes (scenarios/range_edge_family.h); at two and three binades no valid scene we know
/// of can tell.
inline constexpr int kFastSpanBits = 53;
/// Float frames: every value formed (A above) below 2^120, so that sums of three and products of
/// the fast path (squares of values at most) stay far from double overflow, and a far edge plus a
/// tile stays below float's largest value.
inline constexpr int kFloatFrameTopExponent = 120;
/// Double frames: every nonzero input in [2^-250, 2^251), so that no product, TwoProduct error
/// term or filter bound (products of up to four inputs: below 2^1004, above 2^-1000 before the
/// error terms' 2^-106) comes near overflow or underflow.
inline constexpr int kDoubleFrameExponentLimit = 250;
/// Double frames: |origin| < 2^47 tiles, so that a cell estimate from a rounded quotient is off
/// by less than 0.2 cells where it matters (|quotient| < 2^32: u(|c| + |origin|) / tile < 2^-5).
inline constexpr int kDoubleFrameOriginTileBits = 46;
/// Double frames: the far box edge's distances to tile edges come out as exact pairs when the
/// largest coordinate is at most 2^104 times the lowest set bit of the box and grid inputs
/// (admitDoubleFrame derives it: the three-term sum's low terms fit 53 bits).
inline constexpr int kDoubleFramePairSpanBits = 104;

// ---- Contact positions on the fast path (contact_position.h)

/// A contact position's candidate c below 2^-500 in magnitude (or zero) is left to the lattice:
/// the midpoint tests form c*den and h*den (h half the gap from c to its neighbour) with their
/// TwoProduct error terms, which must stay normal to be exact; a smaller c would carry them toward
/// the subnormals (contact_position.h, "Range"). V = 0 exactly is settled there (+0).
inline constexpr double kPositionFloor = 0x1p-500;

}  // namespace tilesweep::detail
