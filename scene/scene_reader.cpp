// SPDX-License-Identifier: MIT
// Reading one scene line (docs/contract.md, "Scene files") into a Scene<T>.
#include "json_value.h"

#include "tilesweep/scene/scalar_text.h"
#include "tilesweep/scene/scene.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace tilesweep {
namespace {

using detail::JsonValue;
using Kind = JsonValue::Kind;

// A problem with one field of the scene. Thrown by the readers below and turned into the error
// of the SceneParse by parseScene, which is the only place that catches; the message starts
// with the field's path ("box[2]: ...", "map.rows[1]: ...").
class FieldError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& field, const std::string& problem) {
    throw FieldError(field + ": " + problem);
}

[[nodiscard]] std::string indexed(const std::string& field, std::size_t k) {
    return field + "[" + std::to_string(k) + "]";
}

// A value from the input, quoted for a message and cut short so that one long line cannot
// make a long error.
[[nodiscard]] std::string quoted(std::string_view text) {
    constexpr std::size_t kMaxQuoted = 40;
    if (text.size() <= kMaxQuoted) return "'" + std::string(text) + "'";
    return "'" + std::string(text.substr(0, kMaxQuoted)) + "...'";
}

[[nodiscard]] bool isBlank(std::string_view line) noexcept {
    return line.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos;
}

// The member `key` of an object, or nullptr when it is absent. A key given twice is an error:
// which of the two values was meant would be a guess.
[[nodiscard]] const JsonValue* findMember(const JsonValue& object, std::string_view key,
                                          const std::string& field) {
    const JsonValue* found = nullptr;
    for (std::size_t k = 0; k < object.keys.size(); ++k) {
        if (object.keys[k] != key) continue;
        if (found != nullptr) fail(field, "given twice");
        found = &object.items[k];
    }
    return found;
}

[[nodiscard]] const JsonValue& requireMember(const JsonValue& object, std::string_view key,
                                             const std::string& field) {
    const JsonValue* member = findMember(object, key, field);
    if (member == nullptr) fail(field, "missing field");
    return *member;
}

// A JSON number, or a string holding a hexfloat, rounded once to T.
template <class T>
[[nodiscard]] T readScalar(const JsonValue& value, const std::string& field) {
    detail::ScalarText<T> read;
    if (value.kind == Kind::Number) {
        read = detail::readDecimalScalar<T>(value.text);
    } else if (value.kind == Kind::String) {
        read = detail::readHexfloatScalar<T>(value.text);
    } else {
        fail(field,
             std::string("expected a number or a hexfloat string, got ") + detail::describe(value.kind));
    }
    switch (read.status) {
        case detail::ScalarTextStatus::Ok:
            return read.value;
        case detail::ScalarTextStatus::NonFinite:
            fail(field, "non-finite value " + quoted(value.text));
        case detail::ScalarTextStatus::Overflow:
            fail(field,
                 "non-finite value " + quoted(value.text) + " (overflows " + detail::scalarName<T>() + ")");
        case detail::ScalarTextStatus::Malformed:
            break;
    }
    fail(field, "expected a number or a hexfloat string like \"0x1.8p+3\", got " + quoted(value.text));
}

// An array of exactly N scalars.
template <class T, std::size_t N>
[[nodiscard]] std::array<T, N> readScalars(const JsonValue& value, const std::string& field) {
    const std::string expected = "expected an array of " + std::to_string(N) + " numbers, got ";
    if (value.kind != Kind::Array) fail(field, expected + detail::describe(value.kind));
    if (value.items.size() != N)
        fail(field, expected + std::to_string(value.items.size()) +
                        (value.items.size() == 1 ? " element" : " elements"));
    std::array<T, N> scalars{};
    for (std::size_t k = 0; k < N; ++k) scalars[k] = readScalar<T>(value.items[k], indexed(field, k));
    return scalars;
}

template <class T>
[[nodiscard]] Vec2<T> readVec2(const JsonValue& value, const std::string& field) {
    const auto xy = readScalars<T, 2>(value, field);
    return {xy[0], xy[1]};
}

