// SPDX-License-Identifier: MIT
// Fuzz target for the scene reader: arbitrary bytes are one scene line, read as float and as
// double. parseScene must give either a scene or a non-empty error that starts with a field path
// ("map.rows[3]: ...", as scene.h promises), never both, never a crash. A scene must be what the
// resolver accepts, must survive formatScene -> parseScene with the same bits and format back to
// the same text, and runScene on it must return one frame per move, each obeying the safety
// rules (frame_safety.h). Resolving is skipped for scenes too big to run many times a second.
#include "frame_safety.h"  // checks/
#include "fuzz_check.h"

#include "tilesweep/scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace tilesweep;

constexpr const char* kTarget = "fuzz_scene_reader";
constexpr std::int64_t kMaxResolvedCells = 256 * 256;  // larger maps are only read and written
constexpr std::size_t kMaxResolvedMoves = 64;

std::string excerpt(std::string_view line) {
    constexpr std::size_t kShown = 300;
    return std::string(line.substr(0, kShown)) + (line.size() > kShown ? "..." : "");
}

/// Whether an error message starts with a field path the reader uses, then ": ", or is the
/// reader's out-of-memory message.
bool startsWithFieldPath(const std::string& error) {
    if (error == "out of memory") return true;
    static const char* const kFields[] = {"map.origin", "map.tile", "map.rows", "map", "box",
                                          "moves",      "move",     "scene",    "name"};
    for (const char* field : kFields) {
        const std::string_view name(field);
        if (error.compare(0, name.size(), name) != 0) continue;
        std::size_t at = name.size();
        while (at < error.size() && error[at] == '[') {  // indices: [3], [2][1]
            const std::size_t close = error.find(']', at);
            if (close == std::string::npos || close == at + 1) return false;
            for (std::size_t k = at + 1; k < close; ++k)
                if (error[k] < '0' || error[k] > '9') return false;
            at = close + 1;
        }
        return error.compare(at, 2, ": ") == 0 && error.size() > at + 2;
    }
    return false;
}

template <class T>
bool sameVec(Vec2<T> a, Vec2<T> b) noexcept {
    return fuzz::sameBits(a.x, b.x) && fuzz::sameBits(a.y, b.y);
}

template <class T>
bool sameScene(const Scene<T>& a, const Scene<T>& b) {
    if (a.name != b.name || a.map.columns != b.map.columns || a.map.rows != b.map.rows ||
        a.map.solid != b.map.solid || a.moves.size() != b.moves.size())
        return false;
    if (!sameVec(a.map.origin, b.map.origin) || !sameVec(a.map.tileSize, b.map.tileSize) ||
        !sameVec(a.box.pos, b.box.pos) || !sameVec(a.box.size, b.box.size))
        return false;
    for (std::size_t k = 0; k < a.moves.size(); ++k)
        if (!sameVec(a.moves[k], b.moves[k])) return false;
    return true;
}

template <class T>
void checkFrames(const Scene<T>& scene, std::string_view line) {
    const std::int64_t cells = static_cast<std::int64_t>(scene.map.columns) * scene.map.rows;
    if (cells > kMaxResolvedCells || scene.moves.size() > kMaxResolvedMoves) return;
    std::vector<FrameResult<T>> frames;
    try {
        frames = runScene(scene);
    } catch (const std::exception& error) {
        fuzz::failCheck(kTarget, std::string("runScene threw on a parsed scene: ") + error.what(),
                        excerpt(line));
    }
    if (frames.size() != scene.moves.size())
        fuzz::failCheck(kTarget, "runScene did not return one frame per move", excerpt(line));

    const TileMapView<T> map = scene.map.view();
    const checks::MapEdges<T> edges = checks::computeEdges(map);
    checks::SafetyScratch scratch;
    Box<T> box = scene.box;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const FrameResult<T>& f = frames[k];
        ResolveResult<T> result;
        result.status = f.contacts.empty() ? ResolveStatus::Moved : ResolveStatus::Blocked;
        result.position = f.position;
        result.contactCount = static_cast<std::int32_t>(f.contacts.size());
        result.startOverlapCount = static_cast<std::int32_t>(f.startOverlaps.size());
        const checks::FrameRecord<T> frame{
            map, box, scene.moves[k], result, f.contacts.data(), f.startOverlaps.data()};
        const checks::SafetyViolation violation = checks::checkFrameSafety(frame, edges, scratch);
        if (violation)
            fuzz::failCheck(kTarget, "frame " + std::to_string(k) + ": " + violation.detail, excerpt(line));
        box.pos = f.position;
    }
}

template <class T>
void fuzzSceneReader(std::string_view line) {
    const SceneParse<T> parsed = parseScene<T>(line);
    if (parsed.scene.has_value() == !parsed.error.empty())
        fuzz::failCheck(kTarget, "parseScene gave both or neither of a scene and an error", excerpt(line));
    if (!parsed.scene) {
        if (!startsWithFieldPath(parsed.error))
            fuzz::failCheck(kTarget, "error without a field path: " + parsed.error, excerpt(line));
        return;
    }

    const Scene<T>& scene = *parsed.scene;
    if (scene.moves.empty() ||
        scene.map.solid.size() !=
            static_cast<std::size_t>(scene.map.columns) * static_cast<std::size_t>(scene.map.rows) ||
        validateTileMap(scene.map.view()) != MapError::None)
        fuzz::failCheck(kTarget, "parsed scene without moves, or with an invalid map", excerpt(line));
    for (const Vec2<T> move : scene.moves)
        if (!isValid(ResolveInput<T>{scene.map.view(), scene.box, move}))
            fuzz::failCheck(kTarget, "parsed scene the resolver refuses", excerpt(line));

    std::string text;
    try {
        text = formatScene(scene);
    } catch (const std::exception& error) {
        fuzz::failCheck(kTarget, std::string("formatScene threw on a parsed scene: ") + error.what(),
                        excerpt(line));
    }
    const SceneParse<T> again = parseScene<T>(text);
    if (!again.scene)
        fuzz::failCheck(kTarget, "formatScene wrote a line parseScene refuses: " + again.error, text);
    if (!sameScene(scene, *again.scene))
        fuzz::failCheck(kTarget, "formatScene -> parseScene changed the scene", text);
    if (formatScene(*again.scene) != text) fuzz::failCheck(kTarget, "formatScene is not stable", text);

    checkFrames(scene, line);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view line(reinterpret_cast<const char*>(data), size);
    fuzzSceneReader<float>(line);
    fuzzSceneReader<double>(line);
    return 0;
}
