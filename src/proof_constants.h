// SPDX-License-Identifier: MIT
#pragma once

// The numbers that carry the fast path's proofs, in one place, each with its derivation, and the
// resolver's tuning knobs after them.
//
// None of them is a tolerance on a decision: every decision of the resolver is exact. They are
// error bounds on estimates (a cell index, a product, a grid coordinate) that only choose which
// exact comparisons to make, or range limits inside which the fast path's arithmetic is exact.
// An estimate's margin that is too large costs a few extra exact tests; one that is too small
// would skip a tile, which is why the fault FILTER_BOUND_HALVED halves two of them and the suite
// must catch it.
//
// A constant that follows from others is computed from them here. Every inequality a derivation
// relies on is checked by a static_assert below the constant, so a value that breaks its proof
// does not compile. The asserts are evaluated in double, so each is written with room: where the
// two sides agree to a few ulps, the common part is subtracted first (kPairProductErrorBound).
//
// Notation: u = 2^-53, the unit roundoff of double (rounding to nearest errs by at most u times
// the result's magnitude, away from underflow and overflow). A bound "in ulps" is a multiple of u.

#include <cstdint>
#include <limits>

namespace tilesweep::detail {

/// 2^e, exactly, for e in double's normal range: for the constants below and their checks.
[[nodiscard]] constexpr double twoToThe(int e) noexcept {
    double v = 1;
    for (; e > 0; --e) v *= 2;
    for (; e < 0; ++e) v /= 2;
    return v;
}

/// The bits of a double's significand, the implicit one included: 53.
inline constexpr int kDoubleDigits = std::numeric_limits<double>::digits;

/// u = 2^-53: the relative error of one double rounding to nearest.
inline constexpr double kUnitRoundoff = twoToThe(-kDoubleDigits);
static_assert(kUnitRoundoff == std::numeric_limits<double>::epsilon() / 2, "u is half of double's epsilon");

/// Veltkamp's splitter for Dekker's TwoProduct (productError, exact_double.h): 2^ceil(53 / 2) + 1
/// splits a double into two halves of 26 significant bits each, whose products are exact.
inline constexpr double kVeltkampSplitter = twoToThe((kDoubleDigits + 1) / 2) + 1;

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
static_assert(5.03 + 1.01 < kCellEstimateErrorUlps * (1 - 2 * kUnitRoundoff),
              "the cell margin covers the estimate's error and its own rounding");

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
static_assert(9.09 < kSecondaryRangeErrorUlps * (1 - 5 * kUnitRoundoff),
              "the secondary range's margin covers the double frames' error");

/// Reach of the zero move's estimates (zero_move.h): cell coordinates q = (v - origin) / tile
/// below 2^31 in magnitude, so that every cell index fits the map's int32 range and the
/// estimates' error stays under kZeroMoveBand. Larger ones take the ordinary path.
inline constexpr double kZeroMoveReach = 0x1p31;
static_assert(kZeroMoveReach <= double(std::numeric_limits<std::int32_t>::max()) + 1,
              "a cell coordinate below the reach truncates to an int32 cell index");
/// Band of the zero move's cell decision (zero_move.h): a rounded cell coordinate q below
/// kZeroMoveReach is within 3.01u * 2^31 < 0.76 * 2^-20 of the exact one (ql = fl(fl(x - o) / t)
/// within (2u + u^2)|Ql|; qh = fl(fl(fl(x - o) + w) / t) within u(1 + u)^2 |Ql| + (2u + u^2)|Qh|;
/// each division adds at most 2^-1075 where it underflows), so a q more than 2^-20 from every
/// integer has the exact coordinate's floor. A q within it takes the exact settlement.
inline constexpr double kZeroMoveBand = 0x1p-20;
static_assert(3.01 * kUnitRoundoff * kZeroMoveReach < kZeroMoveBand && kZeroMoveBand < 0.5,
              "the zero move's band covers its estimates' error, and is less than half a cell");
/// TwoProduct (exact_double.h) is exact for a tile size in (2^-900, 2^900) times a cell index
/// below 2^31: nothing overflows and the error term does not underflow.
inline constexpr double kZeroMoveProductGuard = 0x1p-900;
static_assert(kVeltkampSplitter * kZeroMoveReach / kZeroMoveProductGuard < std::numeric_limits<double>::max(),
              "neither the product nor the split of a factor overflows");
static_assert(kZeroMoveProductGuard * twoToThe(-2 * kDoubleDigits) >= std::numeric_limits<double>::min(),
              "the product's error term, at least 2^-106 of a product above the guard, is normal");

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
// c(1 - u)^3 >= 2u + u^2, with c = (2 + e)u: the two sides agree to within a few ulps, so the
// check takes 2(1 - u)^3 from both and asks e(1 - u)^3 >= u(7 - 6u + 2u^2), where they differ by
// a factor of two.
static_assert((kPairProductErrorBound / kUnitRoundoff - 2) * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) *
                      (1 - kUnitRoundoff) >=
                  kUnitRoundoff * (7 - 6 * kUnitRoundoff + 2 * kUnitRoundoff * kUnitRoundoff),
              "the pair filter's bound covers the error of D");

