// SPDX-License-Identifier: MIT
// Replays every regression scene in properties/corpus/ against every claim, for ever: each file
// is a named test case. A file is a scene line with the property, seed and scalar that found it.
#include "all_claims.h"

#include "tilesweep/resolvers/resolver_registry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace tilesweep::properties {
namespace {

std::vector<std::filesystem::path> corpusFiles() {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path dir = std::filesystem::path(TILESWEEP_SOURCE_DIR) / "properties" / "corpus";
    if (std::filesystem::exists(dir))
        for (const auto& entry : std::filesystem::directory_iterator(dir))
            if (entry.path().extension() == ".jsonl") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

template <class T>
void replay(const std::string& line) {
    const SceneParse<T> parsed = parseScene<T>(line);
    ASSERT_TRUE(parsed.scene.has_value()) << parsed.error;
    std::string error;
    const std::unique_ptr<SceneResolver> core = resolvers::makeResolver("core", error);
    ASSERT_TRUE(core) << error;
    for (const Claim<T>& claim : allClaims<T>()) {
        const std::string message = checkClaim(claim, *parsed.scene, *core);
        EXPECT_TRUE(message.empty()) << claim.name << ": " << message;
    }
}

class Corpus : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(Corpus, holdsEveryClaim) {
    std::ifstream in(GetParam());
    std::string line;
    int scenes = 0;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const auto json = nlohmann::json::parse(line);
        const std::string scalar = json.value("scalar", std::string("float"));
        if (scalar == "double") {
            replay<double>(line);
        } else {
            replay<float>(line);
        }
        ++scenes;
    }
    EXPECT_GT(scenes, 0) << "empty regression file";
}

INSTANTIATE_TEST_SUITE_P(Regressions, Corpus, ::testing::ValuesIn(corpusFiles()),
                         [](const ::testing::TestParamInfo<std::filesystem::path>& p) {
                             std::string name = p.param.stem().string();
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Corpus);

}  // namespace
}  // namespace tilesweep::properties
