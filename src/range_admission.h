// SPDX-License-Identifier: MIT
#pragma once

// Range admission: whether the fast path (fast_frame.h) holds every value of a frame exactly,
// decided from the inputs' exponent fields with a few integer operations. A frame it turns away
// is solved on the lattice (lattice_frame.h).
//
// Float frames. Every finite float is a multiple of its ulp. Let G be the lowest ulp exponent
// among the nonzero inputs. On each axis every value the solver forms (box edges at the start,
// the end and every touch position, tile edges from one cell before the map to one past it,
// grid lines next to them, and every difference of two of these) is a multiple of 2^G below
// |x| + |w| + |dx| + |origin| + (cells + 2) * tile, which admitFloatFrame bounds by 2^(C+1) from
// the inputs' exponent fields; when C + 1 - G <= 53 every one of them is a double exactly
// (kFastSpanBits, proof_constants.h, gives the list and the proof). The single-tile sweep takes
// the same test with its own coordinates (admitFloatPair).
//
// Double frames. Every coordinate the solver forms is a double or an exact pair (admitDoubleFrame
// gives the conditions, FastAxis::farEdgeMinus the use of the last one).

#include "bit_ops.h"
#include "fault_injection.h"
#include "frame_input.h"
#include "input_window.h"
#include "proof_constants.h"
#include "validity.h"

#include "tilesweep/box_sweep.h"
#include "tilesweep/detail/map_range.h"
#include "tilesweep/resolve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace tilesweep::detail {

/// The float range test itself, for values below 2^(top - 126 + headroom) (2^C with C = top -
/// 126 bounds the coordinates, `headroom` bits more the differences the solver takes) that are
/// multiples of the ulp of the smallest input (field `lowest`, ulp 2^G, G = lowest - 150):
/// C + headroom - G <= 53, and C + headroom <= kFloatFrameTopExponent.
[[nodiscard]] inline bool floatSpanFits(int top, int headroom, int lowest) noexcept {
    int span = (top - 126 + headroom) - (lowest - 150);
#if defined(TILESWEEP_FAULT_FAST_RANGE_TOO_WIDE)
    span -= 4;  // deliberate fault: the range test four binades too generous (fault_injection.h)
#endif
#if defined(TILESWEEP_FAULT_FAST_RANGE_FAR_TOO_WIDE)
    span -= 6;  // deliberate fault: six binades too generous, past the test's slack
#endif
    return span <= kFastSpanBits && top - 126 + headroom <= kFloatFrameTopExponent;
}

/// The part of the range test that depends on the map alone (origin, tile size, dimensions,
/// cells) is a MapRange (tilesweep/detail/map_range.h), so that a prepared map computes it once
/// (mover.h, PreparedMap) and resolveMove once a frame. On each axis: `top`, an exponent bounding
/// every tile edge origin + k*tile the solver forms, and `lowest`, an exponent every map input on
/// the axis is a multiple of (float: biased fields, as the float test below reads them; double:
/// unbiased exponents). `admitted` is false for a map the fast path cannot take at all (invalid
/// shape, or outside the ranges below); its frames go to the lattice, which checks validity.

