// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/result_reader.h"

#include "tilesweep/scene/scalar_text.h"  // exact number text, shared with the scene reader

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace tilesweep::resolvers {
namespace {

// nlohmann-json's DOM keeps a number only as a double, which would round a float's text twice;
// its SAX interface hands over the number's own text, so the reader builds a small tree of
// texts and rounds each number once, to T.

/// One JSON value with numbers kept as their text.
struct Node {
    enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
    std::string text;               ///< a number's lexeme, or a string
    std::vector<Node> items;        ///< an array's elements, an object's values
    std::vector<std::string> keys;  ///< an object's keys, beside `items`

    [[nodiscard]] const Node* member(const std::string& key) const {
        for (std::size_t k = 0; k < keys.size(); ++k)
            if (keys[k] == key) return &items[k];
        return nullptr;
    }
};

/// Builds a Node tree from nlohmann-json's SAX events.
class TreeBuilder {
public:
    using json = nlohmann::json;

    bool null() { return add({}); }
    bool boolean(bool) { return add(Node{Node::Kind::Bool, {}, {}, {}}); }
    bool number_integer(json::number_integer_t v) {
        return add(Node{Node::Kind::Number, std::to_string(v), {}, {}});
    }
    bool number_unsigned(json::number_unsigned_t v) {
        return add(Node{Node::Kind::Number, std::to_string(v), {}, {}});
    }
    bool number_float(json::number_float_t, const json::string_t& text) {
        return add(Node{Node::Kind::Number, text, {}, {}});
    }
    bool string(json::string_t& s) { return add(Node{Node::Kind::String, s, {}, {}}); }
    bool binary(json::binary_t&) { return false; }
    bool start_object(std::size_t) {
        open_.push_back(Node{Node::Kind::Object, {}, {}, {}});
        openKeys_.push_back(pendingKey_);  // the key this container is the value of
        return true;
    }
    bool key(json::string_t& k) {
        pendingKey_ = k;
        return true;
    }
    bool end_object() { return close(); }
    bool start_array(std::size_t) {
        open_.push_back(Node{Node::Kind::Array, {}, {}, {}});
        openKeys_.push_back(pendingKey_);
        return true;
    }
    bool end_array() { return close(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        error = e.what();
        return false;
    }

    Node root;
    std::string error;

private:
    bool add(Node node) {
        if (open_.empty()) {
            root = std::move(node);
            return true;
        }
        Node& parent = open_.back();
        if (parent.kind == Node::Kind::Object) parent.keys.push_back(pendingKey_);
        parent.items.push_back(std::move(node));
        return true;
    }
    bool close() {
        Node done = std::move(open_.back());
        open_.pop_back();
        pendingKey_ = std::move(openKeys_.back());
        openKeys_.pop_back();
        return add(std::move(done));
    }

    std::vector<Node> open_;
    std::vector<std::string> openKeys_;
    std::string pendingKey_;
};

/// Thrown inside the reader with the path of the field at fault; caught by parseResultLine.
struct ReadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

const Node& field(const Node& object, const std::string& key, const std::string& path) {
    const Node* n = object.member(key);
    if (!n) throw ReadError(path + "." + key + ": missing field");
    return *n;
}

const Node& arrayOf(const Node& n, const std::string& path, std::size_t size = 0) {
    if (n.kind != Node::Kind::Array) throw ReadError(path + ": expected an array");
    if (size > 0 && n.items.size() != size)
        throw ReadError(path + ": expected " + std::to_string(size) + " elements, got " +
                        std::to_string(n.items.size()));
    return n;
}

template <class T>
T scalarOf(const Node& n, const std::string& path) {
    detail::ScalarText<T> read;
    if (n.kind == Node::Kind::Number)
        read = detail::readDecimalScalar<T>(n.text);
    else if (n.kind == Node::Kind::String)
        read = detail::readHexfloatScalar<T>(n.text);
    else
        throw ReadError(path + ": expected a number or a hexfloat string");
    if (read.status != detail::ScalarTextStatus::Ok || !std::isfinite(read.value))
        throw ReadError(path + ": not a finite " + std::string(detail::scalarName<T>()) + ": '" +
                        n.text.substr(0, 40) + "'");
    return read.value;
}

std::int32_t integerOf(const Node& n, const std::string& path) {
    std::int32_t v = 0;
    const char* end = n.text.data() + n.text.size();
    if (n.kind != Node::Kind::Number || std::from_chars(n.text.data(), end, v).ptr != end || n.text.empty())
        throw ReadError(path + ": expected an integer, got '" + n.text.substr(0, 40) + "'");
    return v;
}

Cell cellOf(const Node& n, const std::string& path) {
    const Node& a = arrayOf(n, path, 2);
    return {integerOf(a.items[0], path + "[0]"), integerOf(a.items[1], path + "[1]")};
}

template <class T>
FrameResult<T> frameOf(const Node& n, const std::string& path) {
    if (n.kind != Node::Kind::Object) throw ReadError(path + ": expected an object");
    FrameResult<T> frame;
    const Node& pos = arrayOf(field(n, "pos", path), path + ".pos", 2);
    frame.position = {scalarOf<T>(pos.items[0], path + ".pos[0]"),
                      scalarOf<T>(pos.items[1], path + ".pos[1]")};
    const Node& contacts = arrayOf(field(n, "contacts", path), path + ".contacts");
    for (std::size_t k = 0; k < contacts.items.size(); ++k) {
        const std::string at = path + ".contacts[" + std::to_string(k) + "]";
        const Node& c = contacts.items[k];
        if (c.kind != Node::Kind::Object) throw ReadError(at + ": expected an object");
        Contact<T> contact{};
        contact.tile = cellOf(field(c, "tile", at), at + ".tile");
        const Cell normal = cellOf(field(c, "normal", at), at + ".normal");
        const bool axisNormal =
            (std::abs(normal.i) == 1 && normal.j == 0) || (normal.i == 0 && std::abs(normal.j) == 1);
        if (!axisNormal) throw ReadError(at + ".normal: expected one of [1, 0], [-1, 0], [0, 1], [0, -1]");
        contact.normal = {static_cast<std::int8_t>(normal.i), static_cast<std::int8_t>(normal.j)};
        contact.time = scalarOf<T>(field(c, "t", at), at + ".t");
        frame.contacts.push_back(contact);
    }
    const Node& overlaps = arrayOf(field(n, "started_overlapping", path), path + ".started_overlapping");
    for (std::size_t k = 0; k < overlaps.items.size(); ++k)
        frame.startOverlaps.push_back(
            cellOf(overlaps.items[k], path + ".started_overlapping[" + std::to_string(k) + "]"));
    return frame;
}

}  // namespace

template <class T>
ResultParse<T> parseResultLine(std::string_view line, std::size_t frameCount) {
    ResultParse<T> out;
    try {
        TreeBuilder builder;
        if (!nlohmann::json::sax_parse(line.begin(), line.end(), &builder)) {
            out.error = "malformed JSON: " + builder.error;
            return out;
        }
        const Node& root = builder.root;
        if (root.kind != Node::Kind::Object) throw ReadError("result: expected a JSON object");
        if (const Node* error = root.member("error"))
            throw ReadError("the resolver answered with an error: " + (error->kind == Node::Kind::String
                                                                           ? error->text
                                                                           : std::string("(not a string)")));
        const Node& frames = arrayOf(field(root, "frames", "result"), "result.frames");
        if (frames.items.size() != frameCount)
            throw ReadError("result.frames: " + std::to_string(frames.items.size()) +
                            " frames for a scene of " + std::to_string(frameCount));
        std::vector<FrameResult<T>> result;
        for (std::size_t f = 0; f < frames.items.size(); ++f)
            result.push_back(frameOf<T>(frames.items[f], "frames[" + std::to_string(f) + "]"));
        out.frames = std::move(result);
    } catch (const std::exception& e) {
        out.frames.reset();
        out.error = e.what();
    }
    return out;
}

template ResultParse<float> parseResultLine<float>(std::string_view, std::size_t);
template ResultParse<double> parseResultLine<double>(std::string_view, std::size_t);

}  // namespace tilesweep::resolvers
