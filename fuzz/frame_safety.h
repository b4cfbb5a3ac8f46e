// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "exact_sum.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

// The contract's safety rules for one resolved frame, checked exactly (exact_sum.h) by the fuzz
// targets and the soak:
//
//   - the box never ends inside (open overlap) a solid tile it did not start inside, but for the
//     sub-ulp overlap with a tile it did not hit that rounding toward the start can leave (see
//     findSafetyViolation);
//   - on each axis the final coordinate lies between the start and start + displacement,
//     inclusive, exactly: the box never moves farther than the exact motion;
//   - the reported start overlaps are exactly the solid tiles the box overlaps at the start, by
//     row, then column; contacts name solid cells of the map, with a unit normal against the
//     motion and a frame time in [0, 1] (the exact time, in [0, 1), rounded to nearest); the status is Blocked exactly when there are contacts.
//
// These are the rules every result must obey, not the whole contract: which tile is hit and
// where the box stops are the oracles' business (oracle/, properties/).

namespace tilesweep::fuzz {

/// The tile edges of a map that passed validateTileMap: x[k] = origin.x + k*tileSize.x for
/// 0 <= k <= columns, likewise y for rows.
template <class T>
struct MapEdges {
    std::vector<T> x;
    std::vector<T> y;
};

/// Computes the edges by repeated addition. Each sum is exact because validateTileMap proved
/// every edge representable, and edge k+1 is the exact sum of edge k and the tile size.
template <class T>
[[nodiscard]] MapEdges<T> computeEdges(const TileMapView<T>& map) {
    MapEdges<T> edges;
    edges.x.resize(static_cast<std::size_t>(map.columns) + 1);
    edges.y.resize(static_cast<std::size_t>(map.rows) + 1);
    edges.x[0] = map.origin.x;
    for (std::size_t k = 1; k < edges.x.size(); ++k) edges.x[k] = edges.x[k - 1] + map.tileSize.x;
    edges.y[0] = map.origin.y;
    for (std::size_t k = 1; k < edges.y.size(); ++k) edges.y[k] = edges.y[k - 1] + map.tileSize.y;
    return edges;
}

/// Inclusive range of cell indices; empty when first > last.
struct CellRange {
    std::int64_t first = 0;
    std::int64_t last = -1;
};

/// The cells of one axis that the span [pos, pos + size] may overlap, with one cell of margin.
/// Estimated in long double: within the map the quotient is below 2^31 and its relative error
/// below 2^-62, so the estimate is off by far less than the margin; far outside the map it only
/// has to land on the right side of the clamp. The exact test decides on every cell it returns.
template <class T>
[[nodiscard]] CellRange candidateCells(T pos, T size, T origin, T tile, std::int32_t cells) noexcept {
    if (cells <= 0) return {};
    using W = long double;
    const W lo = (static_cast<W>(pos) - static_cast<W>(origin)) / static_cast<W>(tile) - 1;
    const W hi = (static_cast<W>(pos) + static_cast<W>(size) - static_cast<W>(origin)) / static_cast<W>(tile) + 1;
    const auto top = static_cast<long double>(cells - 1);
    if (hi < 0 || lo > top) return {};
    CellRange range{0, cells - 1};
    if (lo > 0) range.first = static_cast<std::int64_t>(std::floor(lo));
    if (hi < top) range.last = static_cast<std::int64_t>(std::floor(hi));
    return range;
}

/// Whether the box at `pos` with `size` overlaps tile (i, j) (open interiors), exactly.
template <class T>
[[nodiscard]] bool overlapsTile(Vec2<T> pos, Vec2<T> size, const MapEdges<T>& edges, std::int64_t i,
                                std::int64_t j) noexcept {
    const auto ui = static_cast<std::size_t>(i);
    const auto uj = static_cast<std::size_t>(j);
    return pos.x < edges.x[ui + 1] && pos.y < edges.y[uj + 1] &&
           signOfSumMinus(pos.x, size.x, edges.x[ui]) > 0 && signOfSumMinus(pos.y, size.y, edges.y[uj]) > 0;
}

/// Replaces `out` with the solid tiles the box overlaps, by row, then column.
template <class T>
void listOverlaps(const TileMapView<T>& map, const MapEdges<T>& edges, Vec2<T> pos, Vec2<T> size,
                  std::vector<Cell>& out) {
    out.clear();
    const CellRange is = candidateCells(pos.x, size.x, map.origin.x, map.tileSize.x, map.columns);
    const CellRange js = candidateCells(pos.y, size.y, map.origin.y, map.tileSize.y, map.rows);
    for (std::int64_t j = js.first; j <= js.last; ++j)
        for (std::int64_t i = is.first; i <= is.last; ++i)
            if (map.isSolid(i, j) && overlapsTile(pos, size, edges, i, j))
                out.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
}

/// Whether `end` lies between `start` and the exact start + d, inclusive.
template <class T>
[[nodiscard]] bool withinMotion(T start, T d, T end) noexcept {
    if (!(d > 0 || d < 0)) return end == start;
    const int beyond = signOfSumMinus(start, d, end);  // sign of (start + d) - end
    return d > 0 ? (end >= start && beyond >= 0) : (end <= start && beyond <= 0);
}

/// One resolved frame as the checks see it; the lists hold all the counts (not truncated).
template <class T>
struct FrameRecord {
    TileMapView<T> map;
    Box<T> start{};
    Vec2<T> displacement{};
    SweepResult<T> result{};
    const Contact<T>* contacts = nullptr;
    const Cell* startOverlaps = nullptr;
};

/// Reusable storage for findSafetyViolation, so that a long run allocates nothing per frame.
struct SafetyScratch {
    std::vector<Cell> atStart;
    std::vector<Cell> atEnd;
    std::uint64_t roundingOverlaps = 0;  ///< frames ending in a sub-ulp overlap the rounding allows
};

[[nodiscard]] inline std::string describeCell(Cell c) {
    return "(" + std::to_string(c.i) + ", " + std::to_string(c.j) + ")";
}

/// Empty when the frame obeys the safety rules; otherwise the first rule it breaks. The input
/// must be valid (isValid) and the map must have passed validateTileMap, with `edges` its edges.
template <class T>
[[nodiscard]] std::string findSafetyViolation(const FrameRecord<T>& frame, const MapEdges<T>& edges,
                                              SafetyScratch& scratch) {
    const SweepResult<T>& r = frame.result;
    const Vec2<T> from = frame.start.pos;
    const Vec2<T> d = frame.displacement;
    if (r.status == Status::InvalidInput) return "valid input refused as InvalidInput";
    if (!std::isfinite(r.position.x) || !std::isfinite(r.position.y)) return "non-finite final position";
    if (!withinMotion(from.x, d.x, r.position.x)) return "moved farther than the exact motion on x";
    if (!withinMotion(from.y, d.y, r.position.y)) return "moved farther than the exact motion on y";
    if (r.contactCount < 0 || r.startOverlapCount < 0) return "negative list count";
    if ((r.status == Status::Blocked) != (r.contactCount > 0))
        return "status Blocked does not match the contact count";

    for (std::int32_t k = 0; k < r.contactCount; ++k) {
        const Contact<T>& c = frame.contacts[k];
        if (!frame.map.isSolid(c.tile.i, c.tile.j))
            return "contact " + describeCell(c.tile) + " is not a solid cell of the map";
        const bool onX = c.normal.y == 0 && (c.normal.x == 1 || c.normal.x == -1);
        const bool onY = c.normal.x == 0 && (c.normal.y == 1 || c.normal.y == -1);
        if (!onX && !onY) return "contact normal is not a unit axis vector";
        const T along = onX ? d.x : d.y;
        const int against = onX ? -c.normal.x : -c.normal.y;
        if (!(against > 0 ? along > 0 : along < 0)) return "contact normal does not oppose the motion";
        // The exact time lies in [0, 1); rounded to nearest it may become 1 (a hit a sub-ulp
        // before the end of the frame), so [0, 1] is what a rounded time can be held to.
        if (!(c.time >= 0 && c.time <= 1)) return "contact time outside [0, 1]";
    }

    listOverlaps(frame.map, edges, from, frame.start.size, scratch.atStart);
    const bool sameOverlaps =
        scratch.atStart.size() == static_cast<std::size_t>(r.startOverlapCount) &&
        [&] {
            for (std::size_t k = 0; k < scratch.atStart.size(); ++k)
                if (scratch.atStart[k] != frame.startOverlaps[k]) return false;
            return true;
        }();
    if (!sameOverlaps)
        return "reported start overlaps (" + std::to_string(r.startOverlapCount) +
               ") differ from the exact ones (" + std::to_string(scratch.atStart.size()) + ")";

    listOverlaps(frame.map, edges, r.position, frame.start.size, scratch.atEnd);
    for (const Cell end : scratch.atEnd) {
        bool startedInside = false;
        for (const Cell begin : scratch.atStart) startedInside = startedInside || begin == end;
        if (startedInside) continue;
        // CONTRACT.md rounds each axis toward the start, and that can undo a corner miss: one axis
        // rounds back by less than an ulp while the other moves on (README, "Where the contract's
        // rounding rule and its promise part"). So a new overlap is allowed only with a tile the
        // frame did not hit, and only when one ulp more along the motion on some axis clears it,
        // which the exact end (within one ulp of the rounded one, beyond it) then does.
        bool hit = false;
        for (std::int32_t k = 0; k < r.contactCount; ++k) hit = hit || frame.contacts[k].tile == end;
        if (hit) return "ends inside solid tile " + describeCell(end) + ", which it hit";
        const T inf = std::numeric_limits<T>::infinity();
        Vec2<T> nudgedX = r.position;
        Vec2<T> nudgedY = r.position;
        nudgedX.x = std::nextafter(r.position.x, d.x > 0 ? inf : -inf);
        nudgedY.y = std::nextafter(r.position.y, d.y > 0 ? inf : -inf);
        const bool clearsOnX = (d.x > 0 || d.x < 0) && !overlapsTile(nudgedX, frame.start.size, edges, end.i, end.j);
        const bool clearsOnY = (d.y > 0 || d.y < 0) && !overlapsTile(nudgedY, frame.start.size, edges, end.i, end.j);
        if (!clearsOnX && !clearsOnY)
            return "ends inside solid tile " + describeCell(end) + " it did not start in, deeper than the rounding";
        ++scratch.roundingOverlaps;
    }
    return {};
}

}  // namespace tilesweep::fuzz
