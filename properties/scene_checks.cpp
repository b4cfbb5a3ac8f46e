// SPDX-License-Identifier: MIT
#include "scene_checks.h"

#include "boundary_checks.h"
#include "frame_safety.h"  // checks/
#include "oracle/exact/exact_geometry.h"
#include "oracle/exact/exact_resolve.h"
#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/rational_convert.h"
#include "oracle/substep/substep_oracle.h"
#include "scene_runner.h"

#include "tilesweep/box_sweep.h"
#include "tilesweep/mover.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <tuple>

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
    if (got.size() != want.size())
        return "frame count " + std::to_string(got.size()) + " != " + std::to_string(want.size());
    for (std::size_t f = 0; f < got.size(); ++f) {
        const FrameResult<T>& a = got[f];
        const FrameResult<T>& b = want[f];
        const std::string at = "frame " + std::to_string(f) + ": ";
        if (what.positionX && !sameBits(a.position.x, b.position.x))
            return at + "x " + hex(a.position.x) + " != " + hex(b.position.x);
        if (what.positionY && !sameBits(a.position.y, b.position.y))
            return at + "y " + hex(a.position.y) + " != " + hex(b.position.y);
        if (a.contacts.size() != b.contacts.size())
            return at + std::to_string(a.contacts.size()) +
                   " contacts != " + std::to_string(b.contacts.size());
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
            if (ca[k].tile != cb[k].tile)
                return at + "contact " + std::to_string(k) + " tile " + cellText(ca[k].tile) +
                       " != " + cellText(cb[k].tile);
            if (ca[k].normal != cb[k].normal) return at + "contact " + std::to_string(k) + " normal differs";
            if (!sameBits(ca[k].time, cb[k].time))
                return at + "contact " + std::to_string(k) + " t " + hex(ca[k].time) +
                       " != " + hex(cb[k].time);
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

// ---------------------------------------------------------------------------------------------
// The claims.

/// Decisions, positions, times and start overlaps equal the exact reference's, bit for bit.
template <class T>
std::string matchesExactReferenceBitForBit(const Scene<T>& scene) {
    return diffFrames(resolveUnderTest(scene), oracle::resolveSceneExactRounded(scene));
}

/// The frames of a scene as the shared safety checks see them (checks/frame_safety.h).
template <class T>
struct CheckedFrames {
    std::vector<FrameResult<T>> frames;
    std::vector<Vec2<T>> starts;
    checks::MapEdges<T> edges;
};

template <class T>
CheckedFrames<T> checkedFrames(const Scene<T>& scene) {
    CheckedFrames<T> c;
    c.frames = resolveUnderTest(scene);
    c.starts = frameStarts(scene, c.frames);
    c.edges = checks::computeEdges(scene.map.view());
    return c;
}

template <class T>
checks::FrameRecord<T> recordOf(const Scene<T>& scene, const CheckedFrames<T>& c, std::size_t f) {
    const FrameResult<T>& r = c.frames[f];
    SweepResult<T> result;
    result.status = r.contacts.empty() ? Status::Moved : Status::Blocked;
    result.position = r.position;
    result.contactCount = static_cast<std::int32_t>(r.contacts.size());
    result.startOverlapCount = static_cast<std::int32_t>(r.startOverlaps.size());
    return {scene.map.view(),  {c.starts[f], scene.box.size}, scene.moves[f], result,
            r.contacts.data(), r.startOverlaps.data()};
}

/// At the end of every frame, the box overlaps no solid tile it did not overlap at the frame's
/// start: CONTRACT.md's promise, with no allowance (the amended rounding rule keeps it).
template <class T>
std::string neverEndsInsideATileItDidNotStartIn(const Scene<T>& scene) {
    const CheckedFrames<T> c = checkedFrames(scene);
    checks::SafetyScratch scratch;
    for (std::size_t f = 0; f < c.frames.size(); ++f)
        if (const auto cell =
                checks::findNewOverlap(scene.map.view(), c.edges, Box<T>{c.starts[f], scene.box.size},
                                       c.frames[f].position, scratch))
            return "frame " + std::to_string(f) + ": ends inside tile " + cellText(*cell) +
                   ", which it did not start in";
    return {};
}

/// Over a run of frames, every solid tile the box overlaps at the start of a frame is one it
/// overlapped at the start of the first frame: the box never gets into a wall.
template <class T>
std::string neverGetsIntoAWall(const Scene<T>& scene) {
    const CheckedFrames<T> c = checkedFrames(scene);
    std::vector<Cell> first;
    std::vector<Cell> now;
    checks::listOverlaps(scene.map.view(), c.edges, scene.box.pos, scene.box.size, first);
    for (std::size_t f = 0; f < c.frames.size(); ++f) {
        checks::listOverlaps(scene.map.view(), c.edges, c.frames[f].position, scene.box.size, now);
        for (const Cell cell : now)
            if (std::find(first.begin(), first.end(), cell) == first.end())
                return "after frame " + std::to_string(f) + ": inside tile " + cellText(cell) +
                       ", which it was not in at the first frame's start";
    }
    return {};
}

/// After a hit on a face, the box ends touching it or short of it by less than one ulp.
template <class T>
std::string stopsJustTouching(const Scene<T>& scene) {
    const CheckedFrames<T> c = checkedFrames(scene);
    for (std::size_t f = 0; f < c.frames.size(); ++f)
        if (std::string why = checks::checkHitTilesLeftTouching(recordOf(scene, c, f), c.edges); !why.empty())
            return "frame " + std::to_string(f) + ": " + why;
    return {};
}

/// Every frame obeys every safety rule of checks/frame_safety.h: well formed, the exact start
/// overlaps, no new overlap at the end, hit tiles left touching, and the position between the
/// start and the exact end, or one ulp below it exactly where the rounding rule says.
template <class T>
std::string obeysTheSafetyRules(const Scene<T>& scene) {
    const CheckedFrames<T> c = checkedFrames(scene);
    checks::SafetyScratch scratch;
    for (std::size_t f = 0; f < c.frames.size(); ++f)
        if (const checks::SafetyViolation v =
                checks::checkFrameSafety(recordOf(scene, c, f), c.edges, scratch))
            return "frame " + std::to_string(f) + ": " + checks::ruleName(v.rule) + ": " + v.detail;
    return {};
}

/// The first frame (or none) at which 64 exact substeps along the straight path from each
/// frame's start see an overlap at substep k while `frames` report no hit by k/64 (rounded to
/// nearest, which is monotone).
template <class T>
std::string missedContactSeenBySubsteps(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames) {
    constexpr std::int64_t kSubsteps = 64;
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const auto seen =
            oracle::findFirstOverlapExact(map, oracle::toExact(Box<T>{starts[f], scene.box.size}),
                                          oracle::toExact(scene.moves[f]), kSubsteps);
        if (!seen.found()) continue;
        const T bound = oracle::fromRational<T>(seen.bracketHigh(), oracle::Rounding::NearestEven);
        if (frames[f].contacts.empty() || frames[f].contacts.front().time > bound)
            return "frame " + std::to_string(f) + ": substep " + std::to_string(seen.firstOverlap) +
                   "/64 overlaps, the first contact is later or missing";
    }
    return {};
}

