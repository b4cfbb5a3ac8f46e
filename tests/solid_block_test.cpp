// SPDX-License-Identifier: MIT
// The block read of the free-move test (blockHoldsNoSolidCell, src/solid_block.h), which tells
// the fast path that a short move's swept bounds hold no solid cell, against the map's bytes
// read one by one: it says "empty" exactly for the blocks it can read (at most 4 rows of 16
// columns, not reaching past the map's last byte) that hold no nonzero byte. Random maps of
// several widths, sparse and dense, with blocks of every size up to 5 x 17 at every place,
// including the map's last columns, where a row's 16 bytes run into the next row, and its last
// rows; solid cells in every column and row of a block, the last ones too.
#include "solid_block.h"

#include "cell_range.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace tilesweep::detail {
namespace {

/// Whether the block x by y holds a nonzero byte, read one by one.
[[maybe_unused]] bool holdsASolidCell(const std::vector<std::uint8_t>& solid, std::int64_t columns,
                                      CellRange x, CellRange y) {
    for (std::int64_t j = y.first; j <= y.last; ++j)
        for (std::int64_t i = x.first; i <= x.last; ++i)
            if (solid[static_cast<std::size_t>(j * columns + i)] != 0) return true;
    return false;
}

/// Whether blockHoldsNoSolidCell can read the block: at most 4 rows of at most 16 columns, and
/// the 16 bytes from its first column on its last row in the map's bytes.
[[maybe_unused]] bool readable(std::int64_t columns, std::int64_t rows, CellRange x, CellRange y) {
    const std::int64_t width = x.last - x.first + 1;
    const std::int64_t height = y.last - y.first + 1;
    return width <= kSolidBlockColumns && height <= kSolidBlockRows &&
           y.last * columns + x.first + 16 <= columns * rows;
}

TEST(SolidBlock, saysEmptyExactlyForTheReadableBlocksWithoutASolidCell) {
#if !defined(TILESWEEP_SOLID_BLOCK_SSE2)
    GTEST_SKIP() << "the portable build reads no block (blockHoldsNoSolidCell returns false)";
#else
    std::mt19937_64 rng(20261204);
    int empty = 0;
    int solidInLastColumn = 0;  // read, and solid in its last column alone
    int solidInLastRow = 0;     // read, and solid in its last row alone
    int unreadable = 0;
    int pastTheRowsEnd = 0;  // read, with 16 bytes that run into the next row
    const std::int64_t sizes[][2] = {{1, 24}, {5, 9}, {16, 8}, {17, 7}, {23, 12}, {40, 6}};
    for (const auto& size : sizes) {
        const std::int64_t columns = size[0];
        const std::int64_t rows = size[1];
        for (int map = 0; map < 20; ++map) {
            // Sparse and dense maps, so that empty blocks and solid ones both come up; any nonzero
            // byte is solid.
            const double share = map % 2 == 0 ? 0.05 : 0.5;
            std::vector<std::uint8_t> solid(static_cast<std::size_t>(columns * rows));
            for (auto& cell : solid)
                cell = std::uniform_real_distribution<double>(0, 1)(rng) < share
                           ? static_cast<std::uint8_t>(1 + rng() % 255)
                           : 0;
            for (std::int64_t y0 = 0; y0 < rows; ++y0)
                for (std::int64_t y1 = y0; y1 < rows && y1 <= y0 + 4; ++y1)
                    for (std::int64_t x0 = 0; x0 < columns; ++x0)
                        for (std::int64_t x1 = x0; x1 < columns && x1 <= x0 + 16; ++x1) {
                            const CellRange x{x0, x1};
                            const CellRange y{y0, y1};
                            const bool read = readable(columns, rows, x, y);
                            const bool solidCell = holdsASolidCell(solid, columns, x, y);
                            ASSERT_EQ(blockHoldsNoSolidCell(solid.data(), columns, rows, x, y),
                                      read && !solidCell)
                                << "columns " << columns << " rows " << rows << " block [" << x0 << ", " << x1
                                << "] x [" << y0 << ", " << y1 << "], readable " << read << ", solid "
                                << solidCell;
                            if (!read) {
                                ++unreadable;
                                continue;
                            }
                            empty += solidCell ? 0 : 1;
                            pastTheRowsEnd += x0 + 16 > columns ? 1 : 0;
                            if (x1 > x0 && holdsASolidCell(solid, columns, {x1, x1}, y) &&
                                !holdsASolidCell(solid, columns, {x0, x1 - 1}, y))
                                ++solidInLastColumn;
                            if (y1 > y0 && holdsASolidCell(solid, columns, x, {y1, y1}) &&
                                !holdsASolidCell(solid, columns, x, {y0, y1 - 1}))
                                ++solidInLastRow;
                        }
        }
    }
    // Each case the read must get right came up: 138,440 empty blocks, 17,690 solid in their last
    // column alone, 29,471 in their last row alone, 142,680 unreadable, 226,800 read with bytes
    // that run into the next row.
    EXPECT_GT(empty, 10000);
    EXPECT_GT(solidInLastColumn, 10000);
    EXPECT_GT(solidInLastRow, 10000);
    EXPECT_GT(unreadable, 100000);
    EXPECT_GT(pastTheRowsEnd, 100000);
#endif
}

}  // namespace
}  // namespace tilesweep::detail
