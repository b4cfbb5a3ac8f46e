// SPDX-License-Identifier: MIT
// The C API (include/tilesweep/tilesweep.h) over the game-loop and batch calls. Nothing here
// throws but the pool's thread start, which is caught; memory comes from the map's allocator
// (malloc by default), never from operator new, and no C++ object is made in a caller's buffer.
#include "batch_run.h"
#include "c_types.h"
#include "move_range.h"

#include "tilesweep/batch.h"
#include "tilesweep/mover.h"
#include "tilesweep/tilesweep.h"

#include <cstdlib>
#include <new>
#include <type_traits>

static_assert(TILESWEEP_VERSION_MAJOR >= 0 && TILESWEEP_VERSION_MINOR < 100 && TILESWEEP_VERSION_PATCH < 100,
              "TILESWEEP_VERSION packs minor and patch in two decimal digits each");

namespace {

void* mallocAllocate(std::size_t size, void*) { return std::malloc(size); }
void mallocRelease(void* memory, std::size_t, void*) { std::free(memory); }

/// The allocator a map keeps: the caller's, or malloc and free.
ts_allocator allocatorOf(const ts_allocator* given) noexcept {
    if (given != nullptr && given->allocate != nullptr && given->release != nullptr) return *given;
    return ts_allocator{&mallocAllocate, &mallocRelease, nullptr};
}

}  // namespace

// A map is one block from its allocator: two headers, then columns * rows solid bytes, then (in
// a map from ts_map_create_one_way_*) columns * rows one-way bytes. The first header is the map;
// the second is the same map without its one-way cells (ts_map_without_one_way_*), over the
// same bytes, so that it sees every ts_map_set_* and dies with the map.
template <class T>
struct MapBlock {
    ts_allocator allocator;
    std::size_t bytes;  ///< the block's size, headers included
    tilesweep::PreparedMap<T> map;
    std::uint8_t* solid;   ///< the block's solid bytes
    std::uint8_t* oneWay;  ///< the block's one-way bytes; null when the map has no one-way layer
    bool isDropThrough;    ///< the second header: ts_map_destroy_* ignores it
};

struct ts_map_f : MapBlock<float> {};
struct ts_map_d : MapBlock<double> {};
static_assert(std::is_trivially_destructible<ts_map_f>::value &&
                  std::is_trivially_destructible<ts_map_d>::value,
              "a map's block is released without destructor calls");
static_assert(std::is_trivially_destructible<tilesweep::Contact<float>>::value &&
                  std::is_trivially_destructible<tilesweep::Contact<double>>::value,
              "a scratch contact list is released without destructor calls");

struct ts_pool {
    explicit ts_pool(int threads) : pool(threads) {}
    tilesweep::BatchPool pool;
};

namespace {

using tilesweep::MapError;
using tilesweep::MoveStatus;

template <class T>
using Types = tilesweep::detail::CTypes<T>;

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
        case MapError::InexactArithmetic:
            return TS_ERROR_INEXACT_ARITHMETIC;
        case MapError::NotPrepared:  // a C map is always prepared by ts_map_create_*
            return TS_ERROR_NULL_ARGUMENT;
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
    out.contacts_stored = r.contactsStored ? 1 : 0;
    out.contact_count = r.contactCount;
    out.start_overlap_count = r.startOverlapCount;
    out.clipped_displacement = {r.clippedDisplacement.x, r.clippedDisplacement.y};
}

template <class T>
typename Types<T>::Vec clipVelocity(typename Types<T>::Vec v, const typename Types<T>::Result* r) noexcept {
    if (r == nullptr) return v;
    tilesweep::MoveResult<T> flags;
    flags.onGround = r->on_ground != 0;
    flags.onCeiling = r->on_ceiling != 0;
    flags.wallNormalX = r->wall_normal_x;
    const tilesweep::Vec2<T> clipped = tilesweep::clipVelocity(toVec<T>(v), flags);
    return {clipped.x, clipped.y};
}