/// Whenever the exact 64-substep oracle sees an overlap at substep k, the resolver hit something
/// no later than k/64 in that frame.
template <class T>
std::string substepOracleFindsNoMissedContact(const Scene<T>& scene) {
    return missedContactSeenBySubsteps(scene, resolveUnderTest(scene));
}

/// The same held against the exact reference instead of the resolver: an independent check of
/// the oracle the bit-for-bit claims trust, on the decisions where the substeps are conclusive
/// (an overlap seen at a substep is a contact that must have happened by then).
template <class T>
std::string exactReferenceAgreesWithSubsteps(const Scene<T>& scene) {
    return missedContactSeenBySubsteps(scene, oracle::resolveSceneExactRounded(scene));
}

/// A frame whose move is zero changes nothing and touches nothing, and reports as start overlaps
/// exactly the solid tiles the box overlaps (checked apart from the resolver). The scene's box
/// rarely starts inside a tile, so the claim also places it a quarter tile into the first solid
/// tile of the map and asks the same there; both scenes go to the resolver in one call.
template <class T>
std::string zeroMoveChangedNothing(const Scene<T>& scene, const std::vector<FrameResult<T>>& frames) {
    std::vector<Cell> overlapping;
    checks::listOverlaps(scene.map.view(), checks::computeEdges(scene.map.view()), scene.box.pos,
                         scene.box.size, overlapping);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!sameBits(frames[f].position.x, scene.box.pos.x) ||
            !sameBits(frames[f].position.y, scene.box.pos.y))
            return "frame " + std::to_string(f) + ": a zero move changed the position";
        if (!frames[f].contacts.empty())
            return "frame " + std::to_string(f) + ": a zero move reported a contact";
        if (frames[f].startOverlaps.size() != overlapping.size() ||
            !std::equal(overlapping.begin(), overlapping.end(), frames[f].startOverlaps.begin()))
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

