/* SPDX-License-Identifier: MIT */
#ifndef TILESWEEP_TILESWEEP_H
#define TILESWEEP_TILESWEEP_H

/* The C API of tilesweep: plain C99, for C, C#, Rust, Zig, LuaJIT's FFI and GDExtension.
 *
 * The same resolver as the C++ API (tilesweep/mover.h, tilesweep/batch.h), bit for bit: exact
 * swept-AABB move-and-slide of boxes through a tile map (docs/contract.md). x grows to the
 * right, y downward; landing on a floor is the normal (0, -1). Every function with a suffix _f
 * works in float, _d in double. Nothing throws and nothing aborts: every function that can fail
 * returns a ts_error, ts_error_message names it, and a result is written only on TS_OK (or, for
 * a move refused as invalid, the start position with status TS_MOVE_INVALID_INPUT).
 * Library: tilesweep_c (libtilesweep_c.so; LuaJIT: ffi.load("tilesweep_c")).
 *
 * Versions: TILESWEEP_VERSION_* is the version of this header, ts_get_version() that of the
 * library loaded; a program should check that their major and (while the major is 0) minor
 * numbers agree. While the version is 0.x every minor release may break the ABI, so the shared
 * library's soname carries both (libtilesweep_c.so.0.MINOR); from 1.0 on it carries the major.
 *
 * Usage, C (tests/c_api/recipe_test.c runs it as written, and fails when the two differ):
 *
 *     ts_map_f* map = NULL;  // cells: columns * rows bytes, row by row, 1 = solid
 *     ts_map_desc_f desc = {{0, 0}, {16, 16}, columns, rows, cells, NULL};  // NULL: malloc
 *     ts_error error = ts_map_create_f(&desc, &map);  // copies the cells
 *     if (error != TS_OK) return fail(ts_error_message((int)error));
 *     ts_vec2_f velocity = {vx, vy};
 *     ts_mover_f mover = {{{x, y}, {w, h}}, {velocity.x * dt, velocity.y * dt}};
 *     ts_result_f r;
 *     ts_move_and_slide_f(map, &mover, &r, NULL, 0);  // no contact buffer needed for the flags
 *     x = r.position.x;
 *     y = r.position.y;
 *     velocity = ts_clip_velocity_f(velocity, &r);  // stops on floors, ceilings and walls
 *     ts_map_destroy_f(map);
 *
 * One-way (jump-through) cells (0.4): make the map with ts_map_create_one_way_f(&desc, one_way,
 * &map) instead, one_way laid out as the cells, nonzero one-way. A frame that drops through the
 * platforms passes ts_map_without_one_way_f(map) in place of map to any move or batch call.
 * Every struct and function of 0.3 is unchanged (no struct grew a field), and a map made by
 * ts_map_create_* has no one-way cells and resolves as it did.
 */

#include <stddef.h>
#include <stdint.h>

/* The version of this header; CMakeLists.txt reads the project version from these lines. */
#define TILESWEEP_VERSION_MAJOR 0
#define TILESWEEP_VERSION_MINOR 4
#define TILESWEEP_VERSION_PATCH 0
/* major * 10000 + minor * 100 + patch, as ts_get_version() returns it. */
#define TILESWEEP_VERSION \
    (TILESWEEP_VERSION_MAJOR * 10000 + TILESWEEP_VERSION_MINOR * 100 + TILESWEEP_VERSION_PATCH)

#if defined(_WIN32) && defined(TILESWEEP_C_BUILD)
#define TILESWEEP_EXPORT __declspec(dllexport)
#elif defined(_WIN32)
#define TILESWEEP_EXPORT __declspec(dllimport)
#elif defined(__GNUC__)
#define TILESWEEP_EXPORT __attribute__((visibility("default")))
#else
#define TILESWEEP_EXPORT
#endif