template <class T>
ts_error createMap(const typename Types<T>::Desc* desc, const std::uint8_t* oneWay, bool withOneWay,
                   typename Types<T>::Map** out) noexcept {
    using Map = typename Types<T>::Map;
    if (out == nullptr) return TS_ERROR_NULL_ARGUMENT;
    *out = nullptr;
    if (desc == nullptr) return TS_ERROR_NULL_ARGUMENT;
    // Check the header before copying columns * rows cells from the caller's pointer.
    tilesweep::TileMapView<T> view{toVec<T>(desc->origin), toVec<T>(desc->tile_size), desc->columns,
                                   desc->rows, desc->solid};
    const MapError header = tilesweep::validateTileMap(view);
    if (header != MapError::None) return errorOf(header);
    const ts_allocator allocator = allocatorOf(desc->allocator);
    // validateTileMap bounds columns * rows by kMaxCells (2^31 - 1): no overflow.
    const auto cells = static_cast<std::size_t>(desc->columns) * static_cast<std::size_t>(desc->rows);
    const std::size_t bytes = 2 * sizeof(Map) + (withOneWay ? 2 : 1) * cells;
    void* memory = allocator.allocate(bytes, allocator.user);
    if (memory == nullptr) return TS_ERROR_OUT_OF_MEMORY;
    auto* map = new (memory) Map{};  // the library's own block, not the caller's storage
    auto* dropThrough = new (map + 1) Map{};
    map->allocator = allocator;
    map->bytes = bytes;
    map->solid = reinterpret_cast<std::uint8_t*>(map + 2);
    for (std::size_t k = 0; k < cells; ++k) map->solid[k] = desc->solid[k];
    view.solid = map->solid;
    if (withOneWay) {
        map->oneWay = map->solid + cells;
        for (std::size_t k = 0; k < cells; ++k) map->oneWay[k] = oneWay != nullptr ? oneWay[k] : 0;
        view.oneWay = map->oneWay;
    }
    map->map = tilesweep::prepareMap(view);
    *dropThrough = *map;
    dropThrough->map = map->map.withoutOneWay();
    dropThrough->isDropThrough = true;
    *out = map;
    return errorOf(map->map.error());
}

template <class Map>
void destroyMap(Map* map) noexcept {
    if (map == nullptr || map->isDropThrough) return;
    const ts_allocator allocator = map->allocator;
    const std::size_t bytes = map->bytes;
    allocator.release(map, bytes, allocator.user);  // both headers are trivially destructible
}

template <class T>
ts_error setCell(typename Types<T>::Map* map, std::int32_t i, std::int32_t j, int kind) noexcept {
    if (map == nullptr) return TS_ERROR_NULL_ARGUMENT;
    const auto& v = map->map.view();
    if (i < 0 || j < 0 || i >= v.columns || j >= v.rows) return TS_ERROR_CELL_OUT_OF_RANGE;
    if (kind != TS_CELL_EMPTY && kind != TS_CELL_SOLID && kind != TS_CELL_ONE_WAY) return TS_ERROR_CELL_KIND;
    if (kind == TS_CELL_ONE_WAY && map->oneWay == nullptr) return TS_ERROR_CELL_KIND;
    const std::size_t k =
        static_cast<std::size_t>(j) * static_cast<std::size_t>(v.columns) + static_cast<std::size_t>(i);
    map->solid[k] = kind == TS_CELL_SOLID ? 1 : 0;
    if (map->oneWay != nullptr) map->oneWay[k] = kind == TS_CELL_ONE_WAY ? 1 : 0;
    return TS_OK;
}

template <class T>
ts_error getCell(const typename Types<T>::Map* map, std::int32_t i, std::int32_t j,
                 std::uint8_t* kind) noexcept {
    if (map == nullptr || kind == nullptr) return TS_ERROR_NULL_ARGUMENT;
    const auto& v = map->map.view();
    if (i < 0 || j < 0 || i >= v.columns || j >= v.rows) return TS_ERROR_CELL_OUT_OF_RANGE;
    switch (v.kind(i, j)) {
        case tilesweep::CellKind::Empty:
            *kind = TS_CELL_EMPTY;
            break;
        case tilesweep::CellKind::Solid:
            *kind = TS_CELL_SOLID;
            break;
        case tilesweep::CellKind::OneWay:
            *kind = TS_CELL_ONE_WAY;
            break;
    }
    return TS_OK;
}

template <class Map>
const Map* withoutOneWay(const Map* map) noexcept {
    if (map == nullptr || map->isDropThrough) return map;
    return map + 1;
}

template <class T>
void copyContacts(const tilesweep::Contact<T>* from, std::int32_t count,
                  typename Types<T>::ContactC* to) noexcept {
    for (std::int32_t k = 0; k < count; ++k) {
        const tilesweep::Contact<T>& c = from[k];
        to[k] = {c.tile.i, c.tile.j, c.normal.x, c.normal.y, c.time, {c.position.x, c.position.y}};
    }
}

/// Whether a move's contacts were resolved (and so may be copied out).
bool wasResolved(MoveStatus s) noexcept { return s == MoveStatus::Moved || s == MoveStatus::Blocked; }

