// SPDX-License-Identifier: MIT
// Writing scenes and the output lines of `tilesweep resolve` (docs/contract.md).
#include "tilesweep/scene/scalar_text.h"
#include "tilesweep/scene/scene.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace tilesweep {
namespace {

// A JSON string literal. Invalid UTF-8 becomes U+FFFD instead of an exception: an error
// message may quote raw bytes of the line it complains about.
[[nodiscard]] std::string jsonString(std::string_view text) {
    return nlohmann::json(std::string(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// "0x1.8p+3" with its quotes: a hexfloat travels as a JSON string.
template <class T>
void appendHexfloatString(std::string& out, T value) {
    out += '"';
    detail::appendHexfloat(out, static_cast<double>(value));
    out += '"';
}

template <class T>
void appendHexfloatPair(std::string& out, T a, T b) {
    out += '[';
    appendHexfloatString(out, a);
    out += ", ";
    appendHexfloatString(out, b);
    out += ']';
}

template <class T>
void appendShortestPair(std::string& out, T a, T b) {
    out += '[';
    detail::appendShortest(out, a);
    out += ", ";
    detail::appendShortest(out, b);
    out += ']';
}

void appendIntPair(std::string& out, int a, int b) {
    out += '[';
    out += std::to_string(a);
    out += ", ";
    out += std::to_string(b);
    out += ']';
}

// The rows of a map as strings of '#', '-' and '.', the top row first.
template <class T>
void appendRows(std::string& out, const TileMap<T>& map) {
    if (map.columns < 0 || map.rows < 0 ||
        map.solid.size() != static_cast<std::size_t>(map.columns) * static_cast<std::size_t>(map.rows))
        throw std::invalid_argument("formatScene: map.solid does not hold columns*rows cells");
    if (!map.oneWay.empty() && map.oneWay.size() != map.solid.size())
        throw std::invalid_argument("formatScene: map.oneWay is neither empty nor as long as map.solid");
    const auto columns = static_cast<std::size_t>(map.columns);
    out += '[';
    for (std::size_t j = 0; j < static_cast<std::size_t>(map.rows); ++j) {
        if (j != 0) out += ", ";
        out += '"';
        for (std::size_t i = 0; i < columns; ++i) {
            const std::size_t k = j * columns + i;
            out += map.solid[k] != 0 ? '#' : !map.oneWay.empty() && map.oneWay[k] != 0 ? '-' : '.';
        }
        out += '"';
    }
    out += ']';
}

}  // namespace

template <class T>
std::string formatScene(const Scene<T>& scene) {
    std::string out = "{";
    if (!scene.name.empty()) {
        out += "\"name\": ";
        out += jsonString(scene.name);
        out += ", ";
    }
    out += "\"map\": {\"origin\": ";
    appendHexfloatPair(out, scene.map.origin.x, scene.map.origin.y);
    out += ", \"tile\": ";
    appendHexfloatPair(out, scene.map.tileSize.x, scene.map.tileSize.y);
    out += ", \"rows\": ";
    appendRows(out, scene.map);
    out += "}, \"box\": [";
    appendHexfloatString(out, scene.box.pos.x);
    out += ", ";
    appendHexfloatString(out, scene.box.pos.y);
    out += ", ";
    appendHexfloatString(out, scene.box.size.x);
    out += ", ";
    appendHexfloatString(out, scene.box.size.y);
    out += "], \"moves\": [";
    for (std::size_t k = 0; k < scene.moves.size(); ++k) {
        if (k != 0) out += ", ";
        appendHexfloatPair(out, scene.moves[k].x, scene.moves[k].y);
    }
    out += "]}";
    return out;
}

template <class T>
std::string formatFrames(const std::vector<FrameResult<T>>& frames) {
    std::string out = "{\"frames\": [";
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const FrameResult<T>& frame = frames[f];
        if (f != 0) out += ", ";
        out += "{\"pos\": ";
        appendShortestPair(out, frame.position.x, frame.position.y);
        out += ", \"contacts\": [";
        for (std::size_t k = 0; k < frame.contacts.size(); ++k) {
            const Contact<T>& contact = frame.contacts[k];
            if (k != 0) out += ", ";
            out += "{\"tile\": ";
            appendIntPair(out, contact.tile.i, contact.tile.j);
            out += ", \"normal\": ";
            appendIntPair(out, contact.normal.x, contact.normal.y);
            out += ", \"t\": ";
            detail::appendShortest(out, contact.time);
            out += '}';
        }
        out += "], \"started_overlapping\": [";
        for (std::size_t k = 0; k < frame.startOverlaps.size(); ++k) {
            if (k != 0) out += ", ";
            appendIntPair(out, frame.startOverlaps[k].i, frame.startOverlaps[k].j);
        }
        out += "]}";
    }
    out += "]}";
    return out;
}

std::string formatError(std::string_view message) { return "{\"error\": " + jsonString(message) + "}"; }

template std::string formatScene<float>(const Scene<float>&);
template std::string formatScene<double>(const Scene<double>&);
template std::string formatFrames<float>(const std::vector<FrameResult<float>>&);
template std::string formatFrames<double>(const std::vector<FrameResult<double>>&);

}  // namespace tilesweep
