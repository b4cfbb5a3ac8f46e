// SPDX-License-Identifier: MIT
#pragma once

// Internal: what the fast path's range test needs from a map alone, kept by PreparedMap (mover.h)
// so that it is computed once per map instead of once per frame. Not part of the API: its fields
// and their meaning belong to src/range_admission.h, which computes and reads them.

namespace tilesweep::detail {

/// The map's half of the range test (src/range_admission.h, floatMapRange and doubleMapRange):
/// whether the fast path can take frames through this map at all, and per axis an exponent above
/// every tile edge the solver forms (`top`) and one every map input is a multiple of (`lowest`);
/// and the tile size's reciprocal per axis, fl(1 / tile) in double, which the fast path's cell
/// estimates multiply by (src/fast_frame.h; every estimate carries a certified margin).
/// `common`: whether the range test's short form may decide this map's frames; for float maps,
/// those whose nonzero box inputs have magnitudes in [commonLeast, commonLimit) (the window).
/// `windowMagnitude` per axis: for a frame in the window, a bound on the magnitudes that the fast
/// path's cell estimates sum for their margins (src/fast_frame.h, FastFrame::magnitude).
/// `windowLinesClearBits` (bit a for axis a) and `sizeGrainShift`: the window's share of the grid-line
/// shortcut (src/range_admission.h, setWindowLinesClear).
/// `lineBit` per axis: the exponent of the lowest set bit of the origin and the tile size, which
/// every grid line is a multiple of (src/fast_frame.h, FastFrame::linesClearOf).
struct MapRange {
    bool admitted = false;
    bool common = false;
    int top[2] = {0, 0};
    int lowest[2] = {0, 0};
    int lineBit[2] = {0, 0};
    float commonLeast = 0;
    float commonLimit = 0;
    double inverseTile[2] = {0, 0};
    double windowMagnitude[2] = {0, 0};
    int windowLinesClearBits = 0;
    double sizeGrainShift = 0;
};

}  // namespace tilesweep::detail
