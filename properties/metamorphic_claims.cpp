// SPDX-License-Identifier: MIT
// The metamorphic claims (claims.h): a scene changed in a way whose effect is known (every move
// zero, every length times 8, mirrored, translated by whole tiles) changes the result just so.
#include "claim_support.h"
#include "claims.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

namespace tilesweep::properties {

using namespace claim_support;

/// A frame whose move is zero changes nothing and touches nothing, and reports as start overlaps
/// exactly the solid tiles the box overlaps (checked apart from the resolver), each once, in any
/// order (the contract leaves the order of started_overlapping free). The scene's box
/// rarely starts inside a tile, so the claim also places it a quarter tile into the first one-way
/// tile of the map (which is never listed), or into the first solid tile when there is none,
/// and asks the same there; both scenes go to the resolver in one call.
template <class T>
std::string zeroMoveChangedNothing(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames) {
    std::vector<Cell> overlapping;
    std::vector<Cell> sorted;
    checks::listOverlaps(scene.map.view(), checks::computeEdges(scene.map.view()), scene.box.pos,
                         scene.box.size, overlapping);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!sameBits(frames[f].position.x, scene.box.pos.x) ||
            !sameBits(frames[f].position.y, scene.box.pos.y))
            return "frame " + std::to_string(f) + ": a zero move changed the position";
        if (!frames[f].contacts.empty())
            return "frame " + std::to_string(f) + ": a zero move reported a contact";
        if (!checks::sameCellsInAnyOrder(overlapping, frames[f].startOverlaps.data(),
                                         frames[f].startOverlaps.size(), sorted))
            return "frame " + std::to_string(f) + ": start overlaps differ from the tiles the box overlaps";
    }
    return {};
}

/// The scene with every move replaced by (0, 0).
template <class T>
Scene<T> stillScene(Scene<T> scene) {
    for (auto& m : scene.moves) m = {0, 0};
    return scene;
}

/// The still scene, and when the map has a tile to start in, the still scene inside it.
template <class T>
std::vector<Scene<T>> zeroMoveScenes(const Scene<T>& scene) {
    std::vector<Scene<T>> scenes{stillScene(scene)};
    const std::vector<std::uint8_t>& cells =
        std::find(scene.map.oneWay.begin(), scene.map.oneWay.end(), std::uint8_t{1}) != scene.map.oneWay.end()
            ? scene.map.oneWay
            : scene.map.solid;
    const auto first = std::find(cells.begin(), cells.end(), std::uint8_t{1});
    if (first == cells.end()) return scenes;
    Scene<T> inside = scenes.front();
    const auto index = static_cast<std::int32_t>(first - cells.begin());
    const T i = static_cast<T>(index % scene.map.columns);
    const T j = static_cast<T>(index / scene.map.columns);
    inside.box.pos = {scene.map.origin.x + (i + T(0.25)) * scene.map.tileSize.x,
                      scene.map.origin.y + (j + T(0.25)) * scene.map.tileSize.y};
    if (std::isfinite(inside.box.pos.x) && std::isfinite(inside.box.pos.y))
        scenes.push_back(std::move(inside));
    return scenes;
}

template <class T>
std::string zeroMoveChangesNothing(const Scene<T>& scene, SceneResolver& resolver) {
    const std::vector<Scene<T>> scenes = zeroMoveScenes(scene);
    resolvers::SceneBatch<T> batch;
    for (const Scene<T>& s : scenes) batch.push_back(&s);
    const std::vector<std::vector<FrameResult<T>>> frames = framesFrom(resolver, batch);
    if (std::string why = zeroMoveChangedNothing(scenes[0], frames[0]); !why.empty()) return why;
    if (scenes.size() == 2)
        if (std::string why = zeroMoveChangedNothing(scenes[1], frames[1]); !why.empty())
            return "inside a tile: " + why;
    return {};
}

/// Multiplying every length of the scene by 8 multiplies every position by 8 and leaves every
/// decision and time unchanged, bit for bit (scaling by a power of two is exact, and so is
/// every rounding after it, away from overflow and subnormals).
template <class T>
constexpr T kScale = 8;

