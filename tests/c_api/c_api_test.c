/* SPDX-License-Identifier: MIT */
/* The C API from C99: a map prepared once, single moves with and without contacts, a batch on
 * two threads, and every error code for bad input (none aborts). Expected values are worked
 * out in the comments from docs/contract.md. Exit status 0 when every check holds. */
#include "tilesweep/tilesweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                              \
        }                                                                            \
    } while (0)

/* 8 columns x 4 rows of 16-pixel tiles: a floor on row 3, a wall at column 6 on row 2. */
static const uint8_t level[32] = {
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1,
};

static void testFloat(void) {
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 8, 4, level, NULL};
    ts_map_f* map = NULL;
    ts_mover_f mover = {{{4, 30}, {12, 16}}, {0, 8}};
    ts_result_f r;
    ts_contact_f contacts[8];
    CHECK(ts_map_create_f(&desc, &map) == TS_OK);
    CHECK(map != NULL);
    /* Falls 8 from y = 30 (bottom 46) onto the floor at 48: t = 2/8, stops at y = 32, normal
     * (0, -1), on tile (0, 3) alone: x in [4, 16] touches column 1 without overlapping it. */
    CHECK(ts_move_and_slide_f(map, &mover, &r, contacts, 8) == TS_OK);
    CHECK(r.status == TS_MOVE_BLOCKED);
    CHECK(r.position.x == 4.0f && r.position.y == 32.0f);
    CHECK(r.on_ground && r.blocked_y && !r.on_wall && !r.on_ceiling);
    CHECK(r.contact_count == 1 && r.contacts_stored);
    CHECK(contacts[0].i == 0 && contacts[0].j == 3 && contacts[0].nx == 0 && contacts[0].ny == -1);
    CHECK(contacts[0].time == 0.25f);
    CHECK(contacts[0].position.x == 4.0f && contacts[0].position.y == 32.0f); /* x does not move */
    /* The same fall moving right 8: the floor is reached at t = 2/8 with x = 4 + 2 = 6, over
     * tiles (0, 3) and (1, 3); the box then slides on to x = 12. The contacts are where the box
     * was at the hit: (6, 32). */
    mover.displacement.x = 8;
    CHECK(ts_move_and_slide_f(map, &mover, &r, contacts, 8) == TS_OK);
    CHECK(r.position.x == 12.0f && r.position.y == 32.0f && r.contact_count == 2 && r.contacts_stored);
    CHECK(contacts[0].i == 0 && contacts[1].i == 1 && contacts[1].time == 0.25f);
    CHECK(contacts[0].position.x == 6.0f && contacts[0].position.y == 32.0f);
    CHECK(contacts[1].position.x == 6.0f && contacts[1].position.y == 32.0f);
    /* Walks right 40 along the floor from x = 60 (right edge 72) into the wall at x = 96:
     * stops at x = 84. */
    mover.box.pos.x = 60;
    mover.box.pos.y = 32;
    mover.displacement.x = 40;
    mover.displacement.y = 0;
    CHECK(ts_move_and_slide_f(map, &mover, &r, NULL, 0) == TS_OK);
    CHECK(r.position.x == 84.0f && r.position.y == 32.0f);
    CHECK(r.on_wall && r.wall_normal_x == -1 && r.blocked_x && !r.on_ground);
    CHECK(r.clipped_displacement.x == 0.0f && r.clipped_displacement.y == 0.0f && !r.contacts_stored);
    {
        /* Walking into the wall stops the walk; walking away from it does not. */
        ts_vec2_f into = {120, 0}, away = {-120, 0}, clipped;
        clipped = ts_clip_velocity_f(into, &r);
        CHECK(clipped.x == 0.0f && clipped.y == 0.0f);
        clipped = ts_clip_velocity_f(away, &r);
        CHECK(clipped.x == -120.0f);
    }
    /* The wall removed between frames: the same move goes the whole way. */
    CHECK(ts_map_set_solid_f(map, 6, 2, 0) == TS_OK);
    CHECK(ts_move_and_slide_f(map, &mover, &r, NULL, 0) == TS_OK);
    CHECK(r.status == TS_MOVE_MOVED && r.position.x == 100.0f);
    CHECK(ts_map_set_solid_f(map, 8, 0, 1) == TS_ERROR_CELL_OUT_OF_RANGE);
    CHECK(ts_map_set_solid_f(NULL, 0, 0, 1) == TS_ERROR_NULL_ARGUMENT);
    /* Bad movers are refused, with the start position. */
    mover.displacement.x = NAN;
    CHECK(ts_move_and_slide_f(map, &mover, &r, NULL, 0) == TS_ERROR_INVALID_INPUT);
    CHECK(r.status == TS_MOVE_INVALID_INPUT && r.position.x == 60.0f);
    mover.displacement.x = 1;
    mover.box.size.x = -1;
    CHECK(ts_move_and_slide_f(map, &mover, &r, NULL, 0) == TS_ERROR_INVALID_INPUT);
    CHECK(ts_move_and_slide_f(NULL, &mover, &r, NULL, 0) == TS_ERROR_NULL_ARGUMENT);
    CHECK(ts_move_and_slide_f(map, NULL, &r, NULL, 0) == TS_ERROR_NULL_ARGUMENT);
    CHECK(ts_move_and_slide_f(map, &mover, NULL, NULL, 0) == TS_ERROR_NULL_ARGUMENT);
    ts_map_destroy_f(map);
    ts_map_destroy_f(NULL);
}

