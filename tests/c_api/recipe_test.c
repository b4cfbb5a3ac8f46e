/* SPDX-License-Identifier: MIT */
/* The usage recipe of tilesweep.h, compiled as C99 and run as written: the lines between
 * "// [recipe:tilesweep.h]" and "// [recipe:end]" are the header's recipe (run with this file's
 * path and the header's, the program first checks that the two are the same lines), and the
 * code around them supplies the names the recipe takes for granted and checks what it did:
 * a box falling onto the floor lands on it, flags on_ground, and its velocity is clipped. */
#include "tilesweep/tilesweep.h"

#include <stdio.h>
#include <string.h>

enum { kMaxLines = 64, kLineLength = 256 };

/* Whether `line` is `marker` alone, after its indentation. */
static int isMarker(const char* line, const char* marker) {
    const size_t length = strlen(marker);
    while (*line == ' ') ++line;
    return strncmp(line, marker, length) == 0 && (line[length] == '\n' || line[length] == '\0');
}

/* The lines of `path` between the line that is the marker `start` and the one that is `end`,
 * with the first `indent` characters of each line dropped. */
static int readRegion(const char* path, const char* start, const char* end, size_t indent,
                      char lines[kMaxLines][kLineLength]) {
    FILE* file = fopen(path, "r");
    char line[kLineLength];
    int count = 0;
    int inside = 0;
    if (file == NULL) return -1;
    while (fgets(line, sizeof line, file) != NULL) {
        if (!inside) {
            inside = isMarker(line, start);
            continue;
        }
        if (isMarker(line, end) || count == kMaxLines) break;
        strncpy(lines[count], strlen(line) > indent ? line + indent : "\n", kLineLength - 1);
        lines[count][kLineLength - 1] = '\0';
        ++count;
    }
    fclose(file);
    return count;
}

static int fail(const char* message) {
    fprintf(stderr, "recipe_test: %s\n", message);
    return 1;
}

/* The header's recipe: its lines after "Usage, C" that start with " *     ", up to the first
 * line that does not, against this file's region (indented by four spaces). */
static int recipeIsQuotedVerbatim(const char* header, const char* source) {
    static char quoted[kMaxLines][kLineLength];
    static char region[kMaxLines][kLineLength];
    FILE* file = fopen(header, "r");
    char line[kLineLength];
    int count = 0;
    int afterUsage = 0;
    int regionCount = 0;
    int k = 0;
    if (file == NULL) return fail("cannot open the header");
    while (fgets(line, sizeof line, file) != NULL) {
        if (!afterUsage) {
            afterUsage = strstr(line, " * Usage, C") != NULL;
            continue;
        }
        if (strncmp(line, " *     ", 7) == 0 && count < kMaxLines) {
            strncpy(quoted[count], line + 7, kLineLength - 1);
            quoted[count][kLineLength - 1] = '\0';
            ++count;
        } else if (count > 0) {
            break;
        }
    }
    fclose(file);
    regionCount = readRegion(source, "// [recipe:tilesweep.h]", "// [recipe:end]", 4, region);
    if (count == 0) return fail("tilesweep.h has no usage recipe");
    if (regionCount != count) {
        fprintf(stderr, "recipe_test: the header's recipe has %d lines, this file's region %d\n", count,
                regionCount);
        return 1;
    }
    for (k = 0; k < count; ++k) {
        if (strcmp(quoted[k], region[k]) != 0) {
            fprintf(stderr, "recipe_test: line %d differs:\n  header: %s  test:   %s", k + 1, quoted[k],
                    region[k]);
            return 1;
        }
    }
    return 0;
}

/* 4 columns x 3 rows of 16-unit tiles, the bottom row solid; a 10 x 10 box at (4, 20) falling
 * at 256 units a second for a frame of 1/16 s: 16 units, onto the floor at y = 32 (bottom 30
 * + 2). It lands at y = 22, on the ground, and the clipped velocity is (0, 0). */
static int runRecipe(void) {
    const uint8_t cells[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1};
    const int32_t columns = 4;
    const int32_t rows = 3;
    const float dt = 1.0f / 16;
    const float vx = 0;
    const float vy = 256;
    const float w = 10;
    const float h = 10;
    float x = 4;
    float y = 20;
    // The region stays the header's lines to the letter: clang-format leaves it alone.
    // clang-format off
    // [recipe:tilesweep.h]
    ts_map_f* map = NULL;  // cells: columns * rows bytes, row by row, 1 = solid
    ts_map_desc_f desc = {{0, 0}, {16, 16}, columns, rows, cells, NULL};  // NULL: malloc
    ts_error error = ts_map_create_f(&desc, &map);  // copies the cells
    if (error != TS_OK) return fail(ts_error_message((int)error));
    ts_vec2_f velocity = {vx, vy};
    ts_mover_f mover = {{{x, y}, {w, h}}, {velocity.x * dt, velocity.y * dt}};
    ts_result_f r;
    ts_move_and_slide_f(map, &mover, &r, NULL, 0);  // no contact buffer needed for the flags
    x = r.position.x;
    y = r.position.y;
    velocity = ts_clip_velocity_f(velocity, &r);  // stops on floors, ceilings and walls
    ts_map_destroy_f(map);
    // [recipe:end]
    // clang-format on
    if (x != 4.0f || y != 22.0f) return fail("the box did not land at (4, 22)");
    if (!r.on_ground || r.on_wall || r.on_ceiling) return fail("the flags are not on_ground alone");
    if (velocity.x != 0.0f || velocity.y != 0.0f) return fail("the clipped velocity is not (0, 0)");
    return 0;
}

int main(int argc, char** argv) {
    if (argc != 3) return fail("usage: recipe_test HEADER THIS_SOURCE");
    if (recipeIsQuotedVerbatim(argv[1], argv[2]) != 0) return 1;
    return runRecipe();
}
