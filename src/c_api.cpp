// SPDX-License-Identifier: MIT
// The C API (include/tilesweep/tilesweep.h) over the game-loop and batch calls. Every entry
// point catches everything (allocation and thread start are the only things that can throw)
// and reports a ts_error; none aborts.
#include "tilesweep/batch.h"
#include "tilesweep/mover.h"
#include "tilesweep/tilesweep.h"

#include <cstring>
#include <new>
#include <vector>

struct ts_map_f {
    std::vector<std::uint8_t> cells;
    tilesweep::PreparedMap<float> map;
};

struct ts_map_d {
    std::vector<std::uint8_t> cells;
    tilesweep::PreparedMap<double> map;
};

struct ts_pool {
    explicit ts_pool(int threads) : pool(threads) {}
    tilesweep::BatchPool pool;
};

namespace {

using tilesweep::MapError;
using tilesweep::MoveStatus;

template <class T>
struct Types;
template <>
struct Types<float> {
    using Map = ts_map_f;
    using Desc = ts_map_desc_f;
    using Vec = ts_vec2f;
    using Mover = ts_mover_f;
    using Result = ts_result_f;
    using ContactC = ts_contact_f;
};
template <>
struct Types<double> {
    using Map = ts_map_d;
    using Desc = ts_map_desc_d;
    using Vec = ts_vec2d;
    using Mover = ts_mover_d;
    using Result = ts_result_d;
    using ContactC = ts_contact_d;
};

ts_error errorOf(MapError e) noexcept {
    switch (e) {
        case MapError::None:
            return TS_OK;
        case MapError::NonFiniteOrigin:
            return TS_ERROR_MAP_NON_FINITE_ORIGIN;
        case MapError::NonPositiveTileSize:
            return TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE;
        case MapError::NegativeDimensions:
            return TS_ERROR_MAP_NEGATIVE_DIMENSIONS;
        case MapError::TooLarge:
            return TS_ERROR_MAP_TOO_LARGE;
#if defined(TILESWEEP_FAULT_C_ERROR_CODES_SWAPPED)  // deliberate fault: neighbouring codes swapped
        case MapError::UnrepresentableEdgeX:
            return TS_ERROR_MAP_UNREPRESENTABLE_EDGE_Y;
        case MapError::UnrepresentableEdgeY:
            return TS_ERROR_MAP_UNREPRESENTABLE_EDGE_X;
#else
        case MapError::UnrepresentableEdgeX:
            return TS_ERROR_MAP_UNREPRESENTABLE_EDGE_X;
        case MapError::UnrepresentableEdgeY:
            return TS_ERROR_MAP_UNREPRESENTABLE_EDGE_Y;
#endif
    }
    return TS_ERROR_MAP_NEGATIVE_DIMENSIONS;
}

ts_error errorOf(MoveStatus s) noexcept {
    switch (s) {
        case MoveStatus::Moved:
        case MoveStatus::Blocked:
            return TS_OK;
        case MoveStatus::InvalidInput:
            return TS_ERROR_INVALID_INPUT;
        case MoveStatus::ContactBufferTooSmall:
            return TS_ERROR_CONTACT_BUFFER_TOO_SMALL;
    }
    return TS_ERROR_INVALID_INPUT;
}

template <class T, class V>
tilesweep::Vec2<T> toVec(V v) noexcept {
    return {v.x, v.y};
}

template <class T>
tilesweep::MoveInput<T> toInput(const typename Types<T>::Mover& m) noexcept {
    return {{toVec<T>(m.box.pos), toVec<T>(m.box.size)}, toVec<T>(m.displacement)};
}

template <class T>
void toResult(const tilesweep::MoveResult<T>& r, typename Types<T>::Result& out) noexcept {
    out.position = {r.position.x, r.position.y};
    out.status = static_cast<std::uint8_t>(r.status);
    out.blocked_x = r.blockedX ? 1 : 0;
    out.blocked_y = r.blockedY ? 1 : 0;
    out.on_ground = r.onGround ? 1 : 0;
    out.on_ceiling = r.onCeiling ? 1 : 0;
    out.on_wall = r.onWall ? 1 : 0;
    out.wall_normal_x = r.wallNormalX;
    out.contact_count = r.contactCount;
    out.start_overlap_count = r.startOverlapCount;
}

template <class T>
ts_error createMap(const typename Types<T>::Desc* desc, typename Types<T>::Map** out) noexcept {
    if (out == nullptr) return TS_ERROR_NULL_ARGUMENT;
    *out = nullptr;
    if (desc == nullptr) return TS_ERROR_NULL_ARGUMENT;
    // Check the header before copying columns * rows cells from the caller's pointer.
    tilesweep::TileMapView<T> view{toVec<T>(desc->origin), toVec<T>(desc->tile_size), desc->columns,
                                   desc->rows, desc->solid};
    const MapError header = tilesweep::validateTileMap(view);
    if (header != MapError::None) return errorOf(header);
    auto* map = new (std::nothrow) typename Types<T>::Map;
    if (map == nullptr) return TS_ERROR_OUT_OF_MEMORY;
    try {
        const auto cells = static_cast<std::size_t>(desc->columns) * static_cast<std::size_t>(desc->rows);
        map->cells.assign(desc->solid, desc->solid + cells);
    } catch (...) {
        delete map;
        return TS_ERROR_OUT_OF_MEMORY;
    }
    view.solid = map->cells.data();
    map->map = tilesweep::prepareMap(view);
    *out = map;
    return errorOf(map->map.error());
}

template <class T>
ts_error setSolid(typename Types<T>::Map* map, std::int32_t i, std::int32_t j, int solid) noexcept {
    if (map == nullptr) return TS_ERROR_NULL_ARGUMENT;
    const auto& v = map->map.view();
    if (i < 0 || j < 0 || i >= v.columns || j >= v.rows) return TS_ERROR_CELL_OUT_OF_RANGE;
    map->cells[static_cast<std::size_t>(j) * static_cast<std::size_t>(v.columns) +
               static_cast<std::size_t>(i)] = solid != 0 ? 1 : 0;
    return TS_OK;
}

template <class T>
ts_error moveOne(const typename Types<T>::Map* map, const typename Types<T>::Mover* mover,
                 typename Types<T>::Result* result, typename Types<T>::ContactC* contacts,
                 std::int32_t capacity) noexcept {
    if (map == nullptr || mover == nullptr || result == nullptr) return TS_ERROR_NULL_ARGUMENT;
    if (contacts == nullptr) capacity = 0;
    const tilesweep::MoveInput<T> input = toInput<T>(*mover);
    tilesweep::MoveResult<T> r;
    const std::int32_t bound = tilesweep::maxContacts(input.box.size, map->map.view().tileSize);
    tilesweep::Contact<T> local[tilesweep::kInlineContacts];
    if (capacity >= bound && bound > tilesweep::kInlineContacts) {
        // A box too wide for the inline contacts, with a buffer that holds its bound: resolve
        // into the caller's storage as Contact<T>s (same size: the static_assert), then turn
        // each into a ts_contact_* in place. Only such wide boxes pay for this.
        using ContactC = typename Types<T>::ContactC;
        static_assert(sizeof(ContactC) == sizeof(tilesweep::Contact<T>), "in-place conversion");
        auto* raw = reinterpret_cast<unsigned char*>(contacts);
        const std::size_t size = sizeof(ContactC);
        for (std::int32_t k = 0; k < bound; ++k)
            new (raw + static_cast<std::size_t>(k) * size) tilesweep::Contact<T>{};
        r = tilesweep::moveAndSlide(map->map, input,
                                    std::launder(reinterpret_cast<tilesweep::Contact<T>*>(raw)), bound);
        for (std::int32_t k = 0; k < r.contactCount && k < bound; ++k) {
            tilesweep::Contact<T> c;
            std::memcpy(&c, raw + static_cast<std::size_t>(k) * size, size);
            new (raw + static_cast<std::size_t>(k) * size)
                ContactC{c.tile.i, c.tile.j, c.normal.x, c.normal.y, c.time};
        }
        toResult(r, *result);
        return errorOf(r.status);
    }
    // Otherwise the frame's contacts fit the inline array (or the frame is refused as too wide
    // for the buffer given): copy them out when they fit the caller's capacity.
    r = tilesweep::moveAndSlide(
        map->map, input, local,
        capacity < tilesweep::kInlineContacts ? capacity : tilesweep::kInlineContacts);
    if (r.contactCount <= capacity)
        for (std::int32_t k = 0; k < r.contactCount; ++k) {
            const tilesweep::Contact<T>& c = local[k];
            contacts[k] = {c.tile.i, c.tile.j, c.normal.x, c.normal.y, c.time};
        }
    toResult(r, *result);
    return errorOf(r.status);
}

template <class T>
struct CBatch {
    const tilesweep::PreparedMap<T>* map;
    const typename Types<T>::Mover* movers;
    typename Types<T>::Result* results;
};

template <class T>
void runCBatch(void* context, std::size_t begin, std::size_t end) {
    const auto& job = *static_cast<const CBatch<T>*>(context);
    for (std::size_t k = begin; k < end; ++k)
        toResult(tilesweep::moveAndSlide(*job.map, toInput<T>(job.movers[k])), job.results[k]);
}

template <class T>
ts_error moveBatch(const typename Types<T>::Map* map, const typename Types<T>::Mover* movers,
                   typename Types<T>::Result* results, std::size_t count, ts_pool* pool) noexcept {
    if (map == nullptr || ((movers == nullptr || results == nullptr) && count > 0))
        return TS_ERROR_NULL_ARGUMENT;
    CBatch<T> job{&map->map, movers, results};
    if (pool == nullptr)
        runCBatch<T>(&job, 0, count);
    else
        pool->pool.run(count, 256, &runCBatch<T>, &job);
    ts_error worst = TS_OK;
    for (std::size_t k = 0; k < count && worst == TS_OK; ++k)
        worst = errorOf(static_cast<MoveStatus>(results[k].status));
    return worst;
}

}  // namespace