template <class T>
std::string zeroMoveChangesNothing(const Scene<T>& scene) {
    const Scene<T> still = stillScene(scene);
    const auto first = std::find(scene.map.solid.begin(), scene.map.solid.end(), std::uint8_t{1});
    Scene<T> inside = still;
    bool hasInside = first != scene.map.solid.end();
    if (hasInside) {
        const auto index = static_cast<std::int32_t>(first - scene.map.solid.begin());
        const T i = static_cast<T>(index % scene.map.columns);
        const T j = static_cast<T>(index / scene.map.columns);
        inside.box.pos = {scene.map.origin.x + (i + T(0.25)) * scene.map.tileSize.x,
                          scene.map.origin.y + (j + T(0.25)) * scene.map.tileSize.y};
        hasInside = std::isfinite(inside.box.pos.x) && std::isfinite(inside.box.pos.y);
    }
    if (!hasInside) return zeroMoveChangedNothing(still, resolveUnderTest(still));
    const std::vector<std::vector<FrameResult<T>>> both = resolveUnderTest(still, inside);
    if (std::string why = zeroMoveChangedNothing(still, both[0]); !why.empty()) return why;
    if (std::string why = zeroMoveChangedNothing(inside, both[1]); !why.empty())
        return "inside a solid tile: " + why;
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
    // Away from overflow only: a scaled value that is no longer finite makes another scene.
    bool finite = std::isfinite(big.map.origin.x) && std::isfinite(big.map.origin.y) &&
                  std::isfinite(big.map.tileSize.x) && std::isfinite(big.map.tileSize.y) &&
                  std::isfinite(big.box.pos.x) && std::isfinite(big.box.pos.y) &&
                  std::isfinite(big.box.size.x) && std::isfinite(big.box.size.y);
    for (const auto& m : big.moves) finite = finite && std::isfinite(m.x) && std::isfinite(m.y);
    if (!finite || validateTileMap(big.map.view()) != MapError::None) return {};
    std::vector<std::vector<FrameResult<T>>> both = resolveUnderTest(scene, big);
    std::vector<FrameResult<T>>& expected = both[0];
    for (auto& f : expected) f.position = {f.position.x * kScale, f.position.y * kScale};
    return diffFrames(both[1], expected);
}

