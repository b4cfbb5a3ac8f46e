// SPDX-License-Identifier: MIT
// The scene renderer: the SVG is well-formed XML, draws one rect per solid tile, an arrow per
// contact from the face that was hit, bends the path where the box touched, stays finite and
// translation-invariant at a far origin, and stays compact over many frames. The checks read
// the document the way a viewer would (elements and attributes), not its exact text. The suite
// is named after the function it tests, so that `ctest -R render` selects it.
#include "tilesweep/scene/render.h"

#include "tilesweep/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <optional>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using tilesweep::FrameResult;
using tilesweep::parseScene;
using tilesweep::renderSceneSvg;
using tilesweep::runScene;
using tilesweep::Scene;

// ---- helpers ---------------------------------------------------------------------------

template <class T>
Scene<T> parsed(const std::string& line) {
    tilesweep::SceneParse<T> result = parseScene<T>(line);
    if (!result.scene) throw std::runtime_error("refused: " + result.error + "\n  line: " + line);
    return *std::move(result.scene);
}

/// The picture of a scene line as the production resolver resolves it.
template <class T = float>
std::string render(const std::string& line) {
    const Scene<T> scene = parsed<T>(line);
    return renderSceneSvg(scene, runScene(scene));
}

bool isEntityValid(const std::string& text, std::size_t ampersand) {
    static const std::regex entity("&(amp|lt|gt|quot|apos|#[0-9]+|#x[0-9a-fA-F]+);");
    std::smatch match;
    const std::string rest = text.substr(ampersand, 12);
    return std::regex_search(rest, match, entity, std::regex_constants::match_continuous);
}

/// Character data or an attribute value: no raw '<', every '&' starts an entity, no control
/// characters that XML 1.0 forbids.
std::optional<std::string> checkCharacters(const std::string& text) {
    for (std::size_t k = 0; k < text.size(); ++k) {
        const auto c = static_cast<unsigned char>(text[k]);
        if (c == '<') return "raw '<' in text";
        if (c == '&' && !isEntityValid(text, k)) return "bad entity at '" + text.substr(k, 10) + "'";
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return "control character in text";
    }
    return std::nullopt;
}

/// A minimal XML well-formedness check: one root element (which must be <svg>), balanced and
/// properly nested tags, quoted attributes without duplicates, escaped text, comments skipped.
/// Returns the problem, or nothing.
std::optional<std::string> xmlProblem(const std::string& xml) {
    if (xml.rfind("<svg", 0) != 0) return "does not start with <svg";
    std::vector<std::string> open;
    bool rootClosed = false;
    std::size_t k = 0;
    const auto isNameChar = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' || c == '.';
    };
    const auto skipSpace = [&] {
        while (k < xml.size() && std::isspace(static_cast<unsigned char>(xml[k]))) ++k;
    };
    while (k < xml.size()) {
        const std::size_t lt = xml.find('<', k);
        const std::string text = xml.substr(k, lt == std::string::npos ? std::string::npos : lt - k);
        if (auto problem = checkCharacters(text)) return *problem;
        if ((open.empty()) && text.find_first_not_of(" \t\r\n") != std::string::npos)
            return "text outside the root element";
        if (lt == std::string::npos) break;
        k = lt + 1;
        if (xml.compare(lt, 4, "<!--") == 0) {
            const std::size_t end = xml.find("-->", lt + 4);
            if (end == std::string::npos) return "unterminated comment";
            k = end + 3;
            continue;
        }
        const bool closing = k < xml.size() && xml[k] == '/';
        if (closing) ++k;
        const std::size_t nameStart = k;
        while (k < xml.size() && isNameChar(xml[k])) ++k;
        const std::string name = xml.substr(nameStart, k - nameStart);
        if (name.empty()) return "tag without a name at " + std::to_string(lt);
        if (closing) {
            skipSpace();
            if (k >= xml.size() || xml[k] != '>') return "bad closing tag </" + name;
            ++k;
            if (open.empty() || open.back() != name)
                return "</" + name + "> closes <" + (open.empty() ? std::string("nothing") : open.back()) +
                       ">";
            open.pop_back();
            if (open.empty()) rootClosed = true;
            continue;
        }
        if (rootClosed) return "a second root element <" + name + ">";
        std::set<std::string> attributes;
        for (;;) {
            const std::size_t before = k;
            skipSpace();
            if (k >= xml.size()) return "unterminated tag <" + name;
            if (xml.compare(k, 2, "/>") == 0) {
                k += 2;
                if (open.empty()) rootClosed = true;
                break;
            }
            if (xml[k] == '>') {
                ++k;
                open.push_back(name);
                break;
            }
            if (k == before) return "attributes of <" + name + "> not separated by space";
            const std::size_t attributeStart = k;
            while (k < xml.size() && isNameChar(xml[k])) ++k;
            const std::string attribute = xml.substr(attributeStart, k - attributeStart);
            if (attribute.empty()) return "bad attribute in <" + name + ">";
            if (!attributes.insert(attribute).second) return "duplicate attribute " + attribute;
            if (k >= xml.size() || xml[k] != '=') return "attribute " + attribute + " without '='";
            ++k;
            if (k >= xml.size() || (xml[k] != '"' && xml[k] != '\'')) return "unquoted " + attribute;
            const char quote = xml[k++];
            const std::size_t end = xml.find(quote, k);
            if (end == std::string::npos) return "unterminated value of " + attribute;
            if (auto problem = checkCharacters(xml.substr(k, end - k))) return attribute + ": " + *problem;
            k = end + 1;
        }
    }
    if (!open.empty()) return "<" + open.back() + "> is never closed";
    if (!rootClosed) return "no root element";
    return std::nullopt;
}

