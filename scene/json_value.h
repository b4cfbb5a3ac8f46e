// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// A JSON document tree that keeps every number as the text it was written with, internal to
// tilesweep_scene. nlohmann::json stores a number as a double (or an integer), and rounding
// that double to float would round twice; the scene reader needs the text to round once.

namespace tilesweep::detail {

/// One JSON value. Numbers and strings keep their text; objects keep their keys in document
/// order, duplicates included, so that the reader can refuse an ambiguous field.
struct JsonValue {
    enum class Kind : std::uint8_t { Null, Boolean, Number, String, Array, Object };

    Kind kind = Kind::Null;
    bool boolean = false;           ///< the value of a Boolean
    std::string text;               ///< a Number's lexeme as written, or a String's contents
    std::vector<std::string> keys;  ///< an Object's keys, in document order
    std::vector<JsonValue> items;   ///< an Array's elements, or an Object's values (one per key)
};

/// The deepest nesting accepted: scenes need 3 levels, and a bound keeps a hostile line
/// ("[[[[...") from exhausting the stack when the tree is destroyed.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// A parsed document, or a message saying why the text is not one JSON value.
struct JsonParse {
    std::optional<JsonValue> value;
    std::string error;  ///< empty when `value` is set
};

/// Parses one complete JSON text (RFC 8259, no comments, nothing after the value).
/// May throw std::bad_alloc; reports every other problem in `error`.
[[nodiscard]] JsonParse parseJson(std::string_view text);

/// A short English name of a kind ("number", "array", ...), for messages.
[[nodiscard]] const char* describe(JsonValue::Kind kind) noexcept;

}  // namespace tilesweep::detail
