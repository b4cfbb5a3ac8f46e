// SPDX-License-Identifier: MIT
#pragma once

#include "exact_sum.h"
#include "grid_line.h"

#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

// The contract's safety rules for one resolved frame, checked exactly: the one checker that the
// property suite, the fuzz targets, the soak and the audit all use (docs/contract.md, "Positions").
//
//   - EndsInsideNewTile: the box at the rounded end overlaps (open) no solid tile it did not
//     overlap at the start. No allowance: the amended rounding rule keeps the far edge short of
//     every grid line the exact far edge had not passed.
//   - LeavesHitTileTouching: a hit tile is left touching, or less than one ulp short of its face.
//   - StaysWithinExactMotion: on each axis the position lies between the start and the exact end
//     (the hit face's touching position on a contact axis, start + displacement on a free one),
//     inclusive; or, on an axis moving toward minus infinity, it is the value just below the
//     exact end, exactly when rounding back up would carry the far edge over a grid line; and
//     whenever the rule asks for that value, the position is not the one rounded back up.
//   - StartOverlaps, WellFormed: the reported start overlaps are exactly the solid tiles the box
//     overlaps at the start, each once, in any order (the contract leaves the order free); the
//     status, counts, contact cells, normals and frame times are of the shape the contract gives
//     them (a one-way cell is hit on its top only, and is never a start overlap).
//
// These are the rules every result must obey, not the whole contract: which tile is hit, and
// the exact time, are the oracles' business (oracle/, properties/).

namespace tilesweep::checks {

/// Which rule a frame broke.
enum class SafetyRule : std::uint8_t {
    None,
    WellFormed,
    StartOverlaps,
    EndsInsideNewTile,
    LeavesHitTileTouching,
    StaysWithinExactMotion,
};

/// The first rule a frame breaks, and how; `rule == None` when it obeys them all.
struct SafetyViolation {
    SafetyRule rule = SafetyRule::None;
    std::string detail;