static void testDoubleAndBatch(void) {
    ts_map_desc_d desc = {{0, 0}, {16, 16}, 8, 4, level, NULL};
    ts_map_d* map = NULL;
    ts_pool* pool = NULL;
    ts_mover_d movers[1000];
    ts_result_d results[1000];
    ts_result_d single;
    size_t k;
    CHECK(ts_map_create_d(&desc, &map) == TS_OK);
    CHECK(ts_pool_create(2, &pool) == TS_OK);
    for (k = 0; k < 1000; ++k) {
        ts_mover_d m = {{{(double)(k % 100), (double)(k % 37)}, {10, 10}}, {(double)(k % 13) - 6.5, 9.25}};
        movers[k] = m;
    }
    CHECK(ts_move_and_slide_batch_d(map, movers, results, 1000, pool) == TS_OK);
    for (k = 0; k < 1000; ++k) {
        CHECK(ts_move_and_slide_d(map, &movers[k], &single, NULL, 0) == TS_OK);
        CHECK(memcmp(&single, &results[k], sizeof single) == 0);
    }
    /* One bad mover: the batch says so, its status says which, the others are resolved. */
    movers[500].box.size.y = 0;
    CHECK(ts_move_and_slide_batch_d(map, movers, results, 1000, NULL) == TS_ERROR_INVALID_INPUT);
    CHECK(results[500].status == TS_MOVE_INVALID_INPUT);
    CHECK(results[501].status != TS_MOVE_INVALID_INPUT);
    CHECK(ts_move_and_slide_batch_d(NULL, movers, results, 1000, pool) == TS_ERROR_NULL_ARGUMENT);
    CHECK(ts_move_and_slide_batch_d(map, NULL, results, 0, pool) == TS_OK);
    {
        /* testFloat's landing while moving right, in double: the contacts at (6, 32). */
        ts_mover_d landing = {{{4, 30}, {12, 16}}, {8, 8}};
        ts_contact_d contacts[4];
        CHECK(ts_move_and_slide_d(map, &landing, &single, contacts, 4) == TS_OK);
        CHECK(single.contact_count == 2 && single.contacts_stored && single.position.x == 12.0);
        CHECK(contacts[0].position.x == 6.0 && contacts[0].position.y == 32.0 &&
              contacts[1].position.x == 6.0);
    }
    ts_pool_destroy(pool);
    ts_pool_destroy(NULL);
    ts_map_destroy_d(map);
}