/// The scene with every length times kScale, when that is another valid scene of finite values.
template <class T>
std::optional<Scene<T>> scaledScene(const Scene<T>& scene) {
    Scene<T> big = scene;
    const auto scale = [](Vec2<T>& v) { v = {v.x * kScale<T>, v.y * kScale<T>}; };
    scale(big.map.origin);
    scale(big.map.tileSize);
    scale(big.box.pos);
    scale(big.box.size);
    for (auto& m : big.moves) scale(m);
    // Away from overflow only: a scaled value that is no longer finite makes another scene.
    bool finite = std::isfinite(big.map.origin.x) && std::isfinite(big.map.origin.y) &&
                  std::isfinite(big.map.tileSize.x) && std::isfinite(big.map.tileSize.y) &&
                  std::isfinite(big.box.pos.x) && std::isfinite(big.box.pos.y) &&
                  std::isfinite(big.box.size.x) && std::isfinite(big.box.size.y);
    for (const auto& m : big.moves) finite = finite && std::isfinite(m.x) && std::isfinite(m.y);
    if (!finite || validateTileMap(big.map.view()) != MapError::None) return std::nullopt;
    return big;
}

template <class T>
std::string scalingByPowerOfTwoScalesTheResult(const Scene<T>& scene, SceneResolver& resolver) {
    const std::optional<Scene<T>> big = scaledScene(scene);
    if (!big) return {};
    std::vector<std::vector<FrameResult<T>>> both = framesFrom(resolver, scene, *big);
    std::vector<FrameResult<T>>& expected = both[0];
    for (auto& f : expected) f.position = {f.position.x * kScale<T>, f.position.y * kScale<T>};
    return diffFrames(both[1], expected);
}

/// Mirroring the scene about x = 0 (or y = 0) mirrors every decision: the same tiles (mirrored),
/// normals flipped on that axis, the same times, and the other axis's position unchanged. A map
/// with one-way tiles is mirrored about x = 0 only (their rule is symmetric in x, not in y).
template <class T, Axis kAxis>
std::optional<Scene<T>> mirroredScene(const Scene<T>& scene) {
    const bool onX = kAxis == Axis::X;
    // A one-way tile blocks only downward motion: mirrored about y = 0 it is another scene.
    if (!onX && std::find(scene.map.oneWay.begin(), scene.map.oneWay.end(), std::uint8_t{1}) !=
                    scene.map.oneWay.end())
        return std::nullopt;
    const T pos = onX ? scene.box.pos.x : scene.box.pos.y;
    const T size = onX ? scene.box.size.x : scene.box.size.y;
    const T mirroredPos = -(pos + size);
    if (oracle::toRational(mirroredPos) != -(oracle::toRational(pos) + oracle::toRational(size)))
        return std::nullopt;  // not exact: no claim
    Scene<T> m = scene;
    const std::int32_t count = onX ? scene.map.columns : scene.map.rows;
    const T origin = onX ? scene.map.origin.x : scene.map.origin.y;
    const T tile = onX ? scene.map.tileSize.x : scene.map.tileSize.y;
    const T far = -(origin + static_cast<T>(count) * tile);  // an edge of the map: representable
    if (onX) {
        m.map.origin.x = far;
        m.box.pos.x = mirroredPos;
        for (auto& mv : m.moves) mv.x = -mv.x;
    } else {
        m.map.origin.y = far;
        m.box.pos.y = mirroredPos;
        for (auto& mv : m.moves) mv.y = -mv.y;
    }
    for (std::int32_t j = 0; j < scene.map.rows; ++j)
        for (std::int32_t i = 0; i < scene.map.columns; ++i) {
            const std::int32_t mi = onX ? scene.map.columns - 1 - i : i;
            const std::int32_t mj = onX ? j : scene.map.rows - 1 - j;
            const auto from = static_cast<std::size_t>(j * scene.map.columns + i);
            const auto to = static_cast<std::size_t>(mj * scene.map.columns + mi);
            m.map.solid[to] = scene.map.solid[from];
            if (!scene.map.oneWay.empty()) m.map.oneWay[to] = scene.map.oneWay[from];
        }
    return m;
}

