// SPDX-License-Identifier: MIT
#include "scene_checks.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <tuple>

#include "oracle/exact/exact_geometry.h"
#include "oracle/exact/exact_resolve.h"
#include "oracle/exact/rational_convert.h"
#include "oracle/substep/substep_oracle.h"

namespace tilesweep::properties {
namespace {

using oracle::Rational;

template <class T>
bool sameBits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T>
std::string hex(T v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(v));
    return buffer;
}

std::string cellText(Cell c) { return "(" + std::to_string(c.i) + ", " + std::to_string(c.j) + ")"; }

/// Which parts of two frame lists to compare.
struct Compare {
    bool positionX = true;
    bool positionY = true;
    bool orderWithinTime = true;  ///< contacts in the same order, not only the same set
};

template <class T>
std::string diffFrames(const std::vector<FrameResult<T>>& got, const std::vector<FrameResult<T>>& want,
                       Compare what = {}) {
    if (got.size() != want.size()) return "frame count " + std::to_string(got.size()) + " != " + std::to_string(want.size());
    for (std::size_t f = 0; f < got.size(); ++f) {
        const FrameResult<T>& a = got[f];
        const FrameResult<T>& b = want[f];
        const std::string at = "frame " + std::to_string(f) + ": ";
        if (what.positionX && !sameBits(a.position.x, b.position.x))
            return at + "x " + hex(a.position.x) + " != " + hex(b.position.x);
        if (what.positionY && !sameBits(a.position.y, b.position.y))
            return at + "y " + hex(a.position.y) + " != " + hex(b.position.y);
        if (a.contacts.size() != b.contacts.size())
            return at + std::to_string(a.contacts.size()) + " contacts != " + std::to_string(b.contacts.size());
        std::vector<Contact<T>> ca = a.contacts;
        std::vector<Contact<T>> cb = b.contacts;
        if (!what.orderWithinTime) {
            const auto byTime = [](const Contact<T>& p, const Contact<T>& q) {
                return std::tie(p.time, p.tile.j, p.tile.i) < std::tie(q.time, q.tile.j, q.tile.i);
            };
            std::sort(ca.begin(), ca.end(), byTime);
            std::sort(cb.begin(), cb.end(), byTime);
        }
        for (std::size_t k = 0; k < ca.size(); ++k) {
            if (ca[k].tile != cb[k].tile) return at + "contact " + std::to_string(k) + " tile " + cellText(ca[k].tile) + " != " + cellText(cb[k].tile);
            if (ca[k].normal != cb[k].normal) return at + "contact " + std::to_string(k) + " normal differs";
            if (!sameBits(ca[k].time, cb[k].time)) return at + "contact " + std::to_string(k) + " t " + hex(ca[k].time) + " != " + hex(cb[k].time);
        }
        if (a.startOverlaps.size() != b.startOverlaps.size()) return at + "started_overlapping count differs";
        std::vector<Cell> oa = a.startOverlaps;
        std::vector<Cell> ob = b.startOverlaps;
        const auto byCell = [](Cell p, Cell q) { return std::tie(p.j, p.i) < std::tie(q.j, q.i); };
        std::sort(oa.begin(), oa.end(), byCell);
        std::sort(ob.begin(), ob.end(), byCell);
        for (std::size_t k = 0; k < oa.size(); ++k)
            if (oa[k] != ob[k]) return at + "started_overlapping differs";
    }
    return {};
}

/// The position each frame starts from: the box's, then each frame's result.
template <class T>
std::vector<Vec2<T>> frameStarts(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames) {
    std::vector<Vec2<T>> starts{scene.box.pos};
    for (std::size_t f = 0; f + 1 < frames.size(); ++f) starts.push_back(frames[f].position);
    return starts;
}

template <class T>
T nextUp(T v) { return std::nextafter(v, std::numeric_limits<T>::infinity()); }
template <class T>
T nextDown(T v) { return std::nextafter(v, -std::numeric_limits<T>::infinity()); }

// ---------------------------------------------------------------------------------------------
// The claims.

/// Decisions, positions, times and start overlaps equal the exact reference's, bit for bit.
template <class T>
std::string matchesExactReferenceBitForBit(const Scene<T>& scene) {
    return diffFrames(runScene(scene), oracle::resolveSceneExactRounded(scene));
}

/// At the end of every frame, the exact box overlaps no solid tile it did not overlap at the
/// start, and the rounded box overlaps one only through the rounding: a tile the frame did not
/// hit, which the exact end box misses or only touches.
///
/// Why not "the rounded box never overlaps a new tile", as CONTRACT.md's rounding paragraph says
/// ("The box thus never ... ends inside a tile it did not start inside")? Rounding each axis
/// toward the start can undo a corner miss: when the exact path passes just beside a tile's
/// corner and one axis moves less than an ulp, that axis rounds back to the start while the
/// other moves on, and the rounded box ends overlapping the corner by less than an ulp on each
/// axis (properties/corpus/contract-rounding-undoes-corner-miss.jsonl, found by the soak). The
/// resolver follows the rounding rule bit for bit; this claim holds for the rule as written.
template <class T>
std::string neverEndsInsideATileItDidNotStartIn(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = runScene(scene);
    const std::vector<oracle::ExactFrame> exact = oracle::resolveSceneExact(scene);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    const oracle::ExactVec2 size = oracle::toExact(scene.box.size);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{frames[f].position, scene.box.size}));
        const oracle::ExactRect exactBox = oracle::rectOf(oracle::ExactBox{exact[f].position, size});
        const auto& started = frames[f].startOverlaps;
        for (std::int32_t j = 0; j < map.rows; ++j)
            for (std::int32_t i = 0; i < map.columns; ++i) {
                if (!map.isSolid(i, j) || std::find(started.begin(), started.end(), Cell{i, j}) != started.end()) continue;
                const oracle::ExactRect tile = map.tileRect(i, j);
                if (oracle::overlaps(exactBox, tile))
                    return "frame " + std::to_string(f) + ": the exact end is inside tile " + cellText({i, j});
                if (!oracle::overlaps(box, tile)) continue;
                const auto& hits = frames[f].contacts;
                if (std::any_of(hits.begin(), hits.end(), [&](const Contact<T>& c) { return c.tile == Cell{i, j}; }))
                    return "frame " + std::to_string(f) + ": ends inside tile " + cellText({i, j}) + ", which it hit";
            }
    }
    return {};
}

