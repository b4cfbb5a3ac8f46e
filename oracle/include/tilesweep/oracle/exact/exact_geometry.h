// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"
#include "tilesweep/oracle/exact/rational.h"
#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/scene/scene.h"
#include "tilesweep/tile_map.h"

#include <cstdint>
#include <vector>

// Exact counterparts of the public value types: the contract's geometry with rational
// coordinates. Conventions are those of docs/contract.md: x grows right, y grows down, a box is
// the closed rectangle [pos, pos + size], tile (i, j) is [origin + (i, j) * tileSize,
// origin + (i + 1, j + 1) * tileSize], cells outside the map are empty. A cell is empty, solid
// or one-way (CellKind, tile_map.h).

namespace tilesweep::oracle {

/// A vector with exact coordinates (a position, a size or a displacement).
struct ExactVec2 {
    Rational x;
    Rational y;
};

/// A box with exact coordinates: the closed rectangle [pos, pos + size].
struct ExactBox {
    ExactVec2 pos;
    ExactVec2 size;
};

/// A closed rectangle [min, max] (a tile).
struct ExactRect {
    ExactVec2 min;
    ExactVec2 max;
};

/// A tile map with exact origin and tile size; the edges are computed exactly, never rounded.
/// Each cell is empty, solid ('#') or one-way ('-'), as the scene's map holds it.
struct ExactTileMap {
    ExactVec2 origin;
    ExactVec2 tileSize;
    std::int32_t columns = 0;
    std::int32_t rows = 0;
    std::vector<CellKind> cells;  ///< row-major from the top row

    /// What cell (i, j) holds; cells outside the map are empty.
    [[nodiscard]] CellKind kind(std::int64_t i, std::int64_t j) const {
        if (i < 0 || j < 0 || i >= columns || j >= rows) {
            return CellKind::Empty;
        }
        return cells[static_cast<std::size_t>(j * columns + i)];
    }

    /// True when (i, j) lies in the map and is solid. Only a solid cell hides a face of its
    /// neighbour (the exposed-face rule); a one-way cell counts as empty there.
    [[nodiscard]] bool isSolid(std::int64_t i, std::int64_t j) const { return kind(i, j) == CellKind::Solid; }

    /// True when (i, j) lies in the map and is one-way.
    [[nodiscard]] bool isOneWay(std::int64_t i, std::int64_t j) const {
        return kind(i, j) == CellKind::OneWay;
    }

    /// The same map with every one-way cell empty: the map of a frame that drops through every
    /// platform (the contract's per-call option, TileMapView::withoutOneWay in the library).
    [[nodiscard]] ExactTileMap withoutOneWay() const {
        ExactTileMap map = *this;
        for (CellKind& cell : map.cells) {
            if (cell == CellKind::OneWay) {
                cell = CellKind::Empty;
            }
        }
        return map;
    }

    /// The exact rectangle of cell (i, j).
    [[nodiscard]] ExactRect tileRect(std::int64_t i, std::int64_t j) const {
        const ExactVec2 min{origin.x + Rational(i) * tileSize.x, origin.y + Rational(j) * tileSize.y};
        return {min, {min.x + tileSize.x, min.y + tileSize.y}};
    }
};

/// True when two closed rectangles overlap: their interiors meet (strict on both axes).
/// Touching is not overlapping.
[[nodiscard]] inline bool overlaps(const ExactRect& a, const ExactRect& b) {
    return a.min.x < b.max.x && a.max.x > b.min.x && a.min.y < b.max.y && a.max.y > b.min.y;
}

/// The closed rectangle of a box.
[[nodiscard]] inline ExactRect rectOf(const ExactBox& box) {
    return {box.pos, {box.pos.x + box.size.x, box.pos.y + box.size.y}};
}

/// The component of v on axis a.
[[nodiscard]] inline const Rational& component(const ExactVec2& v, Axis a) {
    return a == Axis::X ? v.x : v.y;
}

/// The exact value of a T vector (its components must be finite).
template <class T>
[[nodiscard]] ExactVec2 toExact(Vec2<T> v) {
    return {toRational(v.x), toRational(v.y)};
}

/// The exact value of a T box.
template <class T>
[[nodiscard]] ExactBox toExact(const Box<T>& box) {
    return {toExact(box.pos), toExact(box.size)};
}

/// The exact value of a T map: the same cells (TileMap::kind, so a cell flagged both solid and
/// one-way is solid), origin and tile size taken at their exact values.
template <class T>
[[nodiscard]] ExactTileMap toExact(const TileMap<T>& map) {
    ExactTileMap exact{toExact(map.origin), toExact(map.tileSize), map.columns, map.rows, {}};
    exact.cells.reserve(static_cast<std::size_t>(map.columns) * static_cast<std::size_t>(map.rows));
    for (std::int32_t j = 0; j < map.rows; ++j) {
        for (std::int32_t i = 0; i < map.columns; ++i) {
            exact.cells.push_back(map.kind(i, j));
        }
    }
    return exact;
}

}  // namespace tilesweep::oracle
