// SPDX-License-Identifier: MIT
#pragma once

// The judge of one scene: each frame an implementation returned, held against the exact frame
// (oracle/exact) that starts from the same position, so that a multi-frame scene that drifts
// early is still judged fairly later. Shared by the tolerance audit (audit.cpp), which runs the
// implementations in process, and the engine rates (engine_rates.cpp), which run outside
// resolvers a batch at a time. The metrics are audit.h's `Metric`; besides counting them, the
// judge measures by how much an implementation breaks the safety claims (`SceneVerdict`'s
// distances), which is what an engine's tolerance is measured from.

#include "frame_safety.h"  // checks/

#include "tilesweep/audit/audit.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/exact_sweep.h"
#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>
#include <vector>

namespace tilesweep::audit::judge {

using oracle::ExactBox;
using oracle::ExactFrame;
using oracle::ExactRect;
using oracle::ExactTileMap;
using oracle::ExactVec2;
using oracle::Rational;

// ---- ulps -----------------------------------------------------------------------------------

/// The error of `got` against the contract's `expected`, in ulps of T at the magnitude of the
/// expected value, floored at the tile size: |got - expected| / ulp(max(|expected|, tile)), rounded
/// up; 0 exactly when the two are equal. (Counting representable values between them would call
/// 1e-7 against 0 a billion ulps, through the subnormals; this counts in the spacing a value at
/// that place in the map has.)
template <class T>
std::uint64_t ulpError(T got, T expected, T tile) {
    if (!std::isfinite(got) || !std::isfinite(expected)) return kNonFiniteUlps;
    if (got == expected) return 0;
    const T scale = std::max(std::fabs(expected), tile);
    const T ulp = std::nextafter(scale, std::numeric_limits<T>::infinity()) - scale;
    const Rational error =
        abs(oracle::toRational(got) - oracle::toRational(expected)) / oracle::toRational(ulp);
    const double ratio = std::ceil(error.convert_to<double>());
    if (!(ratio < 1.8e19)) return kNonFiniteUlps - 1;
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(ratio));
}

