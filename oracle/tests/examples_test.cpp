// SPDX-License-Identifier: MIT
// The exact reference against the worked examples of the contract (shared/examples): every line
// of expected-float.jsonl and expected-double.jsonl, and of oneway-expected.jsonl in both
// scalars, bit for bit. Numbers are compared by value
// in T (read straight into T from their text), error lines as errors (the message is free text).
// Scenes are read with the project's scene reader, tilesweep::parseScene<T>.

#include "expected_json.h"

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/scene/scene.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef TILESWEEP_EXAMPLES_DIR
#error "TILESWEEP_EXAMPLES_DIR must name the directory holding scenes.jsonl"
#endif

namespace tilesweep::oracle {
namespace {

using test::JsonValue;
using test::parseJson;

// The examples live beside the repository (shared/examples); the environment variable
// TILESWEEP_EXAMPLES_DIR overrides the path fixed at configure time.
std::string examplesDir() {
    const char* fromEnvironment = std::getenv("TILESWEEP_EXAMPLES_DIR");
    return fromEnvironment != nullptr ? fromEnvironment : TILESWEEP_EXAMPLES_DIR;
}

// The non-blank lines of a file; empty when it cannot be opened.
std::vector<std::string> readLines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") != std::string::npos) {
            lines.push_back(line);
        }
    }
    return lines;
}

template <class T>
T readNumber(const JsonValue& v);

template <>
float readNumber<float>(const JsonValue& v) {
    return std::strtof(v.text.c_str(), nullptr);
}

template <>
double readNumber<double>(const JsonValue& v) {
    return std::strtod(v.text.c_str(), nullptr);
}

int readInt(const JsonValue& v) { return std::atoi(v.text.c_str()); }

template <class T>
void expectFramesMatch(const std::vector<FrameResult<T>>& actual, const JsonValue& expected) {
    const std::vector<JsonValue>& frames = expected.at("frames").items;
    ASSERT_EQ(actual.size(), frames.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        const JsonValue& e = frames[f];
        const FrameResult<T>& a = actual[f];
        EXPECT_EQ(a.position.x, readNumber<T>(e.at("pos").items.at(0)));
        EXPECT_EQ(a.position.y, readNumber<T>(e.at("pos").items.at(1)));
        const std::vector<JsonValue>& contacts = e.at("contacts").items;
        ASSERT_EQ(a.contacts.size(), contacts.size());
        for (std::size_t k = 0; k < contacts.size(); ++k) {
            SCOPED_TRACE("contact " + std::to_string(k));
            const JsonValue& c = contacts[k];
            EXPECT_EQ(a.contacts[k].tile.i, readInt(c.at("tile").items.at(0)));
            EXPECT_EQ(a.contacts[k].tile.j, readInt(c.at("tile").items.at(1)));
            EXPECT_EQ(a.contacts[k].normal.x, readInt(c.at("normal").items.at(0)));
            EXPECT_EQ(a.contacts[k].normal.y, readInt(c.at("normal").items.at(1)));
            EXPECT_EQ(a.contacts[k].time, readNumber<T>(c.at("t")));
        }
        const std::vector<JsonValue>& overlaps = e.at("started_overlapping").items;
        ASSERT_EQ(a.startOverlaps.size(), overlaps.size());
        for (std::size_t k = 0; k < overlaps.size(); ++k) {
            EXPECT_EQ(a.startOverlaps[k].i, readInt(overlaps[k].items.at(0)));
            EXPECT_EQ(a.startOverlaps[k].j, readInt(overlaps[k].items.at(1)));
        }
    }
}

template <class T>
void expectExamplesReproduced(const std::string& scenesFile, const std::string& expectedFile) {
    const std::string dir = examplesDir();
    const std::vector<std::string> scenes = readLines(dir + "/" + scenesFile);
    const std::vector<std::string> expected = readLines(dir + "/" + expectedFile);
    if (scenes.empty()) {
        GTEST_SKIP() << "no " << scenesFile << " at " << dir << " (set TILESWEEP_EXAMPLES_DIR)";
    }
    ASSERT_EQ(scenes.size(), expected.size());
    for (std::size_t n = 0; n < scenes.size(); ++n) {
        const JsonValue want = parseJson(expected[n]);
        std::string name = "line " + std::to_string(n + 1);
        const JsonValue scene = parseJson(scenes[n]);
        if (scene.has("name")) {
            name += ": " + scene.at("name").text;
        }
        SCOPED_TRACE(name);
        const SceneParse<T> parsed = parseScene<T>(scenes[n]);
        if (want.has("error")) {
            EXPECT_FALSE(parsed.scene.has_value()) << "expected an error";
            EXPECT_FALSE(parsed.error.empty());
            continue;
        }
        ASSERT_TRUE(parsed.scene.has_value()) << parsed.error;
        expectFramesMatch(resolveSceneExactRounded(*parsed.scene), want);
    }
}

TEST(ExactReference, reproducesEveryFloatExampleBitForBit) {
    expectExamplesReproduced<float>("scenes.jsonl", "expected-float.jsonl");
}

TEST(ExactReference, reproducesEveryDoubleExampleBitForBit) {
    expectExamplesReproduced<double>("scenes.jsonl", "expected-double.jsonl");
}

// The one-way examples have one expected file for both scalars: every number in it is exact in
// float and in double.
TEST(ExactReference, reproducesEveryOneWayExampleInFloatBitForBit) {
    expectExamplesReproduced<float>("oneway-scenes.jsonl", "oneway-expected.jsonl");
}

TEST(ExactReference, reproducesEveryOneWayExampleInDoubleBitForBit) {
    expectExamplesReproduced<double>("oneway-scenes.jsonl", "oneway-expected.jsonl");
}

}  // namespace
}  // namespace tilesweep::oracle
