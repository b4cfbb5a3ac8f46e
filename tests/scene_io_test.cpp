// SPDX-License-Identifier: MIT
// The scene layer: reading scene lines (every error names its field; numbers are rounded once,
// straight to the scalar type), writing them back bit for bit, the `tilesweep resolve` output
// format, runScene's chaining of frames, and the percent text of the tools' reports. Expected
// values are worked out by hand from docs/contract.md and IEEE 754 rounding, not copied from
// program output.
#include "tilesweep/scene/file_write.h"
#include "tilesweep/scene/scalar_text.h"
#include "tilesweep/scene/scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cfloat>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using tilesweep::Cell;
using tilesweep::CellKind;
using tilesweep::Contact;
using tilesweep::formatError;
using tilesweep::formatFrames;
using tilesweep::formatScene;
using tilesweep::FrameResult;
using tilesweep::Normal;
using tilesweep::parseScene;
using tilesweep::runScene;
using tilesweep::Scene;
using tilesweep::SceneParse;
using tilesweep::Vec2;

// ---- helpers ---------------------------------------------------------------------------

template <class T>
using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;

template <class T>
Bits<T> bitsOf(T value) {
    Bits<T> bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

std::string hex(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", value);
    return buffer;
}

// Equal bits (so -0 differs from +0), printed as hexfloats when they are not.
template <class T>
::testing::AssertionResult sameBits(T actual, T expected) {
    if (bitsOf(actual) == bitsOf(expected)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << hex(static_cast<double>(actual)) << " is not " << hex(static_cast<double>(expected));
}

const char* const kMap =
    R"({"origin": [0, 0], "tile": [16, 16], "rows": ["........", "...#....", "########"]})";
const char* const kBox = "[20, 10, 12, 14]";
const char* const kMove = R"("move": [3.5, 40])";

// A valid scene line with some of its parts replaced by JSON fragments.
std::string sceneLine(const std::string& map = kMap, const std::string& box = kBox,
                      const std::string& motion = kMove, const std::string& extra = "") {
    return R"({"map": )" + map + R"(, "box": )" + box + ", " + motion + extra + "}";
}

std::string mapLine(const std::string& origin, const std::string& tile, const std::string& rows) {
    return sceneLine(R"({"origin": )" + origin + R"(, "tile": )" + tile + R"(, "rows": )" + rows + "}");
}

// The line is refused, and the message starts with "<field>: " and contains `detail`.
template <class T>
::testing::AssertionResult refusedNaming(const std::string& line, const std::string& field,
                                         const std::string& detail = "") {
    const SceneParse<T> parsed = parseScene<T>(line);
    if (parsed.scene) return ::testing::AssertionFailure() << "accepted: " << line;
    if (parsed.error.rfind(field + ": ", 0) != 0 || parsed.error.find(detail) == std::string::npos)
        return ::testing::AssertionFailure()
               << "message '" << parsed.error << "' does not name '" << field << "' with '" << detail << "'";
    return ::testing::AssertionSuccess();
}

template <class T>
Scene<T> parsed(const std::string& line) {
    SceneParse<T> result = parseScene<T>(line);
    if (!result.scene) throw std::runtime_error("refused: " + result.error + "\n  line: " + line);
    return *std::move(result.scene);
}

// The first box coordinate of a scene whose box x is given as `x` (a JSON fragment).
template <class T>
T boxX(const std::string& x) {
    return parsed<T>(sceneLine(kMap, "[" + x + ", 10, 12, 14]")).box.pos.x;
}

template <class T>
class SceneReaderTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(SceneReaderTyped, Scalars);

// ---- reading: values ---------------------------------------------------------------------

TEST(SceneReader, readsEveryFieldOfTheContractExample) {
    const Scene<float> scene =
        parsed<float>(R"({"map": {"origin": [0, 0], "tile": [16, 16],)"
                      R"( "rows": ["........", "...#....", "########"]},)"
                      R"( "box": [20, 10, 12, 14], "moves": [[3.5, 40], [3.5, 0.25]]})");
    EXPECT_TRUE(scene.name.empty());
    EXPECT_EQ(scene.map.origin, (Vec2<float>{0, 0}));
    EXPECT_EQ(scene.map.tileSize, (Vec2<float>{16, 16}));
    ASSERT_EQ(scene.map.columns, 8);
    ASSERT_EQ(scene.map.rows, 3);
    ASSERT_EQ(scene.map.solid.size(), 24u);
    const auto view = scene.map.view();
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 8; ++i)
            EXPECT_EQ(view.isSolid(i, j), j == 2 || (j == 1 && i == 3)) << i << "," << j;
    EXPECT_EQ(scene.box.pos, (Vec2<float>{20, 10}));
    EXPECT_EQ(scene.box.size, (Vec2<float>{12, 14}));
    ASSERT_EQ(scene.moves.size(), 2u);
    EXPECT_EQ(scene.moves[0], (Vec2<float>{3.5f, 40}));
    EXPECT_EQ(scene.moves[1], (Vec2<float>{3.5f, 0.25f}));
}

TEST(SceneReader, decimalPointOneIsTheNearestFloatAndTheNearestDouble) {
    EXPECT_TRUE(sameBits(boxX<float>("0.1"), 0.1f));
    EXPECT_TRUE(sameBits(boxX<double>("0.1"), 0.1));
}

TEST(SceneReader, decimalIsRoundedOnceNotThroughDouble) {
    // 1 + 2^-24 + 1e-20 lies just above the midpoint 1 + 2^-24 between the floats 1 and
    // 1 + 2^-23, so its nearest float is 1 + 2^-23. Its nearest double is the midpoint itself
    // (1e-20 < 2^-53), which rounds to the even float 1: rounding twice gets it wrong.
    const std::string text = "1.000000059604644775400625";
    ASSERT_EQ(static_cast<float>(std::strtod(text.c_str(), nullptr)), 1.0f);  // the trap
    EXPECT_TRUE(sameBits(boxX<float>(text), 0x1.000002p+0f));
    EXPECT_TRUE(sameBits(boxX<double>(text), 0x1.000001p+0));
}

TEST(SceneReader, integerIsRoundedOnceNotThroughDouble) {
    // 2^60 + 2^36 + 1: just above the float midpoint 2^60 + 2^36, so the nearest float is
    // 2^60 + 2^37. The nearest double is the midpoint (the +1 is below half a double ulp, 2^7),
    // and the midpoint rounds to the even float 2^60.
    const std::string text = "1152921573326323713";
    ASSERT_EQ(static_cast<float>(std::strtod(text.c_str(), nullptr)), 0x1p+60f);  // the trap
    EXPECT_TRUE(sameBits(boxX<float>(text), 0x1.000002p+60f));
    EXPECT_TRUE(sameBits(boxX<double>(text), 0x1.000001p+60));
}

TYPED_TEST(SceneReaderTyped, integersAndSignedZerosAreNumbers) {
    using T = TypeParam;
    EXPECT_TRUE(sameBits(boxX<T>("16"), T(16)));
    EXPECT_TRUE(sameBits(boxX<T>("-3"), T(-3)));
    EXPECT_TRUE(sameBits(boxX<T>("-0"), -T(0)));  // an integer -0 keeps its sign
    EXPECT_TRUE(sameBits(boxX<T>("-0.0"), -T(0)));
    EXPECT_TRUE(sameBits(boxX<T>("0"), T(0)));
    EXPECT_TRUE(sameBits(boxX<T>("1.5e1"), T(15)));
    EXPECT_TRUE(sameBits(boxX<T>("25E-1"), T(2.5)));
    // An integer beyond 64 bits is still just a number.
    EXPECT_TRUE(sameBits(boxX<T>("36893488147419103232"), T(0x1p+65)));
}

TYPED_TEST(SceneReaderTyped, hexfloatStringsAreExact) {
    using T = TypeParam;
    EXPECT_TRUE(sameBits(boxX<T>(R"("0x1.8p+3")"), T(12)));
    EXPECT_TRUE(sameBits(boxX<T>(R"("-0x1p-3")"), T(-0.125)));
    EXPECT_TRUE(sameBits(boxX<T>(R"("0X1.8P3")"), T(12)));  // %A spelling
    EXPECT_TRUE(sameBits(boxX<T>(R"("0x.8p+1")"), T(1)));
    EXPECT_TRUE(sameBits(boxX<T>(R"("-0x0p+0")"), -T(0)));
    EXPECT_TRUE(sameBits(boxX<T>(R"("0x18p-1")"), T(12)));
}

TEST(SceneReader, hexfloatRoundsOnceToNearestEven) {
    // 0x1.000001p0 = 1 + 2^-24: a float tie, to even (1); exact in double.
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1.000001p0")"), 1.0f));
    EXPECT_TRUE(sameBits(boxX<double>(R"("0x1.000001p0")"), 0x1.000001p0));
    // 1 + 3*2^-24: a tie between 1 + 2^-23 (odd) and 1 + 2^-22 (even).
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1.000003p0")"), 0x1.000004p0f));
    // Just above a tie: rounds up, although the excess lies far beyond float precision.
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1.0000010000000000001p0")"), 0x1.000002p0f));
}