/// Mirroring the scene about x = 0 (or y = 0) mirrors every decision: the same tiles (mirrored),
/// normals flipped on that axis, the same times, and the other axis's position unchanged.
template <class T, Axis kAxis>
std::string mirroringMirrorsTheResult(const Scene<T>& scene) {
    const bool onX = kAxis == Axis::X;
    const T pos = onX ? scene.box.pos.x : scene.box.pos.y;
    const T size = onX ? scene.box.size.x : scene.box.size.y;
    const T mirroredPos = -(pos + size);
    if (oracle::toRational(mirroredPos) != -(oracle::toRational(pos) + oracle::toRational(size)))
        return {};  // not exact: no claim
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
    std::vector<std::vector<FrameResult<T>>> both = resolveUnderTest(scene, m);
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
std::string translatingByWholeTilesKeepsDecisions(const Scene<T>& scene) {
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
        return {};
    if (validateTileMap(moved.map.view()) != MapError::None) return {};
    Compare what;
    what.positionX = what.positionY = false;
    std::vector<std::vector<FrameResult<T>>> both = resolveUnderTest(moved, scene);
    std::vector<FrameResult<T>>& got = both[0];
    std::vector<FrameResult<T>>& expected = both[1];
    got.resize(1);  // later frames start from rounded positions that may differ
    expected.resize(1);
    return diffFrames(got, expected, what);
}

/// Whether the box at `pos` stands on the map: a solid tile's top exactly at its bottom, under
/// its open x span.
template <class T>
bool standsOnFloor(const oracle::ExactTileMap& map, const Scene<T>& scene, Vec2<T> pos) {
    const oracle::ExactRect box = oracle::rectOf(oracle::toExact(Box<T>{pos, scene.box.size}));
    for (std::int32_t j = 0; j < map.rows; ++j)
        for (std::int32_t i = 0; i < map.columns; ++i) {
            if (!map.isSolid(i, j)) continue;
            const oracle::ExactRect t = map.tileRect(i, j);
            if (t.min.y == box.max.y && t.min.x < box.max.x && t.max.x > box.min.x) return true;
        }
    return false;
}

/// A box standing on a floor and pushed down by gravity lands at once (a floor contact at time
/// 0) and keeps its height bit for bit, and its x too when it does not walk. Every frame that
/// starts on a floor is checked, so a box that sinks into or falls through the floor fails.
template <class T>
std::string restingContactIsStable(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = resolveUnderTest(scene);
    const std::vector<Vec2<T>> starts = frameStarts(scene, frames);
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Vec2<T> m = scene.moves[f];
        if (!(m.y > 0) || !standsOnFloor(map, scene, starts[f])) continue;
        const auto& hits = frames[f].contacts;
        const bool landed = std::any_of(hits.begin(), hits.end(),
                                        [](const Contact<T>& c) { return c.normal.y == -1 && c.time == 0; });
        if (!landed)
            return "frame " + std::to_string(f) + ": standing on a floor, no floor contact at time 0";
        if (!sameBits(frames[f].position.y, starts[f].y) ||
            (m.x == 0 && !sameBits(frames[f].position.x, starts[f].x)))
            return "frame " + std::to_string(f) + ": resting box moved from (" + hex(starts[f].x) + ", " +
                   hex(starts[f].y) + ") to (" + hex(frames[f].position.x) + ", " +
                   hex(frames[f].position.y) + ")";
    }
    return {};
}

/// A box standing on a floor (a solid tile under its open x span, top exactly at its bottom)
/// and moving sideways and down is never stopped on x by a tile of that floor: no snag on seams.
template <class T>
std::string slidingAlongFloorNeverSnags(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> frames = resolveUnderTest(scene);
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
        if (!sameBits(frames[f].position.y, starts[f].y))
            return "frame " + std::to_string(f) + ": left the floor it stood on, moving down";
        for (const Contact<T>& c : frames[f].contacts)
            if (c.normal.x != 0 && map.tileRect(c.tile.i, c.tile.j).min.y == box.max.y)
                return "frame " + std::to_string(f) + ": snagged on the side of floor tile " +
                       cellText(c.tile);
    }
    return {};
}

/// Every value that is bad input somewhere: NaN and both infinities anywhere, zero and -1 as a size.
/// Each corruption of the scene (four fields) is refused: the library returns InvalidInput with
/// no contact and no NaN, the scene reader an error naming the field.
template <class T>
std::string badInputIsRejected(const Scene<T>& scene) {
    const T values[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                        -std::numeric_limits<T>::infinity(), T(0), T(-1)};
    const char* fields[] = {"box[0]", "box[3]", "moves[last][0]", "box[1]"};
    for (int field = 0; field < 4; ++field)
        for (const T bad : values) {
            const bool nonFinite = !std::isfinite(bad);
            if (!nonFinite && field != 1) continue;  // zero and -1 are only bad as sizes
            Scene<T> s = scene;
            switch (field) {
                case 0:
                    s.box.pos.x = bad;
                    break;
                case 1:
                    s.box.size.y = bad;
                    break;
                case 2:
                    s.moves.back().x = bad;
                    break;
                default:
                    s.box.pos.y = bad;
                    break;
            }
            Contact<T> contacts[8];
            Cell overlaps[8];
            const SweepResult<T> r =
                resolveMove<T>({s.map.view(), s.box, s.moves.back()}, {contacts, 8, overlaps, 8});
            const std::string at = std::string(fields[field]) + " = " + hex(bad) + ": ";
            if (r.status != Status::InvalidInput) return at + "not refused as InvalidInput";
            if (r.contactCount != 0 || std::isnan(r.position.x) || std::isnan(r.position.y))
                return at + "a refused frame reported contacts or NaN";
            // The scene reader, on the same field written as the format would carry it.
            std::string line = formatScene(scene);
            const std::string text =
                nonFinite ? std::string(std::isnan(bad) ? "\"nan\"" : (bad > 0 ? "\"inf\"" : "\"-inf\""))
                          : std::string(bad == 0 ? "0" : "-1");
            Scene<T> marked = scene;  // find the field's text by writing a marker there
            const T marker = T(1234567);
            switch (field) {
                case 0:
                    marked.box.pos.x = marker;
                    break;
                case 1:
                    marked.box.size.y = marker;
                    break;
                case 2:
                    marked.moves.back().x = marker;
                    break;
                default:
                    marked.box.pos.y = marker;
                    break;
            }
            line = formatScene(marked);
            const std::string markerText = "\"" + std::string(hex(marker)) + "\"";
            const std::size_t where = line.find(markerText);
            if (where == std::string::npos) return at + "cannot find the field in the scene line";
            line.replace(where, markerText.size(), text);
            const SceneParse<T> parsed = parseScene<T>(line);
            if (parsed.scene) return at + "the scene reader accepted it";
            if (parsed.error.find(field == 2 ? "move" : "box") == std::string::npos)
                return at + "the error does not name the field: " + parsed.error;
        }
    return {};
}

