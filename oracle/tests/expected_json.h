// SPDX-License-Identifier: MIT
#pragma once

#include <cctype>
#include <cstddef>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

// A small JSON reader for the expected-output files, written for the tests. It keeps every number
// as its source text, so that the test can read it straight into float or double (strtof /
// strtod round once, correctly): going through a double first would round twice for float.

namespace tilesweep::oracle::test {

/// A parsed JSON value; numbers keep their text.
struct JsonValue {
    enum class Kind { Null, Bool, Number, String, Array, Object };
    Kind kind = Kind::Null;
    bool boolean = false;
    std::string text;  ///< a number's source text, or a string's (unescaped) contents
    std::vector<JsonValue> items;
    std::map<std::string, JsonValue> members;

    /// The member named `key`; throws when absent or when this is not an object.
    const JsonValue& at(const std::string& key) const {
        const auto it = members.find(key);
        if (kind != Kind::Object || it == members.end()) {
            throw std::runtime_error("json: no member '" + key + "'");
        }
        return it->second;
    }
    /// True when this is an object with a member `key`.
    bool has(const std::string& key) const { return kind == Kind::Object && members.count(key) != 0; }
};

class JsonReader {
public:
    explicit JsonReader(std::string_view text) : text_(text) {}

    /// Parses the whole text as one value; throws std::runtime_error on malformed input.
    JsonValue parseDocument() {
        JsonValue value = parseValue();
        skipSpace();
        if (pos_ != text_.size()) {
            fail("trailing characters");
        }
        return value;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("json: " + what + " at offset " + std::to_string(pos_));
    }

    void skipSpace() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) {
            ++pos_;
        }
    }

    char peek() {
        skipSpace();
        if (pos_ >= text_.size()) {
            fail("unexpected end");
        }
        return text_[pos_];
    }

    void expect(char c) {
        if (peek() != c) {
            fail(std::string("expected '") + c + "'");
        }
        ++pos_;
    }

    bool consumeWord(std::string_view word) {
        if (text_.substr(pos_, word.size()) == word) {
            pos_ += word.size();
            return true;
        }
        return false;
    }

    JsonValue parseValue() {
        const char c = peek();
        JsonValue value;
        if (c == '{') {
            value.kind = JsonValue::Kind::Object;
            ++pos_;
            if (peek() == '}') {
                ++pos_;
                return value;
            }
            while (true) {
                const std::string key = parseString();
                expect(':');
                value.members[key] = parseValue();
                if (peek() == ',') {
                    ++pos_;
                    continue;
                }
                expect('}');
                return value;
            }
        }
        if (c == '[') {
            value.kind = JsonValue::Kind::Array;
            ++pos_;
            if (peek() == ']') {
                ++pos_;
                return value;
            }
            while (true) {
                value.items.push_back(parseValue());
                if (peek() == ',') {
                    ++pos_;
                    continue;
                }
                expect(']');
                return value;
            }
        }
        if (c == '"') {
            value.kind = JsonValue::Kind::String;
            value.text = parseString();
            return value;
        }
        if (consumeWord("true")) {
            value.kind = JsonValue::Kind::Bool;
            value.boolean = true;
            return value;
        }
        if (consumeWord("false")) {
            value.kind = JsonValue::Kind::Bool;
            return value;
        }
        if (consumeWord("null")) {
            return value;
        }
        const std::size_t start = pos_;
        while (pos_ < text_.size() &&
               (std::isdigit(static_cast<unsigned char>(text_[pos_])) != 0 ||
                std::string_view("+-.eE").find(text_[pos_]) != std::string_view::npos)) {
            ++pos_;
        }
        if (start == pos_) {
            fail("unexpected character");
        }
        value.kind = JsonValue::Kind::Number;
        value.text = std::string(text_.substr(start, pos_ - start));
        return value;
    }

    std::string parseString() {
        expect('"');
        std::string out;
        while (pos_ < text_.size() && text_[pos_] != '"') {
            if (text_[pos_] == '\\') {
                ++pos_;
                if (pos_ >= text_.size()) {
                    fail("bad escape");
                }
                const char e = text_[pos_];
                // The expected files hold ASCII messages; \uXXXX is kept as written.
                out += (e == 'n') ? '\n' : (e == 't') ? '\t' : (e == 'u') ? '?' : e;
                if (e == 'u') {
                    pos_ += 4;
                }
                ++pos_;
                continue;
            }
            out += text_[pos_++];
        }
        if (pos_ >= text_.size()) {
            fail("unterminated string");
        }
        ++pos_;
        return out;
    }

    std::string_view text_;
    std::size_t pos_ = 0;
};

/// Parses one JSON document.
inline JsonValue parseJson(std::string_view text) { return JsonReader(text).parseDocument(); }

}  // namespace tilesweep::oracle::test
