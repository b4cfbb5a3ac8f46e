// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/seed/seed_resolve.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tilesweep::oracle {
namespace {

template <class T>
struct Rect {
    T left, top, right, bottom;
};

template <class T>
Rect<T> rectOf(Vec2<T> pos, Vec2<T> size) {
    return {pos.x, pos.y, pos.x + size.x, pos.y + size.y};
}

template <class T>
Rect<T> tileRect(const TileMap<T>& map, std::int32_t i, std::int32_t j) {
    return {map.origin.x + static_cast<T>(i) * map.tileSize.x,
            map.origin.y + static_cast<T>(j) * map.tileSize.y,
            map.origin.x + static_cast<T>(i + 1) * map.tileSize.x,
            map.origin.y + static_cast<T>(j + 1) * map.tileSize.y};
}

template <class T>
bool overlaps(const Rect<T>& a, const Rect<T>& b) {
    return a.left < b.right && a.right > b.left && a.top < b.bottom && a.bottom > b.top;
}

template <class T>
std::int8_t againstSign(T v) {
    return static_cast<std::int8_t>(v > T(0) ? -1 : (v < T(0) ? 1 : 0));
}

}  // namespace

template <class T>
FrameResult<T> resolveFrameSeed(const TileMap<T>& map, const Box<T>& box, Vec2<T> displacement, T epsilon) {
    FrameResult<T> result;
    const Vec2<T> size = box.size;
    const Rect<T> previous = rectOf(box.pos, size);
    Vec2<T> current{box.pos.x + displacement.x, box.pos.y + displacement.y};

    // "All tiles that are put through this function should be overlapping with the bounds of the
    // swept shape": the union of the old and the new rectangle, in row-major order.
    const Rect<T> next = rectOf(current, size);
    const Rect<T> swept{std::min(previous.left, next.left), std::min(previous.top, next.top),
                        std::max(previous.right, next.right), std::max(previous.bottom, next.bottom)};

    for (std::int32_t j = 0; j < map.rows; ++j) {
        for (std::int32_t i = 0; i < map.columns; ++i) {
            if (map.solid[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.columns) +
                          static_cast<std::size_t>(i)] == 0) {
                continue;
            }
            const Rect<T> tile = tileRect(map, i, j);
            if (!overlaps(swept, tile)) {
                continue;
            }
            const Vec2<T> velocity{current.x - previous.left, current.y - previous.top};
            const T distanceX = velocity.x > T(0) ? tile.left - previous.right : tile.right - previous.left;
            const T distanceY = velocity.y > T(0) ? tile.top - previous.bottom : tile.bottom - previous.top;
            const T disjointX = velocity.x > T(0) ? tile.right - previous.left : tile.left - previous.right;
            const T disjointY = velocity.y > T(0) ? tile.bottom - previous.top : tile.top - previous.bottom;
            const T timeX = distanceX / velocity.x;
            const T timeY = distanceY / velocity.y;
            const T time = std::max(timeX, timeY);
            const T disjoint = std::min(disjointX, disjointY);
            bool collided = !(time > disjoint + epsilon);
            if ((timeX < -epsilon && timeY < -epsilon) || timeX > T(1) + epsilon || timeY > T(1) + epsilon) {
                collided = false;
            }
            if (!collided) {
                continue;
            }
            const T back = T(1) - time;
            current = {current.x - back * velocity.x, current.y - back * velocity.y};
            const Normal normal =
                timeX < timeY ? Normal{0, againstSign(velocity.y)} : Normal{againstSign(velocity.x), 0};
            result.contacts.push_back({{i, j}, normal, time, {}});  // the seed places no contact
        }
    }
    result.position = current;
    return result;
}

template <class T>
std::vector<FrameResult<T>> resolveSceneSeed(const Scene<T>& scene, T epsilon) {
    std::vector<FrameResult<T>> frames;
    Box<T> box = scene.box;
    for (const Vec2<T>& move : scene.moves) {
        frames.push_back(resolveFrameSeed(scene.map, box, move, epsilon));
        box.pos = frames.back().position;
    }
    return frames;
}

template FrameResult<float> resolveFrameSeed<float>(const TileMap<float>&, const Box<float>&, Vec2<float>,
                                                    float);
template FrameResult<double> resolveFrameSeed<double>(const TileMap<double>&, const Box<double>&,
                                                      Vec2<double>, double);
template std::vector<FrameResult<float>> resolveSceneSeed<float>(const Scene<float>&, float);
template std::vector<FrameResult<double>> resolveSceneSeed<double>(const Scene<double>&, double);

}  // namespace tilesweep::oracle
