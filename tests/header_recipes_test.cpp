// SPDX-License-Identifier: MIT
// The usage recipes of the public headers compile and run as written: each region below between
// "// [recipe:<header>]" and "// [recipe:end]" is the recipe of that header, and the test
// `HeaderRecipes.areQuotedVerbatim` fails when the header's recipe and the region differ (as
// example_readme_snippet_is_the_platformer_loop does for the README). The code around each
// region supplies the names the recipe takes for granted and checks what it did.
#include "tilesweep/batch.h"
#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using tilesweep::Box;
using tilesweep::Cell;
using tilesweep::Vec2;

// 4 columns x 3 rows of 16-unit tiles, the bottom row solid.
const std::uint8_t cells[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1};
const std::int32_t columns = 4;
const std::int32_t rows = 3;
const float dt = 1.0f / 16;

// ---- resolve.h ----

void resolveRecipe(Box<float>& player, Vec2<float> velocity, std::vector<Cell>& hits, bool& landed) {
    // [recipe:resolve.h]
    tilesweep::TileMapView<float> map{{0, 0}, {16, 16}, columns, rows, cells};
    if (tilesweep::validateTileMap(map) != tilesweep::MapError::None) return;  // once per map
    tilesweep::Contact<float> contacts[16];
    tilesweep::Cell overlaps[16];
    tilesweep::ResolveOutput<float> out{contacts, 16, overlaps, 16};
    auto result = tilesweep::resolveMove({map, player, velocity * dt}, out);
    if (result.status != tilesweep::ResolveStatus::InvalidInput) player.pos = result.position;
    bool onGround = result.blockedY && velocity.y > 0;       // y grows downward
    for (int k = 0; k < result.contactCount && k < 16; ++k)  // beyond 16: some, unspecified
        hits.push_back(contacts[k].tile);
    // [recipe:end]
    landed = onGround;
}

TEST(HeaderRecipes, resolveRecipeLandsOnTheFloor) {
    // A 10x10 box at (4, 20) falling 16 (256 * dt): its bottom (30) meets the floor (32).
    Box<float> player{{4, 20}, {10, 10}};
    std::vector<Cell> hits;
    bool landed = false;
    resolveRecipe(player, {0, 256}, hits, landed);
    EXPECT_TRUE(landed);
    EXPECT_EQ(player.pos.y, 22.0f);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0], (Cell{0, 2}));
}

// ---- mover.h ----

int failures = 0;
bool fail(const char*) {
    ++failures;
    return false;
}

bool moverRecipe(const tilesweep::TileMapView<float>& view, Box<float>& player, Vec2<float>& velocity,
                 float gravity) {
    // [recipe:mover.h]
    auto map = tilesweep::prepareMap(view);  // once per map: validates it
    if (!map.isValid()) return fail(tilesweep::describe(map.error()));
    // every frame, every mover:
    velocity.y += gravity * dt;
    auto r = tilesweep::moveAndSlide(map, {player, velocity * dt});
    player.pos = r.position;
    velocity = tilesweep::clipVelocity(velocity, r);  // stops on floors, ceilings and walls
    // [recipe:end]
    return true;
}

TEST(HeaderRecipes, moverRecipeLandsAndStops) {
    // Falling at 240 + 16 = 256 units a second from y = 20: lands on the floor at 32 this frame,
    // and clipVelocity stops the fall (the walk on x goes on).
    Box<float> player{{4, 20}, {10, 10}};
    Vec2<float> velocity{16, 240};
    ASSERT_TRUE(moverRecipe({{0, 0}, {16, 16}, columns, rows, cells}, player, velocity, 256));
    EXPECT_EQ(player.pos.y, 22.0f);
    EXPECT_EQ(player.pos.x, 5.0f);
    EXPECT_EQ(velocity, (Vec2<float>{16, 0}));
    // A map that fails validation goes to fail().
    EXPECT_FALSE(moverRecipe({{0, 0}, {0, 16}, columns, rows, cells}, player, velocity, 256));
    EXPECT_EQ(failures, 1);
}

// ---- batch.h ----

TEST(HeaderRecipes, batchRecipeGivesEachMoverItsOwnFrame) {
    const auto map =
        tilesweep::prepareMap(tilesweep::TileMapView<float>{{0, 0}, {16, 16}, columns, rows, cells});
    std::vector<tilesweep::MoveInput<float>> inputs(1000, {{{4, 20}, {10, 10}}, {0, 16}});
    inputs[7].displacement = {0, 1};
    std::vector<tilesweep::MoveResult<float>> results(inputs.size());
    // [recipe:batch.h]
    tilesweep::BatchPool pool(2);  // once: the caller + 1 worker
    tilesweep::moveAndSlideBatch(map, inputs.data(), results.data(), inputs.size(), &pool);
    // [recipe:end]
    EXPECT_EQ(results[0].position.y, 22.0f);
    EXPECT_TRUE(results[999].onGround);
    EXPECT_EQ(results[7].position.y, 21.0f);
    EXPECT_EQ(results[7].status, tilesweep::MoveStatus::Moved);
}

// ---- the check that the headers quote these regions ----

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// The header's recipe: the first run of lines indented as code ("//     ") after the line that
/// says "Usage", without that prefix.
std::vector<std::string> headerRecipe(const std::string& header) {
    const std::string prefix = "//     ";
    std::vector<std::string> recipe;
    bool afterUsage = false;
    for (const std::string& line : linesOf(readFile(header))) {
        if (!afterUsage) {
            afterUsage = line.rfind("//", 0) == 0 && line.find("Usage") != std::string::npos;
            continue;
        }
        if (line.rfind(prefix, 0) == 0) {
            recipe.push_back(line.substr(prefix.size()));
        } else if (!recipe.empty()) {
            break;
        }
    }
    return recipe;
}

/// The region of this file marked for `name`, without the first line's indentation.
std::vector<std::string> region(const std::string& source, const std::string& name) {
    std::vector<std::string> lines;
    bool inside = false;
    std::size_t indent = 0;
    for (const std::string& line : linesOf(source)) {
        const std::size_t text = line.find_first_not_of(' ');
        const std::string trimmed = text == std::string::npos ? "" : line.substr(text);
        if (!inside) {
            inside = trimmed == "// [recipe:" + name + "]";
            indent = text;
            continue;
        }
        if (trimmed == "// [recipe:end]") break;
        lines.push_back(line.size() >= indent ? line.substr(indent) : trimmed);
    }
    return lines;
}

TEST(HeaderRecipes, areQuotedVerbatim) {
    const std::string root = TILESWEEP_SOURCE_DIR;
    const std::string source = readFile(root + "/tests/header_recipes_test.cpp");
    for (const std::string name : {"resolve.h", "mover.h", "batch.h"}) {
        const std::vector<std::string> recipe = headerRecipe(root + "/include/tilesweep/" + name);
        ASSERT_FALSE(recipe.empty()) << name << " has no usage recipe";
        EXPECT_EQ(recipe, region(source, name))
            << "include/tilesweep/" << name << " and tests/header_recipes_test.cpp differ";
    }
}

}  // namespace