/// The bits of a float.
[[nodiscard, gnu::always_inline]] inline std::uint32_t bitsOf(float v) noexcept {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

/// The magnitude bits of a float (its sign cleared): as unsigned integers they order like |v|,
/// and a magnitude's bits >> 23 are its biased exponent field (0 for zero and subnormals, 255 for
/// infinities and NaNs).
[[nodiscard, gnu::always_inline]] inline std::uint32_t magnitudeBits(float v) noexcept {
    return bitsOf(v) & 0x7fffffffu;
}

/// The least field among nonzero magnitudes, given the least of their bits minus one (a zero's
/// bits minus one wrap to the largest value, so zeros never count): 255 when all were zero.
[[nodiscard, gnu::always_inline]] inline int leastField(std::uint32_t leastMinusOne) noexcept {
    const std::uint32_t least = leastMinusOne + 1;
    return least == 0 ? 255 : static_cast<int>(least >> 23);
}

/// The magnitude bits of a double (its sign cleared): as unsigned integers they order like |v|,
/// and bits >> 52 is the biased exponent field (0 for zero and subnormals, 2047 for infinities
/// and NaNs).
[[nodiscard, gnu::always_inline]] inline std::uint64_t magnitudeBits(double v) noexcept {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits & ~(std::uint64_t{1} << 63);
}

/// The unbiased exponent of a double's lowest set bit (its magnitude bits), 100000 for a zero so
/// that a zero bounds nothing.
[[nodiscard, gnu::always_inline]] inline int lowestBitOf(std::uint64_t magnitude) noexcept {
    const int field = static_cast<int>(magnitude >> 52);
    const std::uint64_t significand = (magnitude & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
    const int bit = field - 1023 - 52 + countTrailingZeros64(significand);  // defined for a zero too
    return magnitude == 0 ? 100000 : bit;
}

/// The cell estimates' magnitude bound (FastFrame::magnitude) for every frame whose box inputs
/// lie below `limit` (a power of two) in magnitude, on an axis of origin `origin`: a box's low
/// edge is below limit, its high edge (the sum with the size, exact for float frames, rounded to
/// nearest for double ones) at most 2 limit, the displacement below limit. The sum is formed in
/// the frame's order, so that by monotonic rounding it is at least the frame's own.
[[nodiscard]] inline double windowMagnitudeOf(double limit, double origin) noexcept {
#if defined(TILESWEEP_FAULT_WINDOW_MAGNITUDE_SHORT)
    return ((limit + limit) + limit) +
           std::fabs(origin);  // deliberate fault: the high edge read as below limit
#else
    return ((limit + 2 * limit) + limit) + std::fabs(origin);
#endif
}

/// The window's share of FastFrame::linesClearOf, for the frames in the map's window: every box
/// input below 2^W in magnitude (the window's limit), so every end below 2^(W + 1) (an end lies
/// between the start and the start plus the displacement). The proof of linesClearOf then needs
/// W + 1 <= min(lineBit, the size's lowest bit) + p: per axis, windowLinesClearBits says whether the
/// grid's half holds; the size's half is that the size is a multiple of g = 2^(W + 1 - p), which
/// FastFrame reads as fl(size + C) - C == size with C = 2^52 g (sizeGrainShift): a size in the
/// window is below 2^W <= 2^52 g, so size + C lies in [C, 2C), where doubles are the multiples of
/// g, and it is one exactly when the size is; the subtraction is exact.
inline void setWindowLinesClear(MapRange& r, int windowExponent, int p) noexcept {
#if defined(TILESWEEP_FAULT_WINDOW_LINES_CLEAR_BINADE_SHORT)
    const int ends = windowExponent;  // deliberate fault: the ends read as below the window's limit
#else
    const int ends = windowExponent + 1;
#endif
    r.windowLinesClearBits = 0;
    for (int a = 0; a < 2; ++a) r.windowLinesClearBits |= (ends <= r.lineBit[a] + p ? 1 : 0) << a;
    const std::uint64_t shiftBits = static_cast<std::uint64_t>(ends - p + 52 + 1023)
                                    << 52;  // 2^(ends - p + 52)
    std::memcpy(&r.sizeGrainShift, &shiftBits, sizeof shiftBits);
}

/// The float whose bits are the biased field `field` alone: 2^(field - 127), for fields 1 to 254;
/// infinity for 255.
[[nodiscard]] inline float powerOfField(int field) noexcept {
    const std::uint32_t bits = static_cast<std::uint32_t>(field) << 23;
    float v = 0;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

/// The float map's range (see the top of this file): top[a] is edgeTop on the axis, a biased
/// field with |origin + k*tile| < 2^(top - 126) for |k| <= cells + 2; lowest[a] the least field
/// of the axis's nonzero map inputs (255 when none is nonzero; 0 when one is subnormal, which
/// the frame test turns away). NaNs and infinities read field 255 and fail the frame test's top.
/// lineBit[a]: the lowest set bit of the axis's origin and tile (FastFrame::linesClearOf).
[[nodiscard]] inline MapRange floatMapRange(const TileMapView<float>& map) noexcept {
    MapRange r;
    r.admitted = mapHasValidShape(map) && map.columns < (1 << 24) && map.rows < (1 << 24);
    const float origin[2] = {map.origin.x, map.origin.y};
    const float tile[2] = {map.tileSize.x, map.tileSize.y};
    const std::int32_t cells[2] = {map.columns, map.rows};
    for (int a = 0; a < 2; ++a) {
        const std::uint32_t o = magnitudeBits(origin[a]);
        const std::uint32_t t = magnitudeBits(tile[a]);
        const int cellBits = 32 - countLeadingZeros32(static_cast<std::uint32_t>(cells[a]) + 2);
        // |origin + k*tile| < 2^(fo - 126) + 2^(ft - 126 + cellBits) <= 2^(top - 126). A zero
        // origin reads field 0, below any tile's.
        r.top[a] = std::max(static_cast<int>(o >> 23), static_cast<int>(t >> 23) + cellBits) + 1;
        r.lowest[a] = leastField(std::min(o - 1, t - 1));
        r.lineBit[a] = std::min(lowestBitOf(magnitudeBits(static_cast<double>(origin[a]))),
                                lowestBitOf(magnitudeBits(static_cast<double>(tile[a]))));
        r.inverseTile[a] = 1 / static_cast<double>(tile[a]);
    }
    // The short form's window (admitFloatFrameInWindow): box fields up to fH = top - 1, the
    // binade of the map's farthest tile edges (a box on the map lies within), so that the full
    // test's top is at most fH + 2 = top + 1; and down to the least fL the span test allows with
    // that top. Field fL is 2^(fL - 127) and up, field fH below 2^(fH - 126).
    const int top = std::max(r.top[0], r.top[1]) + 1;
    const int mapLowest = std::min(r.lowest[0], r.lowest[1]);
    const int highField = top - 2;
    const int lowField = std::max(1, top - 126 + 1 + 150 - kFastSpanBits);
    r.common = r.admitted && mapLowest != 0 && lowField <= highField && highField <= 254 &&
               floatSpanFits(top, 1, std::min(lowField, mapLowest));
#if defined(TILESWEEP_FAULT_FLOAT_WINDOW_TOO_LOW)
    r.commonLeast = powerOfField(std::max(1, lowField - 6));  // deliberate fault
#else
    r.commonLeast = powerOfField(lowField);
#endif
    r.commonLimit = powerOfField(std::min(highField + 1, 255));  // 255: infinity (read only when common)
    for (int a = 0; a < 2; ++a)
        r.windowMagnitude[a] =
            windowMagnitudeOf(static_cast<double>(r.commonLimit), static_cast<double>(origin[a]));
    setWindowLinesClear(r, std::min(highField + 1, 255) - 127,
                        std::numeric_limits<float>::digits);  // commonLimit = 2^W
    return r;
}

/// Whether the fast path holds every value of this float frame exactly (see the top of this
/// file), given its map's range: all nonzero inputs normal, the frame valid, C + 1 - G <= 53,
/// and no coordinate near the top of float's range. The six box inputs are read as integers in a
/// tree of scalar minimums and maximums (a loop over an array invites a vectorization that needs
/// SSE4.1 for unsigned minimums and costs twice the instructions without it).
[[nodiscard, gnu::always_inline]] inline bool admitFloatFrameFully(FrameInput<float> in,
                                                                   const MapRange& map) noexcept {
    const std::uint32_t x = magnitudeBits(in.box.pos.x);
    const std::uint32_t y = magnitudeBits(in.box.pos.y);
    const std::uint32_t w = bitsOf(in.box.size.x);  // with the sign: a negative size is refused
    const std::uint32_t h = bitsOf(in.box.size.y);
    const std::uint32_t dx = magnitudeBits(in.displacement.x);
    const std::uint32_t dy = magnitudeBits(in.displacement.y);
    // Box sizes > 0: as signed integers, the bits are positive (a NaN passes here, fails the top).
    const bool positiveSizes = static_cast<std::int32_t>(w) > 0 && static_cast<std::int32_t>(h) > 0;
    const std::uint32_t largest = std::max(std::max(std::max(x, y), std::max(w, h)), std::max(dx, dy));
    const std::uint32_t leastMinusOne =
        std::min(std::min(std::min(x - 1, y - 1), std::min(w - 1, h - 1)), std::min(dx - 1, dy - 1));
    // The least field among the nonzero inputs; 0 when one of them is subnormal (turned away).
    // (When all six are zero, the wrapped sum reads field 0 too; zero sizes are turned away
    // anyway. No test for it, so that the minimums above stay conditional moves.)
    const int lowest =
        std::min(std::min(map.lowest[0], map.lowest[1]), static_cast<int>((leastMinusOne + 1) >> 23));
    // |x| + |w| + |dx| < 3 * 2^(boxTop - 126) < 2^(boxTop + 2 - 126), and the sum of that and the
    // edges' bound is below twice the larger: C = max(boxTop + 2, edgeTop) - 126, headroom 1.
    // (A negative size makes `largest` a field above 255, refused here too.)
    const int boxTop = static_cast<int>(largest >> 23);
    const int top = std::max(boxTop + 2, std::max(map.top[0], map.top[1]));
    const bool fits = floatSpanFits(top, 1, lowest);
    return map.admitted & positiveSizes & (lowest != 0) & fits;
}

/// The short form of admitFloatFrameFully, for the frames of a game: the map's window
/// (floatMapRange: MapRange::commonLeast and commonLimit, 2^(fL - 127) and 2^(fH - 126)) holds
/// every nonzero box input, the sizes positive (input_window.h). Then the box's fields lie in
/// [fL, fH], so the full test's top is at most fH + 2 (which is above the map's tops) and its
/// lowest at least min(fL, map's lowests): the values floatMapRange checked once for the map
/// (MapRange::common), and the full test is monotonic in both. A few vector comparisons: no
/// exponent arithmetic. A frame outside the window takes the full test, which decides.
[[nodiscard, gnu::always_inline]] inline bool admitFloatFrameInWindow(FrameInput<float> in,
                                                                      const MapRange& map) noexcept {
    return map.common & boxInputsInWindow(in.box, in.displacement, map.commonLeast, map.commonLimit);
}

/// Whether the fast path holds every value of this float frame exactly: the short form, then,
/// for a frame outside the map's window, the full test.
[[nodiscard, gnu::always_inline]] inline bool admitFloatFrame(FrameInput<float> in,
                                                              const MapRange& map) noexcept {
    if (admitFloatFrameInWindow(in, map)) return true;  // one branch, which a game predicts
    return admitFloatFrameFully(in, map);
}

/// admitFloatFrame for a map not prepared: its range, then the frame's.
[[nodiscard]] inline bool admitFloatFrame(FrameInput<float> in) noexcept {
    return admitFloatFrame(in, floatMapRange(in.map));
}

/// The same for one box against one tile (sweepBox), with the box's edges (sums of three
/// inputs) and the tile's bounds as the coordinates: every coordinate below 2^C, every
/// difference of two below 2^(C+1), all multiples of 2^G; (C + 1) - G <= 53.
[[nodiscard, gnu::always_inline]] inline bool admitFloatPair(const BoxSweepInput<float>& in) noexcept {
    const float values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x, in.box.size.y,
                              in.displacement.x, in.displacement.y, in.tileMin.x,  in.tileMin.y,
                              in.tileMax.x,      in.tileMax.y};
    int lowest = 255;
    int boxTop = 0;
    int tileTop = 0;
    for (int k = 0; k < 10; ++k) {  // one pass (sweepBox is a few dozen instructions in all)
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        const int f = static_cast<int>((bits >> 23) & 0xff);  // |v| in [2^(f-127), 2^(f-126))
        if ((bits & 0x7fffffff) == 0) continue;
        if (f == 0) return false;  // subnormal
        lowest = std::min(lowest, f);
        if (k < 6)
            boxTop = std::max(boxTop, f);
        else
            tileTop = std::max(tileTop, f);
    }
    return floatSpanFits(std::max(boxTop + 2, tileTop), 1, lowest);
}

/// Whether a nonzero double (its magnitude bits) lies within [2^-250, 2^251)
/// (kDoubleFrameExponentLimit): one unsigned comparison of the field's distance from the bottom.
[[nodiscard, gnu::always_inline]] inline bool fieldInDoubleFrameRange(std::uint64_t magnitude) noexcept {
    const auto field = static_cast<unsigned>(magnitude >> 52);
#if defined(TILESWEEP_FAULT_RANGE_NO_LOWER_BOUND)
    return field <= 1023 + kDoubleFrameExponentLimit;  // deliberate fault: 2^-250 forgotten
#else
    return field - (1023 - kDoubleFrameExponentLimit) <= 2 * kDoubleFrameExponentLimit;
#endif
}

/// Whether a double (its magnitude bits) is zero or within [2^-250, 2^251).
[[nodiscard, gnu::always_inline]] inline bool inDoubleFrameRange(std::uint64_t magnitude) noexcept {
    const bool inRange = fieldInDoubleFrameRange(magnitude);
    return (magnitude == 0) | inRange;
}

/// The unbiased exponent field of a double (its magnitude bits): |v| in [2^f, 2^(f+1)); -100000
/// for a zero, so that a zero bounds nothing.
[[nodiscard, gnu::always_inline]] inline int fieldOf(std::uint64_t magnitude) noexcept {
    return magnitude == 0 ? -100000 : static_cast<int>(magnitude >> 52) - 1023;
}

/// The double map's range (see admitDoubleFrame): per axis, top[a] with |origin + k*tile| <
/// 2^top[a] for |k| <= cells + 2, and lowest[a] the least set bit of origin and tile; admitted
/// when the map is valid, both are in range, every such tile edge is a multiple of 2^lowest[a]
/// below 2^(lowest[a] + 53), and |origin| < 2^47 tile.
[[nodiscard]] inline MapRange doubleMapRange(const TileMapView<double>& map) noexcept {
    MapRange r;
    bool admitted = mapHasValidShape(map);
    bool common = true;  // see admitDoubleFrame's short form
    const double origin[2] = {map.origin.x, map.origin.y};
    const double tile[2] = {map.tileSize.x, map.tileSize.y};
    const std::int32_t cells[2] = {map.columns, map.rows};
    for (int a = 0; a < 2; ++a) {
        const std::uint64_t o = magnitudeBits(origin[a]);
        const std::uint64_t t = magnitudeBits(tile[a]);
        const int cellBits = 64 - countLeadingZeros64(static_cast<std::uint64_t>(cells[a]) + 3);
        // |origin| + (cells + 2) * tile < 2^(max(eo + 1, et + 1 + cellBits) + 1).
        r.top[a] = std::max(fieldOf(o) + 1, fieldOf(t) + 1 + cellBits) + 1;
        r.lowest[a] = std::min(lowestBitOf(o), lowestBitOf(t));
        r.lineBit[a] = r.lowest[a];
        const bool inRange = inDoubleFrameRange(o) && inDoubleFrameRange(t);
        const bool exactEdges = r.top[a] <= r.lowest[a] + kFastSpanBits;
        const bool nearOrigin =
            fieldOf(o) - fieldOf(t) <= kDoubleFrameOriginTileBits;  // |origin| / tile < 2^47
        admitted = admitted && inRange && exactEdges && nearOrigin;
        const int spanned = std::max(r.top[a], kCommonBoxTop);
        common = common && spanned <= std::min(kCommonLowestBit, r.lowest[a]) + kDoubleFramePairSpanBits;
        r.inverseTile[a] = 1 / tile[a];
        r.windowMagnitude[a] = windowMagnitudeOf(kCommonLargest, origin[a]);
    }
    r.admitted = admitted;
    r.common = admitted && common;
    setWindowLinesClear(r, kCommonLargestExponent, kDoubleDigits);
    return r;
}

/// Whether the double fast path holds every value of this double frame (see the top of this
/// file), given its map's range (doubleMapRange): the frame valid; nonzero inputs in [2^-250,
/// 2^251), so that no product, TwoProduct error term or filter bound comes near overflow or
/// underflow; every tile edge origin + k*tile with 0 <= k <= cells + 2 a multiple of 2^g (g the
/// lowest set bit of origin and tile) below 2^(g + 53), so that k*tile and the sum are exact
/// doubles; |origin| < 2^47 tile, so that a cell estimate from a rounded quotient is off by less
/// than one cell; and a span of at most 104 bits between the largest coordinate and the lowest
/// set bit of the box and grid inputs, so that the far box edge's distances to tile edges come
/// out as exact pairs (farEdgeMinus). Branch-free over the six box inputs.
[[nodiscard, gnu::always_inline]] inline bool admitDoubleFrameFully(FrameInput<double> in,
                                                                    const MapRange& map) noexcept {
    const std::uint64_t x = magnitudeBits(in.box.pos.x);
    const std::uint64_t y = magnitudeBits(in.box.pos.y);
    const std::uint64_t w = magnitudeBits(in.box.size.x);
    const std::uint64_t h = magnitudeBits(in.box.size.y);
    const std::uint64_t dx = magnitudeBits(in.displacement.x);
    const std::uint64_t dy = magnitudeBits(in.displacement.y);
    // Every nonzero input in [2^-250, 2^251): the largest magnitude's field and the least nonzero
    // one's (a zero's bits minus one wrap to the largest value, so zeros never count; a NaN or an
    // infinity has the largest field).
    const std::uint64_t largest = std::max(std::max(std::max(x, y), std::max(w, h)), std::max(dx, dy));
    const std::uint64_t least =
        std::min(std::min(std::min(x - 1, y - 1), std::min(w - 1, h - 1)), std::min(dx - 1, dy - 1)) + 1;
    // (All six zero would read field 0 and fail; zero sizes are turned away anyway.)
    const bool positiveSizes = (in.box.size.x > 0) & (in.box.size.y > 0);
    const bool largestInRange = fieldInDoubleFrameRange(largest);
    const bool leastInRange = fieldInDoubleFrameRange(least);
    const bool inRange = largestInRange & leastInRange;
    // The far edge's distances to tile edges (FastAxis::farEdgeMinus). With x, w the box's
    // position and size, h = fl(x + w) and h + l = x + w: |h| <= |x| + |w| < 2^boxTop; for an
    // edge e (|e| < 2^top), fl(h - e) = a with h - e = a + b, |a| < 2^(m + 1), m = max(top,
    // boxTop), so |b| <= 2^(m - 52) and |l| <= 2^(boxTop - 53): |b + l| < 2^(m - 51). All of e, x,
    // w, h, a, b, l are multiples of 2^lowest (the least set bit of x, w, origin and tile), so
    // b + l is a double, exactly, when m - 51 <= lowest + 53. (The larger magnitude has the
    // larger field; a zero position reads field 0, below the size's.)
    const int boxTopX = static_cast<int>(std::max(x, w) >> 52) - 1023 + 2;
    const int boxTopY = static_cast<int>(std::max(y, h) >> 52) - 1023 + 2;
    const int lowestX = std::min(std::min(lowestBitOf(x), lowestBitOf(w)), map.lowest[0]);
    const int lowestY = std::min(std::min(lowestBitOf(y), lowestBitOf(h)), map.lowest[1]);
    const bool spanX = std::max(map.top[0], boxTopX) <= lowestX + kDoubleFramePairSpanBits;
    const bool spanY = std::max(map.top[1], boxTopY) <= lowestY + kDoubleFramePairSpanBits;
    return map.admitted & inRange & positiveSizes & spanX & spanY;
}

/// The short form of admitDoubleFrameFully (above), for the frames of a game: the box's inputs in
/// the window [2^-20, 2^30) (kCommonLeast and kCommonLargest, proof_constants.h, which says why it
/// suffices; input_window.h) on a map whose half of the test holds for every such frame
/// (MapRange::common). A frame outside the window takes the full test, which decides.
[[nodiscard, gnu::always_inline]] inline bool admitDoubleFrameInWindow(FrameInput<double> in,
                                                                       const MapRange& map) noexcept {
    return map.common & boxInputsInWindow(in.box, in.displacement, kCommonLeast, kCommonLargest);
}

/// Whether the double fast path holds every value of this frame: the short form, then, for a
/// frame outside the window, the full test.
[[nodiscard, gnu::always_inline]] inline bool admitDoubleFrame(FrameInput<double> in,
                                                               const MapRange& map) noexcept {
    if (admitDoubleFrameInWindow(in, map)) return true;  // one branch, which a game predicts
    return admitDoubleFrameFully(in, map);
}

/// admitDoubleFrame for a map not prepared: its range, then the frame's.
[[nodiscard]] inline bool admitDoubleFrame(FrameInput<double> in) noexcept {
    return admitDoubleFrame(in, doubleMapRange(in.map));
}

/// The short form and the full test in either type (frame_solve.cpp tells which admitted a
/// frame, so that a frame in the window takes its map's windowMagnitude).
[[nodiscard, gnu::always_inline]] inline bool admitFrameInWindow(FrameInput<float> in,
                                                                 const MapRange& map) noexcept {
    return admitFloatFrameInWindow(in, map);
}
[[nodiscard, gnu::always_inline]] inline bool admitFrameInWindow(FrameInput<double> in,
                                                                 const MapRange& map) noexcept {
    return admitDoubleFrameInWindow(in, map);
}
[[nodiscard, gnu::always_inline]] inline bool admitFrameFully(FrameInput<float> in,
                                                              const MapRange& map) noexcept {
    return admitFloatFrameFully(in, map);
}
[[nodiscard, gnu::always_inline]] inline bool admitFrameFully(FrameInput<double> in,
                                                              const MapRange& map) noexcept {
    return admitDoubleFrameFully(in, map);
}

/// The map's range in either type.
[[nodiscard]] inline MapRange mapRangeOf(const TileMapView<float>& map) noexcept {
    return floatMapRange(map);
}
[[nodiscard]] inline MapRange mapRangeOf(const TileMapView<double>& map) noexcept {
    return doubleMapRange(map);
}

}  // namespace tilesweep::detail