TEST(SceneReader, extremeFloatsReadExactly) {
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1.fffffep+127")"), FLT_MAX));
    EXPECT_TRUE(sameBits(boxX<float>("3.4028235e38"), FLT_MAX));
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1p-149")"), std::numeric_limits<float>::denorm_min()));
    EXPECT_TRUE(sameBits(boxX<float>("1e-45"), std::numeric_limits<float>::denorm_min()));
    // Just below the midpoint between FLT_MAX and 2^128: still FLT_MAX.
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1.fffffe8p+127")"), FLT_MAX));
    EXPECT_TRUE(
        sameBits(boxX<double>(R"("0x0.0000000000001p-1022")"), std::numeric_limits<double>::denorm_min()));
    EXPECT_TRUE(sameBits(boxX<double>("1.7976931348623157e308"), DBL_MAX));
}

TEST(SceneReader, valuesBelowTheSmallestSubnormalRoundToSignedZero) {
    // Zero is the nearest float: not an error, unlike an overflow.
    EXPECT_TRUE(sameBits(boxX<float>("1e-50"), 0.0f));
    EXPECT_TRUE(sameBits(boxX<float>("-1e-50"), -0.0f));
    EXPECT_TRUE(sameBits(boxX<float>(R"("0x1p-150")"), 0.0f));  // exactly half: to even, 0
    EXPECT_TRUE(sameBits(boxX<float>(R"("-0x1p-200")"), -0.0f));
    EXPECT_TRUE(sameBits(boxX<double>("1e-400"), 0.0));
    EXPECT_TRUE(sameBits(boxX<double>("1e-50"), 1e-50));
}

TEST(SceneReader, moveIsOneFrameAndMovesAreSeveralInOrder) {
    const Scene<float> one = parsed<float>(sceneLine(kMap, kBox, R"("move": [-1, 2])"));
    ASSERT_EQ(one.moves.size(), 1u);
    EXPECT_EQ(one.moves[0], (Vec2<float>{-1, 2}));
    const Scene<float> three =
        parsed<float>(sceneLine(kMap, kBox, R"("moves": [[1, 2], [3, 4], ["0x1p-1", 5]])"));
    ASSERT_EQ(three.moves.size(), 3u);
    EXPECT_EQ(three.moves[0], (Vec2<float>{1, 2}));
    EXPECT_EQ(three.moves[1], (Vec2<float>{3, 4}));
    EXPECT_EQ(three.moves[2], (Vec2<float>{0.5f, 5}));
}