/// The filter of roundTimeToDouble (time_rounding.h), in units of u times |d| + |e| + |lo|: the
/// remainder R~ = fl(fl(d - e) + lo) is within (2u + u^2)(|d| + |e| + |lo|) of the exact one;
/// the bound computed as fl(3u fl(fl(|d| + |e|) + |lo|)) is at least 3u(1 - u)^3 of that sum,
/// which exceeds 2u + u^2.
inline constexpr double kTimeRemainderErrorUlps = 3;
static_assert(kTimeRemainderErrorUlps * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) >
                  2 + kUnitRoundoff,
              "the time filter's bound covers the remainder's error");

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
static_assert(4.1 + 2 + 2 < kGridLineReachUlps * (1 - 5.1 * kUnitRoundoff),
              "the grid-line reach covers the estimate's error and the interval searched");
/// The same test, and the float frames' (kFloatLineReachRelative), only run for |z| < 2^40, where
/// the shift below finds the nearest integer exactly, and the doubles near z still resolve 2^-12
/// of a cell (for double frames, |origin| < 2^47 tiles by admitDoubleFrame keeps A / tile below
/// 2^48, so the reach stays below 2 cells). Any limit up to 2^51 would be as sound; a larger z
/// (or a NaN) is not filtered: double frames go to the lattice, float frames to the exact test.
inline constexpr double kGridLineReachLimit = 0x1p40;
static_assert(kGridLineReachLimit <= twoToThe(kDoubleDigits - 2), "the shift finds the nearest integer");

/// 1.5 * 2^52: for |z| < 2^51, fl(z + shift) lies in [2^52, 2^53), where the doubles are the
/// integers, so it is shift + (z rounded to an integer, to nearest), and subtracting the shift is
/// exact. The grid-line filters (FastFrame::lineFree) take the integer nearest z this way, for
/// |z| < kGridLineReachLimit, without a conversion to an integer register.
inline constexpr double kNearestIntegerShift = 0x1.8p52;
static_assert(kNearestIntegerShift - twoToThe(kDoubleDigits - 2) >= twoToThe(kDoubleDigits - 1) &&
                  kNearestIntegerShift + twoToThe(kDoubleDigits - 2) <= twoToThe(kDoubleDigits),
              "z + shift lies in the binade whose doubles are the integers, for |z| < 2^51");

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
// (1 - u)^4, the least share of its exact value that the computed reach keeps.
static_assert(kFloatLineReachRelative * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) *
                      (1 - kUnitRoundoff) >
                  double(std::numeric_limits<float>::epsilon()) + 2 * kUnitRoundoff +
                      kUnitRoundoff * kUnitRoundoff,
              "the float reach covers the estimate's error and a float's relative spacing (2^-23)");
static_assert(kFloatLineReachLeast * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) * (1 - kUnitRoundoff) *
                      (1 - kUnitRoundoff) >
                  double(std::numeric_limits<float>::denorm_min()),
              "the float reach's least term covers the spacing below float's normal range (2^-149)");

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
inline constexpr int kFastSpanBits = kDoubleDigits;
/// Float frames: every value formed (A above) below 2^120, so that sums of three and products of
/// the fast path (squares of values at most) stay far from double overflow, and a far edge plus a
/// tile stays below float's largest value.
inline constexpr int kFloatFrameTopExponent = 120;
static_assert(2 * (kFloatFrameTopExponent + 2) < std::numeric_limits<double>::max_exponent,
              "squares of sums of three values stay below double's overflow");
static_assert(kFloatFrameTopExponent + 1 < std::numeric_limits<float>::max_exponent,
              "a far edge plus a tile stays below float's largest value");
/// Double frames: every nonzero input in [2^-250, 2^251), so that no product, TwoProduct error
/// term or filter bound (products of up to four inputs: below 2^1004, above 2^-1000 before the
/// error terms' 2^-106) comes near overflow or underflow.
inline constexpr int kDoubleFrameExponentLimit = 250;
static_assert(4 * (kDoubleFrameExponentLimit + 1) < std::numeric_limits<double>::max_exponent &&
                  -4 * kDoubleFrameExponentLimit >= std::numeric_limits<double>::min_exponent - 1,
              "a product of four inputs is a normal double");
