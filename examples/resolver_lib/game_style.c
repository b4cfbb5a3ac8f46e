/* SPDX-License-Identifier: MIT */
/* A game-style resolver for `tilesweep check --resolver-lib`: x, then y, each moved whole and
 * pushed back out of the tile its leading corners land in. Deliberately inexact, as many games
 * are: it tests only the box's corners, divides in float, and tunnels through thin walls at
 * speed. One-way cells (s->one_way) stop it only when it moves down and its bottom started at
 * or above their top, tested at the same corners. The README shows it; ctest checks that
 * tilesweep finds what it gets wrong. */
#include "tilesweep/resolver_lib.h"

#include <math.h>

/* Whether the cell of point (x, y) stops the box: a solid one always; a one-way one only when
 * `landing` (a move down whose bottom started at `bottom`) and bottom is at or above its top. */
static int blockedAt(const ts_scene_f* s, float x, float y, int landing, float bottom, ts_contact_f* hit) {
    const ts_map_desc_f* m = &s->map;
    size_t k;
    hit->i = (int32_t)floorf((x - m->origin.x) / m->tile_size.x);
    hit->j = (int32_t)floorf((y - m->origin.y) / m->tile_size.y);
    if (hit->i < 0 || hit->j < 0 || hit->i >= m->columns || hit->j >= m->rows) return 0;
    k = (size_t)hit->j * (size_t)m->columns + (size_t)hit->i;
    if (m->solid[k]) return 1;
    return landing && s->one_way != NULL && s->one_way[k] &&
           bottom <= m->origin.y + (float)hit->j * m->tile_size.y;
}

int ts_user_resolve_f(const ts_scene_f* s, ts_frame_out_f* frames) {
    const ts_map_desc_f* m = &s->map;
    ts_vec2_f p = s->box.pos;
    const float w = s->box.size.x, h = s->box.size.y;
    for (int32_t k = 0; k < s->move_count; ++k) {
        ts_frame_out_f* f = &frames[k];
        f->contact_count = 0;
        f->start_overlap_count = 0;
        for (int axis = 0; axis < 2; ++axis) {
            const float d = axis ? s->moves[k].y : s->moves[k].x;
            const float bottom = p.y + h; /* before this axis's move */
            if (d == 0) continue;
            if (axis)
                p.y += d;
            else
                p.x += d;
            ts_contact_f c = {0, 0, 0, 0, 1.0f, {0, 0}};
            /* the two corners on the leading side */
            const float x0 = axis ? p.x : (d > 0 ? p.x + w : p.x), y0 = axis ? (d > 0 ? p.y + h : p.y) : p.y;
            const float x1 = axis ? p.x + w : x0, y1 = axis ? y0 : p.y + h;
            const int landing = axis && d > 0;
            if (!blockedAt(s, x0, y0, landing, bottom, &c) && !blockedAt(s, x1, y1, landing, bottom, &c))
                continue;
            if (axis) {
                p.y = d > 0 ? m->origin.y + (float)c.j * m->tile_size.y - h
                            : m->origin.y + (float)(c.j + 1) * m->tile_size.y;
                c.ny = d > 0 ? -1 : 1;
            } else {
                p.x = d > 0 ? m->origin.x + (float)c.i * m->tile_size.x - w
                            : m->origin.x + (float)(c.i + 1) * m->tile_size.x;
                c.nx = d > 0 ? -1 : 1;
            }
            if (f->contact_count < f->contact_capacity) f->contacts[f->contact_count] = c;
            f->contact_count++;
        }
        if (f->contact_count > f->contact_capacity) return TS_USER_NEEDS_ROOM;
        f->position = p;
    }
    return TS_USER_OK;
}