TEST(SceneReader, unknownFieldsAreIgnoredAndTheNameIsKept) {
    const Scene<double> scene = parsed<double>(sceneLine(
        kMap, kBox, kMove,
        R"(, "name": "a \"quoted\" name\u00e9", "seed": 1234567, "property": {"claim": [1, "x", null,)"
        R"( true, [[[{"deep": -0}]]]]}, "note": "nan")"));
    EXPECT_EQ(scene.name, "a \"quoted\" name\xc3\xa9");
    EXPECT_EQ(scene.box.pos, (Vec2<double>{20, 10}));

    // A name that is not a string is just an unknown field.
    EXPECT_TRUE(parsed<float>(sceneLine(kMap, kBox, kMove, R"(, "name": 7)")).name.empty());
    // Unknown fields of the map are ignored too.
    EXPECT_EQ(parsed<float>(mapLine("[0, 0]", "[16, 16]", R"(["#"], "legend": {"#": "rock"})")).map.columns,
              1);
}

TEST(SceneReader, windowsLineEndingsAndSurroundingBlanksAreWhitespace) {
    EXPECT_TRUE(parseScene<float>("  \t" + sceneLine() + " \r").scene.has_value());
}

TEST(SceneReader, noRowsOrEmptyRowsMakeAnEmptyMap) {
    for (const char* rows : {"[]", R"([""])", R"(["", "", ""])"}) {
        const Scene<float> scene = parsed<float>(mapLine("[0, 0]", "[16, 16]", rows));
        EXPECT_EQ(scene.map.columns, 0) << rows;
        EXPECT_EQ(scene.map.rows, 0) << rows;
        EXPECT_TRUE(scene.map.solid.empty()) << rows;
    }
}

TEST(SceneReader, tileEdgesNeedOnlyBeRepresentableWhereTilesExist) {
    // 0.1f doubles exactly: edges 0, 0.1f, 0.2f are floats, so two columns are fine.
    EXPECT_TRUE(parseScene<float>(mapLine("[0, 0]", "[0.1, 16]", R"(["..", "##"])")).scene);
    // An empty map has no tile edges at all.
    EXPECT_TRUE(parseScene<float>(mapLine("[0, 0]", "[0.1, 0.1]", "[]")).scene);
}

// ---- reading: errors name their field ----------------------------------------------------

TYPED_TEST(SceneReaderTyped, blankAndMalformedLinesAreRefused) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>("", "scene", "blank"));
    EXPECT_TRUE(refusedNaming<T>(" \t\r", "scene", "blank"));
    EXPECT_TRUE(refusedNaming<T>("{", "scene", "malformed JSON"));
    EXPECT_TRUE(refusedNaming<T>(R"({"map": })", "scene", "malformed JSON"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine() + " x", "scene", "malformed JSON"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine() + sceneLine(), "scene", "malformed JSON"));
    EXPECT_TRUE(refusedNaming<T>(R"({"box": NaN})", "scene", "malformed JSON"));
    EXPECT_TRUE(refusedNaming<T>("{\"name\": \"\xff\"}", "scene", "malformed JSON"));  // bad UTF-8
}

TYPED_TEST(SceneReaderTyped, aSceneIsAnObject) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>("[1, 2]", "scene", "expected a JSON object, got an array"));
    EXPECT_TRUE(refusedNaming<T>("42", "scene", "got a number"));
    EXPECT_TRUE(refusedNaming<T>(R"("map")", "scene", "got a string"));
    EXPECT_TRUE(refusedNaming<T>("null", "scene", "got null"));
}

TYPED_TEST(SceneReaderTyped, deepNestingIsRefusedWithoutCrashing) {
    using T = TypeParam;
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_TRUE(refusedNaming<T>(deep, "scene", "nested"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, kMove, R"(, "note": )" + deep), "scene", "nested"));
}

TYPED_TEST(SceneReaderTyped, missingFieldsAreNamed) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>(R"({"box": [0, 0, 1, 1], "move": [1, 1]})", "map", "missing"));
    EXPECT_TRUE(refusedNaming<T>(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": []},)"
                                 R"( "move": [1, 1]})",
                                 "box", "missing"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, R"("mvoe": [1, 1])"), "move", "missing"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(R"({"tile": [16, 16], "rows": []})"), "map.origin", "missing"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(R"({"origin": [0, 0], "rows": []})"), "map.tile", "missing"));
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(R"({"origin": [0, 0], "tile": [16, 16]})"), "map.rows", "missing"));
}

TYPED_TEST(SceneReaderTyped, wrongTypesAndAritiesAreNamed) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>(sceneLine("[0, 0]"), "map", "expected an object"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, R"("20, 10, 12, 14")"), "box",
                                 "expected an array of 4 numbers, got a string"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, "[20, 10, 12]"), "box",
                                 "expected an array of 4 numbers, got 3 elements"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, "[20, 10, 12, 14, 1]"), "box", "got 5 elements"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, "[20, true, 12, 14]"), "box[1]", "got a boolean"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, "[20, 10, null, 14]"), "box[2]", "got null"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, "[20, 10, 12, [14]]"), "box[3]", "got an array"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, R"("move": [1])"), "move",
                                 "expected an array of 2 numbers, got 1 element"));
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, kBox, R"("move": {"dx": 1, "dy": 2})"), "move", "got an object"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, R"("moves": [1, 2])"), "moves[0]",
                                 "expected an array of 2 numbers, got a number"));
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, kBox, R"("moves": [[1, 2], [3]])"), "moves[1]", "got 1 element"));
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, kBox, R"("moves": [[1, 2], [3, "4"]])"), "moves[1][1]", "hexfloat"));
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, kBox, R"("moves": {"0": [1, 2]})"), "moves", "got an object"));
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0]", "[16, 16]", "[]"), "map.origin", "got 1 element"));
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, false]", "[]"), "map.tile[1]", "got a boolean"));
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"("..##")"), "map.rows",
                                 "expected an array of strings"));
    EXPECT_TRUE(
        refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"(["..", 12])"), "map.rows[1]", "got a number"));
}

TYPED_TEST(SceneReaderTyped, nonFiniteValuesAreNamed) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, R"("move": ["nan", 1])"), "move[0]",
                                 "non-finite value 'nan'"));
    for (const char* spelling : {"inf", "-inf", "Infinity", "-Infinity", "NaN", "+inf", "nan(1)"})
        EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, std::string("[20, 10, 12, \"") + spelling + "\"]"),
                                     "box[3]", std::string("non-finite value '") + spelling + "'"));
    EXPECT_TRUE(refusedNaming<T>(mapLine(R"([0, "inf"])", "[16, 16]", "[]"), "map.origin[1]", "non-finite"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, R"("moves": [[1, 2], [3, "-inf"]])"), "moves[1][1]",
                                 "non-finite"));
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, "[1e400, 10, 12, 14]"), "box[0]", "non-finite value '1e400'"));
}