/// sweepBox, the single-tile entry point, agrees with the exact reference's single-tile test on
/// the first frame's box and move against every solid tile of the map (up to 64): the same
/// state, contact axis and time (rounded to nearest).
template <class T>
std::string sweepBoxMatchesTheReference(const Scene<T>& scene) {
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    const Vec2<T> d = scene.moves.front();
    const int sx = d.x > 0 ? 1 : (d.x < 0 ? -1 : 0);
    const int sy = d.y > 0 ? 1 : (d.y < 0 ? -1 : 0);
    int tested = 0;
    for (std::int32_t j = 0; j < map.rows && tested < 64; ++j)
        for (std::int32_t i = 0; i < map.columns && tested < 64; ++i) {
            if (!map.isSolid(i, j)) continue;
            ++tested;
            const T x0 = scene.map.origin.x + static_cast<T>(i) * scene.map.tileSize.x;
            const T y0 = scene.map.origin.y + static_cast<T>(j) * scene.map.tileSize.y;
            const T x1 = scene.map.origin.x + static_cast<T>(i + 1) * scene.map.tileSize.x;
            const T y1 = scene.map.origin.y + static_cast<T>(j + 1) * scene.map.tileSize.y;
            const bool xExposed = !map.isSolid(i - sx, j);
            const bool yExposed = !map.isSolid(i, j - sy);
            const BoxSweepOutput<T> got = sweepBox<T>({scene.box, d, {x0, y0}, {x1, y1}, xExposed, yExposed});
            const oracle::ExactSweepOutput want = oracle::sweepTileExact(
                {oracle::toExact(scene.box), oracle::toExact(d), map.tileRect(i, j), xExposed, yExposed});
            const std::string at = "tile " + cellText({i, j}) + ": ";
            const BoxSweepState state = want.state == oracle::ExactSweepState::Blocks ? BoxSweepState::Blocks
                                        : want.state == oracle::ExactSweepState::Misses
                                            ? BoxSweepState::Misses
                                            : BoxSweepState::StartsOverlapping;
            if (got.state != state) return at + "sweepBox state differs from the reference";
            if (state != BoxSweepState::Blocks) continue;
            if (got.axis != want.axis) return at + "contact axis differs";
            const T time = oracle::fromRational<T>(want.time, oracle::Rounding::NearestEven);
            if (!sameBits(got.time, time)) return at + "time " + hex(got.time) + " != " + hex(time);
        }
    return {};
}

}  // namespace