static void testWideBox(void) {
    /* A box 100 tiles wide lands on 101 floor tiles: more than the inline contacts. */
    static uint8_t wide[2 * 120];
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 120, 2, wide, NULL};
    ts_map_f* map = NULL;
    ts_mover_f mover = {{{8, 0}, {1600, 8}}, {0, 16}};
    ts_result_f r;
    static ts_contact_f contacts[200];
    int32_t bound;
    int k;
    for (k = 120; k < 240; ++k) wide[k] = 1;
    CHECK(ts_map_create_f(&desc, &map) == TS_OK);
    bound = ts_max_contacts_f(mover.box.size, desc.tile_size);
    CHECK(bound == 104);
    /* No buffer: resolved all the same, flags and all; nothing stored. */
    CHECK(ts_move_and_slide_f(map, &mover, &r, NULL, 0) == TS_OK);
    CHECK(r.status == TS_MOVE_BLOCKED && r.contact_count == 101 && r.position.y == 8.0f && r.on_ground);
    CHECK(!r.contacts_stored && r.clipped_displacement.x == 0.0f && r.clipped_displacement.y == 0.0f);
    /* A buffer of ts_max_contacts_f entries receives them all. */
    CHECK(ts_move_and_slide_f(map, &mover, &r, contacts, bound) == TS_OK);
    CHECK(r.contact_count == 101 && r.position.y == 8.0f && r.on_ground && r.contacts_stored);
    for (k = 0; k < 101; ++k) CHECK(contacts[k].i == k && contacts[k].j == 1 && contacts[k].ny == -1);
    /* Through the scratch list too, each with its position: no x motion, so the final (8, 8). */
    for (k = 0; k < 101; ++k) CHECK(contacts[k].position.x == 8.0f && contacts[k].position.y == 8.0f);
    ts_map_destroy_f(map);
}

static void testBadMaps(void) {
    ts_map_desc_f desc = {{0, 0}, {0, 16}, 8, 4, level, NULL};
    ts_map_f* map = (ts_map_f*)&desc; /* overwritten with NULL on failure */
    CHECK(ts_map_create_f(&desc, &map) == TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE && map == NULL);
    desc.tile_size.x = 16;
    desc.origin.y = INFINITY;
    CHECK(ts_map_create_f(&desc, &map) == TS_ERROR_MAP_NON_FINITE_ORIGIN);
    desc.origin.y = 0;
    desc.columns = -1;
    CHECK(ts_map_create_f(&desc, &map) == TS_ERROR_MAP_NEGATIVE_DIMENSIONS);
    desc.columns = 8;
    desc.solid = NULL;
    CHECK(ts_map_create_f(&desc, &map) == TS_ERROR_MAP_NEGATIVE_DIMENSIONS);
    desc.solid = level;
    desc.tile_size.x = 0.1f; /* 3 * 0.1f is not a float: edge 3 */
    CHECK(ts_map_create_f(&desc, &map) == TS_ERROR_MAP_UNREPRESENTABLE_EDGE_X);
    CHECK(ts_map_create_f(NULL, &map) == TS_ERROR_NULL_ARGUMENT);
    CHECK(ts_map_create_f(&desc, NULL) == TS_ERROR_NULL_ARGUMENT);
    CHECK(ts_max_contacts_f(desc.tile_size, desc.tile_size) > 0);
    {
        ts_vec2_f zero = {0, 1};
        CHECK(ts_max_contacts_f(zero, desc.tile_size) == 0);
    }
}

/* A counting allocator: every block it gives is given back, with the size it was asked for. */
typedef struct Counts {
    int live;
    int allocations;
    size_t bytes;
    int refuse; /* nonzero: allocate returns NULL */
} Counts;

static void* countingAllocate(size_t size, void* user) {
    Counts* counts = (Counts*)user;
    if (counts->refuse) return NULL;
    ++counts->live;
    ++counts->allocations;
    counts->bytes += size;
    return malloc(size);
}

static void countingRelease(void* memory, size_t size, void* user) {
    Counts* counts = (Counts*)user;
    --counts->live;
    counts->bytes -= size;
    free(memory);
}