template <class T, Axis kAxis>
std::string mirroringMirrorsTheResult(const Scene<T>& scene, SceneResolver& resolver) {
    const bool onX = kAxis == Axis::X;
    const std::optional<Scene<T>> m = mirroredScene<T, kAxis>(scene);
    if (!m) return {};
    std::vector<std::vector<FrameResult<T>>> both = framesFrom(resolver, scene, *m);
    std::vector<FrameResult<T>>& expected = both[0];
    for (auto& f : expected) {
        for (auto& c : f.contacts) {
            if (onX) {
                c.tile.i = scene.map.columns - 1 - c.tile.i;
                c.normal.x = static_cast<std::int8_t>(-c.normal.x);
            } else {
                c.tile.j = scene.map.rows - 1 - c.tile.j;
                c.normal.y = static_cast<std::int8_t>(-c.normal.y);
            }
        }
        for (auto& c : f.startOverlaps)
            (onX ? c.i : c.j) = (onX ? scene.map.columns - 1 - c.i : scene.map.rows - 1 - c.j);
    }
    // The mirrored axis's position is rounded toward the mirrored start, which is a different
    // rounding of a different sum: only the other axis is compared bit for bit. Frames after the
    // first start from those roundings, so only the first frame is compared.
    Compare what;
    what.positionX = !onX;
    what.positionY = onX;
    what.orderWithinTime = false;
    std::vector<FrameResult<T>>& got = both[1];
    got.resize(1);
    expected.resize(1);
    return diffFrames(got, expected, what);
}

/// Moving the map and the box by three whole tiles on each axis keeps every decision and time
/// (when the translated values are exact; otherwise the scenes differ and nothing is claimed).
template <class T>
std::optional<Scene<T>> translatedScene(const Scene<T>& scene) {
    Scene<T> moved = scene;
    const auto shift = [](T v, T by, T& out) {
        out = v + by;
        return oracle::toRational(out) == oracle::toRational(v) + oracle::toRational(by);
    };
    const T bx = 3 * scene.map.tileSize.x;
    const T by = 3 * scene.map.tileSize.y;
    if (!shift(scene.map.origin.x, bx, moved.map.origin.x) ||
        !shift(scene.map.origin.y, by, moved.map.origin.y) || !shift(scene.box.pos.x, bx, moved.box.pos.x) ||
        !shift(scene.box.pos.y, by, moved.box.pos.y))
        return std::nullopt;
    if (validateTileMap(moved.map.view()) != MapError::None) return std::nullopt;
    return moved;
}

template <class T>
std::string translatingByWholeTilesKeepsDecisions(const Scene<T>& scene, SceneResolver& resolver) {
    const std::optional<Scene<T>> moved = translatedScene(scene);
    if (!moved) return {};
    Compare what;
    what.positionX = what.positionY = false;
    std::vector<std::vector<FrameResult<T>>> both = framesFrom(resolver, *moved, scene);
    std::vector<FrameResult<T>>& got = both[0];
    std::vector<FrameResult<T>>& expected = both[1];
    got.resize(1);  // later frames start from rounded positions that may differ
    expected.resize(1);
    return diffFrames(got, expected, what);
}

/// The scene and its transformed twin, when there is one.
template <class T>
std::vector<Scene<T>> withTwin(const Scene<T>& scene, std::optional<Scene<T>> twin) {
    if (!twin) return {};
    return {scene, std::move(*twin)};
}

template <class T>
std::vector<Scene<T>> zeroMoveAsks(const Scene<T>& scene) {
    return zeroMoveScenes(scene);
}
template <class T>
std::vector<Scene<T>> scalingAsks(const Scene<T>& scene) {
    return withTwin(scene, scaledScene(scene));
}
template <class T, Axis kAxis>
std::vector<Scene<T>> mirroringAsks(const Scene<T>& scene) {
    return withTwin(scene, mirroredScene<T, kAxis>(scene));
}
template <class T>
std::vector<Scene<T>> translatingAsks(const Scene<T>& scene) {
    return withTwin(scene, translatedScene(scene));
}