template <class T>
const std::vector<Claim<T>>& allClaims() {
    // Scope: what an outside resolver is held to (scene_checks.h, ClaimScope).
    using S = ClaimScope;
    static const std::vector<Claim<T>> claims = {
        {"matchesExactReferenceBitForBit", &matchesExactReferenceBitForBit<T>, S::BitForBit},
        {"neverEndsInsideATileItDidNotStartIn", &neverEndsInsideATileItDidNotStartIn<T>, S::Safety},
        {"neverGetsIntoAWall", &neverGetsIntoAWall<T>, S::Safety},
        {"stopsJustTouching", &stopsJustTouching<T>, S::Safety},
        {"obeysTheSafetyRules", &obeysTheSafetyRules<T>, S::Safety},
        {"substepOracleFindsNoMissedContact", &substepOracleFindsNoMissedContact<T>, S::Safety},
        {"exactReferenceAgreesWithSubsteps", &exactReferenceAgreesWithSubsteps<T>, S::Internal},
        {"zeroMoveChangesNothing", &zeroMoveChangesNothing<T>, S::Safety},
        {"scalingByPowerOfTwoScalesTheResult", &scalingByPowerOfTwoScalesTheResult<T>, S::Safety},
        {"mirroringXMirrorsTheResult", &mirroringMirrorsTheResult<T, Axis::X>, S::Safety},
        {"mirroringYMirrorsTheResult", &mirroringMirrorsTheResult<T, Axis::Y>, S::Safety},
        {"translatingByWholeTilesKeepsDecisions", &translatingByWholeTilesKeepsDecisions<T>, S::Safety},
        {"restingContactIsStable", &restingContactIsStable<T>, S::Safety},
        {"slidingAlongFloorNeverSnags", &slidingAlongFloorNeverSnags<T>, S::Safety},
        {"badInputIsRejected", &badInputIsRejected<T>, S::Internal},
        {"sweepBoxMatchesTheReference", &sweepBoxMatchesTheReference<T>, S::Internal},
        {"storesContactsAtExactCapacity", &storesContactsAtExactCapacity<T>, S::Internal},
        {"reportsEachCErrorByItsCause", &reportsEachCErrorByItsCause<T>, S::Internal},
    };
    return claims;
}

template <class T>
std::string checkClaim(const Claim<T>& claim, const Scene<T>& scene) {
    try {
        return claim.check(scene);
    } catch (const ResolverFailure& failure) {
        return std::string("resolver failed: ") + failure.what();
    } catch (const std::exception& error) {
        return std::string("the check threw: ") + error.what();
    }
}

template <class T>
const Claim<T>* findClaim(const std::string& name) {
    for (const Claim<T>& c : allClaims<T>())
        if (name == c.name) return &c;
    return nullptr;
}

namespace {

/// Whether the contract's rounding rule rounded some axis down, where rounding toward the start
/// would have carried the far edge over a grid line: the two roundings differ.
template <class T>
bool roundedDown(const oracle::ExactFrame& f) {
    const FrameResult<T> rounded = oracle::roundFrame<T>(f);
    const T startX = oracle::fromRational<T>(f.start.x, oracle::Rounding::NearestEven);
    const T startY = oracle::fromRational<T>(f.start.y, oracle::Rounding::NearestEven);
    return rounded.position.x != oracle::roundToward<T>(f.position.x, startX) ||
           rounded.position.y != oracle::roundToward<T>(f.position.y, startY);
}

/// Whether an exact time lies exactly halfway between two neighbouring T values (the
/// ties-to-even case of the frame times' rounding).
template <class T>
bool halfwayBetweenValues(const Rational& t) {
    const T below = oracle::fromRational<T>(t, oracle::Rounding::TowardNegative);
    const T above = oracle::fromRational<T>(t, oracle::Rounding::TowardPositive);
    return below != above && (oracle::toRational(below) + oracle::toRational(above)) / 2 == t;
}

/// Whether, in the first step of some frame with both axes moving, a solid tile is first
/// reached at exactly t = 1 (which the contract does not count as a hit).
template <class T>
bool reachesATileAtTheEnd(const Scene<T>& scene, const std::vector<oracle::ExactFrame>& frames) {
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const oracle::ExactVec2 d = oracle::toExact(scene.moves[f]);
        if (d.x == 0 || d.y == 0) continue;
        for (std::int32_t j = 0; j < map.rows; ++j)
            for (std::int32_t i = 0; i < map.columns; ++i) {
                if (!map.isSolid(i, j)) continue;
                const oracle::ExactSweepOutput sweep =
                    oracle::sweepTileExact({{frames[f].start, frames[f].size}, d, map.tileRect(i, j)});
                if (!sweep.overlap.empty && sweep.overlap.low.isFinite() && sweep.overlap.low.value == 1)
                    return true;
            }
    }
    return false;
}

