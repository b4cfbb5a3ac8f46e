// SPDX-License-Identifier: MIT
// The claims against a resolver that is tilesweep's own with each frame's start overlaps
// rearranged: in another order they still hold, since the contract leaves the order of
// started_overlapping free; with a cell left out, listed twice or replaced they fail. And the
// answer cache a round asks through: a scene it holds is never asked for again.
#include "claims.h"

#include "all_claims.h"
#include "answer_cache.h"
#include "property_suite.h"

#include "tilesweep/resolvers/in_process_resolver.h"
#include "tilesweep/scene/scalar_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace tilesweep::properties {
namespace {

using Rearrange = std::function<void(std::vector<Cell>&)>;

/// tilesweep's own resolver, with `rearrange` applied to every frame's start overlaps that
/// lists at least two cells; counts those frames in `rearranged`.
resolvers::InProcessResolver rearranging(const Rearrange& rearrange, int& rearranged) {
    return resolvers::InProcessResolver(
        "rearranging",
        [rearrange, &rearranged](const Scene<float>& scene) {
            std::vector<FrameResult<float>> frames = runScene(scene);
            for (FrameResult<float>& f : frames)
                if (f.startOverlaps.size() >= 2) {
                    rearrange(f.startOverlaps);
                    ++rearranged;
                }
            return frames;
        },
        nullptr);
}

/// A 6 x 4 map of 16 px tiles with a solid block in its top-left 3 x 2 cells, and a 40 x 24 px
/// box at (4, 4) inside all six of them, moving right into empty space for two frames. The zero
/// move claim also places the box a quarter tile into cell (0, 0): at (4, 4) again.
Scene<float> startsInsideSixTiles() {
    Scene<float> s;
    s.map.origin = {0, 0};
    s.map.tileSize = {16, 16};
    s.map.columns = 6;
    s.map.rows = 4;
    s.map.solid = {1, 1, 1, 0, 0, 0,  //
                   1, 1, 1, 0, 0, 0,  //
                   0, 0, 0, 0, 0, 0,  //
                   0, 0, 0, 0, 0, 0};
    s.box = {{4, 4}, {40, 24}};
    s.moves = {{6, 0}, {6, 0}};
    return s;
}

std::string safetyRules(const Rearrange& rearrange, int* rearranged = nullptr) {
    int count = 0;
    resolvers::InProcessResolver resolver = rearranging(rearrange, count);
    std::string why = obeysTheSafetyRules(startsInsideSixTiles(), resolver);
    if (rearranged) *rearranged = count;
    return why;
}

std::string zeroMove(const Rearrange& rearrange, int* rearranged = nullptr) {
    int count = 0;
    resolvers::InProcessResolver resolver = rearranging(rearrange, count);
    std::string why = zeroMoveChangesNothing(startsInsideSixTiles(), resolver);
    if (rearranged) *rearranged = count;
    return why;
}

const Rearrange kReverse = [](std::vector<Cell>& c) { std::reverse(c.begin(), c.end()); };
const Rearrange kByColumn = [](std::vector<Cell>& c) {
    std::sort(c.begin(), c.end(), [](Cell a, Cell b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
};
const Rearrange kDropOne = [](std::vector<Cell>& c) { c.pop_back(); };
const Rearrange kOneTwiceInPlace = [](std::vector<Cell>& c) { c.back() = c.front(); };
const Rearrange kOneTwiceMore = [](std::vector<Cell>& c) { c.push_back(c.front()); };
const Rearrange kReplaceOne = [](std::vector<Cell>& c) { c.back() = {5, 3}; };

TEST(SafetyClaims, holdWithStartOverlapsInAnyOrder) {
    int rearranged = 0;
    EXPECT_EQ(safetyRules(kReverse, &rearranged), "");
    EXPECT_GT(rearranged, 0);  // the scene does list several start overlaps
    EXPECT_EQ(safetyRules(kByColumn), "");
}

TEST(SafetyClaims, failWithAStartOverlapMissingTwiceOrWrong) {
    for (const Rearrange& r : {kDropOne, kOneTwiceInPlace, kOneTwiceMore, kReplaceOne}) {
        const std::string why = safetyRules([&](std::vector<Cell>& c) {
            kReverse(c);
            r(c);
        });
        EXPECT_NE(why.find("startOverlaps"), std::string::npos) << why;
    }
}

TEST(MetamorphicClaims, zeroMoveHoldsWithStartOverlapsInAnyOrder) {
    int rearranged = 0;
    EXPECT_EQ(zeroMove(kReverse, &rearranged), "");
    EXPECT_GT(rearranged, 0);
    EXPECT_EQ(zeroMove(kByColumn), "");
}

TEST(MetamorphicClaims, zeroMoveFailsWithAStartOverlapMissingTwiceOrWrong) {
    for (const Rearrange& r : {kDropOne, kOneTwiceInPlace, kOneTwiceMore, kReplaceOne}) {
        const std::string why = zeroMove([&](std::vector<Cell>& c) {
            kReverse(c);
            r(c);
        });
        EXPECT_NE(why.find("start overlaps differ"), std::string::npos) << why;
    }
}

/// Every claim is held somewhere, and the properties it declares make a suite whose names are
/// unique (a regression file is named after its property) in both scalar types.
template <class T>
void everyClaimDeclaresUniqueProperties() {
    std::set<std::string> names;
    std::set<std::string> claims;
    for (const Claim<T>& claim : allClaims<T>()) {
        EXPECT_TRUE(claims.insert(claim.name).second) << "claim declared twice: " << claim.name;
        EXPECT_FALSE(claim.properties.empty()) << claim.name << " has no property";
        for (const PropertyOf& p : claim.properties) EXPECT_TRUE(names.insert(p.name).second) << p.name;
        EXPECT_EQ(findClaim<T>(claim.name), &claim);
    }
    std::size_t listed = 0;
    for (const Property& p : allProperties()) listed += p.scalar == detail::scalarName<T>() ? 1 : 0;
    EXPECT_EQ(listed, names.size());
}

TEST(ClaimDeclarations, everyClaimDeclaresUniqueProperties) {
    everyClaimDeclaresUniqueProperties<float>();
    everyClaimDeclaresUniqueProperties<double>();
}

TEST(AnswerCache, aSceneHeldIsNotAskedForAgain) {
    int asked = 0;
    resolvers::InProcessResolver counting(
        "counting",
        [&asked](const Scene<float>& scene) {
            ++asked;
            return runScene(scene);
        },
        nullptr);
    AnswerCache cache(counting);
    Scene<float> a = startsInsideSixTiles();
    Scene<float> b = a;
    b.moves = {{0, 3}};
    cache.fill(std::vector<Scene<float>>{a, b, a});
    EXPECT_EQ(asked, 2);  // the duplicate once
    const std::vector<FrameResult<float>> frames = framesFrom(cache, a);
    EXPECT_EQ(asked, 2);
    EXPECT_EQ(frames.size(), a.moves.size());
    Scene<float> c = a;
    c.moves = {{-1, 0}};
    (void)framesFrom(cache, b, c);  // only c is asked for
    EXPECT_EQ(asked, 3);
    cache.clear();
    (void)framesFrom(cache, a);
    EXPECT_EQ(asked, 4);
}

}  // namespace
}  // namespace tilesweep::properties
