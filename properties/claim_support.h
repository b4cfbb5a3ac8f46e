// SPDX-License-Identifier: MIT
#pragma once

// What the claims (safety_claims.cpp, exact_reference_claims.cpp, metamorphic_claims.cpp,
// game_feel_claims.cpp) share: bit-exact comparison of frame lists with a readable difference,
// the frames of a scene as the shared safety checks see them, and the substep oracle's test for
// a missed contact. Internal to the property suite.

#include "frame_safety.h"  // checks/
#include "resolver_under_test.h"

#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/oracle/substep/substep_oracle.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

namespace tilesweep::properties::claim_support {

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

inline std::string cellText(Cell c) { return "(" + std::to_string(c.i) + ", " + std::to_string(c.j) + ")"; }

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

/// The frames of a scene as the shared safety checks see them (checks/frame_safety.h).
template <class T>
struct CheckedFrames {
    std::vector<FrameResult<T>> frames;
    std::vector<Vec2<T>> starts;
    checks::MapEdges<T> edges;
};

template <class T>
CheckedFrames<T> checkedFrames(const Scene<T>& scene, SceneResolver& resolver) {
    CheckedFrames<T> c;
    c.frames = framesFrom(resolver, scene);
    c.starts = frameStarts(scene, c.frames);
    c.edges = checks::computeEdges(scene.map.view());
    return c;
}

template <class T>
checks::FrameRecord<T> recordOf(const Scene<T>& scene, const CheckedFrames<T>& c, std::size_t f) {
    const FrameResult<T>& r = c.frames[f];
    ResolveResult<T> result;
    result.status = r.contacts.empty() ? ResolveStatus::Moved : ResolveStatus::Blocked;
    result.position = r.position;
    result.contactCount = static_cast<std::int32_t>(r.contacts.size());
    result.startOverlapCount = static_cast<std::int32_t>(r.startOverlaps.size());
    return {scene.map.view(),  {c.starts[f], scene.box.size}, scene.moves[f], result,
            r.contacts.data(), r.startOverlaps.data()};
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

}  // namespace tilesweep::properties::claim_support