::testing::AssertionResult wellFormed(const std::string& svg) {
    if (auto problem = xmlProblem(svg))
        return ::testing::AssertionFailure() << *problem << "\n" << svg.substr(0, 400);
    return ::testing::AssertionSuccess();
}

/// The start tags `<tag ...>` of every element named `tag`.
std::vector<std::string> elements(const std::string& svg, const std::string& tag) {
    std::vector<std::string> found;
    for (std::size_t k = svg.find("<" + tag + " "); k != std::string::npos;
         k = svg.find("<" + tag + " ", k + 1))
        found.push_back(svg.substr(k, svg.find('>', k) - k + 1));
    return found;
}

/// The start tags of elements named `tag` whose class attribute starts with `classPrefix`.
std::vector<std::string> elementsOfClass(const std::string& svg, const std::string& tag,
                                         const std::string& classPrefix) {
    std::vector<std::string> found;
    for (const std::string& element : elements(svg, tag))
        if (element.find(" class=\"" + classPrefix) != std::string::npos) found.push_back(element);
    return found;
}

std::size_t countOf(const std::string& text, const std::string& needle) {
    std::size_t count = 0;
    for (std::size_t k = text.find(needle); k != std::string::npos; k = text.find(needle, k + 1)) ++count;
    return count;
}

std::string attribute(const std::string& element, const std::string& name) {
    const std::size_t k = element.find(" " + name + "=\"");
    if (k == std::string::npos) throw std::runtime_error("no " + name + " in " + element);
    const std::size_t start = k + name.size() + 3;
    return element.substr(start, element.find('"', start) - start);
}

double number(const std::string& element, const std::string& name) {
    return std::stod(attribute(element, name));
}

struct Point {
    double x, y;
};

std::vector<Point> points(const std::string& polyline) {
    std::vector<Point> out;
    static const std::regex pair("(-?[0-9.]+),(-?[0-9.]+)");
    const std::string list = attribute(polyline, "points");
    for (auto it = std::sregex_iterator(list.begin(), list.end(), pair); it != std::sregex_iterator(); ++it)
        out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
    return out;
}

/// Every coordinate-like number of the drawing (x, y, widths, centres, line ends, points).
std::vector<double> allCoordinates(const std::string& svg) {
    std::vector<double> out;
    static const std::regex attribute(R"re( (x|y|x1|y1|x2|y2|cx|cy|r|width|height)="(-?[0-9.eE+]+)")re");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), attribute); it != std::sregex_iterator();
         ++it)
        out.push_back(std::stod((*it)[2]));
    for (const char* tag : {"polyline", "polygon"})
        for (const std::string& element : elements(svg, tag))
            for (const Point& p : points(element)) {
                out.push_back(p.x);
                out.push_back(p.y);
            }
    return out;
}

