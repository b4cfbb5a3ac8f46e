// SPDX-License-Identifier: MIT
#pragma once

// Whether a small block of a map holds no solid cell, from its rows read 16 bytes at a time
// (SSE2). The free-move test (free_move.h) reads a short move's swept bounds so, and finds a
// frame whose bounds hold no solid cell without a loop over them. A frame's swept bounds change
// size from frame to frame (a move of 2 tiles covers 3 or 4 cells on an axis), and a loop over
// them mispredicts its exits: listing the bounds cell by cell would take about half of a free
// frame's time (FreeFlight in bench/).

#include "cell_range.h"
#include "fault_injection.h"

#include <cstdint>

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
#include <emmintrin.h>
#define TILESWEEP_SOLID_BLOCK_SSE2 1
#endif

namespace tilesweep::detail {

inline constexpr std::int64_t kSolidBlockRows = 4;
inline constexpr std::int64_t kSolidBlockColumns = 16;

/// Whether the block x by y of a map (`solid`: columns * rows bytes, row-major; x and y
/// non-empty ranges of its cells) holds no solid cell. Read where it can be, and false (not
/// known to be empty) where it cannot: a block of more than kSolidBlockRows rows or
/// kSolidBlockColumns columns, one whose last row's 16 bytes would reach past the map's last
/// cell (a block at the map's bottom right), and builds without SSE2 (the portable build).
/// The rows' 16 bytes are ORed together and compared with zero once: four rows are always read,
/// the last row again in place of those past the block, so no branch depends on the block's
/// size; a row's 16 bytes may run into the next row, and the columns past the block are masked
/// off.
[[nodiscard, gnu::always_inline]] inline bool blockHoldsNoSolidCell(const std::uint8_t* solid,
                                                                    std::int64_t columns, std::int64_t rows,
                                                                    CellRange x, CellRange y) noexcept {
#if defined(TILESWEEP_SOLID_BLOCK_SSE2)
    const std::int64_t width = x.last - x.first + 1;
    const std::int64_t height = y.last - y.first + 1;
    if (width > kSolidBlockColumns || height > kSolidBlockRows ||
        y.last * columns + x.first + 16 > columns * rows)
        return false;
    const std::uint8_t* first = solid + (y.first * columns + x.first);
    const std::int64_t lastRow = (height - 1) * columns;  // from `first`
    __m128i any = _mm_loadu_si128(reinterpret_cast<const __m128i*>(first));
    for (std::int64_t k = 1; k < kSolidBlockRows; ++k) {
        const std::int64_t row = k * columns < lastRow ? k * columns : lastRow;
        any = _mm_or_si128(any, _mm_loadu_si128(reinterpret_cast<const __m128i*>(first + row)));
    }
    const int emptyColumns = _mm_movemask_epi8(_mm_cmpeq_epi8(any, _mm_setzero_si128()));
#if defined(TILESWEEP_FAULT_SOLID_BLOCK_LAST_COLUMN_MASKED)
    const int blockColumns = (1 << (width - 1)) - 1;  // deliberate fault: the last column left out
#else
    const int blockColumns = (1 << width) - 1;
#endif
    return (emptyColumns & blockColumns) == blockColumns;
#else
    static_cast<void>(solid);
    static_cast<void>(columns);
    static_cast<void>(rows);
    static_cast<void>(x);
    static_cast<void>(y);
    return false;
#endif
}

}  // namespace tilesweep::detail