template <class T>
ts_error moveOne(const typename Types<T>::Map* map, const typename Types<T>::Mover* mover,
                 typename Types<T>::Result* result, typename Types<T>::ContactC* contacts,
                 std::int32_t capacity) noexcept {
    if (map == nullptr || mover == nullptr || result == nullptr) return TS_ERROR_NULL_ARGUMENT;
    if (contacts == nullptr) capacity = 0;
    const tilesweep::MoveInput<T> input = toInput<T>(*mover);
    const std::int32_t bound = tilesweep::maxContacts(input.box.size, map->map.view().tileSize);
    if (capacity >= bound && bound > tilesweep::kInlineContacts) {
        // A box too wide for the inline contacts, with a buffer that holds its bound: resolve into
        // a scratch list of Contact<T> from the map's allocator, then copy into the caller's
        // ts_contact_*s. Only such wide boxes (over 30 tiles on a side) pay for this.
        const std::size_t bytes = static_cast<std::size_t>(bound) * sizeof(tilesweep::Contact<T>);
        void* memory = map->allocator.allocate(bytes, map->allocator.user);
        if (memory == nullptr) return TS_ERROR_OUT_OF_MEMORY;
        auto* scratch = static_cast<tilesweep::Contact<T>*>(memory);
        for (std::int32_t k = 0; k < bound; ++k) new (scratch + k) tilesweep::Contact<T>{};
        const tilesweep::MoveResult<T> r = tilesweep::moveAndSlide(map->map, input, scratch, bound);
        if (wasResolved(r.status) && r.contactsStored) copyContacts<T>(scratch, r.contactCount, contacts);
        map->allocator.release(memory, bytes, map->allocator.user);  // Contact<T> is trivially destructible
        toResult(r, *result);
        return errorOf(r.status);
    }
    // Otherwise the contacts go to the inline array, and are copied out when moveAndSlide says
    // they were all stored there (never for a refused move).
    tilesweep::Contact<T> local[tilesweep::kInlineContacts];
    const tilesweep::MoveResult<T> r = tilesweep::moveAndSlide(
        map->map, input, local,
        capacity < tilesweep::kInlineContacts ? capacity : tilesweep::kInlineContacts);
    if (wasResolved(r.status) && r.contactsStored) copyContacts<T>(local, r.contactCount, contacts);
    toResult(r, *result);
    if (contacts == nullptr) result->contacts_stored = 0;
    return errorOf(r.status);
}

template <class T>
struct CBatch {
    const tilesweep::PreparedMap<T>* map;
    const typename Types<T>::Mover* movers;
    typename Types<T>::Result* results;
};

/// Movers a batch range converts at a time: a chunk's inputs and results in the C++ types live
/// on the stack (6 KiB in double).
constexpr std::size_t kBatchChunk = 64;

/// One range of a C batch: the C++ batch's loop (moveAndSlideRange, move_range.h), which solves
/// each frame inline, on chunks of movers converted to its types and back. Each result is
/// moveAndSlide's for its mover (batch.h), as a C caller's single move would give it.
template <class T>
void runCBatch(void* context, std::size_t begin, std::size_t end) {
    const auto& job = *static_cast<const CBatch<T>*>(context);
    tilesweep::MoveInput<T> inputs[kBatchChunk];
    tilesweep::MoveResult<T> results[kBatchChunk];
    for (std::size_t first = begin; first < end; first += kBatchChunk) {
        const std::size_t count = end - first < kBatchChunk ? end - first : kBatchChunk;
        for (std::size_t k = 0; k < count; ++k) inputs[k] = toInput<T>(job.movers[first + k]);
        tilesweep::detail::moveAndSlideRange(*job.map, inputs, results, 0, count);
        for (std::size_t k = 0; k < count; ++k) toResult(results[k], job.results[first + k]);
    }
}

template <class T>
ts_error moveBatch(const typename Types<T>::Map* map, const typename Types<T>::Mover* movers,
                   typename Types<T>::Result* results, std::size_t count, ts_pool* pool,
                   const ts_task_system* cTasks = nullptr) noexcept {
    if (map == nullptr || ((movers == nullptr || results == nullptr) && count > 0))
        return TS_ERROR_NULL_ARGUMENT;
    CBatch<T> job{&map->map, movers, results};
    tilesweep::TaskSystem tasks;
    if (cTasks != nullptr) {
        // The C and C++ task callbacks have the same parameters, in the same order.
        tasks.enqueue = cTasks->enqueue;
        tasks.finish = cTasks->finish;
        tasks.userContext = cTasks->user_context;
    }
    tilesweep::detail::runBatch(count, &runCBatch<T>, &job, pool != nullptr ? &pool->pool : nullptr, &tasks);
    ts_error worst = TS_OK;
    for (std::size_t k = 0; k < count && worst == TS_OK; ++k)
        worst = errorOf(static_cast<MoveStatus>(results[k].status));
    return worst;
}

}  // namespace