/// The bits between the finest set bit and the largest magnitude among a scene's inputs: what
/// sets the width of the resolver's integers (above about 60 it needs more than 128 bits for
/// products; above about 92, more than 192).
template <class T>
int latticeSpan(const Scene<T>& scene) {
    int lowest = std::numeric_limits<int>::max();
    int highest = std::numeric_limits<int>::min();
    const auto note = [&](T v) {
        if (v == 0) return;
        int e = 0;
        const T fraction = std::frexp(v, &e);
        auto m = static_cast<std::int64_t>(std::ldexp(fraction, std::numeric_limits<T>::digits));
        int low = e - std::numeric_limits<T>::digits;
        while (m % 2 == 0) {
            m /= 2;
            ++low;
        }
        lowest = std::min(lowest, low);
        highest = std::max(highest, e);
    };
    note(scene.map.origin.x);
    note(scene.map.origin.y);
    note(scene.map.tileSize.x);
    note(scene.map.tileSize.y);
    note(scene.box.pos.x);
    note(scene.box.pos.y);
    note(scene.box.size.x);
    note(scene.box.size.y);
    for (const Vec2<T>& m : scene.moves) {
        note(m.x);
        note(m.y);
    }
    return highest >= lowest ? highest - lowest : 0;
}

/// The least frexp exponent of a scene's nonzero inputs (a large number when all are zero).
template <class T>
int smallestInputExponent(const Scene<T>& scene) {
    int lowest = std::numeric_limits<int>::max();
    const auto note = [&lowest](T v) {
        if (v == 0 || !std::isfinite(v)) return;
        int e = 0;
        (void)std::frexp(v, &e);
        lowest = std::min(lowest, e);
    };
    for (const Vec2<T>& v : {scene.map.origin, scene.map.tileSize, scene.box.pos, scene.box.size}) {
        note(v.x);
        note(v.y);
    }
    for (const Vec2<T>& m : scene.moves) {
        note(m.x);
        note(m.y);
    }
    return lowest;
}

/// The most significant bits any input of the scene needs (its significand without trailing zeros).
template <class T>
int widestSignificand(const Scene<T>& scene) {
    int widest = 0;
    const auto note = [&widest](T v) {
        if (v == 0 || !std::isfinite(v)) return;
        int e = 0;
        auto m = static_cast<std::int64_t>(
            std::ldexp(std::frexp(std::fabs(v), &e), std::numeric_limits<T>::digits));
        int bits = std::numeric_limits<T>::digits;
        while (m % 2 == 0) {
            m /= 2;
            --bits;
        }
        widest = std::max(widest, bits);
    };
    for (const Vec2<T>& v : {scene.map.origin, scene.map.tileSize, scene.box.pos, scene.box.size}) {
        note(v.x);
        note(v.y);
    }
    for (const Vec2<T>& m : scene.moves) {
        note(m.x);
        note(m.y);
    }
    return widest;
}

