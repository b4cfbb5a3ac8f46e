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
#include "proof_constants.h"
#include "validity.h"

#include "tilesweep/box_sweep.h"
#include "tilesweep/resolve.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace tilesweep::detail {

/// The biased exponent fields of `count` floats: |v| in [2^(f-127), 2^(f-126)) for field f, -1000
/// for a zero. `lowest` is the least field of the nonzero ones; `subnormal` whether one is.
struct FloatFields {
    int field[10];
    int lowest = 255;
    bool subnormal = false;
};

[[nodiscard]] inline FloatFields readFloatFields(const float* values, int count) noexcept {
    FloatFields r;
    int lowest = 255;  // locals, not r's members, so that the loop keeps them in registers
    bool subnormal = false;
    for (int k = 0; k < count; ++k) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        const int f = static_cast<int>((bits >> 23) & 0xff);
        const bool zero = (bits & 0x7fffffff) == 0;
        subnormal |= f == 0 && !zero;
        r.field[k] = zero ? -1000 : f;
        if (!zero) lowest = std::min(lowest, f);
    }
    r.lowest = lowest;
    r.subnormal = subnormal;
    return r;
}

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

/// Whether the fast path holds every value of this float frame exactly (see the top of this
/// file): all nonzero inputs normal, the frame valid, C + 1 - G <= 53, and no coordinate near
/// the top of float's range.
[[nodiscard]] inline bool admitFloatFrame(const ResolveInput<float>& in) noexcept {
    const float values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x,   in.box.size.y,
                              in.displacement.x, in.displacement.y, in.map.origin.x, in.map.origin.y,
                              in.map.tileSize.x, in.map.tileSize.y};
    const FloatFields f = readFloatFields(values, 10);
    if (f.subnormal || !hasValidShape(in)) return false;
    if (in.map.columns >= (1 << 24) || in.map.rows >= (1 << 24)) return false;
    int boxTop = -1000;  // |box input| < 2^(boxTop - 126)
    for (int k = 0; k < 6; ++k) boxTop = std::max(boxTop, f.field[k]);
    const int cellBits[2] = {32 - countLeadingZeros32(static_cast<std::uint32_t>(in.map.columns) + 2),
                             32 - countLeadingZeros32(static_cast<std::uint32_t>(in.map.rows) + 2)};
    // |origin + k*tile| < 2^(fo - 126) + 2^(ft - 126 + cellBits) <= 2^(edgeTop - 126)
    int edgeTop = -1000;
    for (int a = 0; a < 2; ++a)
        edgeTop = std::max(edgeTop, std::max(f.field[6 + a], f.field[8 + a] + cellBits[a]) + 1);
    // |x| + |w| + |dx| < 3 * 2^(boxTop - 126) < 2^(boxTop + 2 - 126), and the sum of that and the
    // edges' bound is below twice the larger: C = max(boxTop + 2, edgeTop) - 126, headroom 1.
    return floatSpanFits(std::max(boxTop + 2, edgeTop), 1, f.lowest);
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

/// Whether the double fast path holds every value of this double frame (see the top of this
/// file), which must be valid (hasValidShape, validity.h): nonzero inputs in [2^-250, 2^251), so that no
/// product, TwoProduct error term or filter bound comes near overflow or underflow; every tile edge origin +
/// k*tile with 0 <= k <= cells + 2 a multiple of 2^g (g the lowest set bit of origin and tile) below 2^(g +
/// 53), so that k*tile and the sum are exact doubles; |origin| < 2^47 tile, so that a cell estimate from a
/// rounded quotient is off by less than one cell; and a span of at most 104 bits between the largest
/// coordinate and the lowest set bit of the box and grid inputs, so that the far box edge's distances to tile
/// edges come out as exact pairs (farEdgeMinus).
[[nodiscard]] inline bool admitDoubleFrame(const ResolveInput<double>& in) noexcept {
    const double values[10] = {in.box.pos.x,      in.box.pos.y,      in.box.size.x,   in.box.size.y,
                               in.displacement.x, in.displacement.y, in.map.origin.x, in.map.origin.y,
                               in.map.tileSize.x, in.map.tileSize.y};
    int field[10];
    int lsb[10];
    for (int k = 0; k < 10; ++k) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        const int f = static_cast<int>((bits >> 52) & 0x7ff);  // |v| in [2^(f-1023), 2^(f-1022))
        const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
        if (f == 0 && fraction == 0) {
            field[k] = -100000;
            lsb[k] = 100000;
            continue;
        }
#if defined(TILESWEEP_FAULT_RANGE_NO_LOWER_BOUND)
        if (f > 1023 + kDoubleFrameExponentLimit)
            return false;  // deliberate fault: the lower bound 2^-250 forgotten
#else
        if (f < 1023 - kDoubleFrameExponentLimit || f > 1023 + kDoubleFrameExponentLimit) return false;
#endif
        field[k] = f - 1023;
        lsb[k] = f - 1023 - 52 + countTrailingZeros64(fraction | (std::uint64_t{1} << 52));
    }
    if (!hasValidShape(in)) return false;
    const std::int32_t cells[2] = {in.map.columns, in.map.rows};
    for (int a = 0; a < 2; ++a) {
        const int o = 6 + a;
        const int t = 8 + a;
        const int cellBits = 64 - countLeadingZeros64(static_cast<std::uint64_t>(cells[a]) + 3);
        // |origin| + (cells + 2) * tile < 2^(max(eo + 1, et + 1 + cellBits) + 1).
        const int top = std::max(field[o] + 1, field[t] + 1 + cellBits) + 1;
        if (top > std::min(lsb[o], lsb[t]) + kFastSpanBits) return false;
        if (field[o] - field[t] > kDoubleFrameOriginTileBits)
            return false;  // |origin| / tile < 2^(eo + 1 - et) <= 2^47
        // The far edge's distances to tile edges (FastAxis::farEdgeMinus). With x, w the box's
        // position and size, h = fl(x + w) and h + l = x + w: |h| <= |x| + |w| < 2^boxTop; for an
        // edge e (|e| < 2^top), fl(h - e) = a with h - e = a + b, |a| < 2^(m + 1), m = max(top,
        // boxTop), so |b| <= 2^(m - 52) and |l| <= 2^(boxTop - 53): |b + l| < 2^(m - 51). All of
        // e, x, w, h, a, b, l are multiples of 2^lowest (the least set bit of x, w, origin and
        // tile), so b + l is a double, exactly, when m - 51 <= lowest + 53.
        const int boxTop = std::max(field[a], field[2 + a]) + 2;
        const int lowest = std::min(std::min(lsb[a], lsb[2 + a]), std::min(lsb[o], lsb[t]));
        if (std::max(top, boxTop) > lowest + kDoubleFramePairSpanBits) return false;
    }
    return true;
}
}  // namespace tilesweep::detail