/* Marks a name kept for one release after a rename. */
#if defined(__GNUC__) || defined(__clang__)
#define TILESWEEP_DEPRECATED(message) __attribute__((deprecated(message)))
#else
#define TILESWEEP_DEPRECATED(message)
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** Why a call failed; TS_OK (0) when it did not. */
typedef enum ts_error {
    TS_OK = 0,
    TS_ERROR_NULL_ARGUMENT = 1,              /**< a required pointer is NULL */
    TS_ERROR_INVALID_INPUT = 2,              /**< a mover has a non-finite value or a size <= 0 */
    TS_ERROR_MAP_NON_FINITE_ORIGIN = 3,      /**< map origin is NaN or infinite */
    TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE = 4, /**< a tile size is not finite and > 0 */
    TS_ERROR_MAP_NEGATIVE_DIMENSIONS = 5,    /**< columns or rows < 0, or cells missing */
    TS_ERROR_MAP_TOO_LARGE = 6,              /**< more than 2^31 - 1 cells */
    TS_ERROR_MAP_UNREPRESENTABLE_EDGE_X = 7, /**< some tile edge on x is not exactly a float/double */
    TS_ERROR_MAP_UNREPRESENTABLE_EDGE_Y = 8, /**< likewise on y */
    TS_ERROR_CONTACT_BUFFER_TOO_SMALL = 9,   /**< never returned since 0.2 */
    TS_ERROR_CELL_OUT_OF_RANGE = 10,         /**< a cell index outside the map */
    TS_ERROR_OUT_OF_MEMORY = 11,             /**< allocation failed (map or pool creation only) */
    TS_ERROR_THREADS = 12,                   /**< a worker thread could not be started */
    TS_ERROR_INEXACT_ARITHMETIC = 13,        /**< rounding not to nearest, FMA or excess precision */
    TS_ERROR_CELL_KIND = 14                  /**< not a ts_cell_kind, or one-way in a map without them */
} ts_error;

/** What a cell holds (0.4): ts_map_set_cell_*, ts_map_get_cell_*. */
typedef enum ts_cell_kind {
    TS_CELL_EMPTY = 0,
    TS_CELL_SOLID = 1,  /**< blocks from every side */
    TS_CELL_ONE_WAY = 2 /**< blocks only a box moving down onto its top face from at or above it */
} ts_cell_kind;

/** How a move ended (ts_result_*.status). */
typedef enum ts_move_status {
    TS_MOVE_MOVED = 0,                   /**< nothing hit: moved the whole way */
    TS_MOVE_BLOCKED = 1,                 /**< at least one tile hit */
    TS_MOVE_INVALID_INPUT = 2,           /**< refused: nothing moved */
    TS_MOVE_CONTACT_BUFFER_TOO_SMALL = 3 /**< never returned since 0.2 (see contacts_stored) */
} ts_move_status;

/** A vector (x to the right, y downward). */
typedef struct ts_vec2_f {
    float x, y;
} ts_vec2_f;
typedef struct ts_vec2_d {
    double x, y;
} ts_vec2_d;
/** The names of 0.1, deprecated: every float type ends in _f and every double one in _d. */
typedef ts_vec2_f ts_vec2f TILESWEEP_DEPRECATED("renamed ts_vec2_f");
typedef ts_vec2_d ts_vec2d TILESWEEP_DEPRECATED("renamed ts_vec2_d");

/** A box: the closed rectangle [pos, pos + size], size > 0. */
typedef struct ts_box_f {
    ts_vec2_f pos, size;
} ts_box_f;
typedef struct ts_box_d {
    ts_vec2_d pos, size;
} ts_box_d;

/** Where a map's memory comes from (ts_map_desc_*.allocator). allocate returns size bytes aligned
 *  for any type, or NULL when it cannot; release gets back what allocate gave, with the same size.
 *  Both may be called from any thread that creates or destroys a map. */
typedef struct ts_allocator {
    void* (*allocate)(size_t size, void* user);
    void (*release)(void* memory, size_t size, void* user);
    void* user; /**< passed to both */
} ts_allocator;

