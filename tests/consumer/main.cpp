// A box falls onto a floor through the installed library, alone and in a batch on two threads;
// exit status 0 when it lands on it both ways.
#include <cstdio>
#include <tilesweep/batch.h>
#include <tilesweep/tilesweep.hpp>

int main() {
    const std::uint8_t cells[] = {0, 0, 0, 0, 1, 1};  // 2 columns, 3 rows; the bottom row solid
    const tilesweep::TileMapView<float> map{{0, 0}, {16, 16}, 2, 3, cells};
    if (tilesweep::validateTileMap(map) != tilesweep::MapError::None) return 1;
    tilesweep::Contact<float> contacts[4];
    tilesweep::Cell overlaps[4];
    const auto result =
        tilesweep::resolveMove<float>({map, {{4, 0}, {8, 8}}, {0, 100}}, {contacts, 4, overlaps, 4});
    std::printf("consumer: landed at y = %g with %d contact(s)\n", static_cast<double>(result.position.y),
                result.contactCount);
    // tilesweep::batch, installed with its Threads dependency.
    const auto prepared = tilesweep::prepareMap(map);
    tilesweep::BatchPool pool(2);
    const tilesweep::MoveInput<float> movers[2] = {{{{4, 0}, {8, 8}}, {0, 100}}, {{{4, 0}, {8, 8}}, {0, 4}}};
    tilesweep::MoveResult<float> moved[2];
    tilesweep::moveAndSlideBatch(prepared, movers, moved, 2, &pool);
    std::printf("consumer: the batch landed at y = %g and fell to y = %g\n",
                static_cast<double>(moved[0].position.y), static_cast<double>(moved[1].position.y));
    return result.position.y == 24.0f && result.contactCount == 1 && moved[0].position.y == 24.0f &&
                   moved[0].onGround && moved[1].position.y == 4.0f
               ? 0
               : 1;
}
