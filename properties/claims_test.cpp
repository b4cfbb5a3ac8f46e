// SPDX-License-Identifier: MIT
// The claims against an outside resolver that is tilesweep's own with each frame's start
// overlaps rearranged (scene_runner.h): in another order they still hold, since the contract
// leaves the order of started_overlapping free; with a cell left out, listed twice or replaced
// they fail.
#include "claims.h"

#include "scene_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace tilesweep::properties {
namespace {

using Rearrange = std::function<void(std::vector<Cell>&)>;

/// tilesweep's own resolver, with `rearrange` applied to every frame's start overlaps that
/// lists at least two cells.
class RearrangingRunner final : public SceneRunner<float> {
public:
    explicit RearrangingRunner(Rearrange rearrange) : rearrange_(std::move(rearrange)) {}
    std::vector<std::vector<FrameResult<float>>> runAll(
        const std::vector<const Scene<float>*>& scenes) override {
        std::vector<std::vector<FrameResult<float>>> all;
        for (const Scene<float>* scene : scenes) {
            std::vector<FrameResult<float>> frames = runScene(*scene);
            for (FrameResult<float>& f : frames)
                if (f.startOverlaps.size() >= 2) {
                    rearrange_(f.startOverlaps);
                    ++rearranged;
                }
            all.push_back(std::move(frames));
        }
        return all;
    }
    std::string answerText(const Scene<float>&) override { return {}; }
    std::string name() const override { return "rearranging"; }

    int rearranged = 0;  ///< frames whose list was rearranged

private:
    Rearrange rearrange_;
};

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
    RearrangingRunner runner(rearrange);
    ScopedSceneRunner<float> use(runner);
    std::string why = obeysTheSafetyRules(startsInsideSixTiles());
    if (rearranged) *rearranged = runner.rearranged;
    return why;
}

std::string zeroMove(const Rearrange& rearrange, int* rearranged = nullptr) {
    RearrangingRunner runner(rearrange);
    ScopedSceneRunner<float> use(runner);
    std::string why = zeroMoveChangesNothing(startsInsideSixTiles());
    if (rearranged) *rearranged = runner.rearranged;
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

}  // namespace
}  // namespace tilesweep::properties