TEST(SceneReader, valuesThatRoundToInfinityInTheScalarTypeAreNonFinite) {
    // 2^128 and beyond are not floats; 3.40282357e38 and 0x1.ffffffp127 are at or past the
    // midpoint between FLT_MAX and 2^128, so they round to infinity as well.
    for (const char* text : {"1e39", "3.40282357e38", R"("0x1.ffffffp+127")", R"("0x1p+128")",
                             R"("-0x1p+1000")", R"("0x1p+99999999999999")"}) {
        EXPECT_TRUE(refusedNaming<float>(sceneLine(kMap, std::string("[") + text + ", 10, 12, 14]"), "box[0]",
                                         "overflows float"))
            << text;
    }
    // All of them but the last are ordinary doubles.
    EXPECT_TRUE(sameBits(boxX<double>("1e39"), 1e39));
    EXPECT_TRUE(sameBits(boxX<double>(R"("-0x1p+1000")"), -0x1p+1000));
    EXPECT_TRUE(
        refusedNaming<double>(sceneLine(kMap, R"(["0x1p+1024", 10, 12, 14])"), "box[0]", "overflows double"));
    EXPECT_TRUE(refusedNaming<double>(sceneLine(kMap, "[2e308, 10, 12, 14]"), "box[0]", "overflows double"));
}

TYPED_TEST(SceneReaderTyped, stringsThatAreNotHexfloatsAreRefused) {
    using T = TypeParam;
    for (const char* text : {"12", "1.5", "0x", "0x1", "0x1.8", "0xp3", "0x1p", "0x1p+", " 0x1p3", "0x1p3 ",
                             "+0x1p3", "--0x1p3", "0x1.8e+3", "1p3", "0x1.g", "", "ten"})
        EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, std::string("[20, \"") + text + "\", 12, 14]"), "box[1]",
                                     "hexfloat string"))
            << "'" << text << "'";
}

TYPED_TEST(SceneReaderTyped, nonPositiveSizesAreRefused) {
    using T = TypeParam;
    for (const char* box : {"[0, 0, 0, 4]", "[0, 0, 4, 0]", "[0, 0, -4, 4]", "[0, 0, 4, -0]",
                            R"([0, 0, "-0x1p-149", 4])", "[0, 0, 1e-400, 4]"})
        EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, box), "box", "width and height must be > 0")) << box;
    for (const char* tile : {"[0, 16]", "[16, -16]", "[-0, 16]"})
        EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", tile, R"(["#"])"), "map.tile",
                                     "tile width and height must be > 0"))
            << tile;
}

TYPED_TEST(SceneReaderTyped, raggedRowsAreRefused) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"(["...", ".."])"), "map.rows",
                                 "ragged rows (row 1 has length 2, row 0 has 3)"));
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"(["", "#"])"), "map.rows",
                                 "ragged rows (row 1 has length 1, row 0 has 0)"));
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"(["..", "..", "..."])"), "map.rows",
                                 "row 2 has length 3"));
}

TYPED_TEST(SceneReaderTyped, oneWayCellsReadIntoOneWay) {
    using T = TypeParam;
    const Scene<T> scene = parsed<T>(mapLine("[0, 0]", "[16, 16]", R"(["#-.", "--#"])"));
    ASSERT_EQ(scene.map.columns, 3);
    ASSERT_EQ(scene.map.rows, 2);
    EXPECT_EQ(scene.map.solid, (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 1}));
    EXPECT_EQ(scene.map.oneWay, (std::vector<std::uint8_t>{0, 1, 0, 1, 1, 0}));
    const auto view = scene.map.view();
    ASSERT_NE(view.oneWay, nullptr);
    EXPECT_EQ(view.kind(0, 0), CellKind::Solid);
    EXPECT_EQ(view.kind(1, 0), CellKind::OneWay);
    EXPECT_EQ(view.kind(2, 0), CellKind::Empty);
    EXPECT_EQ(view.kind(0, 1), CellKind::OneWay);
    EXPECT_EQ(view.kind(1, 1), CellKind::OneWay);
    EXPECT_EQ(view.kind(2, 1), CellKind::Solid);
    EXPECT_FALSE(view.isSolid(1, 0));
}

TYPED_TEST(SceneReaderTyped, aMapWithoutOneWayCellsLeavesOneWayEmpty) {
    using T = TypeParam;
    const Scene<T> scene = parsed<T>(sceneLine());  // kMap: '#' and '.' only
    ASSERT_EQ(scene.map.solid.size(), 24u);
    EXPECT_TRUE(scene.map.oneWay.empty());
    EXPECT_EQ(scene.map.view().oneWay, nullptr);
    const Scene<T> empty = parsed<T>(mapLine("[0, 0]", "[16, 16]", "[]"));
    EXPECT_TRUE(empty.map.oneWay.empty());
}

TYPED_TEST(SceneReaderTyped, unknownTileCharactersAreNamedWithRowAndColumn) {
    using T = TypeParam;
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"(["...", ".x."])"), "map.rows[1]",
                                 "unknown tile character 'x' at column 1"));
    EXPECT_TRUE(
        refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"(["## "])"), "map.rows[0]", "' ' at column 2"));
    // "é" is two bytes; the first is reported as a byte.
    EXPECT_TRUE(refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", "[\"\xc3\xa9\"]"), "map.rows[0]",
                                 "byte 0xC3 at column 0"));
    // The message names the three characters a row may hold.
    const SceneParse<T> bad = parseScene<T>(mapLine("[0, 0]", "[16, 16]", R"(["-=."])"));
    ASSERT_FALSE(bad.scene);
    EXPECT_NE(bad.error.find("'='"), std::string::npos) << bad.error;
    for (const char* allowed : {"'#'", "'-'", "'.'"})
        EXPECT_NE(bad.error.find(allowed), std::string::npos) << allowed << " in " << bad.error;
}