/// The drawing of a scene, without its text and canvas: the start tags of the shapes that
/// stand for something in the scene (they carry a class), in order.
std::vector<std::string> shapes(const std::string& svg) {
    std::vector<std::string> out;
    static const std::regex shape("<(rect|line|polyline|polygon|circle) [^>]* class=\"[^>]*>");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), shape); it != std::sregex_iterator(); ++it)
        out.push_back(it->str());
    return out;
}

// A box flying at a one-tile wall (the seed picture): it stops against the wall's left face.
const char* const kWallScene =
    R"({"name": "wall", "map": {"origin": [0, 0], "tile": [16, 16],)"
    R"( "rows": ["..........", ".....#....", ".........."]}, "box": [4, 18, 10, 10], "move": [200, 0]})";

// ---- well-formedness and content -------------------------------------------------------

TEST(renderSceneSvg, isWellFormedXmlStartingWithSvg) {
    const std::string svg = render(kWallScene);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_EQ(elements(svg, "svg").size(), 1u);
    EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    // Self-contained: nothing is fetched from elsewhere.
    EXPECT_EQ(svg.find("href"), std::string::npos);
    EXPECT_EQ(svg.find("<image"), std::string::npos);
    EXPECT_EQ(svg.find("<script"), std::string::npos);
}

TEST(renderSceneSvg, theCheckerRefusesBrokenDocuments) {
    // The well-formedness check must be able to fail, or the other tests prove nothing.
    EXPECT_FALSE(wellFormed("<svg><g></svg>"));
    EXPECT_FALSE(wellFormed("<svg><rect x=1/></svg>"));
    EXPECT_FALSE(wellFormed("<svg><text>a < b</text></svg>"));
    EXPECT_FALSE(wellFormed("<svg><text>a & b</text></svg>"));
    EXPECT_FALSE(wellFormed("<svg/><svg/>"));
    EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?><svg/>"));
    EXPECT_TRUE(wellFormed("<svg a=\"1\"><!-- <x> --><g b='&amp;'/></svg>\n"));
}

TEST(renderSceneSvg, drawsOneRectPerSolidTileAtItsCell) {
    const std::string svg =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 8], "rows": ["#..#", "....", ".##."]},)"
               R"( "box": [20, 1, 6, 4], "move": [1, 0]})");
    ASSERT_TRUE(wellFormed(svg));
    const std::vector<std::string> tiles = elementsOfClass(svg, "rect", "tile-solid");
    std::set<std::string> cells;
    for (const std::string& tile : tiles) cells.insert(attribute(tile, "data-cell"));
    EXPECT_EQ(tiles.size(), 4u);
    EXPECT_EQ(cells, (std::set<std::string>{"0,0", "3,0", "1,2", "2,2"}));
    // Tiles are 16 x 8 units: every tile rect has the same 2:1 aspect.
    for (const std::string& tile : tiles)
        EXPECT_NEAR(number(tile, "width"), 2 * number(tile, "height"), 0.02) << tile;
    // Same column, rows 0 and 2: the y of row 2 is two tile heights below row 0.
    const auto at = [&](const std::string& cell) {
        for (const std::string& tile : tiles)
            if (attribute(tile, "data-cell") == cell) return tile;
        return std::string();
    };
    EXPECT_NEAR(number(at("1,2"), "x") - number(at("0,0"), "x"), number(at("0,0"), "width"), 0.02);
    EXPECT_NEAR(number(at("1,2"), "y") - number(at("0,0"), "y"), 2 * number(at("0,0"), "height"), 0.02);
}

