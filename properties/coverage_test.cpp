// SPDX-License-Identifier: MIT
// Coverage floors judged statistically (coverage_judgement.h): a floor is settled only when the
// share's interval lies on one side of it, a correct resolver passes the whole suite at a small
// budget, and a floor the generator cannot reach is insufficient coverage, not a failed claim.
#include "coverage_judgement.h"
#include "property_suite.h"

#include "tilesweep/resolvers/in_process_resolver.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace tilesweep::properties {
namespace {

TEST(CoverageJudgement, wilsonIntervalHoldsTheShareAndNarrowsWithCases) {
    const ShareInterval few = wilsonInterval(5, 100);
    const ShareInterval many = wilsonInterval(500, 10000);
    EXPECT_LT(few.low, 0.05);
    EXPECT_GT(few.high, 0.05);
    EXPECT_LT(many.low, 0.05);
    EXPECT_GT(many.high, 0.05);
    EXPECT_LT(many.high - many.low, few.high - few.low);
    // At z = 1.96 and 50 of 100, the textbook Wilson interval is 0.404 to 0.596.
    const ShareInterval textbook = wilsonInterval(50, 100, 1.96);
    EXPECT_NEAR(textbook.low, 0.4038, 5e-4);
    EXPECT_NEAR(textbook.high, 0.5962, 5e-4);
    EXPECT_EQ(wilsonInterval(0, 0).low, 0.0);
    EXPECT_EQ(wilsonInterval(0, 0).high, 1.0);
}

TEST(CoverageJudgement, aFloorIsSettledOnlyWhenTheIntervalLiesOnOneSide) {
    // 2 of 100 against a floor of 3% (the share that failed a correct resolver before): undecided.
    EXPECT_EQ(judgeFloor(2, 100, 0.03), FloorVerdict::Undecided);
    // 0 of 100 cannot show a 3% floor missed at 1e-9 either.
    EXPECT_EQ(judgeFloor(0, 100, 0.03), FloorVerdict::Undecided);
    // None in 16,000: certainly short.
    EXPECT_EQ(judgeFloor(0, 16000, 0.03), FloorVerdict::Short);
    // Half of 1,000 against 20%: certainly met.
    EXPECT_EQ(judgeFloor(500, 1000, 0.2), FloorVerdict::Met);
    // Exactly at the floor, enough cases: met by the tolerance (QuickCheck's 0.9).
    EXPECT_EQ(judgeFloor(6000, 200000, 0.03), FloorVerdict::Met);
    // Just under the tolerance with many cases: short never, met never: undecided or short.
    EXPECT_NE(judgeFloor(2600, 100000, 0.03), FloorVerdict::Met);
    EXPECT_EQ(judgeFloor(2000, 100000, 0.03), FloorVerdict::Short);
}

TEST(CoverageFloors, aFloorFarAboveTheTrueShareIsInsufficientCoverageNotAFailure) {
    // Random scenes hit something in about 20% of cases; a floor of 95% cannot be met.
    const Property p = makeProperty("hitsAlmostAlways", "matchesExactReferenceBitForBit", "float", "random",
                                    {{"hit", 0.95}, {"miss", 0.01}});
    RunOptions options;
    options.cases = 100;
    const PropertyOutcome o = p.run(options);
    EXPECT_TRUE(o.passed) << o.message;
    EXPECT_TRUE(o.message.empty()) << o.message;
    EXPECT_NE(o.coverageShortfall.find("'hit'"), std::string::npos) << o.coverageShortfall;
    EXPECT_EQ(o.coverageShortfall.find("'miss'"), std::string::npos) << o.coverageShortfall;
    // Settled well before the cap: 100 cases, then 100 more (the interval at 200 lies below 95%).
    EXPECT_LT(o.cases, 1000);
}

TEST(CoverageFloors, aFloorNearTheTrueShareDrawsMoreCasesButNeverFails) {
    const Property p = makeProperty("hitsAsOftenAsItDoes", "matchesExactReferenceBitForBit", "float",
                                    "random", {{"hit", 0.12}});
    RunOptions options;
    options.cases = 50;
    options.maxCases = 3200;
    const PropertyOutcome o = p.run(options);
    EXPECT_TRUE(o.passed) << o.message;
    EXPECT_TRUE(o.coverageShortfall.empty()) << o.coverageShortfall;
    EXPECT_GT(o.cases, 50);  // 50 cases cannot settle a floor of 12% at 1e-9
    EXPECT_LE(o.cases, 3200);
}

/// A resolver that never moves and never hits anything.
resolvers::InProcessResolver standStill() {
    return resolvers::InProcessResolver(
        "stand-still",
        [](const Scene<float>& scene) {
            std::vector<FrameResult<float>> frames(scene.moves.size());
            for (FrameResult<float>& f : frames) f.position = scene.box.pos;
            return frames;
        },
        nullptr);
}

TEST(CoverageFloors, tagsNeverComeFromTheResolverUnderTest) {
    // A claim the resolver does not enter (the reference against substeps), so it holds with
    // either runner; the cases are the same (same seed), and so must be their tags: a resolver
    // that never hits anything cannot lower the share of 'hit'.
    const Property p =
        makeProperty("referenceAgrees", "exactReferenceAgreesWithSubsteps", "float", "mixed", {{"hit", 0.2}});
    RunOptions options;
    options.cases = 200;
    const PropertyOutcome builtIn = p.run(options);
    resolvers::InProcessResolver still = standStill();
    options.resolver = &still;
    const PropertyOutcome outside = p.run(options);
    EXPECT_TRUE(builtIn.passed && outside.passed) << builtIn.message << outside.message;
    EXPECT_GT(builtIn.tagCounts.at("hit"), 0);
    EXPECT_EQ(outside.tagCounts, builtIn.tagCounts);
    EXPECT_EQ(outside.coverageShortfall, builtIn.coverageShortfall);
}

/// The whole suite, tilesweep's own resolver, at `cases` a property: every claim holds and every
/// floor is met or undecided, never short.
void expectTheSuitePassesAt(int cases) {
    for (const Property& p : allProperties()) {
        RunOptions options;
        options.cases = cases;
        if (const char* seed = std::getenv("TILESWEEP_PROPERTY_DEFAULT_SEED"))
            options.seed = std::strtoull(seed, nullptr, 10);
        const PropertyOutcome o = p.run(options);
        EXPECT_TRUE(o.passed) << p.name << ": " << o.message;
        EXPECT_TRUE(o.coverageShortfall.empty()) << p.name << ": " << o.coverageShortfall;
    }
}

TEST(CoverageFloors, aCorrectResolverPassesEveryPropertyAt50Cases) { expectTheSuitePassesAt(50); }

TEST(CoverageFloors, aCorrectResolverPassesEveryPropertyAt100Cases) { expectTheSuitePassesAt(100); }

}  // namespace
}  // namespace tilesweep::properties