/// The path that decided the scene's frames (tilesweep/frame_stats.h): "exact" when any frame fell
/// back to the lattice, else "filtered" when any predicate needed the exact refinement, else "fast".
template <class T>
const char* decisionPathOf(const Scene<T>& scene) {
    DecisionPath worst = DecisionPath::Fast;
    Vec2<T> start = scene.box.pos;
    std::vector<Contact<T>> contacts(64);
    std::vector<Cell> overlaps(64);
    for (const Vec2<T>& move : scene.moves) {
        FrameStats stats;
        const SweepResult<T> r = resolveMove<T>({scene.map.view(), {start, scene.box.size}, move},
                                                {contacts.data(), 64, overlaps.data(), 64, &stats});
        const DecisionPath path = stats.path;
        if (static_cast<int>(path) > static_cast<int>(worst)) worst = path;
        start = r.position;
    }
    return worst == DecisionPath::Fast ? "fast" : (worst == DecisionPath::Filtered ? "filtered" : "exact");
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
    bool down = false;
    bool timeTie = false;
    for (const auto& f : frames) {
        hit = hit || !f.contacts.empty();
        startOverlap = startOverlap || !f.startOverlaps.empty();
        down = down || roundedDown<T>(f);
        for (std::size_t k = 0; k < f.contacts.size(); ++k) {
            const auto& c = f.contacts[k];
            tie = tie || c.tie;
            touch0 = touch0 || c.time == 0;
            twoStep = twoStep || c.step == 2;
            timeTie = timeTie || halfwayBetweenValues<T>(c.time);
            if (k > 0 && f.contacts[k - 1].step == c.step && f.contacts[k - 1].normal == c.normal)
                seam = true;
        }
    }
    tags.push_back(hit ? "hit" : "miss");
    if (down) tags.push_back("rounded-down");
    if (tie) tags.push_back("tie");
    if (timeTie) tags.push_back("time-tie");
    if (reachesATileAtTheEnd(scene, frames)) tags.push_back("reaches-at-end");
    if (touch0) tags.push_back("touch-at-0");
    if (twoStep) tags.push_back("two-step");
    if (seam) tags.push_back("seam");
    if (startOverlap) tags.push_back("start-overlap");
    if (std::find(scene.map.solid.begin(), scene.map.solid.end(), std::uint8_t{1}) == scene.map.solid.end())
        tags.push_back("empty-map");
    const T huge = std::ldexp(T(1), 40);
    if (std::any_of(scene.moves.begin(), scene.moves.end(),
                    [huge](Vec2<T> m) { return std::fabs(m.x) >= huge || std::fabs(m.y) >= huge; }))
        tags.push_back("huge-move");
    const int span = latticeSpan(scene);
    if (span > 60) tags.push_back("lattice-wide");
    if (span > 92) tags.push_back("lattice-192");
    if (std::fabs(scene.map.origin.x) >= T(1048576) || std::fabs(scene.map.origin.y) >= T(1048576))
        tags.push_back("far-origin");
    const std::string path = decisionPathOf(scene);
    tags.push_back("path:" + path);
    if (path != "fast") tags.push_back("fallback");
    // A near tie its refinement settled: no exact tie, yet the filter could not decide alone.
    if (path == "filtered" && !tie && hit) tags.push_back("near-tie-refined");
    // Code only double frames reach: a refinement on inputs of more than 27 significant bits,
    // where TwoProduct's split leaves both low halves nonzero (productError's aLow * bLow term)
    // and contact times are exact pairs rounded by roundTimeToDouble's remainder test.
    if (std::is_same<T, double>::value && path == "filtered" && widestSignificand(scene) > 27)
        tags.push_back("full-precision-refined");
    // The tiny end of the range: some nonzero input below 2^-500 (double) or 2^-100 (float),
    // where a product of two inputs would underflow a double (or come near it).
    if (smallestInputExponent(scene) < (std::is_same<T, float>::value ? -100 : -500)) tags.push_back("tiny");
    // Capacity boundaries (mover.h): the contact bound at the inline limit, or past it (the wide
    // path), and frames with many contacts (an exact count the buffers are sized to).
    const std::int32_t bound = maxContacts(scene.box.size, scene.map.tileSize);
    if (bound == kInlineContacts) tags.push_back("bound-inline-limit");
    if (bound > kInlineContacts && bound <= kInlineContacts + 2) tags.push_back("bound-wide");
    std::size_t most = 0;
    for (const auto& f : frames) most = std::max(most, f.contacts.size());
    if (most >= 16) tags.push_back("many-contacts");
    // The C error claim's unrepresentable-edge causes need tile * 2^(digits + 2) finite.
    constexpr int digits = std::numeric_limits<T>::digits;
    if (std::isfinite(std::ldexp(scene.map.tileSize.x, digits + 2)) &&
        std::isfinite(std::ldexp(scene.map.tileSize.y, digits + 2)))
        tags.push_back("edge-causes-built");
    return tags;
}

template const std::vector<Claim<float>>& allClaims<float>();
template const std::vector<Claim<double>>& allClaims<double>();
template const Claim<float>* findClaim<float>(const std::string&);
template const Claim<double>* findClaim<double>(const std::string&);
template std::string checkClaim<float>(const Claim<float>&, const Scene<float>&);
template std::string checkClaim<double>(const Claim<double>&, const Scene<double>&);
template std::vector<std::string> classifyScene<float>(const Scene<float>&);
template std::vector<std::string> classifyScene<double>(const Scene<double>&);

}  // namespace tilesweep::properties