// "x" for a printable ASCII character, "byte 0xC3" for anything else (a piece of a UTF-8
// sequence printed alone would not be text).
[[nodiscard]] std::string describeTileCharacter(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) return "'" + std::string(1, c) + "'";
    constexpr char kHex[] = "0123456789ABCDEF";
    return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 0xf];
}

// "map.rows": equal-length strings of '#' (solid), '-' (one-way) and '.' (empty), the top row
// first. map.oneWay is filled only when some cell is '-'.
// No rows, or rows of length zero, make an empty map: every cell is empty, and its size is
// stored as 0 x 0 so that no edge of a tile that does not exist has to be representable.
template <class T>
void readRows(const JsonValue& rows, TileMap<T>& map) {
    const std::string field = "map.rows";
    if (rows.kind != Kind::Array)
        fail(field, std::string("expected an array of strings, got ") + detail::describe(rows.kind));
    for (std::size_t j = 0; j < rows.items.size(); ++j) {
        const JsonValue& row = rows.items[j];
        if (row.kind != Kind::String)
            fail(indexed(field, j),
                 std::string("expected a string of '#', '-' and '.', got ") + detail::describe(row.kind));
        if (row.text.size() != rows.items.front().text.size())
            fail(field, "ragged rows (row " + std::to_string(j) + " has length " +
                            std::to_string(row.text.size()) + ", row 0 has " +
                            std::to_string(rows.items.front().text.size()) + ")");
    }
    if (rows.items.empty() || rows.items.front().text.empty()) return;  // empty map, 0 x 0

    const std::size_t columns = rows.items.front().text.size();
    const std::size_t rowCount = rows.items.size();
    const auto limit = static_cast<std::size_t>(kMaxCells);
    if (columns > limit || rowCount > limit || columns * rowCount > limit)
        fail(field, std::to_string(columns) + " columns x " + std::to_string(rowCount) +
                        " rows exceed the limit of " + std::to_string(kMaxCells) + " cells");

    map.columns = static_cast<std::int32_t>(columns);
    map.rows = static_cast<std::int32_t>(rowCount);
    map.solid.reserve(columns * rowCount);
    bool anyOneWay = false;
    for (std::size_t j = 0; j < rowCount; ++j) {
        const std::string& row = rows.items[j].text;
        for (std::size_t i = 0; i < columns; ++i) {
            if (row[i] != '#' && row[i] != '.' && row[i] != '-')
                fail(indexed(field, j), "unknown tile character " + describeTileCharacter(row[i]) +
                                            " at column " + std::to_string(i) +
                                            " (expected '#', '-' or '.')");
            map.solid.push_back(row[i] == '#' ? 1 : 0);
            anyOneWay = anyOneWay || row[i] == '-';
        }
    }
    if (!anyOneWay) return;
    map.oneWay.reserve(columns * rowCount);
    for (std::size_t j = 0; j < rowCount; ++j)
        for (const char c : rows.items[j].text) map.oneWay.push_back(c == '-' ? 1 : 0);
}

// Refuses a map unless the core resolver accepts it: in particular every tile edge must be a T,
// so that a contact can end exactly on the face it touches.
template <class T>
void checkMap(const TileMap<T>& map) {
    std::int64_t badEdge = 0;
    const MapError error = validateTileMap(map.view(), &badEdge);
    switch (error) {
        case MapError::None:
            return;
        case MapError::UnrepresentableEdgeX:
        case MapError::UnrepresentableEdgeY: {
            const bool x = error == MapError::UnrepresentableEdgeX;
            fail("map.tile", std::string("tile edge ") + (x ? "x = origin[0] + " : "y = origin[1] + ") +
                                 std::to_string(badEdge) + (x ? "*tile[0]" : "*tile[1]") +
                                 " is not representable in " + detail::scalarName<T>());
        }
        case MapError::TooLarge:
            fail("map.rows", describe(error));
        default:
            fail("map", describe(error));
    }
}