/// Double frames: |origin| < 2^47 tiles, so that a cell estimate from a rounded quotient is off
/// by less than 0.2 cells where it matters (|quotient| < 2^32: u(|c| + |origin|) / tile < 2^-5).
inline constexpr int kDoubleFrameOriginTileBits = 46;
static_assert(kUnitRoundoff * (twoToThe(32) + twoToThe(kDoubleFrameOriginTileBits + 1)) < twoToThe(-5),
              "a cell estimate near the map is off by less than 2^-5 cells");
static_assert(kGridLineReachUlps * kUnitRoundoff * twoToThe(kDoubleFrameOriginTileBits + 2) < 2,
              "A / tile < 2^48 keeps a double frame's grid-line reach below two cells");
/// Double frames: the far box edge's distances to tile edges come out as exact pairs when the
/// largest coordinate is at most 2^104 times the lowest set bit of the box and grid inputs
/// (admitDoubleFrame derives it: |b + l| < 2^(m - 51), a multiple of 2^lowest, is a double when
/// m - 51 <= lowest + 53, that is m - lowest <= 2 * 53 - 2).
inline constexpr int kDoubleFramePairSpanBits = 2 * kDoubleDigits - 2;

/// The double frames' window (admitDoubleFrameInWindow, input_window.h): every nonzero box input
/// in [2^kCommonLeastExponent, 2^kCommonLargestExponent), that is [2^-20, 2^30). Inside it the
/// full test's conditions on the box hold (admitDoubleFrameFully): the inputs lie within
/// [2^-250, 2^251); boxTop (the field of max(|x|, |w|) plus 2) is at most kCommonBoxTop; and each
/// nonzero input's lowest set bit is at or above its ulp, 2^(field - 52) >= 2^kCommonLowestBit.
/// So the span test max(top, boxTop) <= min(lowest bits, map's lowest) + kDoubleFramePairSpanBits
/// holds when max(top, kCommonBoxTop) <= min(kCommonLowestBit, map's lowest) +
/// kDoubleFramePairSpanBits on each axis: the map's half of that is MapRange::common, computed
/// once per map (doubleMapRange). A frame the window does not admit takes the full test.
inline constexpr int kCommonLargestExponent = 30;
inline constexpr int kCommonLeastExponent = -20;
inline constexpr double kCommonLargest = twoToThe(kCommonLargestExponent);
inline constexpr double kCommonLeast = twoToThe(kCommonLeastExponent);
inline constexpr int kCommonBoxTop = (kCommonLargestExponent - 1) + 2;
inline constexpr int kCommonLowestBit = kCommonLeastExponent - (kDoubleDigits - 1);
static_assert(-kDoubleFrameExponentLimit <= kCommonLeastExponent &&
                  kCommonLargestExponent <= kDoubleFrameExponentLimit + 1,
              "the window lies inside the double frames' range");
static_assert(
    kCommonBoxTop <= kCommonLowestBit + kDoubleFramePairSpanBits,
    "some map admits the window's boxes (otherwise the window would cost a test and admit nothing)");

// ---- Contact positions on the fast path (contact_position.h)

/// A contact position's candidate c below 2^-500 in magnitude (or zero) is left to the lattice:
/// the midpoint tests form c*den and h*den (h half the gap from c to its neighbour) with their
/// TwoProduct error terms, which must stay normal to be exact; a smaller c would carry them toward
/// the subnormals (contact_position.h, "Range"). V = 0 exactly is settled there (+0).
inline constexpr double kPositionFloor = 0x1p-500;

/// The error bound of a contact position's estimate (contact_position.h), in units of u times a
/// magnitude. Float frames (nearestFloatOfEstimate): v = fl(x0 + fl(q * d)) is within
/// 3u(|v| + |P~|) of V, and the bound fl(4u * fl(|v| + |P~|)) is at least 4u(1 - u)(|v| + |P~|).
/// Double frames (nearestDoubleOfEstimate): the error is under 2.01u|p|, and the bound 4u|p| is
/// exact (a power of two times |p|).
inline constexpr double kPositionEstimateErrorUlps = 4;
static_assert(kPositionEstimateErrorUlps * (1 - kUnitRoundoff) > 3 && kPositionEstimateErrorUlps > 2.01,
              "the position estimates' bound covers their error");