template <class T>
bool sameBits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T>
bool isFinite(Vec2<T> v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

// ---- contacts -------------------------------------------------------------------------------

struct ContactKey {
    std::int32_t i, j;
    int nx, ny;
    bool operator<(const ContactKey& o) const {
        return std::tie(j, i, nx, ny) < std::tie(o.j, o.i, o.nx, o.ny);
    }
    bool operator==(const ContactKey& o) const { return i == o.i && j == o.j && nx == o.nx && ny == o.ny; }
};

template <class C>
std::vector<ContactKey> decisionKeys(const std::vector<C>& contacts) {
    std::vector<ContactKey> keys;
    keys.reserve(contacts.size());
    for (const C& c : contacts) keys.push_back({c.tile.i, c.tile.j, c.normal.x, c.normal.y});
    std::sort(keys.begin(), keys.end());
    return keys;
}

template <class C>
bool mentions(const std::vector<C>& contacts, Cell cell) {
    return std::any_of(contacts.begin(), contacts.end(), [&](const C& c) { return c.tile == cell; });
}

// ---- the judge ------------------------------------------------------------------------------

/// What the exact reference says about one frame from one start, with the corner and floor
/// facts the metrics need; computed once per (frame, start) and shared by every implementation.
template <class T>
struct FrameFacts {
    Vec2<T> start{};
    Vec2<T> move{};  ///< the frame's displacement
    ExactFrame exact;
    FrameResult<T> rounded;
    std::vector<Cell> clipTiles;        ///< first-step contacts that clip a corner
    std::vector<Cell> missTiles;        ///< corner-missed tiles in the swept bounds, never touched exactly
    bool cornerPass = false;            ///< some miss is a path exactly through a corner point
    std::int32_t restingRow = -1;       ///< the floor row the box starts resting on, or -1
    std::vector<Cell> landedPlatforms;  ///< one-way tiles the exact frame lands on
    std::vector<Cell> passedPlatforms;  ///< one-way tiles in the straight move's swept bounds it passes
    std::int32_t platformRow = -1;      ///< the row of the one-way tile the box starts standing on, or -1
};

/// One implementation's verdicts on one scene. The distances are in the map's units (pixels),
/// the largest over the scene's frames, 0 when the claim held: what tolerance the claim would
/// need to hold on this scene.
struct SceneVerdict {
    std::array<bool, kMetricCount> failed{};
    bool clipEligible = false, cornerEligible = false, restingEligible = false;
    /// Frames that land on a platform, pass one, start standing on one (the platform metrics' trials).
    bool platformLandingEligible = false, platformPassEligible = false, platformRestingEligible = false;
    std::uint64_t positionUlps = 0;
    bool hasTime = false;
    double timeError = 0;
    double insideDepth = 0;  ///< how deep inside a tile it did not start in (the smaller overlap side)
    double shortfall = 0;    ///< how far short of touching, on an axis the exact frame stops on
    double overshoot = 0;    ///< how far past the exact end, along the frame's motion
};

/// `a - b` as a double (the difference of two exact values, rounded once).
inline double difference(const Rational& a, const Rational& b) {
    return Rational(a - b).convert_to<double>();
}

template <class T>
class SceneJudge {
public:
    explicit SceneJudge(const Scene<T>& scene)
        : scene_(scene), map_(oracle::toExact(scene.map)), edges_(checks::computeEdges(scene.map.view())) {
        for (std::int32_t j = 0; j < scene.map.rows; ++j)
            for (std::int32_t i = 0; i < scene.map.columns; ++i) {
                if (map_.isSolid(i, j)) solid_.push_back({i, j});
                if (map_.isOneWay(i, j)) oneWay_.push_back({i, j});
            }
        facts_.resize(scene.moves.size());
    }

    /// The exact facts of frame k started from `start`.
    const FrameFacts<T>& facts(std::size_t k, Vec2<T> start) {
        for (const FrameFacts<T>& f : facts_[k])
            if (sameBits(f.start.x, start.x) && sameBits(f.start.y, start.y)) return f;
        facts_[k].push_back(computeFacts(start, scene_.moves[k]));
        return facts_[k].back();
    }

    /// Judges the frames an implementation returned, each against the exact frame from its start.
    SceneVerdict judge(const std::vector<FrameResult<T>>& frames) {
        SceneVerdict v;
        Vec2<T> start = scene_.box.pos;
        for (std::size_t k = 0; k < frames.size() && k < scene_.moves.size(); ++k) {
            const FrameFacts<T>& f = facts(k, start);
            const FrameResult<T>& got = frames[k];
            judgeFrame(f, got, v);
            if (!isFinite(got.position)) {
                v.failed[static_cast<std::size_t>(Metric::NonFinite)] = true;
                v.positionUlps = kNonFiniteUlps;
                break;
            }
            start = got.position;
        }
        v.failed[static_cast<std::size_t>(Metric::Position)] = v.positionUlps > 0;
        v.failed[static_cast<std::size_t>(Metric::Time)] = v.hasTime && v.timeError > 0;
        return v;
    }

    /// Only whether the decisions match on every frame (for the epsilon search).
    bool decisionsMatch(const std::vector<FrameResult<T>>& frames) {
        Vec2<T> start = scene_.box.pos;
        for (std::size_t k = 0; k < frames.size() && k < scene_.moves.size(); ++k) {
            const FrameFacts<T>& f = facts(k, start);
            if (decisionKeys(frames[k].contacts) != decisionKeys(f.exact.contacts)) return false;
            if (!isFinite(frames[k].position)) return false;
            start = frames[k].position;
        }
        return true;
    }

    const Scene<T>& scene() const { return scene_; }

private:
    FrameFacts<T> computeFacts(Vec2<T> start, Vec2<T> move) {
        FrameFacts<T> f;
        f.start = start;
        f.move = move;
        const ExactBox box{oracle::toExact(start), oracle::toExact(scene_.box.size)};
        const ExactVec2 d = oracle::toExact(move);
        f.exact = oracle::resolveFrameExact(map_, box, d);
        f.rounded = oracle::roundFrame<T>(f.exact);

        // Corner facts for the straight move (the first step): tiles in its swept bounds.
        if (move.x != T(0) && move.y != T(0)) {
            const ExactRect sweptA = oracle::rectOf(box);
            const ExactBox moved{{box.pos.x + d.x, box.pos.y + d.y}, box.size};
            const ExactRect sweptB = oracle::rectOf(moved);
            const ExactRect swept{
                {std::min(sweptA.min.x, sweptB.min.x), std::min(sweptA.min.y, sweptB.min.y)},
                {std::max(sweptA.max.x, sweptB.max.x), std::max(sweptA.max.y, sweptB.max.y)}};
            for (const Cell& c : solid_) {
                const ExactRect tile = map_.tileRect(c.i, c.j);
                if (!oracle::overlaps(swept, tile)) continue;
                const oracle::ExactSweepOutput s = oracle::sweepTileExact({box, d, tile, true, true});
                if (s.state == oracle::ExactSweepState::Blocks) {
                    const oracle::TimeInterval& own = s.axis == Axis::X ? s.xTimes : s.yTimes;
                    const oracle::TimeInterval& other = s.axis == Axis::X ? s.yTimes : s.xTimes;
                    // A clip: entered on one axis (not a tie), and the overlap window closes
                    // on the other axis inside the frame, before the box would leave the tile
                    // on the first: unstopped, it would pass the corner and come out.
                    const oracle::ExtendedTime one = oracle::ExtendedTime::finite(Rational(1));
                    const bool clips =
                        !s.tie && other.high < own.high && s.overlap.high == other.high && other.high < one;
                    const bool recorded = std::any_of(
                        f.exact.contacts.begin(), f.exact.contacts.end(),
                        [&](const oracle::ExactContact& e) { return e.step == 1 && e.tile == c; });
                    if (clips && recorded) f.clipTiles.push_back(c);
                } else if (s.state == oracle::ExactSweepState::Misses && !s.xTimes.empty && !s.yTimes.empty &&
                           s.xTimes.meetsOpenUnitInterval() && s.yTimes.meetsOpenUnitInterval() &&
                           !mentions(f.exact.contacts, c)) {
                    f.missTiles.push_back(c);
                    if (s.xTimes.low == s.yTimes.high || s.yTimes.low == s.xTimes.high) f.cornerPass = true;
                }
            }
        }

        platformFacts(f, box, d);

        // Resting: the box's bottom on the top of a solid tile it overlaps on x, cell above empty.
        const Rational bottom = box.pos.y + box.size.y;
        const Rational row = (bottom - map_.origin.y) / map_.tileSize.y;
        if (boost::multiprecision::denominator(row) == 1 && row >= 0 && row < map_.rows) {
            const auto j =
                static_cast<std::int32_t>(boost::multiprecision::numerator(row).convert_to<long long>());
            for (const Cell& c : solid_) {
                if (c.j != j || map_.isSolid(c.i, c.j - 1)) continue;
                const ExactRect tile = map_.tileRect(c.i, c.j);
                if (box.pos.x < tile.max.x && box.pos.x + box.size.x > tile.min.x) {
                    f.restingRow = j;
                    break;
                }
            }
        }
        return f;
    }

    /// The one-way facts of a frame: the platforms the exact frame lands on, those in the straight
    /// move's swept bounds that it passes (jumping up through, entering from the side, starting
    /// inside), and the platform row the box starts standing on (its bottom on a one-way tile's top,
    /// over it on x).
    void platformFacts(FrameFacts<T>& f, const ExactBox& box, const ExactVec2& d) const {
        if (oneWay_.empty()) return;
        for (const oracle::ExactContact& e : f.exact.contacts)
            if (map_.isOneWay(e.tile.i, e.tile.j)) f.landedPlatforms.push_back(e.tile);
        const ExactRect from = oracle::rectOf(box);
        const ExactRect to = oracle::rectOf(ExactBox{{box.pos.x + d.x, box.pos.y + d.y}, box.size});
        const ExactRect swept{{std::min(from.min.x, to.min.x), std::min(from.min.y, to.min.y)},
                              {std::max(from.max.x, to.max.x), std::max(from.max.y, to.max.y)}};
        const Rational bottom = box.pos.y + box.size.y;
        for (const Cell& c : oneWay_) {
            const ExactRect tile = map_.tileRect(c.i, c.j);
            if (oracle::overlaps(swept, tile) && !mentions(f.exact.contacts, c))
                f.passedPlatforms.push_back(c);
            if (f.platformRow < 0 && bottom == tile.min.y && from.min.x < tile.max.x &&
                from.max.x > tile.min.x)
                f.platformRow = c.j;
        }
    }

    /// The platform metrics of one frame: falling through a platform the exact frame lands on,
    /// being stopped by one it passes, snagging on a seam of the platform the box stands on.
    void judgePlatforms(const FrameFacts<T>& f, const FrameResult<T>& got, SceneVerdict& v) const {
        auto fail = [&](Metric m) { v.failed[static_cast<std::size_t>(m)] = true; };
        if (!f.landedPlatforms.empty()) v.platformLandingEligible = true;
        if (!f.passedPlatforms.empty()) v.platformPassEligible = true;
        if (f.platformRow >= 0) v.platformRestingEligible = true;
        if (isFinite(got.position)) {
            const Rational bottom =
                oracle::toRational(got.position.y) + oracle::toRational(scene_.box.size.y);
            for (const Cell& c : f.landedPlatforms)
                if (bottom > map_.tileRect(c.i, c.j).min.y) fail(Metric::PlatformFall);
        }
        for (const Cell& c : f.passedPlatforms)
            if (mentions(got.contacts, c)) fail(Metric::PlatformBlock);
        // A jump that the exact frame lets through on y, ended lower than the contract's position:
        // held back under a platform it should have passed.
        const bool exactStopsOnY = std::any_of(f.exact.contacts.begin(), f.exact.contacts.end(),
                                               [](const oracle::ExactContact& e) { return e.normal.y != 0; });
        if (!f.passedPlatforms.empty() && f.move.y < T(0) && !exactStopsOnY &&
            got.position.y > f.rounded.position.y)
            fail(Metric::PlatformBlock);
        if (f.platformRow >= 0)
            for (const Contact<T>& c : got.contacts)
                if (c.normal.x != 0 && c.tile.j == f.platformRow && map_.isOneWay(c.tile.i, c.tile.j))
                    fail(Metric::PlatformSnag);
    }

    void judgeFrame(const FrameFacts<T>& f, const FrameResult<T>& got, SceneVerdict& v) {
        auto fail = [&](Metric m) { v.failed[static_cast<std::size_t>(m)] = true; };
        if (decisionKeys(got.contacts) != decisionKeys(f.exact.contacts)) fail(Metric::Decision);
        judgePlatforms(f, got, v);

        // Bit for bit against the contract's rounding: contacts in the contract's order, start
        // overlaps in any order (the contract leaves that order free), each listed once.
        bool exact = sameBits(got.position.x, f.rounded.position.x) &&
                     sameBits(got.position.y, f.rounded.position.y) &&
                     got.contacts.size() == f.rounded.contacts.size();
        for (std::size_t n = 0; exact && n < got.contacts.size(); ++n) {
            const Contact<T>& a = got.contacts[n];
            const Contact<T>& b = f.rounded.contacts[n];
            exact = a.tile == b.tile && a.normal == b.normal && sameBits(a.time, b.time);
        }
        exact = exact && checks::sameCellsInAnyOrder(f.rounded.startOverlaps, got.startOverlaps.data(),
                                                     got.startOverlaps.size(), scratch_.listed);
        if (!exact) fail(Metric::Inexact);

        v.positionUlps =
            std::max({v.positionUlps, ulpError(got.position.x, f.rounded.position.x, scene_.map.tileSize.x),
                      ulpError(got.position.y, f.rounded.position.y, scene_.map.tileSize.y)});

        // Frame times of the contacts both report on the same tile, against the contract's
        // (the exact time rounded to nearest), so that a correct resolver reads 0.
        for (const Contact<T>& e : f.rounded.contacts) {
            for (const Contact<T>& c : got.contacts) {
                if (!(c.tile == e.tile)) continue;
                double error = std::numeric_limits<double>::infinity();
                if (std::isfinite(c.time)) {
                    const Rational difference = abs(oracle::toRational(c.time) - oracle::toRational(e.time));
                    error = difference.convert_to<double>();
                }
                v.hasTime = true;
                v.timeError = std::max(v.timeError, error);
                break;
            }
        }

        // Corner facts.
        if (!f.clipTiles.empty()) v.clipEligible = true;
        for (const Cell& c : f.clipTiles)
            if (!mentions(got.contacts, c)) fail(Metric::ClipMiss);
        if (!f.missTiles.empty()) v.cornerEligible = true;
        for (const Cell& c : f.missTiles)
            if (mentions(got.contacts, c)) fail(Metric::CornerHit);

        // Seam snags.
        if (f.restingRow >= 0) {
            v.restingEligible = true;
            for (const Contact<T>& c : got.contacts) {
                if (c.normal.x == 0 || c.tile.j != f.restingRow || map_.isSolid(c.tile.i, c.tile.j - 1))
                    continue;
                const bool exactToo = std::any_of(
                    f.exact.contacts.begin(), f.exact.contacts.end(),
                    [&](const oracle::ExactContact& e) { return e.tile == c.tile && e.normal == c.normal; });
                if (!exactToo) fail(Metric::Snag);
            }
        }

        // Decisions, one way and the other.
        for (const oracle::ExactContact& e : f.exact.contacts)
            if (!std::any_of(got.contacts.begin(), got.contacts.end(),
                             [&](const Contact<T>& c) { return c.tile == e.tile && c.normal == e.normal; }))
                fail(Metric::Missed);
        for (const Contact<T>& c : got.contacts)
            if (!std::any_of(
                    f.exact.contacts.begin(), f.exact.contacts.end(),
                    [&](const oracle::ExactContact& e) { return e.tile == c.tile && e.normal == c.normal; }))
                fail(Metric::Extra);

        if (!isFinite(got.position)) return;
        const ExactBox end{oracle::toExact(got.position), oracle::toExact(scene_.box.size)};
        const ExactRect endRect = oracle::rectOf(end);

        // Short of touching and past the exact end, per axis, against the contract's position
        // (so that a correct resolver reads zero) and measured from the exact one.
        for (int axis = 0; axis < 2; ++axis) {
            const Rational& exactEnd = axis == 0 ? f.exact.position.x : f.exact.position.y;
            const Rational& start = axis == 0 ? f.exact.start.x : f.exact.start.y;
            const Rational ended = oracle::toRational(axis == 0 ? got.position.x : got.position.y);
            const Rational contract =
                oracle::toRational(axis == 0 ? f.rounded.position.x : f.rounded.position.y);
            const T moveAxis = axis == 0 ? f.move.x : f.move.y;
            // The side the exact frame stops on, when it stops on this axis: a contact's normal.
            int stopNormal = 0;
            for (const oracle::ExactContact& e : f.exact.contacts)
                if ((axis == 0 ? e.normal.x : e.normal.y) != 0)
                    stopNormal = axis == 0 ? e.normal.x : e.normal.y;
            if (stopNormal != 0) {
                // Moving against the normal: short means farther along the normal than allowed.
                const bool behind = stopNormal > 0 ? ended > contract : ended < contract;
                if (behind) {
                    fail(Metric::Short);
                    v.shortfall = std::max(v.shortfall, std::fabs(difference(ended, exactEnd)));
                }
            }
            const int direction = moveAxis > T(0) ? 1 : moveAxis < T(0) ? -1 : 0;
            const bool past = direction > 0   ? ended > contract
                              : direction < 0 ? ended < contract
                                              : ended != start;
            if (past) {
                fail(Metric::Overshoot);
                v.overshoot = std::max(v.overshoot, std::fabs(difference(ended, exactEnd)));
            }
        }

        // Tunnelling: entirely beyond a tile the exact frame stops at, on that contact's axis.
        for (const oracle::ExactContact& e : f.exact.contacts) {
            const ExactRect tile = map_.tileRect(e.tile.i, e.tile.j);
            const bool beyond = e.normal.x < 0   ? endRect.min.x >= tile.max.x
                                : e.normal.x > 0 ? endRect.max.x <= tile.min.x
                                : e.normal.y < 0 ? endRect.min.y >= tile.max.y
                                : e.normal.y > 0 ? endRect.max.y <= tile.min.y
                                                 : false;
            if (beyond) fail(Metric::Tunnel);
        }

        // Ends inside a tile it did not start in: the shared safety rule, no allowance.
        if (checks::findNewOverlap(scene_.map.view(), edges_, Box<T>{f.start, scene_.box.size}, got.position,
                                   scratch_)) {
            fail(Metric::Inside);
            v.insideDepth = std::max(v.insideDepth, newOverlapDepth(f, endRect));
        }
    }

    /// The depth of the deepest overlap of `endRect` with a solid tile the frame did not start
    /// overlapping: per tile the smaller of the two overlap lengths (how far the box must move
    /// to come out), the largest over the tiles.
    double newOverlapDepth(const FrameFacts<T>& f, const ExactRect& endRect) const {
        double deepest = 0;
        for (const Cell& c : solid_) {
            if (std::find(f.exact.startOverlaps.begin(), f.exact.startOverlaps.end(), c) !=
                f.exact.startOverlaps.end())
                continue;
            const ExactRect tile = map_.tileRect(c.i, c.j);
            if (!oracle::overlaps(endRect, tile)) continue;
            const Rational x = std::min(endRect.max.x, tile.max.x) - std::max(endRect.min.x, tile.min.x);
            const Rational y = std::min(endRect.max.y, tile.max.y) - std::max(endRect.min.y, tile.min.y);
            deepest = std::max(deepest, Rational(std::min(x, y)).convert_to<double>());
        }
        return deepest;
    }

    const Scene<T>& scene_;
    ExactTileMap map_;
    std::vector<Cell> solid_;
    std::vector<Cell> oneWay_;
    checks::MapEdges<T> edges_;
    checks::SafetyScratch scratch_;
    std::vector<std::vector<FrameFacts<T>>> facts_;
};

}  // namespace tilesweep::audit::judge