TYPED_TEST(SceneReaderTyped, moveAndMovesAreExclusiveAndMovesIsNotEmpty) {
    using T = TypeParam;
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, kBox, R"("move": [1, 2], "moves": [[1, 2]])"), "moves", "not both"));
    EXPECT_TRUE(refusedNaming<T>(sceneLine(kMap, kBox, R"("moves": [])"), "moves", "must not be empty"));
}

TYPED_TEST(SceneReaderTyped, aKnownFieldGivenTwiceIsRefused) {
    using T = TypeParam;
    EXPECT_TRUE(
        refusedNaming<T>(sceneLine(kMap, kBox, kMove, R"(, "box": [0, 0, 1, 1])"), "box", "given twice"));
    EXPECT_TRUE(
        refusedNaming<T>(mapLine("[0, 0]", "[16, 16]", R"([], "rows": ["#"])"), "map.rows", "given twice"));
}

TEST(SceneReader, unrepresentableTileEdgesNameTheFirstBadEdgeAndTheType) {
    // 3 * 0.1f needs more than 24 significant bits; so does 3 * 0.1 in double (55 bits).
    EXPECT_TRUE(refusedNaming<float>(mapLine("[0, 0]", "[0.1, 16]", R"(["...."])"), "map.tile",
                                     "tile edge x = origin[0] + 3*tile[0] is not representable in "
                                     "float"));
    EXPECT_TRUE(refusedNaming<double>(mapLine("[0, 0]", "[0.1, 16]", R"(["...."])"), "map.tile",
                                      "3*tile[0] is not representable in double"));
    EXPECT_TRUE(refusedNaming<float>(mapLine("[0, 0]", "[16, 0.1]", R"([".", ".", "."])"), "map.tile",
                                     "tile edge y = origin[1] + 3*tile[1]"));
    // 2^24 + 1 is the first integer that is not a float; it is a double.
    EXPECT_TRUE(refusedNaming<float>(mapLine("[16777216, 0]", "[1, 1]", R"(["##"])"), "map.tile",
                                     "tile edge x = origin[0] + 1*tile[0]"));
    EXPECT_TRUE(parseScene<double>(mapLine("[16777216, 0]", "[1, 1]", R"(["##"])")).scene);
}

TYPED_TEST(SceneReaderTyped, longValuesAreCutShortInMessages) {
    using T = TypeParam;
    const std::string longText(1000, 'z');
    const SceneParse<T> result = parseScene<T>(sceneLine(kMap, "[20, \"" + longText + "\", 12, 14]"));
    ASSERT_FALSE(result.scene);
    EXPECT_LT(result.error.size(), 200u);
    EXPECT_NE(result.error.find("...'"), std::string::npos);
}

// ---- writing scenes ----------------------------------------------------------------------

template <class T>
Scene<T> trickyScene() {
    using L = std::numeric_limits<T>;
    Scene<T> scene;
    scene.name = "tricky \"values\" \\ \xc3\xa9\n\t";
    scene.map.origin = {-T(0), T(-1024)};
    scene.map.tileSize = {T(0.1), T(0.75)};  // 0.1 doubles exactly: two columns are valid
    scene.map.columns = 2;
    scene.map.rows = 3;
    scene.map.solid = {0, 1, 1, 0, 0, 0};
    scene.box = {{-T(0), L::max()}, {L::denorm_min(), L::min()}};
    scene.moves = {{L::denorm_min(), -L::max()},
                   {-T(0), T(1) / T(3)},
                   {L::min() / 2, L::epsilon()},
                   {T(0.1), T(16777217)}};
    return scene;
}

template <class T>
void expectSameScene(const Scene<T>& actual, const Scene<T>& expected) {
    EXPECT_EQ(actual.name, expected.name);
    EXPECT_TRUE(sameBits(actual.map.origin.x, expected.map.origin.x));
    EXPECT_TRUE(sameBits(actual.map.origin.y, expected.map.origin.y));
    EXPECT_TRUE(sameBits(actual.map.tileSize.x, expected.map.tileSize.x));
    EXPECT_TRUE(sameBits(actual.map.tileSize.y, expected.map.tileSize.y));
    EXPECT_EQ(actual.map.columns, expected.map.columns);
    EXPECT_EQ(actual.map.rows, expected.map.rows);
    EXPECT_EQ(actual.map.solid, expected.map.solid);
    EXPECT_EQ(actual.map.oneWay, expected.map.oneWay);
    EXPECT_TRUE(sameBits(actual.box.pos.x, expected.box.pos.x));
    EXPECT_TRUE(sameBits(actual.box.pos.y, expected.box.pos.y));
    EXPECT_TRUE(sameBits(actual.box.size.x, expected.box.size.x));
    EXPECT_TRUE(sameBits(actual.box.size.y, expected.box.size.y));
    ASSERT_EQ(actual.moves.size(), expected.moves.size());
    for (std::size_t k = 0; k < actual.moves.size(); ++k) {
        EXPECT_TRUE(sameBits(actual.moves[k].x, expected.moves[k].x)) << "move " << k;
        EXPECT_TRUE(sameBits(actual.moves[k].y, expected.moves[k].y)) << "move " << k;
    }
}

TYPED_TEST(SceneReaderTyped, formattedScenesReadBackBitForBit) {
    using T = TypeParam;
    const Scene<T> scene = trickyScene<T>();
    const std::string line = formatScene(scene);
    EXPECT_EQ(line.find('\n'), std::string::npos) << "one line";
    const SceneParse<T> back = parseScene<T>(line);
    ASSERT_TRUE(back.scene) << back.error << "\n" << line;
    expectSameScene(*back.scene, scene);
    EXPECT_EQ(formatScene(*back.scene), line);
}

TYPED_TEST(SceneReaderTyped, formattedScenesWriteHexfloatsAsPrintfDoes) {
    using T = TypeParam;
    const Scene<T> scene = trickyScene<T>();
    const nlohmann::json json = nlohmann::json::parse(formatScene(scene));
    // %a of the value promoted to double, which is exact.
    const auto a = [](T value) { return hex(static_cast<double>(value)); };
    EXPECT_EQ(json["map"]["origin"], nlohmann::json({"-0x0p+0", "-0x1p+10"}));
    EXPECT_EQ(json["map"]["tile"], nlohmann::json({a(T(0.1)), "0x1.8p-1"}));
    EXPECT_EQ(json["map"]["rows"], nlohmann::json({".#", "#.", ".."}));
    EXPECT_EQ(json["box"],
              nlohmann::json({"-0x0p+0", a(scene.box.pos.y), a(scene.box.size.x), a(scene.box.size.y)}));
    EXPECT_EQ(json["moves"][1], nlohmann::json({"-0x0p+0", a(T(1) / T(3))}));
    EXPECT_EQ(json["name"], scene.name);
    // Spelled out, so a broken %a on this machine cannot hide a broken writer.
    if constexpr (std::is_same_v<T, float>) {
        EXPECT_EQ(json["map"]["tile"][0], "0x1.99999ap-4");
        EXPECT_EQ(json["box"][1], "0x1.fffffep+127");
        EXPECT_EQ(json["box"][2], "0x1p-149");
    } else {
        EXPECT_EQ(json["map"]["tile"][0], "0x1.999999999999ap-4");
        EXPECT_EQ(json["box"][2], "0x0.0000000000001p-1022");
    }
}

TYPED_TEST(SceneReaderTyped, aSceneWithOneWayCellsWrittenAndReadBackIsIdentical) {
    using T = TypeParam;
    Scene<T> scene = trickyScene<T>();  // rows ".#", "#.", ".."
    scene.map.set(0, 2, CellKind::OneWay);
    scene.map.set(1, 2, CellKind::OneWay);
    scene.map.set(0, 0, CellKind::OneWay);
    ASSERT_EQ(scene.map.oneWay, (std::vector<std::uint8_t>{1, 0, 0, 0, 1, 1}));
    const std::string line = formatScene(scene);
    EXPECT_EQ(nlohmann::json::parse(line)["map"]["rows"], nlohmann::json({"-#", "#.", "--"}));
    const SceneParse<T> back = parseScene<T>(line);
    ASSERT_TRUE(back.scene) << back.error << "\n" << line;
    expectSameScene(*back.scene, scene);
    EXPECT_EQ(formatScene(*back.scene), line);
}

TEST(SceneWriter, alwaysWritesMovesAndWritesNameOnlyWhenSet) {
    Scene<float> scene = parsed<float>(sceneLine());
    const nlohmann::json unnamed = nlohmann::json::parse(formatScene(scene));
    EXPECT_FALSE(unnamed.contains("name"));
    EXPECT_FALSE(unnamed.contains("move"));
    ASSERT_TRUE(unnamed.contains("moves"));
    EXPECT_EQ(unnamed["moves"],  // [[3.5, 40]]
              nlohmann::json::array({nlohmann::json::array({"0x1.cp+1", "0x1.4p+5"})}));
    scene.name = "x";
    EXPECT_EQ(nlohmann::json::parse(formatScene(scene))["name"], "x");
}

TEST(SceneWriter, anEmptyMapWritesNoRowsAndReadsBack) {
    const Scene<float> scene = parsed<float>(mapLine("[8, 8]", "[16, 16]", R"(["", ""])"));
    const std::string line = formatScene(scene);
    EXPECT_EQ(nlohmann::json::parse(line)["map"]["rows"], nlohmann::json::array());
    expectSameScene(parsed<float>(line), scene);
}

TEST(SceneWriter, refusesWhatCannotBeWritten) {
    Scene<float> scene = parsed<float>(sceneLine());
    scene.moves[0].x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW((void)formatScene(scene), std::invalid_argument);
    scene = parsed<float>(sceneLine());
    scene.map.solid.pop_back();
    EXPECT_THROW((void)formatScene(scene), std::invalid_argument);
}

// ---- writing results ---------------------------------------------------------------------

template <class T>
std::vector<FrameResult<T>> sampleFrames() {
    FrameResult<T> first;
    first.position = {T(0.1), -T(0)};
    first.contacts = {Contact<T>{Cell{3, 2}, Normal{0, -1}, T(1) / T(3), {}},
                      Contact<T>{Cell{-1, 40000}, Normal{1, 0}, T(0), {}}};
    first.startOverlaps = {Cell{1, 2}, Cell{0, -7}};
    FrameResult<T> second;
    second.position = {T(16), T(36)};
    return {first, second};
}

TEST(FrameFormat, writesTheContractShapeWithShortestFloats) {
    // Shortest round-trip forms: 0.1f is "0.1", 1/3f is "0.33333334" (8 digits identify it).
    EXPECT_EQ(formatFrames(sampleFrames<float>()),
              R"({"frames": [{"pos": [0.1, -0], "contacts": [)"
              R"({"tile": [3, 2], "normal": [0, -1], "t": 0.33333334}, )"
              R"({"tile": [-1, 40000], "normal": [1, 0], "t": 0}], )"
              R"("started_overlapping": [[1, 2], [0, -7]]}, )"
              R"({"pos": [16, 36], "contacts": [], "started_overlapping": []}]})");
}

TEST(FrameFormat, writesShortestDoubles) {
    const std::string text = formatFrames(sampleFrames<double>());
    EXPECT_NE(text.find(R"("pos": [0.1, -0])"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("t": 0.3333333333333333})"), std::string::npos) << text;  // 16 digits
}

TEST(FrameFormat, noFramesIsAnEmptyList) {
    EXPECT_EQ(formatFrames(std::vector<FrameResult<float>>{}), R"({"frames": []})");
}

// A JSON reader whose floating-point numbers are floats: nlohmann then reads them with
// strtof, rounding once, so a float written in shortest form must come back with its bits.
using FloatJson =
    nlohmann::basic_json<std::map, std::vector, std::string, bool, std::int64_t, std::uint64_t, float>;

// A number read back with the bits it was written with. An integral one ("16", "-0") is read
// as an integer, which has no -0, so it is compared by value; the exact-text test above pins
// the sign of zero.
template <class T, class Json>
::testing::AssertionResult readsBackAs(const Json& json, T expected) {
    if (json.is_number_float()) return sameBits(json.template get<T>(), expected);
    if (!json.is_number()) return ::testing::AssertionFailure() << json.dump() << " is no number";
    const auto value = static_cast<T>(json.template get<std::int64_t>());
    if (value == expected) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << json.dump() << " is not " << hex(static_cast<double>(expected));
}

template <class T, class Json>
void expectFramesReadBack(const std::vector<FrameResult<T>>& frames) {
    const Json json = Json::parse(formatFrames(frames));
    ASSERT_TRUE(json.is_object());
    ASSERT_EQ(json.size(), 1u);
    const Json& list = json.at("frames");
    ASSERT_EQ(list.size(), frames.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Json& frame = list[f];
        ASSERT_EQ(frame.size(), 3u);
        ASSERT_EQ(frame.at("pos").size(), 2u);
        EXPECT_TRUE(readsBackAs(frame.at("pos")[0], frames[f].position.x));
        EXPECT_TRUE(readsBackAs(frame.at("pos")[1], frames[f].position.y));
        ASSERT_EQ(frame.at("contacts").size(), frames[f].contacts.size());
        for (std::size_t k = 0; k < frames[f].contacts.size(); ++k) {
            const Json& contact = frame.at("contacts")[k];
            const Contact<T>& expected = frames[f].contacts[k];
            ASSERT_EQ(contact.size(), 3u);
            EXPECT_EQ(contact.at("tile"), Json({expected.tile.i, expected.tile.j}));
            EXPECT_EQ(contact.at("normal"), Json({expected.normal.x, expected.normal.y}));
            EXPECT_TRUE(readsBackAs(contact.at("t"), expected.time));
        }
        ASSERT_EQ(frame.at("started_overlapping").size(), frames[f].startOverlaps.size());
        for (std::size_t k = 0; k < frames[f].startOverlaps.size(); ++k)
            EXPECT_EQ(frame.at("started_overlapping")[k],
                      Json({frames[f].startOverlaps[k].i, frames[f].startOverlaps[k].j}));
    }
}

template <class T>
std::vector<FrameResult<T>> extremeFrames() {
    using L = std::numeric_limits<T>;
    std::vector<FrameResult<T>> frames;
    const T values[] = {L::max(),    -L::max(), L::denorm_min(), L::min(), L::min() / 3, L::epsilon(),
                        T(1) / T(3), T(0.1),    T(65540.001),    T(1e21),  T(-1e-7),     T(123456789)};
    for (T x : values) {
        FrameResult<T> frame;
        frame.position = {x, -x};
        frame.contacts = {Contact<T>{Cell{0, 0}, Normal{0, 1}, x < 1 && x > 0 ? x : T(0.5), {}}};
        frames.push_back(frame);
    }
    return frames;
}

TEST(FrameFormat, extremeFloatsReadBackBitForBit) {
    expectFramesReadBack<float, FloatJson>(sampleFrames<float>());
    expectFramesReadBack<float, FloatJson>(extremeFrames<float>());
}

TEST(FrameFormat, extremeDoublesReadBackBitForBit) {
    expectFramesReadBack<double, nlohmann::json>(sampleFrames<double>());
    expectFramesReadBack<double, nlohmann::json>(extremeFrames<double>());
}

TEST(FrameFormat, refusesNonFiniteNumbers) {
    auto frames = sampleFrames<float>();
    frames[1].position.y = std::numeric_limits<float>::infinity();
    EXPECT_THROW((void)formatFrames(frames), std::invalid_argument);
}

TEST(ErrorFormat, escapesTheMessageAsAJsonString) {
    const std::string message = "box[2]: \"quoted\" \\ back\nslash\ttab \x01 caf\xc3\xa9";
    const std::string line = formatError(message);
    EXPECT_EQ(line.find('\n'), std::string::npos) << "one line";
    const nlohmann::json json = nlohmann::json::parse(line);
    ASSERT_TRUE(json.is_object());
    ASSERT_EQ(json.size(), 1u);
    EXPECT_EQ(json.at("error"), message);
}

TEST(ErrorFormat, replacesInvalidUtf8InsteadOfThrowing) {
    const std::string line = formatError("scene: last read: '\xff'");
    EXPECT_EQ(nlohmann::json::parse(line).at("error"), "scene: last read: '\xef\xbf\xbd'");
}

TEST(ErrorFormat, readerErrorsBecomeValidErrorLines) {
    // A parse error quotes the raw bytes of the line, invalid UTF-8 included.
    const SceneParse<float> result = parseScene<float>("{\"map\": \xff\xfe}");
    ASSERT_FALSE(result.scene);
    const nlohmann::json json = nlohmann::json::parse(formatError(result.error));
    EXPECT_EQ(json.at("error").get<std::string>().rfind("scene: malformed JSON", 0), 0u);
}

// ---- running scenes ----------------------------------------------------------------------

TEST(SceneRunner, aFallingBoxLandsOnTheFloor) {
    // The floor's top is y = 48; the box's bottom starts at 16 and moves 40: it lands after 32,
    // at t = 0.8, on the one floor tile under x in [20, 32] (x = 32 only touches column 2).
    const Scene<float> scene =
        parsed<float>(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["......", "......", "......",)"
                      R"( "######"]}, "box": [20, 4, 12, 12], "move": [0, 40]})");
    const auto result = runScene(scene);
    ASSERT_EQ(result.size(), 1u);
    EXPECT_EQ(result[0].position, (Vec2<float>{20, 36}));
    ASSERT_EQ(result[0].contacts.size(), 1u);
    EXPECT_EQ(result[0].contacts[0].tile, (Cell{1, 3}));
    EXPECT_EQ(result[0].contacts[0].normal, (Normal{0, -1}));
    EXPECT_TRUE(sameBits(result[0].contacts[0].time, 0.8f));
    EXPECT_TRUE(result[0].startOverlaps.empty());
}

std::string wideFloorScene(const std::string& box, const std::string& moves) {
    // 24 columns; a solid floor on row 2 (y in [32, 48]).
    return R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": [")" + std::string(24, '.') + R"(", ")" +
           std::string(24, '.') + R"(", ")" + std::string(24, '#') + R"("]}, "box": )" + box +
           R"(, "moves": )" + moves + "}";
}

TEST(SceneRunner, reportsEveryContactOfAWideLandingAndChainsFrames) {
    // A box 320 wide at x = 8 spans columns 0..20 (x = 328 lies inside column 20): 21 floor
    // tiles, more than any small fixed buffer, all hit at t = 24/40 = 0.6. The second frame
    // starts on the floor (y = 24) and slides along it without touching anything.
    const auto frames = runScene(parsed<float>(wideFloorScene("[8, 0, 320, 8]", "[[0, 40], [5, 0]]")));
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].position, (Vec2<float>{8, 24}));
    ASSERT_EQ(frames[0].contacts.size(), 21u);
    for (int i = 0; i < 21; ++i) {
        const auto& contact = frames[0].contacts[static_cast<std::size_t>(i)];
        EXPECT_EQ(contact.tile, (Cell{i, 2})) << i;  // one step: by row, then column
        EXPECT_EQ(contact.normal, (Normal{0, -1})) << i;
        EXPECT_TRUE(sameBits(contact.time, 0.6f)) << i;
    }
    EXPECT_EQ(frames[1].position, (Vec2<float>{13, 24}));
    EXPECT_TRUE(frames[1].contacts.empty());
}

TEST(SceneRunner, reportsEveryTileTheBoxStartsIn) {
    // y in [36, 40] lies inside the floor row; x in [8, 328] overlaps columns 0..20.
    const auto frames = runScene(parsed<double>(wideFloorScene("[8, 36, 320, 4]", "[[0, 0]]")));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].position, (Vec2<double>{8, 36}));
    EXPECT_TRUE(frames[0].contacts.empty());
    ASSERT_EQ(frames[0].startOverlaps.size(), 21u);
    for (int i = 0; i < 21; ++i)
        EXPECT_EQ(frames[0].startOverlaps[static_cast<std::size_t>(i)], (Cell{i, 2})) << i;
}

TEST(SceneRunner, anEmptyMapLetsTheBoxMoveFreely) {
    const auto frames = runScene(parsed<float>(mapLine("[0, 0]", "[16, 16]", "[]")));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].position, (Vec2<float>{23.5f, 50}));  // (20, 10) + (3.5, 40)
    EXPECT_TRUE(frames[0].contacts.empty());
}