/// Whether the filter of signAgainst (contact_position.h) is sound for sums of up to `most` terms:
/// recursive summation of n terms errs by at most gamma(n - 1) sum|t|, gamma(k) = ku / (1 - ku)
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 4.2), and the bound, computed as
/// fl((n + 1)u * M) with M = fl(sum|t|) >= (1 - u)^(n - 1) sum|t|, is at least
/// (n + 1)u(1 - u)^n sum|t|.
[[nodiscard]] constexpr bool sumFilterCovers(int most) noexcept {
    for (int n = 1; n <= most; ++n) {
        double kept = n + 1;  // (n + 1)(1 - u)^n
        for (int k = 0; k < n; ++k) kept *= 1 - kUnitRoundoff;
        const double gamma = (n - 1) / (1 - (n - 1) * kUnitRoundoff);  // in units of u
        if (!(kept > gamma)) return false;
    }
    return true;
}
/// The most terms signAgainst's filter may sum (its Remainder holds fewer).
inline constexpr int kSumFilterMostTerms = 16;
static_assert(sumFilterCovers(kSumFilterMostTerms), "the sum filter's bound covers recursive summation");

// ---- exact distances ---------------------------------------------------------------------------

/// A double frame whose tile distances are all exact doubles (FastFrame::distancesExact) passes
/// two tests on each axis, on the values its set-up computes: the far edge is a double, and
///   fl(2 L - H) >= kExactDistanceSpanTiles * tile,  margin <= kExactDistanceMarginLimit,
/// with L and H the swept bounds' ends, fl(min(low, low + disp)) and fl(max(high, high + disp)),
/// and margin the swept cells' (kCellEstimateErrorUlps). Why they suffice:
///   - Every tile the frame tests has its edges in [L* - 3 tile, H* + 3 tile], L* and H* the exact
///     ends. Each cell range reaches past the exact one by its margin on either side: the near
///     listing's (the swept cells) by the swept margin, the walk's secondary ranges by theirs,
///     kSecondaryRangeErrorUlps / kCellEstimateErrorUlps times that, computed within 6u; both
///     below 1/2 cell, so a range starts at most one cell before the exact one and ends at most
///     one after it, or two where fl(v + 1) rounds up (estimateCells). The walk's primary cells
///     are entered before t = 1, so they lie between the start and the end.
///   - The box's edges at t = 0 lie in [L*, H*]. Two values of [A, B] with 0 < A, B <= 2A differ
///     exactly in double (Sterbenz's lemma: y / 2 <= x <= 2y), and with A = L* - 3 tile and
///     B = H* + 3 tile that is 2 L* - H* >= 9 tile (then A >= 6 tile, since H* >= L*).
///   - The computed test errs by at most 6.01u max(|L*|, |H*|) (L and H within u of theirs, 2L
///     exact, the difference rounded once), and the margin's limit bounds u M / tile, with M >=
///     max(|L*|, |H*|) the estimates' magnitude, by kExactDistanceMarginLimit / 7.99: the error
///     is below tile / 10, so 16 tiles computed leave 2 L* - H* above 15 tiles.
inline constexpr double kExactDistanceSpanTiles = 16;
inline constexpr double kExactDistanceMarginLimit = 0.125;
static_assert(kExactDistanceMarginLimit * kSecondaryRangeErrorUlps / kCellEstimateErrorUlps *
                      (1 + 6 * kUnitRoundoff) <
                  0.5,
              "both cell margins stay below half a cell");
static_assert(6.01 * kExactDistanceMarginLimit / (kCellEstimateErrorUlps * (1 - 3 * kUnitRoundoff)) <
                  kExactDistanceSpanTiles - 9,
              "the computed span test errs by less than its slack");

// ---- tuning knobs ------------------------------------------------------------------------------
//
// These choose how the broadphase looks for tiles, never what it finds: every tile that can block
// is tested exactly whichever way is taken. Changes cost, never results.

/// Near listing (FrameLoop::collectNear): swept bounds of up to this many cells are listed row by
/// row and their solid cells tested one by one, instead of walked cell by cell along the path.
/// Unit: cells. Usual value: 12 (a box of a tile moving up to about a tile a frame).
inline constexpr std::int64_t kNearArea = 12;
/// Sparse listing: larger swept bounds, up to this many cells, are listed too when they are
/// narrow (kSparseAcross) and sparse (kSparseSolids): on floors and walls, testing a few tiles
/// costs less than walking the path. Unit: cells. Usual value: 48.
inline constexpr std::int64_t kSparseArea = 48;
/// The most cells across (the shorter side of the swept bounds) of a sparse listing: a move much
/// longer along one axis than the other, whose bounds hold little more than its path. Unit:
/// cells. Usual value: 4.
inline constexpr std::int64_t kSparseAcross = 4;
/// The most solid cells of a sparse listing; past it the scan stops at the end of its row and
/// the walk runs (on a dense map the walk costs less). Unit: solid cells. Usual value: 4.
inline constexpr std::int64_t kSparseSolids = 4;
static_assert(kNearArea <= kSparseArea,
              "FrameLoop's listing buffer (kSparseArea cells) holds a near listing");

}  // namespace tilesweep::detail