TEST(renderSceneSvg, drawsOneWayTilesInTheirOwnStyle) {
    // A platform "--" at row 1 over a solid floor; the box lands on the platform.
    const std::string svg =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 8], "rows": ["....", ".--.", "####"]},)"
               R"( "box": [18, 0, 6, 4], "move": [0, 6]})");
    ASSERT_TRUE(wellFormed(svg));
    const std::vector<std::string> slabs = elementsOfClass(svg, "rect", "tile-one-way");
    const std::vector<std::string> outlines = elementsOfClass(svg, "rect", "one-way-outline");
    const std::vector<std::string> solids = elementsOfClass(svg, "rect", "tile-solid");
    ASSERT_EQ(slabs.size(), 2u);
    ASSERT_EQ(outlines.size(), 2u);
    ASSERT_EQ(solids.size(), 4u);  // the platform is not drawn as solid
    std::set<std::string> slabCells, outlineCells;
    for (const std::string& slab : slabs) slabCells.insert(attribute(slab, "data-cell"));
    for (const std::string& outline : outlines) outlineCells.insert(attribute(outline, "data-cell"));
    EXPECT_EQ(slabCells, (std::set<std::string>{"1,1", "2,1"}));
    EXPECT_EQ(outlineCells, slabCells);
    // Its own colour, and the outline dashed and unfilled.
    EXPECT_NE(attribute(slabs[0], "fill"), attribute(solids[0], "fill"));
    EXPECT_NE(attribute(slabs[0], "fill"), "none");
    EXPECT_EQ(attribute(outlines[0], "fill"), "none");
    EXPECT_FALSE(attribute(outlines[0], "stroke-dasharray").empty());
    EXPECT_EQ(solids[0].find("stroke-dasharray"), std::string::npos);
    // The slab lies along the top face: the cell's x, y and width, a quarter of its height. A
    // solid tile's rect is the whole cell: same width, four times the slab's height.
    for (const std::string& slab : slabs) {
        const std::string cell = attribute(slab, "data-cell");
        const std::string outline =
            *std::find_if(outlines.begin(), outlines.end(),
                          [&](const std::string& o) { return attribute(o, "data-cell") == cell; });
        EXPECT_NEAR(number(slab, "x"), number(outline, "x"), 0.02) << cell;
        EXPECT_NEAR(number(slab, "y"), number(outline, "y"), 0.02) << cell;
        EXPECT_NEAR(number(slab, "width"), number(outline, "width"), 0.02) << cell;
        EXPECT_NEAR(number(outline, "width"), number(solids[0], "width"), 0.02) << cell;
        EXPECT_NEAR(number(outline, "height"), number(solids[0], "height"), 0.02) << cell;
        EXPECT_NEAR(4 * number(slab, "height"), number(solids[0], "height"), 0.05) << cell;
    }
    // The platform's row is one tile height above the floor's.
    EXPECT_NEAR(number(solids[0], "y") - number(slabs[0], "y"), number(solids[0], "height"), 0.02);
    // The legend names it, and only for a map that has one.
    EXPECT_NE(svg.find("one-way tile"), std::string::npos);
    const std::string plain =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 8], "rows": ["....", "####"]},)"
               R"( "box": [18, 0, 6, 4], "move": [0, 6]})");
    EXPECT_EQ(plain.find("one-way tile"), std::string::npos);
    EXPECT_TRUE(elementsOfClass(plain, "rect", "tile-one-way").empty());
    EXPECT_TRUE(elementsOfClass(plain, "rect", "one-way-outline").empty());
}

TEST(renderSceneSvg, refusesAOneWayLayerThatDoesNotMatchTheMap) {
    Scene<float> scene = parsed<float>(kWallScene);
    const std::vector<FrameResult<float>> frames = runScene(scene);
    scene.map.oneWay.assign(scene.map.solid.size() - 1, 1);
    EXPECT_THROW((void)renderSceneSvg(scene, frames), std::invalid_argument);
    scene.map.oneWay.assign(scene.map.solid.size(), 0);
    EXPECT_NO_THROW((void)renderSceneSvg(scene, frames));
}

TEST(renderSceneSvg, showsTheSceneNameAsTitleEscaped) {
    const std::string svg =
        render(R"({"name": "a < b & \"c\" \u0001 d", "map": {"origin": [0, 0], "tile": [16, 16],)"
               R"( "rows": [".."]}, "box": [0, 0, 4, 4], "move": [1, 1]})");
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_NE(svg.find("<title>a &lt; b &amp; &quot;c&quot;   d</title>"), std::string::npos);
    // The visible title says the same.
    EXPECT_NE(svg.find("class=\"title\">a &lt; b &amp; &quot;c&quot;   d</text>"), std::string::npos);
}

