// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/scene/scene.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// Builds scenes for hand-worked tests straight from the pieces a scene file holds, without the
// JSON reader: rows of '#' (solid), '-' (one-way) and '.' (empty), top row first.

namespace tilesweep::oracle::test {

template <class T>
TileMap<T> makeMap(const std::vector<std::string>& rows, Vec2<T> origin = {0, 0},
                   Vec2<T> tileSize = {16, 16}) {
    TileMap<T> map;
    map.origin = origin;
    map.tileSize = tileSize;
    map.rows = static_cast<std::int32_t>(rows.size());
    map.columns = rows.empty() ? 0 : static_cast<std::int32_t>(rows.front().size());
    map.solid.assign(static_cast<std::size_t>(map.rows) * static_cast<std::size_t>(map.columns), 0);
    for (std::int32_t j = 0; j < map.rows; ++j) {
        const std::string& row = rows[static_cast<std::size_t>(j)];
        if (static_cast<std::int32_t>(row.size()) != map.columns) {
            throw std::invalid_argument("makeMap: ragged rows");
        }
        for (std::int32_t i = 0; i < map.columns; ++i) {
            const char c = row[static_cast<std::size_t>(i)];
            if (c != '#' && c != '-' && c != '.') {
                throw std::invalid_argument("makeMap: a cell is '#', '-' or '.'");
            }
            map.set(i, j, c == '#' ? CellKind::Solid : c == '-' ? CellKind::OneWay : CellKind::Empty);
        }
    }
    return map;
}

template <class T>
Scene<T> makeScene(TileMap<T> map, Box<T> box, std::vector<Vec2<T>> moves) {
    Scene<T> scene;
    scene.map = std::move(map);
    scene.box = box;
    scene.moves = std::move(moves);
    return scene;
}

}  // namespace tilesweep::oracle::test
