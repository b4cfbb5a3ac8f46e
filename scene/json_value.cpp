// SPDX-License-Identifier: MIT
#include "json_value.h"

#include "tilesweep/scene/scalar_text.h"

#include <nlohmann/json.hpp>

#include <utility>

namespace tilesweep::detail {
namespace {

using Json = nlohmann::json;

[[nodiscard]] bool isNumberChar(char c) noexcept {
    return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
}

// -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?, the JSON number grammar (RFC 8259, 6).
[[nodiscard]] bool isJsonNumber(std::string_view text) noexcept {
    std::size_t k = 0;
    const auto digits = [&] {
        const std::size_t start = k;
        while (k < text.size() && text[k] >= '0' && text[k] <= '9') ++k;
        return k - start;
    };
    if (k < text.size() && text[k] == '-') ++k;
    if (k < text.size() && text[k] == '0')
        ++k;
    else if (digits() == 0)
        return false;
    if (k < text.size() && text[k] == '.') {
        ++k;
        if (digits() == 0) return false;
    }
    if (k < text.size() && (text[k] == 'e' || text[k] == 'E')) {
        ++k;
        if (k < text.size() && (text[k] == '+' || text[k] == '-')) ++k;
        if (digits() == 0) return false;
    }
    return k == text.size();
}

// The text of every number of a JSON document, in document order. nlohmann's SAX interface
// hands over a number's text only when it has a fraction or an exponent; an integer arrives as
// its value, which loses "-0". So the tree takes every number's text from here.
//
// nlohmann also refuses a number that overflows double ("1e400") as a syntax error, before the
// reader could say which field holds it. Such a number is overwritten in `patched` (a copy of
// the text) by "0" and spaces: the same length, so that the positions in nlohmann's messages
// still match the line; the tree still gets the original text, and the reader reports it.
//
// Scanning is easy because it only has to be right for valid JSON: outside strings, a number
// is the only token that starts with '-' or a digit, and it runs to the first character that
// cannot be part of one. A run that is not a valid number is left for nlohmann to refuse.
[[nodiscard]] std::vector<std::string_view> scanNumbers(std::string_view text, std::string& patched) {
    std::vector<std::string_view> lexemes;
    std::size_t k = 0;
    while (k < text.size()) {
        const char c = text[k];
        if (c == '"') {
            for (++k; k < text.size() && text[k] != '"'; ++k)
                if (text[k] == '\\') ++k;  // an escaped character, '"' included, is skipped
            ++k;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            const std::size_t start = k;
            while (k < text.size() && isNumberChar(text[k])) ++k;
            const std::string_view run = text.substr(start, k - start);
            if (!isJsonNumber(run)) continue;
            lexemes.push_back(run);
            if (readDecimalScalar<double>(run).status == ScalarTextStatus::Overflow)
                patched.replace(start, run.size(), "0" + std::string(run.size() - 1, ' '));
        } else {
            ++k;
        }
    }
    return lexemes;
}

// "[json.exception.parse_error.101] parse error at ..." without the bracketed tag.
[[nodiscard]] std::string withoutExceptionTag(const char* what) {
    std::string message = what;
    if (!message.empty() && message.front() == '[') {
        const std::size_t close = message.find("] ");
        if (close != std::string::npos) message.erase(0, close + 2);
    }
    return message;
}

// A nlohmann SAX handler that builds a JsonValue tree. Containers under construction live on
// a stack by value and are moved into their parent when they close, so no pointer into a
// growing vector is ever held.
class TreeBuilder {
public:
    using number_integer_t = Json::number_integer_t;
    using number_unsigned_t = Json::number_unsigned_t;
    using number_float_t = Json::number_float_t;
    using string_t = Json::string_t;
    using binary_t = Json::binary_t;

    explicit TreeBuilder(const std::vector<std::string_view>& lexemes) : lexemes_(lexemes) {}

    bool null() { return add(JsonValue{}); }
    bool boolean(bool value) {
        JsonValue leaf;
        leaf.kind = JsonValue::Kind::Boolean;
        leaf.boolean = value;
        return add(std::move(leaf));
    }
    bool number_integer(number_integer_t /*value*/) { return addNumber(); }
    bool number_unsigned(number_unsigned_t /*value*/) { return addNumber(); }
    bool number_float(number_float_t /*value*/, const string_t& /*text*/) { return addNumber(); }
    bool string(string_t& value) {
        JsonValue leaf;
        leaf.kind = JsonValue::Kind::String;
        leaf.text = std::move(value);
        return add(std::move(leaf));
    }
    bool binary(binary_t& /*value*/) {
        error_ = "binary value in JSON text";  // only the binary formats produce these
        return false;
    }
    bool start_object(std::size_t /*size*/) { return open(JsonValue::Kind::Object); }
    bool key(string_t& name) {
        open_.back().keys.push_back(std::move(name));
        return true;
    }
    bool end_object() { return close(); }
    bool start_array(std::size_t /*size*/) { return open(JsonValue::Kind::Array); }
    bool end_array() { return close(); }
    bool parse_error(std::size_t /*position*/, const std::string& /*lastToken*/,
                     const nlohmann::detail::exception& error) {
        error_ = withoutExceptionTag(error.what());
        return false;
    }

    [[nodiscard]] std::optional<JsonValue>& root() { return root_; }
    [[nodiscard]] const std::string& error() const { return error_; }

private:
    bool add(JsonValue value) {
        if (open_.empty())
            root_ = std::move(value);
        else
            open_.back().items.push_back(std::move(value));
        return true;
    }

    bool addNumber() {
        if (nextLexeme_ >= lexemes_.size()) {
            error_ = "internal error: number text out of step with the parser";
            return false;
        }
        JsonValue leaf;
        leaf.kind = JsonValue::Kind::Number;
        leaf.text = std::string(lexemes_[nextLexeme_++]);
        return add(std::move(leaf));
    }

    bool open(JsonValue::Kind kind) {
        if (open_.size() >= kMaxJsonDepth) {
            error_ = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
            return false;
        }
        open_.emplace_back();
        open_.back().kind = kind;
        return true;
    }

    bool close() {
        JsonValue done = std::move(open_.back());
        open_.pop_back();
        return add(std::move(done));
    }

    const std::vector<std::string_view>& lexemes_;
    std::size_t nextLexeme_ = 0;
    std::vector<JsonValue> open_;
    std::optional<JsonValue> root_;
    std::string error_;
};

}  // namespace

JsonParse parseJson(std::string_view text) {
    std::string patched(text);
    const std::vector<std::string_view> lexemes = scanNumbers(text, patched);
    TreeBuilder builder(lexemes);
    bool ok = false;
    try {
        ok = Json::sax_parse(patched.begin(), patched.end(), &builder);
    } catch (const Json::exception& error) {
        return {std::nullopt, withoutExceptionTag(error.what())};
    }
    if (!ok || !builder.root()) {
        return {std::nullopt, builder.error().empty() ? "not a JSON value" : builder.error()};
    }
    return {std::move(builder.root()), {}};
}

const char* describe(JsonValue::Kind kind) noexcept {
    switch (kind) {
        case JsonValue::Kind::Null:
            return "null";
        case JsonValue::Kind::Boolean:
            return "a boolean";
        case JsonValue::Kind::Number:
            return "a number";
        case JsonValue::Kind::String:
            return "a string";
        case JsonValue::Kind::Array:
            return "an array";
        case JsonValue::Kind::Object:
            return "an object";
    }
    return "an unknown value";
}

}  // namespace tilesweep::detail