extern "C" {

uint32_t ts_get_version(void) { return TILESWEEP_VERSION; }

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
        case TS_ERROR_INEXACT_ARITHMETIC:
            return "arithmetic: the floating-point environment is not exact (rounding mode not to nearest, "
                   "fused multiply-add or excess precision); the library refuses every map";
        case TS_ERROR_CELL_KIND:
            return "cell: kind is not TS_CELL_EMPTY, TS_CELL_SOLID or TS_CELL_ONE_WAY, or is TS_CELL_ONE_WAY "
                   "in a "
                   "map made without one-way cells (use ts_map_create_one_way_*)";
    }
    return "unknown tilesweep error code";
}

ts_error ts_map_create_f(const ts_map_desc_f* desc, ts_map_f** out) {
    return createMap<float>(desc, nullptr, false, out);
}
ts_error ts_map_create_d(const ts_map_desc_d* desc, ts_map_d** out) {
    return createMap<double>(desc, nullptr, false, out);
}
void ts_map_destroy_f(ts_map_f* map) { destroyMap(map); }
void ts_map_destroy_d(ts_map_d* map) { destroyMap(map); }
ts_error ts_map_set_solid_f(ts_map_f* map, int32_t i, int32_t j, int solid) {
    return setCell<float>(map, i, j, solid != 0 ? TS_CELL_SOLID : TS_CELL_EMPTY);
}
ts_error ts_map_set_solid_d(ts_map_d* map, int32_t i, int32_t j, int solid) {
    return setCell<double>(map, i, j, solid != 0 ? TS_CELL_SOLID : TS_CELL_EMPTY);
}

ts_error ts_map_create_one_way_f(const ts_map_desc_f* desc, const uint8_t* one_way, ts_map_f** out) {
    return createMap<float>(desc, one_way, true, out);
}
ts_error ts_map_create_one_way_d(const ts_map_desc_d* desc, const uint8_t* one_way, ts_map_d** out) {
    return createMap<double>(desc, one_way, true, out);
}
ts_error ts_map_set_cell_f(ts_map_f* map, int32_t i, int32_t j, int kind) {
    return setCell<float>(map, i, j, kind);
}
ts_error ts_map_set_cell_d(ts_map_d* map, int32_t i, int32_t j, int kind) {
    return setCell<double>(map, i, j, kind);
}
ts_error ts_map_get_cell_f(const ts_map_f* map, int32_t i, int32_t j, uint8_t* kind) {
    return getCell<float>(map, i, j, kind);
}
ts_error ts_map_get_cell_d(const ts_map_d* map, int32_t i, int32_t j, uint8_t* kind) {
    return getCell<double>(map, i, j, kind);
}
const ts_map_f* ts_map_without_one_way_f(const ts_map_f* map) { return withoutOneWay(map); }
const ts_map_d* ts_map_without_one_way_d(const ts_map_d* map) { return withoutOneWay(map); }

int32_t ts_max_contacts_f(ts_vec2_f box, ts_vec2_f tile) {
    return tilesweep::maxContacts(tilesweep::Vec2<float>{box.x, box.y},
                                  tilesweep::Vec2<float>{tile.x, tile.y});
}
int32_t ts_max_contacts_d(ts_vec2_d box, ts_vec2_d tile) {
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

ts_vec2_f ts_clip_velocity_f(ts_vec2_f velocity, const ts_result_f* result) {
    return clipVelocity<float>(velocity, result);
}
ts_vec2_d ts_clip_velocity_d(ts_vec2_d velocity, const ts_result_d* result) {
    return clipVelocity<double>(velocity, result);
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

ts_error ts_move_and_slide_batch_tasks_f(const ts_map_f* map, const ts_mover_f* movers, ts_result_f* results,
                                         size_t count, const ts_task_system* tasks) {
    if (tasks == nullptr) return TS_ERROR_NULL_ARGUMENT;
    return moveBatch<float>(map, movers, results, count, nullptr, tasks);
}
ts_error ts_move_and_slide_batch_tasks_d(const ts_map_d* map, const ts_mover_d* movers, ts_result_d* results,
                                         size_t count, const ts_task_system* tasks) {
    if (tasks == nullptr) return TS_ERROR_NULL_ARGUMENT;
    return moveBatch<double>(map, movers, results, count, nullptr, tasks);
}

}  // extern "C"