/// After a hit on a face, the box ends touching it or short of it by less than one ulp.
template <class T>
std::string stopsJustTouching(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = runScene(scene);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    const Rational w = oracle::toRational(scene.box.size.x);
    const Rational h = oracle::toRational(scene.box.size.y);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Vec2<T> p = frames[f].position;
        for (const Contact<T>& c : frames[f].contacts) {
            const oracle::ExactRect tile = map.tileRect(c.tile.i, c.tile.j);
            bool ok = true;
            if (c.normal.x == -1) ok = oracle::toRational(p.x) + w <= tile.min.x && oracle::toRational(nextUp(p.x)) + w > tile.min.x;
            if (c.normal.x == 1) ok = oracle::toRational(p.x) >= tile.max.x && oracle::toRational(nextDown(p.x)) < tile.max.x;
            if (c.normal.y == -1) ok = oracle::toRational(p.y) + h <= tile.min.y && oracle::toRational(nextUp(p.y)) + h > tile.min.y;
            if (c.normal.y == 1) ok = oracle::toRational(p.y) >= tile.max.y && oracle::toRational(nextDown(p.y)) < tile.max.y;
            if (!ok) return "frame " + std::to_string(f) + ": not just touching tile " + cellText(c.tile);
        }
    }
    return {};
}

