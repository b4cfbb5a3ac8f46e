// SPDX-License-Identifier: MIT
#pragma once

// Which cells of a small block of a map are solid, as one bit per cell: each of the block's rows
// read as 16 bytes and compared with zero at once (SSE2). The near listing of a short move
// (frame_loop.h, collectNear) reads its swept bounds so, and a frame whose bounds hold no solid
// cell moves freely without a loop over them. A frame's swept bounds change size from frame to
// frame (a move of 2 tiles covers 3 or 4 cells on an axis), and a loop over them mispredicts its
// exits: on FreeFlight<double>/4 (every frame free), listing the bounds cell by cell took 18 of
// the frame's 35 ns (bench/, the listing left out), and with this read the frame takes 21 ns.

#include "cell_range.h"
#include "fault_injection.h"

#include <cstdint>

#if defined(__SSE2__) && !defined(TILESWEEP_PORTABLE_INTEGERS)
#include <emmintrin.h>
#define TILESWEEP_SOLID_BLOCK_SSE2 1
#endif

namespace tilesweep::detail {

/// The solid cells of a block of at most kSolidBlockRows rows of at most kSolidBlockColumns
/// cells: bit 16k + c is cell (first column + c, first row + k).
struct SolidBlock {
    std::uint64_t bits = 0;
};

inline constexpr std::int64_t kSolidBlockRows = 4;
inline constexpr std::int64_t kSolidBlockColumns = 16;

/// Reads the solid cells of the block x by y of a map (`solid`: columns * rows bytes, row-major;
/// x and y non-empty ranges of its cells) into `out`. False, writing nothing, where it cannot:
/// a block of more than kSolidBlockRows rows or kSolidBlockColumns columns, one whose last row's
/// 16 bytes would reach past the map's last cell (a block at the map's bottom right), and
/// builds without SSE2 (the portable build). The 16 bytes of a row may run into the next row;
/// the columns past the block are masked off. Rows are read in a fixed count of four, the last
/// row again in place of those past the block, and masked off, so no branch depends on the
/// block's size.
[[nodiscard, gnu::always_inline]] inline bool readSolidBlock(const std::uint8_t* solid, std::int64_t columns,
                                                             std::int64_t rows, CellRange x, CellRange y,
                                                             SolidBlock& out) noexcept {
#if defined(TILESWEEP_SOLID_BLOCK_SSE2)
    const std::int64_t width = x.last - x.first + 1;
    const std::int64_t height = y.last - y.first + 1;
    if (width > kSolidBlockColumns || height > kSolidBlockRows || height < 1 ||
        (y.first + kSolidBlockRows - 1) * columns + x.first + 16 > columns * rows)
        return false;
#if defined(TILESWEEP_FAULT_SOLID_BLOCK_LAST_COLUMN_MASKED)
    const auto columnMask = static_cast<std::uint64_t>((1u << (width - 1)) - 1);  // deliberate fault
#else
    const auto columnMask = static_cast<std::uint64_t>((1u << width) - 1);
#endif
    // The block's rows, repeated for each of them: 1, 2, 3 or 4 copies of the column mask.
    static constexpr std::uint64_t kRowCopies[kSolidBlockRows] = {0x1, 0x10001, 0x100010001, 0x1000100010001};
    const std::uint64_t blockMask = columnMask * kRowCopies[height - 1];
    const std::uint8_t* row = solid + y.first * columns + x.first;
    const __m128i zero = _mm_setzero_si128();
    std::uint64_t empty = 0;
    for (std::int64_t k = 0; k < kSolidBlockRows; ++k) {
        const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + k * columns));
        empty |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, zero))))
                 << (16 * k);
    }
    const std::uint64_t bits = ~empty & blockMask;
    out.bits = bits;
    return true;
#else
    static_cast<void>(solid);
    static_cast<void>(columns);
    static_cast<void>(rows);
    static_cast<void>(x);
    static_cast<void>(y);
    static_cast<void>(out);
    return false;
#endif
}

}  // namespace tilesweep::detail