template std::vector<Scene<float>> zeroMoveAsks<float>(const Scene<float>&);
template std::vector<Scene<double>> zeroMoveAsks<double>(const Scene<double>&);
template std::vector<Scene<float>> scalingAsks<float>(const Scene<float>&);
template std::vector<Scene<double>> scalingAsks<double>(const Scene<double>&);
template std::vector<Scene<float>> mirroringAsks<float, Axis::X>(const Scene<float>&);
template std::vector<Scene<float>> mirroringAsks<float, Axis::Y>(const Scene<float>&);
template std::vector<Scene<double>> mirroringAsks<double, Axis::X>(const Scene<double>&);
template std::vector<Scene<double>> mirroringAsks<double, Axis::Y>(const Scene<double>&);
template std::vector<Scene<float>> translatingAsks<float>(const Scene<float>&);
template std::vector<Scene<double>> translatingAsks<double>(const Scene<double>&);
template std::string zeroMoveChangesNothing<float>(const Scene<float>&, SceneResolver&);
template std::string zeroMoveChangesNothing<double>(const Scene<double>&, SceneResolver&);
template std::string scalingByPowerOfTwoScalesTheResult<float>(const Scene<float>&, SceneResolver&);
template std::string scalingByPowerOfTwoScalesTheResult<double>(const Scene<double>&, SceneResolver&);
template std::string translatingByWholeTilesKeepsDecisions<float>(const Scene<float>&, SceneResolver&);
template std::string translatingByWholeTilesKeepsDecisions<double>(const Scene<double>&, SceneResolver&);
template std::string mirroringMirrorsTheResult<float, Axis::X>(const Scene<float>&, SceneResolver&);
template std::string mirroringMirrorsTheResult<float, Axis::Y>(const Scene<float>&, SceneResolver&);
template std::string mirroringMirrorsTheResult<double, Axis::X>(const Scene<double>&, SceneResolver&);
template std::string mirroringMirrorsTheResult<double, Axis::Y>(const Scene<double>&, SceneResolver&);

// ---- The claims of this file, with their properties (claim.h) ----------------------------------

template <class T>
std::vector<Claim<T>> metamorphicClaims() {
    using S = ClaimScope;
    return {
        {"zeroMoveChangesNothing",
         &zeroMoveChangesNothing<T>,
         S::Safety,
         &zeroMoveAsks<T>,
         {{"zeroMoveChangesNothing", Family::Mixed, {}}}},
        {"scalingByPowerOfTwoScalesTheResult",
         &scalingByPowerOfTwoScalesTheResult<T>,
         S::Safety,
         &scalingAsks<T>,
         {{"scalingByPowerOfTwoScalesTheResult", Family::Mixed, {{"hit", 0.2}, {"tie", 0.02}}}}},
        {"mirroringXMirrorsTheResult",
         &mirroringMirrorsTheResult<T, Axis::X>,
         S::Safety,
         &mirroringAsks<T, Axis::X>,
         {{"mirroringXMirrorsTheResult", Family::Mixed, {{"hit", 0.2}}}}},
        {"mirroringYMirrorsTheResult",
         &mirroringMirrorsTheResult<T, Axis::Y>,
         S::Safety,
         &mirroringAsks<T, Axis::Y>,
         {{"mirroringYMirrorsTheResult", Family::Mixed, {{"hit", 0.2}}}}},
        {"translatingByWholeTilesKeepsDecisions",
         &translatingByWholeTilesKeepsDecisions<T>,
         S::Safety,
         &translatingAsks<T>,
         {{"translatingByWholeTilesKeepsDecisions", Family::Mixed, {{"hit", 0.2}}}}},
    };
}

template std::vector<Claim<float>> metamorphicClaims<float>();
template std::vector<Claim<double>> metamorphicClaims<double>();

}  // namespace tilesweep::properties
