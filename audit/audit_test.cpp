// SPDX-License-Identifier: MIT
// The audit on a tiny budget: the production rows read zero, the naive rows show their known
// flaws, and every generated scene is replayable (it survives formatScene/parseScene bit for bit).
#include "tilesweep/audit/audit.h"

#include "scene_judge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace tilesweep::audit {
namespace {

constexpr std::uint64_t kTinyCases = 24;
constexpr std::uint64_t kSeed = 7;

const AuditResult& tinyAudit() {
    static const AuditResult result = [] {
        AuditConfig config;
        config.cases = kTinyCases;
        config.seed = kSeed;
        config.jobs = 2;
        return runAudit(config);
    }();
    return result;
}

std::uint64_t failures(const CellStats& c, Metric m) { return c.failures[static_cast<std::size_t>(m)]; }

TEST(Audit, productionRowsReadZeroOnEveryFamily) {
    const AuditResult& r = tinyAudit();
    for (const std::string impl : {"core-float", "core-double"}) {
        for (const Family& f : r.families) {
            if (impl == "core-float" && !f.floatToo) continue;
            const CellStats& c = r.cell(impl, f.name);
            EXPECT_EQ(c.scenes, kTinyCases) << impl << " " << f.name;
            for (std::size_t m = 0; m < kMetricCount; ++m)
                EXPECT_EQ(c.failures[m], 0u)
                    << impl << " " << f.name << " " << metricName(static_cast<Metric>(m));
            ASSERT_FALSE(c.positionUlps.empty());
            EXPECT_EQ(c.positionUlps.back(), 0u) << impl << " " << f.name;
        }
    }
}

TEST(Audit, seedVariantShowsItsKnownFlaws) {
    const AuditResult& r = tinyAudit();
    for (const std::string impl : {"seed-float", "seed-double"}) {
        // Moving left or up it never hits anything; without a slide it never matches a two-step frame.
        EXPECT_GT(failures(r.cell(impl, "random"), Metric::Decision), 0u) << impl;
        EXPECT_GT(failures(r.cell(impl, "random"), Metric::Tunnel) +
                      failures(r.cell(impl, "random"), Metric::Inside),
                  0u)
            << impl;
        // A box falling straight onto a floor divides by zero and falls through.
        EXPECT_GT(failures(r.cell(impl, "seam-landing"), Metric::Decision), 0u) << impl;
        EXPECT_EQ(smallestFixingEpsilon(r.cell(impl, "random")), "none") << impl;
    }
}

TEST(Audit, coarseSubstepsTunnelAtHighSpeed) {
    const AuditResult& r = tinyAudit();
    const CellStats& c = r.cell("substep4-float", "high-speed");
    EXPECT_GT(failures(c, Metric::Tunnel), 0u);
    EXPECT_GT(failures(r.cell("substep4-float", "corner-pass"), Metric::Decision), 0u);
}

TEST(Audit, familiesCoverTheirRules) {
    const AuditResult& r = tinyAudit();
    for (std::size_t c = 0; c < r.families.size(); ++c) {
        const Family& f = r.families[c];
        const Coverage& cv = r.coverage[c][1];
        EXPECT_EQ(cv.scenes, kTinyCases) << f.name;
        if (f.name == "corner-tie") {
            EXPECT_GT(cv.tie, 0u);
        }
        if (f.name == "corner-pass") {
            EXPECT_GT(cv.cornerMiss, 0u);
            EXPECT_GT(cv.cornerPass, 0u);
            EXPECT_GT(cv.cornerClip, 0u);
        }
        if (f.name == "resting") {
            EXPECT_GT(cv.resting, 0u);
        }
    }
}

template <class T>
void expectReplayable(const Family& f) {
    for (std::uint64_t k = 0; k < 40; ++k) {
        const Scene<T> s = generateScene<T>(f, kSeed, k);
        const SceneParse<T> back = parseScene<T>(formatScene(s));
        ASSERT_TRUE(back.scene.has_value()) << f.name << " case " << k << ": " << back.error;
        EXPECT_EQ(formatScene(*back.scene), formatScene(s)) << f.name << " case " << k;
    }
}

TEST(Audit, everyGeneratedSceneIsAValidReplayableSceneLine) {
    for (const Family& f : auditFamilies()) {
        if (f.floatToo) expectReplayable<float>(f);
        expectReplayable<double>(f);
    }
}

// A far column builds the same local scene as the others, at its magnitude: the map origin is the
// magnitude rounded down to whole tiles, and the map and the box's size do not depend on it.
TEST(Audit, farColumnsBuildTheSameLocalSceneAtTheirMagnitude) {
    std::vector<Family> far;
    for (const Family& f : auditFamilies())
        if (f.kind == FamilyKind::Far && f.floatToo) far.push_back(f);
    ASSERT_GE(far.size(), 3u);
    for (std::uint64_t k = 0; k < 16; ++k) {
        const Scene<float> nearest = generateScene<float>(far.front(), kSeed, k);
        for (const Family& f : far) {
            const Scene<float> s = generateScene<float>(f, kSeed, k);
            const double tile = static_cast<double>(s.map.tileSize.x);
            EXPECT_EQ(static_cast<double>(s.map.origin.x), std::floor(f.magnitude / tile) * tile)
                << f.name << " " << k;
            EXPECT_EQ(s.map.solid, nearest.map.solid) << f.name << " " << k;
            EXPECT_EQ(s.box.size.x, nearest.box.size.x) << f.name << " " << k;
            EXPECT_EQ(s.moves.size(), nearest.moves.size()) << f.name << " " << k;
        }
    }
}

TEST(Audit, figuresDoNotDependOnTheNumberOfJobs) {
    AuditConfig config;
    config.cases = 6;
    config.seed = kSeed;
    config.jobs = 1;
    const AuditResult one = runAudit(config);
    config.jobs = 3;
    const AuditResult three = runAudit(config);
    for (std::size_t i = 0; i < one.implementations.size(); ++i)
        for (std::size_t c = 0; c < one.families.size(); ++c) {
            EXPECT_EQ(one.cells[i][c].failures, three.cells[i][c].failures);
            EXPECT_EQ(one.cells[i][c].positionUlps, three.cells[i][c].positionUlps);
        }
}

/// A 6 x 4 map of 16 px tiles with a solid block in its top-left 3 x 2 cells, and a 40 x 24 px
/// box at (4, 4) inside all six of them, moving right into empty space for two frames.
Scene<float> startsInsideSixTiles() {
    Scene<float> s;
    s.map = {{0, 0}, {16, 16}, 6, 4, {1, 1, 1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
             {}};
    s.box = {{4, 4}, {40, 24}};
    s.moves = {{6, 0}, {6, 0}};
    return s;
}

/// The judge's verdict on tilesweep's own frames with `rearrange` applied to every frame's start
/// overlaps.
template <class Rearrange>
judge::SceneVerdict judgeRearranged(Rearrange rearrange) {
    const Scene<float> scene = startsInsideSixTiles();
    std::vector<FrameResult<float>> frames = runScene(scene);
    for (FrameResult<float>& f : frames) {
        EXPECT_EQ(f.startOverlaps.size(), 6u);
        rearrange(f.startOverlaps);
    }
    judge::SceneJudge<float> judge(scene);
    return judge.judge(frames);
}

bool failed(const judge::SceneVerdict& v, Metric m) { return v.failed[static_cast<std::size_t>(m)]; }

TEST(SceneJudge, startOverlapsInAnyOrderAreBitExact) {
    EXPECT_FALSE(failed(judgeRearranged([](std::vector<Cell>&) {}), Metric::Inexact));
    EXPECT_FALSE(failed(judgeRearranged([](std::vector<Cell>& c) { std::reverse(c.begin(), c.end()); }),
                        Metric::Inexact));
    EXPECT_FALSE(failed(judgeRearranged([](std::vector<Cell>& c) {
                            std::sort(c.begin(), c.end(),
                                      [](Cell a, Cell b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
                        }),
                        Metric::Inexact));
}

TEST(SceneJudge, startOverlapsMissingTwiceOrWrongAreInexact) {
    const auto reversedThen = [](auto change) {
        return [change](std::vector<Cell>& c) {
            std::reverse(c.begin(), c.end());
            change(c);
        };
    };
    EXPECT_TRUE(
        failed(judgeRearranged(reversedThen([](std::vector<Cell>& c) { c.pop_back(); })), Metric::Inexact));
    EXPECT_TRUE(failed(judgeRearranged(reversedThen([](std::vector<Cell>& c) { c.back() = c.front(); })),
                       Metric::Inexact));
    EXPECT_TRUE(failed(judgeRearranged(reversedThen([](std::vector<Cell>& c) { c.push_back(c.front()); })),
                       Metric::Inexact));
    EXPECT_TRUE(failed(judgeRearranged(reversedThen([](std::vector<Cell>& c) {
                           c.back() = {5, 3};
                       })),
                       Metric::Inexact));
}

}  // namespace
}  // namespace tilesweep::audit
