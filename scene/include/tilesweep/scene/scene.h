// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/math.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Scenes and their results as the command-line tool, the regression corpus and outside
// harnesses exchange them: one JSON object per line (docs/contract.md, "Scene files").
// This layer owns its containers; it is part of the `tilesweep_scene` target, not of the
// dependency-free core library.

namespace tilesweep {

/// An owning tile map; `view()` lends it to the resolver.
template <class T>
struct TileMap {
    Vec2<T> origin{};
    Vec2<T> tileSize{};
    std::int32_t columns = 0;
    std::int32_t rows = 0;
    std::vector<std::uint8_t> solid;  ///< row-major from the top row; 1 is solid, 0 empty
    /// Laid out as `solid`, 1 where the cell is one-way ('-'); empty when no cell is.
    std::vector<std::uint8_t> oneWay;

    /// A view of this map, valid while the map lives and is not resized.
    [[nodiscard]] TileMapView<T> view() const noexcept {
        return {origin, tileSize, columns, rows, solid.data(), oneWay.empty() ? nullptr : oneWay.data()};
    }

    /// What cell (i, j) holds; cells outside the map are empty.
    [[nodiscard]] CellKind kind(std::int64_t i, std::int64_t j) const noexcept { return view().kind(i, j); }

    /// Sets cell (i, j), which lies in the map, to `kind` (allocating `oneWay` on the first
    /// one-way cell).
    void set(std::int64_t i, std::int64_t j, CellKind kind) {
        const auto k = static_cast<std::size_t>(j * columns + i);
        solid[k] = kind == CellKind::Solid ? 1 : 0;
        if (kind == CellKind::OneWay && oneWay.empty()) oneWay.assign(solid.size(), 0);
        if (!oneWay.empty()) oneWay[k] = kind == CellKind::OneWay ? 1 : 0;
    }
};

/// One scene: a map, a box and one or more frames of motion, with every number already
/// rounded (once, to nearest) to T.
template <class T>
struct Scene {
    std::string name;  ///< the scene's "name" field, or empty
    TileMap<T> map;
    Box<T> box{};
    std::vector<Vec2<T>> moves;  ///< one displacement per frame, in order; never empty
};

/// What one frame of a scene produced.
template <class T>
struct FrameResult {
    Vec2<T> position{};
    std::vector<Contact<T>> contacts;  ///< step by step; within a step by row, then column
    std::vector<Cell> startOverlaps;   ///< solid cells overlapped at the frame's start
};

/// A parsed scene line: either a scene, or an error naming the field that is wrong.
template <class T>
struct SceneParse {
    std::optional<Scene<T>> scene;
    std::string error;  ///< empty when `scene` is set
};

/// Parses one scene line (JSON object) into T. Never throws: malformed JSON, missing or
/// ill-typed fields, non-finite numbers, non-positive sizes, ragged rows, unknown tile
/// characters and maps whose edges are not representable in T all give an error.
/// Every number (a JSON number, or a hexfloat string such as "0x1.8p+3") is rounded once,
/// straight from its text to T, to nearest; one that rounds to an infinity is an error. A map
/// with no rows, or with rows of length zero, is an empty map (0 x 0, every cell empty).
/// Unknown fields are ignored; a known field given twice is an error. Error messages start
/// with the path of the field ("box: ...", "moves[2][1]: ...", "map.rows[3]: ...").
template <class T>
[[nodiscard]] SceneParse<T> parseScene(std::string_view line);

/// Writes a scene as one JSON line with every number as a C99 hexfloat string, so that
/// parsing it back into T gives the same bits. Always writes "moves", and "name" when it is
/// not empty. Throws std::invalid_argument for a non-finite number or a map whose `solid`
/// does not hold columns*rows cells (neither comes out of parseScene).
template <class T>
[[nodiscard]] std::string formatScene(const Scene<T>& scene);

/// Runs every frame of a scene through the production resolver, each frame starting where
/// the previous one ended; the box keeps its size. Throws std::invalid_argument if the
/// resolver refuses a frame as invalid input (never for a scene from parseScene).
template <class T>
[[nodiscard]] std::vector<FrameResult<T>> runScene(const Scene<T>& scene);

/// Formats the output line of `tilesweep resolve` for one scene: {"frames": [...]}, numbers
/// in the shortest form that reads back to the same T. Throws std::invalid_argument for a
/// non-finite number, which JSON cannot carry.
template <class T>
[[nodiscard]] std::string formatFrames(const std::vector<FrameResult<T>>& frames);

/// Formats the error line of `tilesweep resolve`: {"error": "..."}, the message escaped as a
/// JSON string (invalid UTF-8 replaced by U+FFFD).
[[nodiscard]] std::string formatError(std::string_view message);

}  // namespace tilesweep
