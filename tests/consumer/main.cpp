// A box falls onto a floor through the installed library; exit status 0 when it lands on it.
#include <cstdio>
#include <tilesweep/sweep.h>

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
    return result.position.y == 24.0f && result.contactCount == 1 ? 0 : 1;
}