/// Whenever the exact 64-substep oracle sees an overlap at substep k, the resolver hit something
/// no later than k/64 (rounded to nearest, which is monotone) in that frame.
template <class T>
std::string substepOracleFindsNoMissedContact(const Scene<T>& scene) {
    constexpr std::int64_t kSubsteps = 64;
    const std::vector<FrameResult<T>> frames = runScene(scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const auto seen = oracle::findFirstOverlapExact(map, oracle::toExact(Box<T>{starts[f], scene.box.size}),
                                                        oracle::toExact(scene.moves[f]), kSubsteps);
        if (!seen.found()) continue;
        const T bound = oracle::fromRational<T>(seen.bracketHigh(), oracle::Rounding::NearestEven);
        if (frames[f].contacts.empty() || frames[f].contacts.front().time > bound)
            return "frame " + std::to_string(f) + ": substep " + std::to_string(seen.firstOverlap) +
                   "/64 overlaps, the resolver's first contact is later or missing";
    }
    return {};
}

/// A frame whose move is zero changes nothing and touches nothing.
template <class T>
std::string zeroMoveChangesNothing(const Scene<T>& scene) {
    Scene<T> still = scene;
    for (auto& m : still.moves) m = {0, 0};
    const std::vector<FrameResult<T>> frames = runScene(still);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!sameBits(frames[f].position.x, scene.box.pos.x) || !sameBits(frames[f].position.y, scene.box.pos.y))
            return "frame " + std::to_string(f) + ": a zero move changed the position";
        if (!frames[f].contacts.empty()) return "frame " + std::to_string(f) + ": a zero move reported a contact";
    }
    return {};
}

/// Multiplying every length of the scene by 8 multiplies every position by 8 and leaves every
/// decision and time unchanged, bit for bit (scaling by a power of two is exact, and so is
/// every rounding after it, away from overflow and subnormals).
template <class T>
std::string scalingByPowerOfTwoScalesTheResult(const Scene<T>& scene) {
    constexpr T kScale = 8;
    Scene<T> big = scene;
    const auto scale = [](Vec2<T>& v) { v = {v.x * kScale, v.y * kScale}; };
    scale(big.map.origin);
    scale(big.map.tileSize);
    scale(big.box.pos);
    scale(big.box.size);
    for (auto& m : big.moves) scale(m);
    std::vector<FrameResult<T>> expected = runScene(scene);
    for (auto& f : expected) f.position = {f.position.x * kScale, f.position.y * kScale};
    return diffFrames(runScene(big), expected);
}

/// Mirroring the scene about x = 0 (or y = 0) mirrors every decision: the same tiles (mirrored),
/// normals flipped on that axis, the same times, and the other axis's position unchanged.
template <class T, Axis kAxis>
std::string mirroringMirrorsTheResult(const Scene<T>& scene) {
    const bool onX = kAxis == Axis::X;
    const T pos = onX ? scene.box.pos.x : scene.box.pos.y;
    const T size = onX ? scene.box.size.x : scene.box.size.y;
    const T mirroredPos = -(pos + size);
    if (oracle::toRational(mirroredPos) != -(oracle::toRational(pos) + oracle::toRational(size))) return {};  // not exact: no claim
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
            m.map.solid[static_cast<std::size_t>(mj * scene.map.columns + mi)] =
                scene.map.solid[static_cast<std::size_t>(j * scene.map.columns + i)];
        }
    std::vector<FrameResult<T>> expected = runScene(scene);
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
        for (auto& c : f.startOverlaps) (onX ? c.i : c.j) = (onX ? scene.map.columns - 1 - c.i : scene.map.rows - 1 - c.j);
    }
    // The mirrored axis's position is rounded toward the mirrored start, which is a different
    // rounding of a different sum: only the other axis is compared bit for bit. Frames after the
    // first start from those roundings, so only the first frame is compared.
    Compare what;
    what.positionX = !onX;
    what.positionY = onX;
    what.orderWithinTime = false;
    std::vector<FrameResult<T>> got = runScene(m);
    got.resize(1);
    expected.resize(1);
    return diffFrames(got, expected, what);
}