static void testAllocator(void) {
    /* The map comes from the allocator (one block), and so does a wide box's scratch list. */
    static uint8_t wide[2 * 120];
    Counts counts = {0, 0, 0, 0};
    ts_allocator allocator = {countingAllocate, countingRelease, NULL};
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 120, 2, wide, NULL};
    ts_map_f* map = NULL;
    ts_map_f* other = NULL;
    ts_mover_f mover = {{{8, 0}, {1600, 8}}, {0, 16}};
    ts_result_f r;
    static ts_contact_f contacts[200];
    int k;
    allocator.user = &counts;
    desc.allocator = &allocator;
    for (k = 120; k < 240; ++k) wide[k] = 1;
    CHECK(ts_map_create_f(&desc, &map) == TS_OK);
    CHECK(counts.live == 1 && counts.allocations == 1 && counts.bytes > 240);
    CHECK(ts_move_and_slide_f(map, &mover, &r, contacts, 200) == TS_OK);
    CHECK(r.contact_count == 101 && contacts[100].i == 100 && counts.live == 1 && counts.allocations == 2);
    counts.refuse = 1;
    CHECK(ts_move_and_slide_f(map, &mover, &r, contacts, 200) == TS_ERROR_OUT_OF_MEMORY);
    CHECK(ts_map_create_f(&desc, &other) == TS_ERROR_OUT_OF_MEMORY && other == NULL);
    counts.refuse = 0;
    ts_map_destroy_f(map);
    CHECK(counts.live == 0 && counts.bytes == 0);
}

/* 6 columns x 6 rows of 16-pixel tiles: a solid floor on row 5 and a one-way platform on row 2,
 * columns 1 to 3 (x in [16, 64], its top at y = 32). platformSolid is the same map without the
 * platform, and platformOneWay its one-way layer (the byte under the solid (0, 5) is set too:
 * a solid byte wins). */
static const uint8_t platformSolid[36] = {
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1,
};
static const uint8_t platformOneWay[36] = {
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0,
};