/** A map to prepare: columns * rows cells, row-major from the top row, nonzero is solid. */
typedef struct ts_map_desc_f {
    ts_vec2_f origin;    /**< top-left corner of cell (0, 0) */
    ts_vec2_f tile_size; /**< > 0 */
    int32_t columns;
    int32_t rows;
    const uint8_t* solid;
    /** NULL: malloc and free. Otherwise the map (one block: its headers and a copy of the cells)
     *  and the scratch list of a wide box's contacts come from it; it is copied into the map. */
    const ts_allocator* allocator;
} ts_map_desc_f;
typedef struct ts_map_desc_d {
    ts_vec2_d origin;
    ts_vec2_d tile_size;
    int32_t columns;
    int32_t rows;
    const uint8_t* solid;
    const ts_allocator* allocator;
} ts_map_desc_d;

/** A prepared map (validated, cells copied); opaque. */
typedef struct ts_map_f ts_map_f;
typedef struct ts_map_d ts_map_d;
/** Worker threads for the batch calls; opaque. */
typedef struct ts_pool ts_pool;

/** One mover's frame: its box at the start and its motion over the frame (velocity * dt). */
typedef struct ts_mover_f {
    ts_box_f box;
    ts_vec2_f displacement;
} ts_mover_f;
typedef struct ts_mover_d {
    ts_box_d box;
    ts_vec2_d displacement;
} ts_mover_d;

/** What happened to one mover. The flags come from the solver's steps: right with or without a
 *  contact buffer, for a box of any size. y grows downward: on_ground is a floor below the box
 *  (in a y-up world, read on_ground and on_ceiling the other way round). */
typedef struct ts_result_f {
    ts_vec2_f position;             /**< the end position; the start unless moved or blocked */
    uint8_t status;                 /**< a ts_move_status */
    uint8_t blocked_x;              /**< a tile stopped the motion on x (= on_wall) */
    uint8_t blocked_y;              /**< a tile stopped the motion on y */
    uint8_t on_ground;              /**< a contact with normal (0, -1) */
    uint8_t on_ceiling;             /**< a contact with normal (0, 1) */
    uint8_t on_wall;                /**< a contact with normal (+-1, 0) */
    int8_t wall_normal_x;           /**< 1: wall on the left, -1: on the right, 0: none */
    uint8_t contacts_stored;        /**< the buffer given holds all contact_count contacts */
    int32_t contact_count;          /**< tiles hit, stored or not */
    int32_t start_overlap_count;    /**< solid tiles overlapped at the start (never blocking) */
    ts_vec2_f clipped_displacement; /**< the displacement with the blocked components zeroed */
} ts_result_f;
typedef struct ts_result_d {
    ts_vec2_d position;
    uint8_t status;
    uint8_t blocked_x;
    uint8_t blocked_y;
    uint8_t on_ground;
    uint8_t on_ceiling;
    uint8_t on_wall;
    int8_t wall_normal_x;
    uint8_t contacts_stored;
    int32_t contact_count;
    int32_t start_overlap_count;
    ts_vec2_d clipped_displacement;
} ts_result_d;

/** One tile hit: cell (i, j), the normal leaving its face, the fraction of the frame elapsed
 *  (the exact one rounded to nearest), and where the box was then (0.3). */
typedef struct ts_contact_f {
    int32_t i, j;
    int8_t nx, ny;
    float time;
    /** The box's position (pos, its min corner) at the hit. On the normal's axis: the result's
     *  position there (the box stops at the hit). On the other axis, when the box slides on along
     *  it after a first-step hit: start + time * displacement, exact, rounded to nearest; otherwise
     *  the result's position there too. */
    ts_vec2_f position;
} ts_contact_f;
typedef struct ts_contact_d {
    int32_t i, j;
    int8_t nx, ny;
    double time;
    ts_vec2_d position;
} ts_contact_d;

/** The version of the library loaded: major * 10000 + minor * 100 + patch (TILESWEEP_VERSION). */
TILESWEEP_EXPORT uint32_t ts_get_version(void);