/// Moving the map and the box by three whole tiles on each axis keeps every decision and time
/// (when the translated values are exact; otherwise the scenes differ and nothing is claimed).
template <class T>
std::string translatingByWholeTilesKeepsDecisions(const Scene<T>& scene) {
    Scene<T> moved = scene;
    const auto shift = [](T v, T by, T& out) {
        out = v + by;
        return oracle::toRational(out) == oracle::toRational(v) + oracle::toRational(by);
    };
    const T bx = 3 * scene.map.tileSize.x;
    const T by = 3 * scene.map.tileSize.y;
    if (!shift(scene.map.origin.x, bx, moved.map.origin.x) || !shift(scene.map.origin.y, by, moved.map.origin.y) ||
        !shift(scene.box.pos.x, bx, moved.box.pos.x) || !shift(scene.box.pos.y, by, moved.box.pos.y))
        return {};
    if (validateTileMap(moved.map.view()) != MapError::None) return {};
    Compare what;
    what.positionX = what.positionY = false;
    std::vector<FrameResult<T>> got = runScene(moved);
    std::vector<FrameResult<T>> expected = runScene(scene);
    got.resize(1);  // later frames start from rounded positions that may differ
    expected.resize(1);
    return diffFrames(got, expected, what);
}

/// Under gravity on a floor, once landed, the position is identical frame after frame.
template <class T>
std::string restingContactIsStable(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = runScene(scene);
    for (std::size_t f = 1; f < frames.size(); ++f) {
        const Vec2<T> m = scene.moves[f];
        const Vec2<T> previous = scene.moves[f - 1];
        if (!(m.x == 0 && m.y > 0 && previous.x == 0 && previous.y == m.y)) continue;
        const auto& before = frames[f - 1].contacts;
        const bool landed = std::any_of(before.begin(), before.end(), [](const Contact<T>& c) { return c.normal.y == -1; });
        if (!landed) continue;
        if (!sameBits(frames[f].position.x, frames[f - 1].position.x) || !sameBits(frames[f].position.y, frames[f - 1].position.y))
            return "frame " + std::to_string(f) + ": resting box moved from (" + hex(frames[f - 1].position.x) + ", " +
                   hex(frames[f - 1].position.y) + ") to (" + hex(frames[f].position.x) + ", " + hex(frames[f].position.y) + ")";
    }
    return {};
}

/// A box standing on a floor (a solid tile under its open x span, top exactly at its bottom)
/// and moving sideways and down is never stopped on x by a tile of that floor: no snag on seams.
template <class T>
std::string slidingAlongFloorNeverSnags(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = runScene(scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!(scene.moves[f].y > 0)) continue;
        const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{starts[f], scene.box.size}));
        bool supported = false;
        for (std::int32_t j = 0; j < map.rows && !supported; ++j)
            for (std::int32_t i = 0; i < map.columns && !supported; ++i) {
                if (!map.isSolid(i, j)) continue;
                const oracle::ExactRect t = map.tileRect(i, j);
                supported = t.min.y == box.max.y && t.min.x < box.max.x && t.max.x > box.min.x;
            }
        if (!supported) continue;
        for (const Contact<T>& c : frames[f].contacts)
            if (c.normal.x != 0 && map.tileRect(c.tile.i, c.tile.j).min.y == box.max.y)
                return "frame " + std::to_string(f) + ": snagged on the side of floor tile " + cellText(c.tile);
    }
    return {};
}

}  // namespace