static void testOneWayFloat(void) {
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 6, 6, platformSolid, NULL};
    ts_map_f* map = NULL;
    ts_map_f* solidOnly = NULL;
    const ts_map_f* drop;
    ts_result_f r;
    ts_contact_f contacts[8];
    uint8_t kind = 99;
    CHECK(ts_map_create_one_way_f(&desc, platformOneWay, &map) == TS_OK && map != NULL);
    drop = ts_map_without_one_way_f(map);
    CHECK(drop != NULL && drop != map && ts_map_without_one_way_f(drop) == drop);
    CHECK(ts_map_without_one_way_f(NULL) == NULL);
    /* The cells, as moves through each handle see them. */
    CHECK(ts_map_get_cell_f(map, 2, 2, &kind) == TS_OK && kind == TS_CELL_ONE_WAY);
    CHECK(ts_map_get_cell_f(drop, 2, 2, &kind) == TS_OK && kind == TS_CELL_EMPTY);
    CHECK(ts_map_get_cell_f(map, 0, 5, &kind) == TS_OK && kind == TS_CELL_SOLID); /* solid wins */
    CHECK(ts_map_get_cell_f(drop, 0, 5, &kind) == TS_OK && kind == TS_CELL_SOLID);
    CHECK(ts_map_get_cell_f(map, 0, 2, &kind) == TS_OK && kind == TS_CELL_EMPTY);
    CHECK(ts_map_get_cell_f(map, 6, 0, &kind) == TS_ERROR_CELL_OUT_OF_RANGE);
    CHECK(ts_map_get_cell_f(map, 0, 0, NULL) == TS_ERROR_NULL_ARGUMENT);
    {
        /* Landed on: a 12x14 box at (20, 8), bottom 22, falls 16. Its bottom is above the top at
         * 32 and it moves down, so it lands at t = 10/16 on (1, 2) alone (x in [20, 32] touches
         * column 2 without overlapping it), at y = 18, normal (0, -1). */
        ts_mover_f fall = {{{20, 8}, {12, 14}}, {0, 16}};
        CHECK(ts_move_and_slide_f(map, &fall, &r, contacts, 8) == TS_OK);
        CHECK(r.status == TS_MOVE_BLOCKED && r.position.x == 20.0f && r.position.y == 18.0f);
        CHECK(r.on_ground && r.blocked_y && !r.on_ceiling && !r.on_wall);
        CHECK(r.contact_count == 1 && r.contacts_stored && contacts[0].i == 1 && contacts[0].j == 2);
        CHECK(contacts[0].nx == 0 && contacts[0].ny == -1 && contacts[0].time == 0.625f);
        /* Dropped through: the same fall through the handle without one-way cells goes the whole
         * way, to y = 24, inside the platform's row. */
        CHECK(ts_move_and_slide_f(drop, &fall, &r, contacts, 8) == TS_OK);
        CHECK(r.status == TS_MOVE_MOVED && r.position.y == 24.0f && r.contact_count == 0 && !r.on_ground);
    }
    {
        /* Standing on it (bottom exactly at 32) and pushing down 8: it stays; dropping through,
         * it falls the 8. */
        ts_mover_f stand = {{{20, 18}, {12, 14}}, {0, 8}};
        CHECK(ts_move_and_slide_f(map, &stand, &r, NULL, 0) == TS_OK);
        CHECK(r.status == TS_MOVE_BLOCKED && r.position.y == 18.0f && r.on_ground);
        CHECK(ts_move_and_slide_f(drop, &stand, &r, NULL, 0) == TS_OK);
        CHECK(r.status == TS_MOVE_MOVED && r.position.y == 26.0f);
    }
    {
        /* Jumped through: from below (y = 50, top 50 under the platform's bottom at 48) up 40, to
         * y = 10: nothing blocks a move up. */
        ts_mover_f jump = {{{20, 50}, {12, 14}}, {0, -40}};
        CHECK(ts_move_and_slide_f(map, &jump, &r, NULL, 0) == TS_OK);
        CHECK(r.status == TS_MOVE_MOVED && r.position.y == 10.0f && !r.on_ceiling);
    }
    {
        /* Falling back while inside it (bottom 38 below the top at 32 at the start) goes on down,
         * and the platform it overlaps is not a start overlap: those are solid tiles only. */
        ts_mover_f inside = {{{20, 24}, {12, 14}}, {0, 8}};
        CHECK(ts_move_and_slide_f(map, &inside, &r, NULL, 0) == TS_OK);
        CHECK(r.status == TS_MOVE_MOVED && r.position.y == 32.0f && r.start_overlap_count == 0);
    }
    {
        /* Walked into from the side: a box level with the platform (y in [34, 46]) walking right
         * from x = 0 passes through it, to x = 40. */
        ts_mover_f walk = {{{0, 34}, {12, 12}}, {40, 0}};
        CHECK(ts_move_and_slide_f(map, &walk, &r, NULL, 0) == TS_OK);
        CHECK(r.status == TS_MOVE_MOVED && r.position.x == 40.0f);
    }
    {
        /* A batch through either handle gives what single moves through it give. */
        ts_mover_f movers[2] = {{{{20, 8}, {12, 14}}, {0, 16}}, {{{40, 18}, {12, 14}}, {0, 8}}};
        ts_result_f results[2];
        CHECK(ts_move_and_slide_batch_f(map, movers, results, 2, NULL) == TS_OK);
        CHECK(results[0].position.y == 18.0f && results[1].position.y == 18.0f && results[1].on_ground);
        CHECK(ts_move_and_slide_batch_f(drop, movers, results, 2, NULL) == TS_OK);
        CHECK(results[0].position.y == 24.0f && results[1].position.y == 26.0f && !results[1].on_ground);
    }
    {
        /* Cells set between frames, seen through both handles: a platform at (4, 2) stops a fall
         * at column 4 (x in [68, 80]), but not through the drop-through handle; emptied with
         * ts_map_set_solid_f, it stops nothing. */
        ts_mover_f fall = {{{68, 8}, {12, 14}}, {0, 16}};
        CHECK(ts_move_and_slide_f(map, &fall, &r, NULL, 0) == TS_OK && r.position.y == 24.0f);
        CHECK(ts_map_set_cell_f(map, 4, 2, TS_CELL_ONE_WAY) == TS_OK);
        CHECK(ts_map_get_cell_f(map, 4, 2, &kind) == TS_OK && kind == TS_CELL_ONE_WAY);
        CHECK(ts_move_and_slide_f(map, &fall, &r, NULL, 0) == TS_OK && r.position.y == 18.0f && r.on_ground);
        CHECK(ts_move_and_slide_f(drop, &fall, &r, NULL, 0) == TS_OK && r.position.y == 24.0f);
        CHECK(ts_map_set_solid_f(map, 4, 2, 0) == TS_OK);
        CHECK(ts_map_get_cell_f(map, 4, 2, &kind) == TS_OK && kind == TS_CELL_EMPTY);
        CHECK(ts_move_and_slide_f(map, &fall, &r, NULL, 0) == TS_OK && r.position.y == 24.0f);
        /* Solid set over a one-way cell: solid through both handles. */
        CHECK(ts_map_set_cell_f(map, 4, 2, TS_CELL_SOLID) == TS_OK);
        CHECK(ts_map_get_cell_f(drop, 4, 2, &kind) == TS_OK && kind == TS_CELL_SOLID);
        CHECK(ts_move_and_slide_f(drop, &fall, &r, NULL, 0) == TS_OK && r.position.y == 18.0f);
        CHECK(ts_map_set_cell_f(map, 4, 2, TS_CELL_EMPTY) == TS_OK);
        CHECK(ts_map_set_cell_f(map, 4, 2, 3) == TS_ERROR_CELL_KIND);
        CHECK(ts_map_set_cell_f(map, 4, 2, -1) == TS_ERROR_CELL_KIND);
        CHECK(ts_map_set_cell_f(map, 6, 2, TS_CELL_EMPTY) == TS_ERROR_CELL_OUT_OF_RANGE);
        CHECK(ts_map_set_cell_f(NULL, 0, 0, TS_CELL_EMPTY) == TS_ERROR_NULL_ARGUMENT);
    }
    /* A map made by ts_map_create_f has no one-way layer: the platform cannot be set, its
     * drop-through handle moves as it does, and ts_map_destroy_f ignores that handle. */
    CHECK(ts_map_create_f(&desc, &solidOnly) == TS_OK);
    CHECK(ts_map_set_cell_f(solidOnly, 2, 2, TS_CELL_ONE_WAY) == TS_ERROR_CELL_KIND);
    CHECK(ts_map_get_cell_f(solidOnly, 2, 2, &kind) == TS_OK && kind == TS_CELL_EMPTY);
    {
        ts_mover_f fall = {{{20, 8}, {12, 14}}, {0, 16}};
        CHECK(ts_move_and_slide_f(solidOnly, &fall, &r, NULL, 0) == TS_OK && r.position.y == 24.0f);
        CHECK(ts_move_and_slide_f(ts_map_without_one_way_f(solidOnly), &fall, &r, NULL, 0) == TS_OK &&
              r.position.y == 24.0f);
    }
    ts_map_destroy_f((ts_map_f*)drop); /* ignored: the map still resolves */
    {
        ts_mover_f stand = {{{20, 18}, {12, 14}}, {0, 8}};
        CHECK(ts_move_and_slide_f(map, &stand, &r, NULL, 0) == TS_OK && r.position.y == 18.0f);
    }
    {
        ts_map_f* refused = map;
        CHECK(ts_map_create_one_way_f(NULL, platformOneWay, &refused) == TS_ERROR_NULL_ARGUMENT &&
              refused == NULL);
    }
    ts_map_destroy_f(solidOnly);
    ts_map_destroy_f(map);
}

