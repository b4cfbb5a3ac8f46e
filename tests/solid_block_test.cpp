// SPDX-License-Identifier: MIT
// The block read of the near listing (readSolidBlock, src/solid_block.h), which tells the frame
// loop that a short move's swept bounds hold no solid cell, against the map's bytes read one by
// one: every block it accepts has exactly the bits of its solid cells, at 16k + c for the cell c
// columns and k rows from its first, and it refuses exactly the blocks it cannot read (too wide,
// too tall, or reaching past the map's last byte). Random maps of several widths, with blocks
// of every size up to 5 x 17 at every place, including the map's last columns, where a row's 16
// bytes run into the next row, and its last rows.
#include "cell_range.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace tilesweep::detail {
namespace {

/// The bits readSolidBlock must give for the block x by y, from the bytes one by one.
std::uint64_t expectedBits(const std::vector<std::uint8_t>& solid, std::int64_t columns, CellRange x, CellRange y) {
    std::uint64_t bits = 0;
    for (std::int64_t j = y.first; j <= y.last; ++j)
        for (std::int64_t i = x.first; i <= x.last; ++i)
            if (solid[static_cast<std::size_t>(j * columns + i)] != 0)
                bits |= std::uint64_t{1} << (16 * (j - y.first) + (i - x.first));
    return bits;
}

/// Whether readSolidBlock can read the block: at most 4 rows of at most 16 columns, and the
/// 16 bytes from its first column on each of the 4 rows from its first in the map's bytes.
bool readable(std::int64_t columns, std::int64_t rows, CellRange x, CellRange y) {
    const std::int64_t width = x.last - x.first + 1;
    const std::int64_t height = y.last - y.first + 1;
    return width <= kSolidBlockColumns && height <= kSolidBlockRows &&
           (y.first + kSolidBlockRows - 1) * columns + x.first + 16 <= columns * rows;
}

TEST(SolidBlock, givesTheBitsOfExactlyTheSolidCellsOfEveryBlockItReads) {
#if !defined(TILESWEEP_SOLID_BLOCK_SSE2)
    GTEST_SKIP() << "the portable build reads no block (readSolidBlock returns false)";
#else
    std::mt19937_64 rng(20261204);
    int read = 0;
    int refused = 0;
    int empty = 0;
    int pastTheRowsEnd = 0;  // blocks whose 16 bytes run into the next row
    const std::int64_t sizes[][2] = {{1, 24}, {5, 9}, {16, 8}, {17, 7}, {23, 12}, {40, 6}};
    for (const auto& size : sizes) {
        const std::int64_t columns = size[0];
        const std::int64_t rows = size[1];
        for (int map = 0; map < 20; ++map) {
            // Sparse and dense maps, so that empty blocks and full ones both come up; any nonzero
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
                            SolidBlock block;
                            block.bits = 0xdeadbeef;
                            const bool ok = readSolidBlock(solid.data(), columns, rows, x, y, block);
                            ASSERT_EQ(ok, readable(columns, rows, x, y))
                                << "columns " << columns << " rows " << rows << " block [" << x0 << ", " << x1
                                << "] x [" << y0 << ", " << y1 << "]";
                            if (!ok) {
                                EXPECT_EQ(block.bits, 0xdeadbeefu) << "a refused block wrote its bits";
                                ++refused;
                                continue;
                            }
                            ASSERT_EQ(block.bits, expectedBits(solid, columns, x, y))
                                << "columns " << columns << " rows " << rows << " block [" << x0 << ", " << x1
                                << "] x [" << y0 << ", " << y1 << "]";
                            ++read;
                            empty += block.bits == 0 ? 1 : 0;
                            pastTheRowsEnd += x0 + 16 > columns ? 1 : 0;
                        }
        }
    }
    // Each case the read must get right came up: 372,080 blocks read, 271,320 refused, 97,300
    // empty, 167,280 running into the next row.
    EXPECT_GT(read, 100000);
    EXPECT_GT(refused, 100000);
    EXPECT_GT(empty, 10000);
    EXPECT_GT(pastTheRowsEnd, 100000);
#endif
}

}  // namespace
}  // namespace tilesweep::detail
