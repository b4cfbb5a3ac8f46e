/* SPDX-License-Identifier: MIT */
#ifndef TILESWEEP_RESOLVER_LIB_H
#define TILESWEEP_RESOLVER_LIB_H

/*
 * Your resolver, checked by tilesweep's claims at native speed: a shared library that exports
 * ts_user_resolve_f (and ts_user_resolve_d, to be checked in double), with the C API's types.
 *
 *     tilesweep check --resolver-lib ./libmine.so                # float
 *     tilesweep check --resolver-lib ./libmine.so --scalar double
 *
 * The tool loads the library in a child process of its own (`tilesweep resolve --resolver
 * lib:PATH`, which speaks the --resolver-cmd protocol), so a crash inside it fails the scene it
 * was given and a fresh process takes the next: it never takes the tool down. Failures are
 * shrunk, written to the regression corpus, replayed and audited as for --resolver-cmd.
 *
 * One call resolves one scene: the map, the box, and its moves, one a frame, each starting where
 * the last ended. For frame k it writes frames[k]: the end position, the contacts in the order
 * the box met them, and the solid cells the box overlapped at the frame's start (never a
 * one-way cell). The tool gives
 * each frame room for contact_capacity contacts and start_overlap_capacity cells; when a frame
 * needs more, set its count to what it needs and return TS_USER_NEEDS_ROOM: the tool calls
 * again with that much room. Return TS_USER_OK when every frame is written, and any other value
 * to refuse the scene (an error line, which the claims count as a failure).
 *
 *     int ts_user_resolve_f(const ts_scene_f* scene, ts_frame_out_f* frames) {
 *         for (int32_t k = 0; k < scene->move_count; ++k) {
 *             ... frames[k].position = ...; frames[k].contact_count = 0; ...
 *         }
 *         return TS_USER_OK;
 *     }
 *
 * Cells are (i, j): column i from the left, row j from the top; y grows downward, and a
 * contact's normal leaves the face the box met (a floor below the box is (0, -1)).
 */

#include "tilesweep/tilesweep.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What ts_user_resolve_* returns. */
enum {
    TS_USER_OK = 0,        /**< every frame written */
    TS_USER_NEEDS_ROOM = 1 /**< some frame's contact_count or start_overlap_count exceeds its room */
};

/** A cell of the map: column i, row j. */
typedef struct ts_cell {
    int32_t i, j;
} ts_cell;

/** One scene: map.solid holds map.columns * map.rows cells, row by row from the top, nonzero
 *  solid (map.allocator is NULL); moves holds move_count displacements. one_way (0.4) is NULL
 *  when the scene has no one-way cell ('-' in a scene file), and otherwise holds a byte per cell
 *  laid out as map.solid, nonzero one-way where map.solid is zero (docs/contract.md,
 *  "One-way tiles"); ts_map_create_one_way_* takes the two as they are. It is the last field,
 *  so a library built against an older header reads the scene it knows. */
typedef struct ts_scene_f {
    ts_map_desc_f map;
    ts_box_f box;
    const ts_vec2_f* moves;
    int32_t move_count;
    const uint8_t* one_way;
} ts_scene_f;
typedef struct ts_scene_d {
    ts_map_desc_d map;
    ts_box_d box;
    const ts_vec2_d* moves;
    int32_t move_count;
    const uint8_t* one_way;
} ts_scene_d;

/** One frame's answer. The tool sets the buffers and their capacities; the resolver sets the
 *  rest. A contact's position is not read (the protocol has no field for it). */
typedef struct ts_frame_out_f {
    ts_vec2_f position;
    ts_contact_f* contacts;
    int32_t contact_capacity;
    int32_t contact_count;
    ts_cell* start_overlaps;
    int32_t start_overlap_capacity;
    int32_t start_overlap_count;
} ts_frame_out_f;
typedef struct ts_frame_out_d {
    ts_vec2_d position;
    ts_contact_d* contacts;
    int32_t contact_capacity;
    int32_t contact_count;
    ts_cell* start_overlaps;
    int32_t start_overlap_capacity;
    int32_t start_overlap_count;
} ts_frame_out_d;

/** The functions a --resolver-lib library exports (by these names; ts_user_resolve_d may be
 *  left out when only float is checked). frames has scene->move_count entries. */
typedef int (*ts_user_resolve_f_fn)(const ts_scene_f* scene, ts_frame_out_f* frames);
typedef int (*ts_user_resolve_d_fn)(const ts_scene_d* scene, ts_frame_out_d* frames);
#define TS_USER_RESOLVE_F_NAME "ts_user_resolve_f"
#define TS_USER_RESOLVE_D_NAME "ts_user_resolve_d"

#ifdef __cplusplus
}
#endif

#endif /* TILESWEEP_RESOLVER_LIB_H */