TEST(renderSceneSvg, captionStatesTileSizeAndOrigin) {
    const std::string svg = render(
        R"({"map": {"origin": [-8, 4.5], "tile": [16, 32], "rows": ["#"]}, "box": [20, 0, 4, 4], "move": [1, 1]})");
    EXPECT_NE(svg.find("tile 16 \u00D7 32, origin (-8, 4.5)"), std::string::npos);
}

// ---- contacts ----------------------------------------------------------------------------

TEST(renderSceneSvg, aContactDrawsAnArrowLeavingTheFaceThatWasHit) {
    const std::string svg = render(kWallScene);
    ASSERT_TRUE(wellFormed(svg));
    const std::vector<std::string> arrows = elementsOfClass(svg, "g", "normal-arrow");
    ASSERT_EQ(arrows.size(), 1u);
    EXPECT_EQ(attribute(arrows[0], "data-tile"), "5,1");
    EXPECT_EQ(attribute(arrows[0], "data-normal"), "-1,0");

    // The arrow's shaft is the first line after its group: it starts on the tile's left face
    // and points left (-x), level.
    const std::size_t group = svg.find("class=\"normal-arrow\"");
    const std::string shaft = elements(svg.substr(group), "line").front();
    const std::string tile = elementsOfClass(svg, "rect", "tile-solid").front();
    EXPECT_NEAR(number(shaft, "x1"), number(tile, "x"), 0.02);
    EXPECT_LT(number(shaft, "x2"), number(shaft, "x1") - 5);
    EXPECT_DOUBLE_EQ(number(shaft, "y2"), number(shaft, "y1"));
    // The shaft starts within the face's vertical extent.
    EXPECT_GT(number(shaft, "y1"), number(tile, "y"));
    EXPECT_LT(number(shaft, "y1"), number(tile, "y") + number(tile, "height"));

    const std::vector<std::string> hits = elementsOfClass(svg, "rect", "hit-tile");
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(attribute(hits[0], "data-cell"), "5,1");
}

TEST(renderSceneSvg, noContactDrawsNoArrowAndNoHitTile) {
    const std::string svg = render(
        R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["....", ".#.."]}, "box": [0, 0, 8, 8], "move": [20, 0]})");
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_TRUE(elementsOfClass(svg, "g", "normal-arrow").empty());
    EXPECT_TRUE(elementsOfClass(svg, "rect", "hit-tile").empty());
    EXPECT_EQ(elementsOfClass(svg, "rect", "tile-solid").size(), 1u);
}

TEST(renderSceneSvg, pathBendsWhereTheBoxTouched) {
    // Diagonal into a corner: the floor of row 2 at t = 0.6 (box at (50, 22)), then the wall
    // of column 4 at t = 0.68 (box at (54, 22)), where the frame ends.
    const std::string svg =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["....#", "....#", "#####"]},)"
               R"( "box": [20, 4, 10, 10], "move": [50, 30]})");
    ASSERT_TRUE(wellFormed(svg));
    const std::vector<std::string> paths = elementsOfClass(svg, "polyline", "path");
    ASSERT_EQ(paths.size(), 1u);
    const std::vector<Point> p = points(paths[0]);
    ASSERT_EQ(p.size(), 4u);  // start, floor contact, wall contact, end
    // Centres: (25, 9) -> (55, 27) -> (59, 27) -> (59, 27), one scale on both axes.
    const double scale = (p[1].y - p[0].y) / 18;
    EXPECT_GT(scale, 0);
    EXPECT_NEAR(p[1].x - p[0].x, 30 * scale, 0.02);
    EXPECT_NEAR(p[2].x - p[1].x, 4 * scale, 0.02);
    EXPECT_DOUBLE_EQ(p[2].y, p[1].y);  // sliding on the floor keeps y
    EXPECT_DOUBLE_EQ(p[3].x, p[2].x);
    EXPECT_DOUBLE_EQ(p[3].y, p[2].y);

    std::set<std::string> arrows;
    for (const std::string& arrow : elementsOfClass(svg, "g", "normal-arrow"))
        arrows.insert(attribute(arrow, "data-tile") + " " + attribute(arrow, "data-normal"));
    EXPECT_EQ(arrows, (std::set<std::string>{"3,2 0,-1", "4,1 -1,0"}));
}