template <class T>
[[nodiscard]] TileMap<T> readMap(const JsonValue& scene) {
    const JsonValue& value = requireMember(scene, "map", "map");
    if (value.kind != Kind::Object)
        fail("map", std::string("expected an object with \"origin\", \"tile\" and \"rows\", got ") +
                        detail::describe(value.kind));
    TileMap<T> map;
    map.origin = readVec2<T>(requireMember(value, "origin", "map.origin"), "map.origin");
    map.tileSize = readVec2<T>(requireMember(value, "tile", "map.tile"), "map.tile");
    if (!(map.tileSize.x > 0 && map.tileSize.y > 0)) fail("map.tile", "tile width and height must be > 0");
    readRows(requireMember(value, "rows", "map.rows"), map);
    checkMap(map);
    return map;
}

template <class T>
[[nodiscard]] Box<T> readBox(const JsonValue& scene) {
    const auto xywh = readScalars<T, 4>(requireMember(scene, "box", "box"), "box");
    if (!(xywh[2] > 0 && xywh[3] > 0)) fail("box", "width and height must be > 0");
    return {{xywh[0], xywh[1]}, {xywh[2], xywh[3]}};
}

// "move": [dx, dy] is one frame; "moves": [[dx, dy], ...] (non-empty) is several.
template <class T>
[[nodiscard]] std::vector<Vec2<T>> readMoves(const JsonValue& scene) {
    const JsonValue* move = findMember(scene, "move", "move");
    const JsonValue* moves = findMember(scene, "moves", "moves");
    if (move != nullptr && moves != nullptr) fail("moves", "give either \"move\" or \"moves\", not both");
    if (move != nullptr) return {readVec2<T>(*move, "move")};
    if (moves == nullptr)
        fail("move", "missing field (give \"move\": [dx, dy] or \"moves\": [[dx, dy], ...])");
    if (moves->kind != Kind::Array)
        fail("moves",
             std::string("expected an array of [dx, dy] pairs, got ") + detail::describe(moves->kind));
    if (moves->items.empty()) fail("moves", "must not be empty");
    std::vector<Vec2<T>> displacements;
    displacements.reserve(moves->items.size());
    for (std::size_t k = 0; k < moves->items.size(); ++k)
        displacements.push_back(readVec2<T>(moves->items[k], indexed("moves", k)));
    return displacements;
}

// A backstop: the checks above mirror the resolver's own validity rules, and this makes sure
// that a scene the reader accepts is never refused by resolveMove at its first step.
template <class T>
void checkResolvable(const Scene<T>& scene) {
    for (std::size_t k = 0; k < scene.moves.size(); ++k) {
        if (!isValid(ResolveInput<T>{scene.map.view(), scene.box, scene.moves[k]}))
            fail("scene",
                 "the resolver refuses the input of frame " + std::to_string(k) + " (tilesweep::isValid)");
    }
}

template <class T>
[[nodiscard]] Scene<T> readScene(std::string_view line) {
    if (isBlank(line)) fail("scene", "blank line, expected a JSON object");
    detail::JsonParse json = detail::parseJson(line);
    if (!json.value) fail("scene", "malformed JSON: " + json.error);
    const JsonValue& root = *json.value;
    if (root.kind != Kind::Object)
        fail("scene", std::string("expected a JSON object, got ") + detail::describe(root.kind));

    Scene<T> scene;
    const JsonValue* name = findMember(root, "name", "name");
    if (name != nullptr && name->kind == Kind::String) scene.name = name->text;
    scene.map = readMap<T>(root);
    scene.box = readBox<T>(root);
    scene.moves = readMoves<T>(root);
    checkResolvable(scene);
    return scene;
}

}  // namespace

template <class T>
SceneParse<T> parseScene(std::string_view line) {
    SceneParse<T> result;
    try {
        try {
            result.scene = readScene<T>(line);
        } catch (const FieldError& error) {
            result.error = error.what();
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::exception& error) {
            result.error = std::string("scene: ") + error.what();
        } catch (...) {
            result.error = "scene: unexpected error";
        }
    } catch (...) {
        // Out of memory, perhaps while writing a message above. This one fits in the string's
        // own small-string storage, so assigning it cannot allocate, and parseScene never throws.
        result.scene.reset();
        result.error = "out of memory";
    }
    return result;
}

template SceneParse<float> parseScene<float>(std::string_view);
template SceneParse<double> parseScene<double>(std::string_view);

}  // namespace tilesweep