/** A short English message naming the problem (a ts_error, or any other int); never NULL. */
TILESWEEP_EXPORT const char* ts_error_message(int error);

/** Validates and copies a map into memory from desc->allocator; *out receives it (destroy
 *  with ts_map_destroy_*). */
TILESWEEP_EXPORT ts_error ts_map_create_f(const ts_map_desc_f* desc, ts_map_f** out);
TILESWEEP_EXPORT ts_error ts_map_create_d(const ts_map_desc_d* desc, ts_map_d** out);
/** Frees a map; NULL is allowed, and so is a ts_map_without_one_way_* handle, which is ignored. */
TILESWEEP_EXPORT void ts_map_destroy_f(ts_map_f* map);
TILESWEEP_EXPORT void ts_map_destroy_d(ts_map_d* map);
/** Sets cell (i, j) solid (nonzero) or empty, between frames: ts_map_set_cell_* with
 *  TS_CELL_SOLID or TS_CELL_EMPTY. */
TILESWEEP_EXPORT ts_error ts_map_set_solid_f(ts_map_f* map, int32_t i, int32_t j, int solid);
TILESWEEP_EXPORT ts_error ts_map_set_solid_d(ts_map_d* map, int32_t i, int32_t j, int solid);

/** ts_map_create_* with one-way cells (0.4). one_way holds columns * rows bytes laid out as
 *  desc->solid, nonzero one-way where desc->solid is zero (a solid byte wins); NULL gives a map
 *  with none yet. Both are copied. The map keeps a one-way layer either way, so that
 *  ts_map_set_cell_* can add platforms later; its frames that move down read that layer, which a
 *  map from ts_map_create_* does not have and does not pay for. */
TILESWEEP_EXPORT ts_error ts_map_create_one_way_f(const ts_map_desc_f* desc, const uint8_t* one_way,
                                                  ts_map_f** out);
TILESWEEP_EXPORT ts_error ts_map_create_one_way_d(const ts_map_desc_d* desc, const uint8_t* one_way,
                                                  ts_map_d** out);
/** Sets cell (i, j) to kind, a ts_cell_kind, between frames (0.4). TS_ERROR_CELL_KIND for any
 *  other value, and for TS_CELL_ONE_WAY in a map made by ts_map_create_* (no one-way layer). */
TILESWEEP_EXPORT ts_error ts_map_set_cell_f(ts_map_f* map, int32_t i, int32_t j, int kind);
TILESWEEP_EXPORT ts_error ts_map_set_cell_d(ts_map_d* map, int32_t i, int32_t j, int kind);
/** The ts_cell_kind of cell (i, j) into *kind, as moves through this map see it: through
 *  ts_map_without_one_way_* a one-way cell is TS_CELL_EMPTY (0.4). */
TILESWEEP_EXPORT ts_error ts_map_get_cell_f(const ts_map_f* map, int32_t i, int32_t j, uint8_t* kind);
TILESWEEP_EXPORT ts_error ts_map_get_cell_d(const ts_map_d* map, int32_t i, int32_t j, uint8_t* kind);
/** The same map with its one-way cells left out (0.4): every move through it treats each
 *  TS_CELL_ONE_WAY cell as empty, which is how a player drops through a platform. Pass it in
 *  place of map to any move or batch call for the frames that drop through; the choice is per
 *  call and costs nothing. It is part of map: it shares map's cells (ts_map_set_* on map shows
 *  in it), is valid until map is destroyed, and is never destroyed itself (ts_map_destroy_*
 *  ignores it). NULL for NULL. */
TILESWEEP_EXPORT const ts_map_f* ts_map_without_one_way_f(const ts_map_f* map);
TILESWEEP_EXPORT const ts_map_d* ts_map_without_one_way_d(const ts_map_d* map);

/** The most contacts one frame of a box this size can record: a buffer this large never falls
 *  short. 0 for sizes that are not finite and > 0. */
TILESWEEP_EXPORT int32_t ts_max_contacts_f(ts_vec2_f box_size, ts_vec2_f tile_size);
TILESWEEP_EXPORT int32_t ts_max_contacts_d(ts_vec2_d box_size, ts_vec2_d tile_size);

