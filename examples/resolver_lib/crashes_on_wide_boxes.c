/* SPDX-License-Identifier: MIT */
/* A resolver library that dies (SIGSEGV) on every box wider than a tile, and answers the others
 * by moving through everything, one-way cells (s->one_way) as well as solid ones: ctest checks
 * that its crash fails scenes, not the tool. */
#include "tilesweep/resolver_lib.h"

#include <signal.h>

int ts_user_resolve_f(const ts_scene_f* s, ts_frame_out_f* frames) {
    if (s->box.size.x > s->map.tile_size.x) raise(SIGSEGV);
    ts_vec2_f p = s->box.pos;
    for (int32_t k = 0; k < s->move_count; ++k) {
        p.x += s->moves[k].x;
        p.y += s->moves[k].y;
        frames[k].position = p;
        frames[k].contact_count = 0;
        frames[k].start_overlap_count = 0;
    }
    return TS_USER_OK;
}