static void testOneWayDouble(void) {
    /* testOneWayFloat's landing and drop, in double, with the allocator: one block, freed once. */
    ts_map_desc_d desc = {{0, 0}, {16, 16}, 6, 6, platformSolid, NULL};
    Counts counts = {0, 0, 0, 0};
    ts_allocator allocator = {countingAllocate, countingRelease, NULL};
    ts_map_d* map = NULL;
    ts_mover_d fall = {{{20, 8}, {12, 14}}, {0, 16}};
    ts_result_d r;
    uint8_t kind = 99;
    allocator.user = &counts;
    desc.allocator = &allocator;
    CHECK(ts_map_create_one_way_d(&desc, platformOneWay, &map) == TS_OK && counts.live == 1);
    CHECK(ts_map_get_cell_d(map, 1, 2, &kind) == TS_OK && kind == TS_CELL_ONE_WAY);
    CHECK(ts_move_and_slide_d(map, &fall, &r, NULL, 0) == TS_OK);
    CHECK(r.status == TS_MOVE_BLOCKED && r.position.y == 18.0 && r.on_ground);
    CHECK(ts_move_and_slide_d(ts_map_without_one_way_d(map), &fall, &r, NULL, 0) == TS_OK);
    CHECK(r.status == TS_MOVE_MOVED && r.position.y == 24.0);
    CHECK(ts_map_set_cell_d(map, 1, 2, TS_CELL_EMPTY) == TS_OK);
    CHECK(ts_move_and_slide_d(map, &fall, &r, NULL, 0) == TS_OK && r.position.y == 24.0);
    CHECK(ts_map_set_cell_d(map, 1, 2, TS_CELL_ONE_WAY) == TS_OK);
    CHECK(ts_move_and_slide_d(map, &fall, &r, NULL, 0) == TS_OK && r.position.y == 18.0);
    ts_map_destroy_d((ts_map_d*)ts_map_without_one_way_d(map)); /* ignored */
    CHECK(counts.live == 1);
    /* Without a one-way layer (NULL): every platform byte reads empty. */
    {
        ts_map_d* none = NULL;
        CHECK(ts_map_create_one_way_d(&desc, NULL, &none) == TS_OK && counts.live == 2);
        CHECK(ts_map_get_cell_d(none, 1, 2, &kind) == TS_OK && kind == TS_CELL_EMPTY);
        CHECK(ts_move_and_slide_d(none, &fall, &r, NULL, 0) == TS_OK && r.position.y == 24.0);
        ts_map_destroy_d(none);
    }
    ts_map_destroy_d(map);
    CHECK(counts.live == 0 && counts.bytes == 0);
}