    [[nodiscard]] explicit operator bool() const noexcept { return rule != SafetyRule::None; }
};

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
    const W hi =
        (static_cast<W>(pos) + static_cast<W>(size) - static_cast<W>(origin)) / static_cast<W>(tile) + 1;
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

[[nodiscard]] inline std::string describeCell(Cell c) {
    return "(" + std::to_string(c.i) + ", " + std::to_string(c.j) + ")";
}

/// Reusable storage for the checks, so that a long run allocates nothing per frame.
struct SafetyScratch {
    std::vector<Cell> atStart;
    std::vector<Cell> atEnd;
    std::vector<Cell> listed;       ///< a reported list, sorted (sameCellsInAnyOrder)
    std::uint64_t roundedDown = 0;  ///< axes the rounding rule's exception rounded down, so far
};

/// Whether cell `a` comes before `b` by row, then column: listOverlaps' order.
[[nodiscard]] inline bool comesBeforeByRow(Cell a, Cell b) noexcept {
    return a.j != b.j ? a.j < b.j : a.i < b.i;
}

/// Whether the `count` cells at `listed` are the cells of `exact` in any order, each listed once.
/// The contract leaves the order of started_overlapping free but not its content: a cell left
/// out, or listed twice, is another answer. `exact` is by row, then column with no cell twice
/// (listOverlaps, the exact oracle's startOverlaps); `sorted` receives the listed cells in that
/// order, reused so that a long run allocates nothing per frame.
[[nodiscard]] inline bool sameCellsInAnyOrder(const std::vector<Cell>& exact, const Cell* listed,
                                              std::size_t count, std::vector<Cell>& sorted) {
    if (count != exact.size()) return false;
    sorted.assign(listed, listed + count);
    std::sort(sorted.begin(), sorted.end(), comesBeforeByRow);
    return std::equal(sorted.begin(), sorted.end(), exact.begin());
}

/// The first solid tile the box at `end` overlaps that it did not overlap at `start` (same size),
/// or nothing. `scratch.atStart` and `scratch.atEnd` are left holding both lists.
template <class T>
[[nodiscard]] std::optional<Cell> findNewOverlap(const TileMapView<T>& map, const MapEdges<T>& edges,
                                                 Box<T> start, Vec2<T> end, SafetyScratch& scratch) {
    listOverlaps(map, edges, start.pos, start.size, scratch.atStart);
    listOverlaps(map, edges, end, start.size, scratch.atEnd);
    for (const Cell c : scratch.atEnd)
        if (std::find(scratch.atStart.begin(), scratch.atStart.end(), c) == scratch.atStart.end()) return c;
    return std::nullopt;
}

/// One resolved frame as the checks see it; the lists hold all the counts (not truncated).
template <class T>
struct FrameRecord {
    TileMapView<T> map;
    Box<T> start{};
    Vec2<T> displacement{};
    ResolveResult<T> result{};
    const Contact<T>* contacts = nullptr;
    const Cell* startOverlaps = nullptr;
};

/// The contract's shape of a result: status, finite position, counts, contacts on solid cells
/// (or on one-way cells, with the normal (0, -1) of their top) with a unit normal against the
/// motion and a frame time in [0, 1]. Empty when it holds.
template <class T>
[[nodiscard]] std::string checkWellFormed(const FrameRecord<T>& frame) {
    const ResolveResult<T>& r = frame.result;
    const Vec2<T> d = frame.displacement;
    if (r.status == ResolveStatus::InvalidInput) return "valid input refused as InvalidInput";
    if (!std::isfinite(r.position.x) || !std::isfinite(r.position.y)) return "non-finite final position";
    if (r.contactCount < 0 || r.startOverlapCount < 0) return "negative list count";
    if ((r.status == ResolveStatus::Blocked) != (r.contactCount > 0))
        return "status Blocked does not match the contact count";
    for (std::int32_t k = 0; k < r.contactCount; ++k) {
        const Contact<T>& c = frame.contacts[k];
        const CellKind kind = frame.map.kind(c.tile.i, c.tile.j);
        if (kind == CellKind::Empty)
            return "contact " + describeCell(c.tile) + " is not a solid or one-way cell of the map";
        const bool onX = c.normal.y == 0 && (c.normal.x == 1 || c.normal.x == -1);
        const bool onY = c.normal.x == 0 && (c.normal.y == 1 || c.normal.y == -1);
        if (!onX && !onY) return "contact normal is not a unit axis vector";
        if (kind == CellKind::OneWay && !(onY && c.normal.y == -1))
            return "contact " + describeCell(c.tile) + " is on a one-way cell, whose only face is its top";
        const T along = onX ? d.x : d.y;
        const int against = onX ? -c.normal.x : -c.normal.y;
        if (!(against > 0 ? along > 0 : along < 0)) return "contact normal does not oppose the motion";
        // The exact time lies in [0, 1); rounded to nearest it may become 1 (a hit a sub-ulp
        // before the end of the frame), so [0, 1] is what a rounded time can be held to.
        if (!(c.time >= 0 && c.time <= 1)) return "contact time outside [0, 1]";
    }
    return {};
}

/// Every hit tile is left touching its face, or less than one ulp short of it, on the contact
/// axis. Contacts must name cells of the map (checkWellFormed). Empty when it holds.
template <class T>
[[nodiscard]] std::string checkHitTilesLeftTouching(const FrameRecord<T>& frame, const MapEdges<T>& edges) {
    const T inf = std::numeric_limits<T>::infinity();
    const Vec2<T> p = frame.result.position;
    const Vec2<T> size = frame.start.size;
    for (std::int32_t k = 0; k < frame.result.contactCount; ++k) {
        const Contact<T>& c = frame.contacts[k];
        const auto i = static_cast<std::size_t>(c.tile.i);
        const auto j = static_cast<std::size_t>(c.tile.j);
        bool touching = true;
        // Moving +x onto the left face L: p + w <= L < next(p) + w. Moving -x onto the right
        // face R: p >= R > previous(p). Likewise on y.
        if (c.normal.x == -1)
            touching = signOfSumMinus(p.x, size.x, edges.x[i]) <= 0 &&
                       signOfSumMinus(std::nextafter(p.x, inf), size.x, edges.x[i]) > 0;
        if (c.normal.x == 1) touching = p.x >= edges.x[i + 1] && std::nextafter(p.x, -inf) < edges.x[i + 1];
        if (c.normal.y == -1)
            touching = signOfSumMinus(p.y, size.y, edges.y[j]) <= 0 &&
                       signOfSumMinus(std::nextafter(p.y, inf), size.y, edges.y[j]) > 0;
        if (c.normal.y == 1) touching = p.y >= edges.y[j + 1] && std::nextafter(p.y, -inf) < edges.y[j + 1];
        if (!touching) return "not left touching hit tile " + describeCell(c.tile);
    }
    return {};
}

/// The position on each axis lies between the start and the exact end, or just below it where
/// the rounding rule asks for that (see the header note); counts the axes rounded down in
/// `scratch.roundedDown`. Contacts must be well formed (checkWellFormed). Empty when it holds.
template <class T>
[[nodiscard]] std::string checkWithinExactMotion(const FrameRecord<T>& frame, const MapEdges<T>& edges,
                                                 SafetyScratch& scratch) {
    const T inf = std::numeric_limits<T>::infinity();
    for (int axis = 0; axis < 2; ++axis) {
        const bool onX = axis == 0;
        const char* name = onX ? "x" : "y";
        const T s = onX ? frame.start.pos.x : frame.start.pos.y;
        const T d = onX ? frame.displacement.x : frame.displacement.y;
        const T z = onX ? frame.start.size.x : frame.start.size.y;
        const T q = onX ? frame.result.position.x : frame.result.position.y;
        if (!(d > 0 || d < 0)) {
            if (!(q == s)) return std::string("moved on ") + name + ", which did not move";
            continue;
        }
        // The exact end e = a + b: the touching position on a contact axis, else s + d.
        T a = s;
        T b = d;
        for (std::int32_t k = 0; k < frame.result.contactCount; ++k) {
            const Contact<T>& c = frame.contacts[k];
            const std::int8_t n = onX ? c.normal.x : c.normal.y;
            const auto cell = static_cast<std::size_t>(onX ? c.tile.i : c.tile.j);
            const std::vector<T>& lines = onX ? edges.x : edges.y;
            if (n == -1) {
                a = lines[cell];
                b = -z;
            } else if (n == 1) {
                a = lines[cell + 1];
                b = 0;
            }
        }
        const int endVsQ = signOfSumMinus(a, b, q);  // sign of e - q
        if (d > 0) {
            if (q < s || endVsQ < 0) return std::string("moved past the exact end on ") + name;
            continue;
        }
        // Moving toward minus infinity: e <= q <= s, or q the value just below e, where a grid
        // line lies in [e + z, next(q) + z).
        if (q > s) return std::string("moved backward on ") + name;
        if (endVsQ > 0) {
            const T up = std::nextafter(q, inf);
            const bool justBelow = signOfSumMinus(a, b, up) < 0;
            if (!justBelow ||
                !gridLineIn<T>({a, b, z}, {up, z}, onX ? frame.map.origin.x : frame.map.origin.y,
                               onX ? frame.map.tileSize.x : frame.map.tileSize.y))
                return std::string("moved past the exact end on ") + name +
                       " where the rounding rule does not allow it";
            ++scratch.roundedDown;
            continue;
        }
        // q >= e. If q is e rounded up (e < q, previous(q) < e) and rounding up carries the far
        // edge over a line, the rule asks for the value below e (when one is finite).
        const T down = std::nextafter(q, -inf);
        if (endVsQ < 0 && signOfSumMinus(a, b, down) > 0 && std::isfinite(down) &&
            gridLineIn<T>({a, b, z}, {q, z}, onX ? frame.map.origin.x : frame.map.origin.y,
                          onX ? frame.map.tileSize.x : frame.map.tileSize.y))
            return std::string("rounded back on ") + name + ", carrying the far edge over a grid line";
    }
    return {};
}

/// Checks every safety rule of one frame; the first broken one, or `rule == None`. The input must
/// be valid (isValid) and the map must have passed validateTileMap, with `edges` its edges.
template <class T>
[[nodiscard]] SafetyViolation checkFrameSafety(const FrameRecord<T>& frame, const MapEdges<T>& edges,
                                               SafetyScratch& scratch) {
    if (std::string why = checkWellFormed(frame); !why.empty()) return {SafetyRule::WellFormed, why};
    const ResolveResult<T>& r = frame.result;
    if (std::optional<Cell> entered = findNewOverlap(frame.map, edges, frame.start, r.position, scratch))
        return {SafetyRule::EndsInsideNewTile,
                "ends inside solid tile " + describeCell(*entered) + " it did not start in"};
    const bool sameStart = sameCellsInAnyOrder(scratch.atStart, frame.startOverlaps,
                                               static_cast<std::size_t>(r.startOverlapCount), scratch.listed);
    if (!sameStart)
        return {SafetyRule::StartOverlaps, "reported start overlaps (" + std::to_string(r.startOverlapCount) +
                                               ") differ from the exact ones (" +
                                               std::to_string(scratch.atStart.size()) + ")"};
    if (std::string why = checkHitTilesLeftTouching(frame, edges); !why.empty())
        return {SafetyRule::LeavesHitTileTouching, why};
    if (std::string why = checkWithinExactMotion(frame, edges, scratch); !why.empty())
        return {SafetyRule::StaysWithinExactMotion, why};
    return {};
}

/// The rule's name, as the reports print it.
[[nodiscard]] inline const char* ruleName(SafetyRule rule) noexcept {
    switch (rule) {
        case SafetyRule::None:
            return "none";
        case SafetyRule::WellFormed:
            return "wellFormed";
        case SafetyRule::StartOverlaps:
            return "startOverlaps";
        case SafetyRule::EndsInsideNewTile:
            return "endsInsideNewTile";
        case SafetyRule::LeavesHitTileTouching:
            return "leavesHitTileTouching";
        case SafetyRule::StaysWithinExactMotion:
            return "staysWithinExactMotion";
    }
    return "?";
}

}  // namespace tilesweep::checks