extern "C" {

const char* ts_error_message(int error) {
    // An int, not a ts_error: a caller may pass any code, and loading a value outside the
    // enumeration into the enum type would be undefined in C++.
    switch (error) {
        case TS_OK:
            return "ok";
        case TS_ERROR_NULL_ARGUMENT:
            return "a required pointer argument is NULL";
        case TS_ERROR_INVALID_INPUT:
            return "mover: a value is not finite, or a box size is not > 0";
        case TS_ERROR_MAP_NON_FINITE_ORIGIN:
            return "map.origin: non-finite value";
        case TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE:
            return "map.tile_size: tile sizes must be finite and > 0";
        case TS_ERROR_MAP_NEGATIVE_DIMENSIONS:
            return "map: columns and rows must be >= 0, with cells present";
        case TS_ERROR_MAP_TOO_LARGE:
            return "map: more than 2147483647 cells";
        case TS_ERROR_MAP_UNREPRESENTABLE_EDGE_X:
            return "map.tile_size: a tile edge origin.x + k*tile_size.x is not representable";
        case TS_ERROR_MAP_UNREPRESENTABLE_EDGE_Y:
            return "map.tile_size: a tile edge origin.y + k*tile_size.y is not representable";
        case TS_ERROR_CONTACT_BUFFER_TOO_SMALL:
            return "contacts: this box needs a buffer of ts_max_contacts_* entries";
        case TS_ERROR_CELL_OUT_OF_RANGE:
            return "cell: index outside the map";
        case TS_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case TS_ERROR_THREADS:
            return "pool: a worker thread could not be started";
    }
    return "unknown tilesweep error code";
}

ts_error ts_map_create_f(const ts_map_desc_f* desc, ts_map_f** out) { return createMap<float>(desc, out); }
ts_error ts_map_create_d(const ts_map_desc_d* desc, ts_map_d** out) { return createMap<double>(desc, out); }
void ts_map_destroy_f(ts_map_f* map) { delete map; }
void ts_map_destroy_d(ts_map_d* map) { delete map; }
ts_error ts_map_set_solid_f(ts_map_f* map, int32_t i, int32_t j, int solid) {
    return setSolid<float>(map, i, j, solid);
}
ts_error ts_map_set_solid_d(ts_map_d* map, int32_t i, int32_t j, int solid) {
    return setSolid<double>(map, i, j, solid);
}

int32_t ts_max_contacts_f(ts_vec2f box, ts_vec2f tile) {
    return tilesweep::maxContacts(tilesweep::Vec2<float>{box.x, box.y},
                                  tilesweep::Vec2<float>{tile.x, tile.y});
}
int32_t ts_max_contacts_d(ts_vec2d box, ts_vec2d tile) {
    return tilesweep::maxContacts(tilesweep::Vec2<double>{box.x, box.y},
                                  tilesweep::Vec2<double>{tile.x, tile.y});
}

ts_error ts_move_and_slide_f(const ts_map_f* map, const ts_mover_f* mover, ts_result_f* result,
                             ts_contact_f* contacts, int32_t capacity) {
    return moveOne<float>(map, mover, result, contacts, capacity);
}
ts_error ts_move_and_slide_d(const ts_map_d* map, const ts_mover_d* mover, ts_result_d* result,
                             ts_contact_d* contacts, int32_t capacity) {
    return moveOne<double>(map, mover, result, contacts, capacity);
}

ts_error ts_pool_create(int32_t threads, ts_pool** out) {
    if (out == nullptr) return TS_ERROR_NULL_ARGUMENT;
    *out = nullptr;
    try {
        *out = new ts_pool(threads);
    } catch (const std::bad_alloc&) {
        return TS_ERROR_OUT_OF_MEMORY;
    } catch (...) {
        return TS_ERROR_THREADS;
    }
    return TS_OK;
}
void ts_pool_destroy(ts_pool* pool) { delete pool; }

ts_error ts_move_and_slide_batch_f(const ts_map_f* map, const ts_mover_f* movers, ts_result_f* results,
                                   size_t count, ts_pool* pool) {
    return moveBatch<float>(map, movers, results, count, pool);
}
ts_error ts_move_and_slide_batch_d(const ts_map_d* map, const ts_mover_d* movers, ts_result_d* results,
                                   size_t count, ts_pool* pool) {
    return moveBatch<double>(map, movers, results, count, pool);
}

}  // extern "C"
