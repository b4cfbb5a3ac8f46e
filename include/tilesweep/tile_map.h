// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"

#include <cstdint>

// The tile grid a box moves through.
//
// Tile (i, j) is the closed rectangle [origin.x + i*tileSize.x, origin.x + (i+1)*tileSize.x] x
// [origin.y + j*tileSize.y, origin.y + (j+1)*tileSize.y], where i is the column and j the row
// (row 0 is the top). Cells outside [0, columns) x [0, rows) are empty. A cell is empty, solid,
// or one-way (a jump-through platform: it blocks only a box moving down onto its top face, from
// at or above it; docs/contract.md, "One-way tiles"). A map is valid when
// every tile edge it defines is exactly representable in T: the resolver is exact either way,
// but a contact position must be able to land exactly on the edge it touches.

namespace tilesweep {

/// What a cell holds.
enum class CellKind : std::uint8_t {
    Empty,
    Solid,   ///< blocks from every side
    OneWay,  ///< blocks only a box moving down onto its top face from at or above it
};

/// A non-owning view of a grid of cells; it borrows `solid` and `oneWay`.
template <class T>
struct TileMapView {
    Vec2<T> origin;            ///< top-left corner of cell (0, 0), in length units
    Vec2<T> tileSize;          ///< width and height of one cell, > 0
    std::int32_t columns = 0;  ///< number of cells per row, >= 0
    std::int32_t rows = 0;     ///< number of rows, >= 0
    const std::uint8_t* solid =
        nullptr;  ///< columns*rows flags, row-major from the top row; nonzero is solid
    /// columns*rows flags laid out as `solid`, nonzero is one-way where `solid` is zero (a solid
    /// flag wins); null when the map has no one-way cell. A frame resolved with it null treats
    /// every one-way cell as empty: that is how a game drops through a platform (withoutOneWay).
    const std::uint8_t* oneWay = nullptr;

    /// True when cell (i, j) lies in the map and is solid; cells outside the map are empty.
    [[nodiscard]] constexpr bool isSolid(std::int64_t i, std::int64_t j) const noexcept {
        return i >= 0 && j >= 0 && i < columns && j < rows && solid[j * columns + i] != 0;
    }

    /// True when cell (i, j) lies in the map and is one-way (not solid, its oneWay flag set).
    [[nodiscard]] constexpr bool isOneWay(std::int64_t i, std::int64_t j) const noexcept {
        return oneWay != nullptr && i >= 0 && j >= 0 && i < columns && j < rows &&
               solid[j * columns + i] == 0 && oneWay[j * columns + i] != 0;
    }

    /// What cell (i, j) holds; cells outside the map are empty.
    [[nodiscard]] constexpr CellKind kind(std::int64_t i, std::int64_t j) const noexcept {
        return isSolid(i, j) ? CellKind::Solid : isOneWay(i, j) ? CellKind::OneWay : CellKind::Empty;
    }

    /// The same map with its one-way cells left out: the view a frame that drops through every
    /// platform resolves on (the contract's per-call option; scene files do not carry it).
    [[nodiscard]] constexpr TileMapView withoutOneWay() const noexcept {
        TileMapView view = *this;
        view.oneWay = nullptr;
        return view;
    }
};

/// Why a map is not valid; `None` when it is.
enum class MapError : std::uint8_t {
    None,
    NonFiniteOrigin,       ///< an origin component is NaN or infinite
    NonPositiveTileSize,   ///< a tile size is not finite or not > 0
    NegativeDimensions,    ///< columns or rows is negative, or the cells are missing
    TooLarge,              ///< columns*rows exceeds kMaxCells
    UnrepresentableEdgeX,  ///< some origin.x + i*tileSize.x, 0 <= i <= columns, is not a T
    UnrepresentableEdgeY,  ///< some origin.y + j*tileSize.y, 0 <= j <= rows, is not a T
    InexactArithmetic,     ///< isArithmeticExact() is false here: no map can be resolved exactly
    NotPrepared,           ///< a default-constructed PreparedMap: no map was given to prepareMap
};

/// The largest number of cells a map may have (2^31 - 1: a cell index fits an int32).
inline constexpr std::int64_t kMaxCells = 0x7fffffff;

/// True when the floating-point arithmetic the library runs on is what its exact code needs:
/// each float and double operation rounded on its own (no fused multiply-add, no excess
/// precision) and to nearest (the current rounding mode; a game that calls fesetround must
/// restore FE_TONEAREST before resolving). A few operations, no state: validateTileMap calls it.
[[nodiscard]] bool isArithmeticExact() noexcept;

/// Checks a map: finite origin, tile sizes > 0, consistent dimensions and every tile edge
/// exactly representable in T, and exact arithmetic (isArithmeticExact). Runs in O(columns +
/// rows); call it once per map, not per frame.
/// When the result is an Unrepresentable* error, `firstBadEdge` (if given) receives the
/// index of the first edge that is not representable.
template <class T>
[[nodiscard]] MapError validateTileMap(const TileMapView<T>& map,
                                       std::int64_t* firstBadEdge = nullptr) noexcept;

/// A short English description of a map error, naming the field.
[[nodiscard]] const char* describe(MapError error) noexcept;

extern template MapError validateTileMap<float>(const TileMapView<float>&, std::int64_t*) noexcept;
extern template MapError validateTileMap<double>(const TileMapView<double>&, std::int64_t*) noexcept;

}  // namespace tilesweep