TEST(renderSceneSvg, hatchesTheCellsTheBoxStartedOverlapping) {
    const std::string svg =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["....", ".#..", "...."]},)"
               R"( "box": [20, 20, 8, 8], "move": [-20, 0]})");
    ASSERT_TRUE(wellFormed(svg));
    const std::vector<std::string> overlaps = elementsOfClass(svg, "rect", "overlap-tile");
    ASSERT_EQ(overlaps.size(), 1u);
    EXPECT_EQ(attribute(overlaps[0], "data-cell"), "1,1");
    EXPECT_EQ(attribute(overlaps[0], "fill"), "url(#tilesweep-hatch)");
    EXPECT_NE(svg.find("<pattern id=\"tilesweep-hatch\""), std::string::npos);
}

// ---- scale and translation ---------------------------------------------------------------

std::vector<double> viewBox(const std::string& svg) {
    std::vector<double> values;
    std::size_t k = 0;
    const std::string text = attribute(elements(svg, "svg").front(), "viewBox");
    while (k < text.size()) {
        std::size_t used = 0;
        values.push_back(std::stod(text.substr(k), &used));
        k += used;
    }
    return values;
}

::testing::AssertionResult everythingInsideTheViewBox(const std::string& svg) {
    const std::vector<double> box = viewBox(svg);
    if (box.size() != 4) return ::testing::AssertionFailure() << "viewBox has " << box.size() << " numbers";
    for (const double v : box)
        if (!std::isfinite(v)) return ::testing::AssertionFailure() << "viewBox not finite";
    if (!(box[2] > 0 && box[3] > 0 && box[2] < 1e4 && box[3] < 1e4))
        return ::testing::AssertionFailure() << "viewBox size " << box[2] << " x " << box[3];
    const double limit = std::max(box[2], box[3]);
    for (const double v : allCoordinates(svg))
        if (!std::isfinite(v) || v < -1 || v > limit + 1)
            return ::testing::AssertionFailure() << "coordinate " << v << " outside the view";
    return ::testing::AssertionSuccess();
}

TEST(renderSceneSvg, farOriginGivesFiniteViewBoxAndTheSameDrawing) {
    const std::string near =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["......", "......", "######"]},)"
               R"( "box": [3.25, 4.5, 10, 10], "move": [7.75, 30]})");
    const std::string far = render(
        R"({"map": {"origin": [1000000, 2000000], "tile": [16, 16], "rows": ["......", "......", "######"]},)"
        R"( "box": [1000003.25, 2000004.5, 10, 10], "move": [7.75, 30]})");
    EXPECT_TRUE(wellFormed(far));
    EXPECT_TRUE(everythingInsideTheViewBox(far));
    // Only the text may differ: the picture is drawn relative to the map origin.
    EXPECT_GT(shapes(near).size(), 10u);
    EXPECT_EQ(shapes(far), shapes(near));
    EXPECT_NE(far.find("origin (1000000, 2000000)"), std::string::npos);
    // Positions near the far origin keep their fraction in the listing.
    EXPECT_NE(far.find("(1000003.25, 2000004.5)"), std::string::npos);
}

TEST(renderSceneSvg, originAtTwoToTheFortyInDoubleRendersLikeTheOrigin) {
    const std::string near =
        render<double>(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["....", "..#.", "####"]},)"
                       R"( "box": [1.5, 2, 10, 10], "moves": [[40, 0], [3, 30]]})");
    const std::string far = render<double>(
        R"({"map": {"origin": [1099511627776, -1099511627776], "tile": [16, 16], "rows": ["....", "..#.", "####"]},)"
        R"( "box": [1099511627777.5, -1099511627774, 10, 10], "moves": [[40, 0], [3, 30]]})");
    EXPECT_TRUE(wellFormed(far));
    EXPECT_TRUE(everythingInsideTheViewBox(far));
    EXPECT_EQ(shapes(far), shapes(near));
    EXPECT_NE(far.find("1099511627776"), std::string::npos);
}

