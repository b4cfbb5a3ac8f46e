// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/substep/substep_float.h"

#include "tilesweep/oracle/substep/normal_guess.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace tilesweep::oracle {
namespace {

template <class T>
struct FloatRect {
    T minX, minY, maxX, maxY;
};

template <class T>
int signOf(T v) {
    return v > T(0) ? 1 : (v < T(0) ? -1 : 0);
}

// Every comparison a tutorial writes: strict overlap of the two rectangles, in T.
template <class T>
bool overlapsX(const FloatRect<T>& a, const FloatRect<T>& b) {
    return a.minX < b.maxX && a.maxX > b.minX;
}
template <class T>
bool overlapsY(const FloatRect<T>& a, const FloatRect<T>& b) {
    return a.minY < b.maxY && a.maxY > b.minY;
}

template <class T>
FloatRect<T> boxAt(Vec2<T> p, Vec2<T> size) {
    return {p.x, p.y, p.x + size.x, p.y + size.y};
}

template <class T>
FloatRect<T> tileAt(const TileMap<T>& map, std::int32_t i, std::int32_t j) {
    const T minX = map.origin.x + static_cast<T>(i) * map.tileSize.x;
    const T minY = map.origin.y + static_cast<T>(j) * map.tileSize.y;
    return {minX, minY, map.origin.x + static_cast<T>(i + 1) * map.tileSize.x,
            map.origin.y + static_cast<T>(j + 1) * map.tileSize.y};
}

}  // namespace

template <class T>
std::vector<SubstepFrame<T>> resolveSceneSubstepFloat(const Scene<T>& scene, std::int64_t substeps) {
    if (substeps < 1) {
        throw std::invalid_argument("substep-float oracle: the number of substeps must be >= 1");
    }
    const TileMap<T>& map = scene.map;
    const Vec2<T> size = scene.box.size;
    const T n = static_cast<T>(substeps);
    std::vector<SubstepFrame<T>> frames;
    Vec2<T> p = scene.box.pos;
    for (const Vec2<T>& d : scene.moves) {
        SubstepFrame<T> out;
        out.substeps = substeps;
        const Vec2<T> step{d.x / n, d.y / n};

        // Tiles overlapped at the start are left alone (the box may leave them); the others are
        // tested at every substep. A platform is tested only on a move down that starts with the
        // box's bottom at or above its top, and is never a start overlap.
        std::vector<Cell> tested;
        const FloatRect<T> start = boxAt(p, size);
        for (std::int32_t j = 0; j < map.rows; ++j) {
            for (std::int32_t i = 0; i < map.columns; ++i) {
                const CellKind kind = map.kind(i, j);
                if (kind == CellKind::Empty) {
                    continue;
                }
                const FloatRect<T> tile = tileAt(map, i, j);
                if (kind == CellKind::OneWay) {
                    if (d.y > T(0) && start.maxY <= tile.minY) tested.push_back({i, j});
                } else if (overlapsX(start, tile) && overlapsY(start, tile)) {
                    out.frame.startOverlaps.push_back({i, j});
                } else {
                    tested.push_back({i, j});
                }
            }
        }

        Vec2<T> previous = p;
        for (std::int64_t k = 1; k <= substeps; ++k) {
            const Vec2<T> next{previous.x + step.x, previous.y + step.y};
            const FloatRect<T> at = boxAt(next, size);
            const FloatRect<T> before = boxAt(previous, size);
            for (const Cell& c : tested) {
                const FloatRect<T> tile = tileAt(map, c.i, c.j);
                if (!overlapsX(at, tile) || !overlapsY(at, tile)) {
                    continue;
                }
                // A platform stops the box only if it was over it and above its top a substep ago.
                if (map.kind(c.i, c.j) == CellKind::OneWay &&
                    !(overlapsX(before, tile) && before.maxY <= tile.minY)) {
                    continue;
                }
                const Normal normal = guessNormal(!overlapsX(before, tile), !overlapsY(before, tile),
                                                  signOf(d.x), signOf(d.y), std::fabs(d.x) > std::fabs(d.y));
                out.frame.contacts.push_back({c, normal, static_cast<T>(k) / n, {}});  // no position
            }
            if (!out.frame.contacts.empty()) {
                out.firstOverlap = k;
                break;
            }
            previous = next;
        }
        out.frame.position = previous;
        p = previous;
        frames.push_back(std::move(out));
    }
    return frames;
}

template std::vector<SubstepFrame<float>> resolveSceneSubstepFloat<float>(const Scene<float>&, std::int64_t);
template std::vector<SubstepFrame<double>> resolveSceneSubstepFloat<double>(const Scene<double>&,
                                                                            std::int64_t);

}  // namespace tilesweep::oracle