static void testSolidOnlyUnchanged(void) {
    /* A solid-only caller: the same moves through ts_map_create_f's map, through
     * ts_map_create_one_way_f's with no one-way layer, and through either's drop-through handle
     * give the same results, bit for bit (level, 300 moves of a 10x10 box). */
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 8, 4, level, NULL};
    ts_map_f* plain = NULL;
    ts_map_f* layered = NULL;
    int k;
    CHECK(ts_map_create_f(&desc, &plain) == TS_OK && ts_map_create_one_way_f(&desc, NULL, &layered) == TS_OK);
    for (k = 0; k < 300; ++k) {
        ts_mover_f m = {{{(float)(k % 100), (float)(k % 37)}, {10, 10}},
                        {(float)(k % 13) - 6.5f, (float)(k % 7) * 4.25f - 12.0f}};
        ts_result_f a, b, c, d;
        ts_contact_f ca[8], cb[8];
        memset(&a, 0, sizeof a);
        memset(&b, 0, sizeof b);
        memset(&c, 0, sizeof c);
        memset(&d, 0, sizeof d);
        CHECK(ts_move_and_slide_f(plain, &m, &a, ca, 8) == TS_OK);
        CHECK(ts_move_and_slide_f(layered, &m, &b, cb, 8) == TS_OK);
        CHECK(ts_move_and_slide_f(ts_map_without_one_way_f(plain), &m, &c, NULL, 0) == TS_OK);
        CHECK(ts_move_and_slide_f(ts_map_without_one_way_f(layered), &m, &d, NULL, 0) == TS_OK);
        CHECK(memcmp(&a, &b, sizeof a) == 0 && a.contacts_stored);
        for (int n = 0; n < a.contact_count && n < 8; ++n)
            CHECK(ca[n].i == cb[n].i && ca[n].j == cb[n].j && ca[n].nx == cb[n].nx && ca[n].ny == cb[n].ny &&
                  ca[n].time == cb[n].time && ca[n].position.x == cb[n].position.x &&
                  ca[n].position.y == cb[n].position.y);
        CHECK(memcmp(&a.position, &c.position, sizeof a.position) == 0 && a.on_ground == c.on_ground);
        CHECK(memcmp(&c, &d, sizeof c) == 0);
    }
    ts_map_destroy_f(plain);
    ts_map_destroy_f(layered);
}