TEST(renderSceneSvg, motionFarBeyondTheMapIsInView) {
    // The view holds the map and the whole motion, however far the box goes.
    const std::string svg = render(
        R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["##"]}, "box": [0, -20, 4, 4], "move": [5000, -3000]})");
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_TRUE(everythingInsideTheViewBox(svg));
    EXPECT_EQ(elementsOfClass(svg, "rect", "tile-solid").size(), 2u);
}

// ---- degenerate and large scenes -----------------------------------------------------------

TEST(renderSceneSvg, emptyMapRenders) {
    const std::string svg = render(
        R"({"name": "nothing here", "map": {"origin": [5, 5], "tile": [16, 16], "rows": []}, "box": [0, 0, 4, 4], "move": [10, 3]})");
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_TRUE(everythingInsideTheViewBox(svg));
    EXPECT_TRUE(elementsOfClass(svg, "rect", "tile-solid").empty());
    EXPECT_EQ(elementsOfClass(svg, "rect", "box-start").size(), 1u);
    EXPECT_EQ(elementsOfClass(svg, "rect", "frame-end").size(), 1u);
    EXPECT_NE(svg.find("empty map"), std::string::npos);
    EXPECT_NE(svg.find("<title>nothing here</title>"), std::string::npos);
}

TEST(renderSceneSvg, hundredFramesStayCompact) {
    std::string moves;
    for (int k = 0; k < 100; ++k) moves += std::string(k == 0 ? "" : ", ") + "[1.5, 2]";
    const Scene<float> scene = parsed<float>(
        R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": [".............", "#############"]},)"
        R"( "box": [0, 0, 8, 8], "moves": [)" +
        moves + "]}");
    const std::vector<FrameResult<float>> frames = runScene(scene);
    const std::string svg = renderSceneSvg(scene, frames);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_TRUE(everythingInsideTheViewBox(svg));
    // Every frame end is marked, but only the first and the last as boxes, and labelled.
    EXPECT_EQ(countOf(svg, "class=\"frame-end"), 100u);
    EXPECT_EQ(countOf(svg, "class=\"frame-end box"), 2u);
    EXPECT_NE(svg.find(">end 1</text>"), std::string::npos);
    EXPECT_NE(svg.find(">end 100</text>"), std::string::npos);
    EXPECT_EQ(svg.find(">end 2</text>"), std::string::npos);
    EXPECT_EQ(elementsOfClass(svg, "polyline", "path").size(), 100u);
    // The listing is cut short, the picture is not.
    EXPECT_NE(svg.find("more frames"), std::string::npos);
    EXPECT_LT(svg.size(), 200000u);
}

TEST(renderSceneSvg, fewFramesAreEachDrawnAsABox) {
    const std::string svg =
        render(R"({"map": {"origin": [0, 0], "tile": [16, 16], "rows": ["....", "....", "####"]},)"
               R"( "box": [4, 20, 12, 12], "moves": [[12, 20], [12, 4], [12, 4]]})");
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_EQ(countOf(svg, "class=\"frame-end box"), 3u);
    EXPECT_EQ(countOf(svg, "class=\"frame-end box last"), 1u);
    EXPECT_NE(svg.find(">end 3</text>"), std::string::npos);
}

TEST(renderSceneSvg, refusesFramesThatDoNotMatchTheMoves) {
    const Scene<float> scene = parsed<float>(kWallScene);
    EXPECT_THROW((void)renderSceneSvg(scene, std::vector<FrameResult<float>>{}), std::invalid_argument);
    Scene<float> broken = scene;
    broken.map.solid.pop_back();
    EXPECT_THROW((void)renderSceneSvg(broken, runScene(scene)), std::invalid_argument);
}

TEST(renderSceneSvg, aForeignResolversNonFinitePositionIsListedNotDrawn) {
    const Scene<double> scene = parsed<double>(kWallScene);
    std::vector<FrameResult<double>> frames = runScene(scene);
    frames[0].position.x = std::nan("");
    const std::string svg = renderSceneSvg(scene, frames);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_TRUE(everythingInsideTheViewBox(svg));
    EXPECT_EQ(svg.find("nan\""), std::string::npos);  // no NaN in an attribute
    EXPECT_NE(svg.find("-&gt; (nan, 18)"), std::string::npos);
}

}  // namespace