// ---- the shipped examples ----------------------------------------------------------------

TEST(ShippedExamples, everyLineReadsUnlessItsNameSaysBad) {
    const std::filesystem::path folder = std::filesystem::path(TILESWEEP_SOURCE_DIR) / "examples";
    ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
    int lines = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".jsonl") continue;
        std::ifstream file(entry.path());
        std::string line;
        while (std::getline(file, line)) {
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            ++lines;
            const std::string name = nlohmann::json::parse(line).value("name", "");
            const bool bad = name.rfind("bad:", 0) == 0;
            EXPECT_EQ(parseScene<float>(line).scene.has_value(), !bad) << entry.path() << ": " << name;
            EXPECT_EQ(parseScene<double>(line).scene.has_value(), !bad) << entry.path() << ": " << name;
        }
    }
    EXPECT_GE(lines, 5);
}

// writeFileWhole: a new file, a replaced one, and a failure that leaves no temporary file.
TEST(FileWrite, writesWholeReplacesAndLeavesNothingBehindOnFailure) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tilesweep_file_write_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "out.txt").string();
    const auto read = [](const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    std::string error;
    ASSERT_TRUE(tilesweep::writeFileWhole(path, "first\n", error)) << error;
    EXPECT_EQ(read(path), "first\n");
    ASSERT_TRUE(tilesweep::writeFileWhole(path, "second", error)) << error;
    EXPECT_EQ(read(path), "second");
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    const std::string missing = (dir / "no-such-directory" / "out.txt").string();
    EXPECT_FALSE(tilesweep::writeFileWhole(missing, "text", error));
    EXPECT_NE(error.find("no-such-directory"), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists(missing + ".tmp"));
    std::filesystem::remove_all(dir);
}