static void testRefusedMovesLeaveContactsAlone(void) {
    /* A refused move stores no contact: the buffer keeps what the caller put in it. */
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 8, 4, level, NULL};
    ts_map_f* map = NULL;
    ts_mover_f mover = {{{4, 30}, {12, 16}}, {NAN, 8}};
    ts_result_f r;
    ts_contact_f contacts[4];
    memset(contacts, 0x5a, sizeof contacts);
    CHECK(ts_map_create_f(&desc, &map) == TS_OK);
    CHECK(ts_move_and_slide_f(map, &mover, &r, contacts, 4) == TS_ERROR_INVALID_INPUT);
    CHECK(contacts[0].i == 0x5a5a5a5a && contacts[0].j == 0x5a5a5a5a);
    ts_map_destroy_f(map);
}

/* A job system that runs the ranges it is given last one first, on this thread, and counts the
 * calls: the batch must not depend on the order its ranges run in. */
typedef struct Jobs {
    int enqueued;
    int finished;
    size_t ranges;
} Jobs;

static void* enqueueBackwards(ts_task_fn* task, size_t count, size_t min_range, void* task_context,
                              void* user) {
    Jobs* jobs = (Jobs*)user;
    size_t begin = (count - 1) / min_range * min_range;
    ++jobs->enqueued;
    for (;;) {
        size_t end = count - begin < min_range ? count : begin + min_range;
        task(begin, end, task_context);
        ++jobs->ranges;
        if (begin == 0) break;
        begin -= min_range;
    }
    return jobs;
}

static void finishJobs(void* user_task, void* user) {
    Jobs* jobs = (Jobs*)user;
    if (user_task == user) ++jobs->finished;
}

static void testTaskSystem(void) {
    ts_map_desc_f desc = {{0, 0}, {16, 16}, 8, 4, level, NULL};
    ts_map_f* map = NULL;
    static ts_mover_f movers[1000];
    static ts_result_f results[1000];
    ts_result_f single;
    Jobs jobs = {0, 0, 0};
    ts_task_system tasks = {enqueueBackwards, finishJobs, NULL};
    size_t k;
    tasks.user_context = &jobs;
    CHECK(ts_map_create_f(&desc, &map) == TS_OK);
    for (k = 0; k < 1000; ++k) {
        ts_mover_f m = {{{(float)(k % 100), (float)(k % 37)}, {10, 10}}, {(float)(k % 13) - 6.5f, 9.25f}};
        movers[k] = m;
    }
    CHECK(ts_move_and_slide_batch_tasks_f(map, movers, results, 1000, &tasks) == TS_OK);
    CHECK(jobs.enqueued == 1 && jobs.finished == 1 && jobs.ranges > 1);
    for (k = 0; k < 1000; ++k) {
        CHECK(ts_move_and_slide_f(map, &movers[k], &single, NULL, 0) == TS_OK);
        CHECK(memcmp(&single, &results[k], sizeof single) == 0);
    }
    CHECK(ts_move_and_slide_batch_tasks_f(map, movers, results, 1000, NULL) == TS_ERROR_NULL_ARGUMENT);
    ts_map_destroy_f(map);
}

static void testVersion(void) {
    CHECK(ts_get_version() == TILESWEEP_VERSION);
    CHECK(TILESWEEP_VERSION ==
          TILESWEEP_VERSION_MAJOR * 10000 + TILESWEEP_VERSION_MINOR * 100 + TILESWEEP_VERSION_PATCH);
}

static void testMessages(void) {
    int code;
    for (code = 0; code <= 14; ++code) {
        const char* m = ts_error_message(code);
        CHECK(m != NULL && strlen(m) > 0 && strcmp(m, "unknown tilesweep error code") != 0);
    }
    CHECK(strcmp(ts_error_message(99), "unknown tilesweep error code") == 0);
    CHECK(strstr(ts_error_message(TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE), "tile_size") != NULL);
    CHECK(strstr(ts_error_message(TS_ERROR_CELL_KIND), "TS_CELL_ONE_WAY") != NULL);
}

int main(void) {
    testFloat();
    testDoubleAndBatch();
    testWideBox();
    testBadMaps();
    testMessages();
    testAllocator();
    testRefusedMovesLeaveContactsAlone();
    testVersion();
    testTaskSystem();
    testOneWayFloat();
    testOneWayDouble();
    testSolidOnlyUnchanged();
    if (failures != 0) {
        fprintf(stderr, "%d checks failed\n", failures);
        return 1;
    }
    printf("c_api_test: all checks hold\n");
    return 0;
}
