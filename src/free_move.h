// SPDX-License-Identifier: MIT
#pragma once

// The cheap exit of the game-loop calls: a move whose swept bounds meet no solid cell.
//
// Such a move hits nothing and starts inside nothing, so resolveMove returns Moved, no lists,
// and on each axis the exact end x + d rounded by CONTRACT.md's rule. This file decides that
// with a byte scan over a widened range of cells and computes the rounded end, for the cases
// where it can do so exactly; anything else (a solid byte in range, or a rounding it does not
// settle) returns false and the caller runs the full resolver. Results are bit-identical to
// resolveMove's (tests/mover_test.cpp compares them over random scenes).

#include "cell_range.h"
#include "exact_double.h"
#include "final_rounding.h"
#include "proof_constants.h"

#include "tilesweep/math.h"
#include "tilesweep/tile_map.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace tilesweep::detail {

/// The exact end x + d of one free axis, as the arithmetic final_rounding.h asks for: the sum
/// s = fl(x + d) and its error (x + d) - s, exact by TwoSum. It cannot test grid lines, so the
/// grid-line exception answers Undecided and the caller runs the full resolver.
template <class T>
class FreeEnd {
public:
    struct Sum {
        T s;
        T error;
    };
    FreeEnd(T x, T d) noexcept : x_(x), d_(d) {}
    T start(int) const noexcept { return x_; }
    int compareWithStart(const Sum&, int) const noexcept { return (d_ > 0) - (d_ < 0); }
    T roundDirected(const Sum& e, bool up) const noexcept {
        // By the bits, not std::nextafter (a libm call): the same neighbour, infinity past the
        // largest finite value included.
        if (up) return e.error > 0 ? stepScalar(e.s, true) : e.s;
        return e.error < 0 ? stepScalar(e.s, false) : e.s;
    }
    T roundNearest(const Sum& e) const noexcept { return e.s; }
    bool isExactly(const Sum& e, T v) const noexcept { return e.error == 0 && e.s == v; }
    LineTest gridLineAhead(const Sum&, T, int) const noexcept { return LineTest::Undecided; }

private:
    T x_;
    T d_;
};

/// The exact end x + d rounded by the contract's rule (roundFinal, the frame loop's own), when
/// that is settled here: d == 0 keeps x's bits (a -0 stays -0); a zero or infinite sum, or an
/// inexact one toward -infinity (the grid-line exception may apply), returns false.
template <class T>
[[nodiscard]] inline bool roundFreeCoordinate(T x, T d, T& q) noexcept {
    if (d == 0) {
        q = x;
        return true;
    }
    const T s = x + d;
    if (!std::isfinite(s) || s == 0) return false;
    return roundFinal(FreeEnd<T>(x, d), typename FreeEnd<T>::Sum{s, twoSum(x, d).lo}, 0, q);
}

/// The cells of one axis that a closed interval [lo, hi] can touch, widened by one cell on each
/// side and clamped to [0, count) (estimateCells: empty when the interval lies off the map);
/// false (not settled here: resolve fully) when `magnitude`, the sum of the input magnitudes, is
/// too large against the tile for the estimate (kFreeMoveMagnitudeScale, proof_constants.h: the
/// estimate is then within a sixteenth of a cell, which the widening by one covers with the
/// closed ends).
[[nodiscard]] inline bool cellRangeOf(double lo, double hi, double origin, double tile, double inverseTile,
                                      double magnitude, std::int32_t count, CellRange& range) noexcept {
    if (!(magnitude * kFreeMoveMagnitudeScale < tile * 0.25)) return false;  // not settled here
    range = estimateCells((lo - origin) * inverseTile, (hi - origin) * inverseTile, 1.0, count);
    return true;
}

/// True when a row-major block of cells holds no solid byte. Rows are read from the side the box
/// moves toward on y (`down`: from the last row up), where a mover's floor or ceiling lies, and
/// each row stops at its first solid byte: a move that is not free usually fails on the first row
/// read. (Rows are a few cells wide here: a plain loop, not a vectorised OR with its set-up.)
[[nodiscard]] inline bool blockIsEmpty(const std::uint8_t* solid, std::int32_t columns, const CellRange& x,
                                       const CellRange& y, bool down) noexcept {
    const std::int64_t rows = y.last - y.first + 1;
    for (std::int64_t n = 0; n < rows; ++n) {
        const std::int64_t j = down ? y.last - n : y.first + n;
        const std::uint8_t* row = solid + j * columns;
        for (std::int64_t i = x.first; i <= x.last; ++i)
            if (row[i] != 0) return false;
    }
    return true;
}

/// Whether the cells that the move of `box` by `d` sweeps hold no solid byte (on each axis, from
/// the box's low edge at the start or the end to its high edge at the start or the end, widened
/// by one cell); false too when the estimate is not settled here. The map must have cells.
template <class T>
[[nodiscard]] inline bool sweptCellsAreEmpty(const TileMapView<T>& map, Vec2<double> inverseTile,
                                             const Box<T>& box, Vec2<T> d) noexcept {
    const double x = static_cast<double>(box.pos.x);
    const double y = static_cast<double>(box.pos.y);
    const double dx = static_cast<double>(d.x);
    const double dy = static_cast<double>(d.y);
    const double w = static_cast<double>(box.size.x);
    const double h = static_cast<double>(box.size.y);
    const double ox = static_cast<double>(map.origin.x);
    const double oy = static_cast<double>(map.origin.y);
    const double magX = std::fabs(x) + std::fabs(dx) + w + std::fabs(ox);
    const double magY = std::fabs(y) + std::fabs(dy) + h + std::fabs(oy);
    CellRange cx{};
    CellRange cy{};
    if (!cellRangeOf(dx < 0 ? x + dx : x, dx > 0 ? x + dx + w : x + w, ox,
                     static_cast<double>(map.tileSize.x), inverseTile.x, magX, map.columns, cx) ||
        !cellRangeOf(dy < 0 ? y + dy : y, dy > 0 ? y + dy + h : y + h, oy,
                     static_cast<double>(map.tileSize.y), inverseTile.y, magY, map.rows, cy))
        return false;
    return cx.first > cx.last || cy.first > cy.last || blockIsEmpty(map.solid, map.columns, cx, cy, dy > 0);
}

/// If the move of `box` by `d` through `map` meets no solid cell and its end is settled here,
/// stores the end in `position` and returns true; otherwise false (resolve it fully).
/// The inputs must be finite with sizes > 0 and the map valid (the caller checks).
template <class T>
[[nodiscard]] inline bool tryFreeMove(const TileMapView<T>& map, Vec2<double> inverseTile, const Box<T>& box,
                                      Vec2<T> d, Vec2<T>& position) noexcept {
    // The cells first: a move that is not free mostly fails there, before any rounding.
    if (map.columns != 0 && map.rows != 0 && !sweptCellsAreEmpty(map, inverseTile, box, d)) return false;
    Vec2<T> end{};
    if (!roundFreeCoordinate(box.pos.x, d.x, end.x) || !roundFreeCoordinate(box.pos.y, d.y, end.y))
        return false;
    position = end;
    return true;
}

}  // namespace tilesweep::detail
