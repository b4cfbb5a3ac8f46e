// SPDX-License-Identifier: MIT
// Every property of the suite as one GoogleTest case, so ctest runs them, GoogleTest sharding
// (GTEST_TOTAL_SHARDS, GTEST_SHARD_INDEX) fans them out, and --gtest_filter picks one.
// TILESWEEP_PROPERTY_SEED / TILESWEEP_PROPERTY_CASES / TILESWEEP_CORPUS_DIR set the run.
#include "property_suite.h"

#include <gtest/gtest.h>

#include <iostream>

namespace tilesweep::properties {
namespace {

class Property : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Property, holds) {
    const auto& property = allProperties()[GetParam()];
    const RunOptions options = optionsFromEnvironment();
    const PropertyOutcome outcome = property.run(options);
    std::cout << property.name << ": " << outcome.cases << " cases, seed " << options.seed << ", "
              << outcome.seconds << " s\n";
    for (const auto& [tag, count] : outcome.tagCounts)
        std::cout << "  " << tag << ": " << 100.0 * count / std::max(outcome.cases, 1) << "%\n";
    if (!outcome.coverageUndecided.empty())
        std::cout << "  coverage undecided at the cap (not a failure): " << outcome.coverageUndecided << "\n";
    EXPECT_TRUE(outcome.coverageShortfall.empty()) << "insufficient coverage: " << outcome.coverageShortfall;
    EXPECT_TRUE(outcome.passed) << outcome.message
                                << (outcome.corpusFile.empty() ? ""
                                                               : "\nregression file: " + outcome.corpusFile)
                                << (outcome.pictureFile.empty() ? "" : "\npicture: " + outcome.pictureFile);
}

INSTANTIATE_TEST_SUITE_P(Suite, Property, ::testing::Range<std::size_t>(0, allProperties().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& p) {
                             return allProperties()[p.param].name;
                         });

}  // namespace
}  // namespace tilesweep::properties