/** Resolves one frame of one mover into *result. contacts (optional, may be NULL) receives all
 *  of the frame's contacts when capacity >= ts_max_contacts_*, or >= contact_count for a frame of
 *  at most 64 contacts; otherwise none (result->contacts_stored says which). The flags never
 *  need the buffer. TS_ERROR_INVALID_INPUT also fills *result (start position, its status). A
 *  box whose ts_max_contacts_* is above 64 (over 30 tiles on a side) given a buffer that large
 *  resolves through a scratch list from the map's allocator (TS_ERROR_OUT_OF_MEMORY if that
 *  fails). */
TILESWEEP_EXPORT ts_error ts_move_and_slide_f(const ts_map_f* map, const ts_mover_f* mover,
                                              ts_result_f* result, ts_contact_f* contacts, int32_t capacity);
TILESWEEP_EXPORT ts_error ts_move_and_slide_d(const ts_map_d* map, const ts_mover_d* mover,
                                              ts_result_d* result, ts_contact_d* contacts, int32_t capacity);

/** velocity with the components that push into a face the move hit set to zero (x into the
 *  wall, y down onto a floor or up into a ceiling); call it after every move. */
TILESWEEP_EXPORT ts_vec2_f ts_clip_velocity_f(ts_vec2_f velocity, const ts_result_f* result);
TILESWEEP_EXPORT ts_vec2_d ts_clip_velocity_d(ts_vec2_d velocity, const ts_result_d* result);

/** Starts a pool of `threads` threads for the batch calls (the caller counts as one). */
TILESWEEP_EXPORT ts_error ts_pool_create(int32_t threads, ts_pool** out);
/** Stops a pool; NULL is allowed. */
TILESWEEP_EXPORT void ts_pool_destroy(ts_pool* pool);

/** Resolves movers[k] into results[k], k < count, each as ts_move_and_slide_* with no contact
 *  buffer; pool may be NULL (this thread only). TS_ERROR_INVALID_INPUT when some mover was
 *  refused: its status says so, the others are resolved. */
TILESWEEP_EXPORT ts_error ts_move_and_slide_batch_f(const ts_map_f* map, const ts_mover_f* movers,
                                                    ts_result_f* results, size_t count, ts_pool* pool);
TILESWEEP_EXPORT ts_error ts_move_and_slide_batch_d(const ts_map_d* map, const ts_mover_d* movers,
                                                    ts_result_d* results, size_t count, ts_pool* pool);

/** A range of a batch's work: items [begin, end), on any thread. */
typedef void ts_task_fn(size_t begin, size_t end, void* task_context);

/** A game's job system for the batch calls (Box2D's enqueueTask/finishTask). enqueue runs
 *  task over disjoint ranges covering [0, item_count), each at least min_range items long but
 *  the last, on any threads (the calling one included), and returns a handle for finish, or
 *  NULL when every range has already run; finish waits until every range of that handle has
 *  run. A batch calls each once. */
typedef struct ts_task_system {
    void* (*enqueue)(ts_task_fn* task, size_t item_count, size_t min_range, void* task_context,
                     void* user_context);
    void (*finish)(void* user_task, void* user_context);
    void* user_context; /**< passed to both */
} ts_task_system;

/** ts_move_and_slide_batch_* on a game's job system: the same results, bit for bit. */
TILESWEEP_EXPORT ts_error ts_move_and_slide_batch_tasks_f(const ts_map_f* map, const ts_mover_f* movers,
                                                          ts_result_f* results, size_t count,
                                                          const ts_task_system* tasks);
TILESWEEP_EXPORT ts_error ts_move_and_slide_batch_tasks_d(const ts_map_d* map, const ts_mover_d* movers,
                                                          ts_result_d* results, size_t count,
                                                          const ts_task_system* tasks);

#ifdef __cplusplus
}
#endif

#endif /* TILESWEEP_TILESWEEP_H */