// percentText: two significant digits in fixed notation, trailing zeros dropped; only 0 and 1
// read "0%" and "100%".
TEST(PercentText, twoSignificantDigitsWithoutTrailingZerosOrExponents) {
    using tilesweep::detail::percentText;
    EXPECT_EQ(percentText(0), "0%");
    EXPECT_EQ(percentText(1), "100%");
    EXPECT_EQ(percentText(0.453), "45%");
    EXPECT_EQ(percentText(0.0453), "4.5%");
    EXPECT_EQ(percentText(0.05), "5%");
    EXPECT_EQ(percentText(0.001), "0.1%");
    EXPECT_EQ(percentText(0.0016), "0.16%");
    EXPECT_EQ(percentText(0.0996), "10%");
    EXPECT_EQ(percentText(0.000034), "0.0034%");
    EXPECT_EQ(percentText(1.0 / 3), "33%");
    EXPECT_EQ(percentText(2.0 / 3), "67%");
    EXPECT_EQ(percentText(1e-7), "0.00001%");
    EXPECT_EQ(percentText(1.2e-8), "0.000001%");
    EXPECT_EQ(percentText(4e-9), "<0.000001%");
    EXPECT_EQ(percentText(0.997), "99.7%");
    EXPECT_EQ(percentText(0.9996), "99.96%");
    EXPECT_EQ(percentText(1 - 1e-10), ">99.999999%");
    EXPECT_EQ(percentText(-0.5), "0%");
    EXPECT_EQ(percentText(std::numeric_limits<double>::quiet_NaN()), "0%");
    EXPECT_EQ(percentText(2), "100%");
}

}  // namespace