template <class T>
const std::vector<Claim<T>>& allClaims() {
    static const std::vector<Claim<T>> claims = {
        {"matchesExactReferenceBitForBit", &matchesExactReferenceBitForBit<T>},
        {"neverEndsInsideATileItDidNotStartIn", &neverEndsInsideATileItDidNotStartIn<T>},
        {"stopsJustTouching", &stopsJustTouching<T>},
        {"substepOracleFindsNoMissedContact", &substepOracleFindsNoMissedContact<T>},
        {"zeroMoveChangesNothing", &zeroMoveChangesNothing<T>},
        {"scalingByPowerOfTwoScalesTheResult", &scalingByPowerOfTwoScalesTheResult<T>},
        {"mirroringXMirrorsTheResult", &mirroringMirrorsTheResult<T, Axis::X>},
        {"mirroringYMirrorsTheResult", &mirroringMirrorsTheResult<T, Axis::Y>},
        {"translatingByWholeTilesKeepsDecisions", &translatingByWholeTilesKeepsDecisions<T>},
        {"restingContactIsStable", &restingContactIsStable<T>},
        {"slidingAlongFloorNeverSnags", &slidingAlongFloorNeverSnags<T>},
    };
    return claims;
}

template <class T>
const Claim<T>* findClaim(const std::string& name) {
    for (const Claim<T>& c : allClaims<T>())
        if (name == c.name) return &c;
    return nullptr;
}

namespace {

/// The exact frames under the contract's rounding (what every resolver must return).
template <class T>
std::vector<FrameResult<T>> toFrameResultsForTags(const Scene<T>& scene) {
    return oracle::resolveSceneExactRounded(scene);
}

}  // namespace

template <class T>
std::vector<std::string> classifyScene(const Scene<T>& scene) {
    std::vector<std::string> tags;
    const auto frames = oracle::resolveSceneExact(scene);
    bool hit = false;
    bool tie = false;
    bool touch0 = false;
    bool twoStep = false;
    bool seam = false;
    bool startOverlap = false;
    for (const auto& f : frames) {
        hit = hit || !f.contacts.empty();
        startOverlap = startOverlap || !f.startOverlaps.empty();
        for (std::size_t k = 0; k < f.contacts.size(); ++k) {
            const auto& c = f.contacts[k];
            tie = tie || c.tie;
            touch0 = touch0 || c.time == 0;
            twoStep = twoStep || c.step == 2;
            if (k > 0 && f.contacts[k - 1].step == c.step && f.contacts[k - 1].normal == c.normal) seam = true;
        }
    }
    // The rounded end overlapping a tile the frame neither started in nor hit: the case where the
    // contract's rounding undoes a corner miss (see neverEndsInsideATileItDidNotStartIn).
    const std::vector<FrameResult<T>> rounded = toFrameResultsForTags(scene);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    bool roundingOverlap = false;
    for (const FrameResult<T>& f : rounded) {
        const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{f.position, scene.box.size}));
        for (std::int32_t j = 0; j < map.rows && !roundingOverlap; ++j)
            for (std::int32_t i = 0; i < map.columns && !roundingOverlap; ++i)
                roundingOverlap = map.isSolid(i, j) && oracle::overlaps(box, map.tileRect(i, j)) &&
                                  std::find(f.startOverlaps.begin(), f.startOverlaps.end(), Cell{i, j}) ==
                                      f.startOverlaps.end();
    }
    tags.push_back(hit ? "hit" : "miss");
    if (roundingOverlap) tags.push_back("rounding-overlap");
    if (tie) tags.push_back("tie");
    if (touch0) tags.push_back("touch-at-0");
    if (twoStep) tags.push_back("two-step");
    if (seam) tags.push_back("seam");
    if (startOverlap) tags.push_back("start-overlap");
    if (std::fabs(scene.map.origin.x) >= T(1048576) || std::fabs(scene.map.origin.y) >= T(1048576)) tags.push_back("far-origin");
    return tags;
}

template const std::vector<Claim<float>>& allClaims<float>();
template const std::vector<Claim<double>>& allClaims<double>();
template const Claim<float>* findClaim<float>(const std::string&);
template const Claim<double>* findClaim<double>(const std::string&);
template std::vector<std::string> classifyScene<float>(const Scene<float>&);
template std::vector<std::string> classifyScene<double>(const Scene<double>&);

}  // namespace tilesweep::properties
