// SPDX-License-Identifier: MIT
// The audit's driver: scenes from scene_families.cpp, each implementation run on them, each
// frame judged against the exact frame from the same start (scene_judge below), the figures
// gathered per (implementation, family) cell on worker threads with no shared mutable state
// (each worker owns its cells; the GMP rationals of the oracle are per-object), merged at the end.
#include "audit/audit.h"

#include "bench/grid_resolve.h"
#include "bench/twin_resolve.h"
#include "frame_safety.h"  // checks/
#include "oracle/exact/exact_resolve.h"
#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/rational_convert.h"
#include "oracle/seed/seed_resolve.h"
#include "oracle/substep/substep_float.h"
#include "src/decision_path.h"

#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>

namespace tilesweep::audit {

using oracle::ExactBox;
using oracle::ExactFrame;
using oracle::ExactRect;
using oracle::ExactTileMap;
using oracle::ExactVec2;
using oracle::Rational;

const char* metricName(Metric m) {
    switch (m) {
        case Metric::Decision:
            return "decision";
        case Metric::Inexact:
            return "inexact";
        case Metric::Tunnel:
            return "tunnel";
        case Metric::Inside:
            return "inside";
        case Metric::ClipMiss:
            return "clip-miss";
        case Metric::CornerHit:
            return "corner-hit";
        case Metric::Snag:
            return "snag";
        case Metric::NonFinite:
            return "non-finite";
        case Metric::Position:
            return "position";
        case Metric::Time:
            return "time";
    }
    return "?";
}

std::vector<Implementation> auditImplementations() {
    return {
        {"core-float", ImplementationKind::Core, false, 0},
        {"core-double", ImplementationKind::Core, true, 0},
        {"seed-float", ImplementationKind::Seed, false, 0},
        {"seed-double", ImplementationKind::Seed, true, 0},
        {"substep4-float", ImplementationKind::SubstepFloat, false, 4},
        {"substep16-float", ImplementationKind::SubstepFloat, false, 16},
        {"substep256-float", ImplementationKind::SubstepFloat, false, 256},
        {"twin-float", ImplementationKind::Twin, false, 0},
        {"twin-double", ImplementationKind::Twin, true, 0},
        {"grid-float", ImplementationKind::Grid, false, 0},
        {"grid-double", ImplementationKind::Grid, true, 0},
    };
}

namespace {

void mergeWorst(WorstCase& into, const WorstCase& other) {
    if (!other.found) return;
    if (!into.found || other.score > into.score ||
        (other.score == into.score && other.caseIndex < into.caseIndex))
        into = other;
}

}  // namespace

void CellStats::merge(const CellStats& other) {
    scenes += other.scenes;
    for (std::size_t m = 0; m < kMetricCount; ++m) {
        failures[m] += other.failures[m];
        mergeWorst(worst[m], other.worst[m]);
    }
    clipEligible += other.clipEligible;
    cornerEligible += other.cornerEligible;
    restingEligible += other.restingEligible;
    positionUlps.insert(positionUlps.end(), other.positionUlps.begin(), other.positionUlps.end());
    timeErrors.insert(timeErrors.end(), other.timeErrors.begin(), other.timeErrors.end());
    if (epsilonMismatches.size() < other.epsilonMismatches.size())
        epsilonMismatches.resize(other.epsilonMismatches.size());
    for (std::size_t k = 0; k < other.epsilonMismatches.size(); ++k)
        epsilonMismatches[k] += other.epsilonMismatches[k];
}

void Coverage::merge(const Coverage& o) {
    scenes += o.scenes;
    hit += o.hit;
    twoStep += o.twoStep;
    tie += o.tie;
    cornerClip += o.cornerClip;
    cornerMiss += o.cornerMiss;
    cornerPass += o.cornerPass;
    startOverlap += o.startOverlap;
    resting += o.resting;
    filtered += o.filtered;
    exactPath += o.exactPath;
}

const CellStats& AuditResult::cell(const std::string& implementation, const std::string& family) const {
    for (std::size_t r = 0; r < implementations.size(); ++r)
        if (implementations[r].name == implementation)
            for (std::size_t c = 0; c < families.size(); ++c)
                if (families[c].name == family) return cells[r][c];
    throw std::out_of_range("no audit cell " + implementation + " x " + family);
}

std::string smallestFixingEpsilon(const CellStats& cell) {
    for (std::size_t k = 0; k < cell.epsilonMismatches.size() && k < kSeedEpsilons.size(); ++k) {
        if (cell.epsilonMismatches[k] == 0 && cell.scenes > 0) {
            char text[32];
            std::snprintf(text, sizeof text, "%g", kSeedEpsilons[k]);
            return text;
        }
    }
    return "none";
}

namespace {

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
    ExactFrame exact;
    FrameResult<T> rounded;
    std::vector<Cell> clipTiles;   ///< first-step contacts that clip a corner
    std::vector<Cell> missTiles;   ///< corner-missed tiles in the swept bounds, never touched exactly
    bool cornerPass = false;       ///< some miss is a path exactly through a corner point
    std::int32_t restingRow = -1;  ///< the floor row the box starts resting on, or -1
};

/// One implementation's verdicts on one scene.
struct SceneVerdict {
    std::array<bool, kMetricCount> failed{};
    bool clipEligible = false, cornerEligible = false, restingEligible = false;
    std::uint64_t positionUlps = 0;
    bool hasTime = false;
    double timeError = 0;
};

template <class T>
class SceneJudge {
public:
    explicit SceneJudge(const Scene<T>& scene)
        : scene_(scene), map_(oracle::toExact(scene.map)), edges_(checks::computeEdges(scene.map.view())) {
        for (std::int32_t j = 0; j < scene.map.rows; ++j)
            for (std::int32_t i = 0; i < scene.map.columns; ++i)
                if (map_.isSolid(i, j)) solid_.push_back({i, j});
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

    void judgeFrame(const FrameFacts<T>& f, const FrameResult<T>& got, SceneVerdict& v) {
        auto fail = [&](Metric m) { v.failed[static_cast<std::size_t>(m)] = true; };
        if (decisionKeys(got.contacts) != decisionKeys(f.exact.contacts)) fail(Metric::Decision);

        // Bit for bit against the contract's rounding.
        bool exact = sameBits(got.position.x, f.rounded.position.x) &&
                     sameBits(got.position.y, f.rounded.position.y) &&
                     got.contacts.size() == f.rounded.contacts.size() &&
                     got.startOverlaps.size() == f.rounded.startOverlaps.size();
        for (std::size_t n = 0; exact && n < got.contacts.size(); ++n) {
            const Contact<T>& a = got.contacts[n];
            const Contact<T>& b = f.rounded.contacts[n];
            exact = a.tile == b.tile && a.normal == b.normal && sameBits(a.time, b.time);
        }
        for (std::size_t n = 0; exact && n < got.startOverlaps.size(); ++n)
            exact = got.startOverlaps[n] == f.rounded.startOverlaps[n];
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

        if (!isFinite(got.position)) return;
        const ExactBox end{oracle::toExact(got.position), oracle::toExact(scene_.box.size)};
        const ExactRect endRect = oracle::rectOf(end);

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
                                   scratch_))
            fail(Metric::Inside);
    }

    const Scene<T>& scene_;
    ExactTileMap map_;
    std::vector<Cell> solid_;
    checks::MapEdges<T> edges_;
    checks::SafetyScratch scratch_;
    std::vector<std::vector<FrameFacts<T>>> facts_;
};

// ---- running the implementations ----------------------------------------------------------

/// A scene's frames through a resolver with resolveMove's signature (the game-style baselines),
/// each frame from the last one's position, with room for every list entry.
template <class T, class Resolve>
std::vector<FrameResult<T>> runFrames(const Scene<T>& scene, Resolve resolve) {
    std::vector<FrameResult<T>> frames;
    Vec2<T> start = scene.box.pos;
    std::vector<Contact<T>> contacts(16);
    std::vector<Cell> overlaps(16);
    for (const Vec2<T>& move : scene.moves) {
        const SweepInput<T> input{scene.map.view(), {start, scene.box.size}, move};
        SweepResult<T> r{};
        for (;;) {
            r = resolve(input, ResolveOutput<T>{contacts.data(), static_cast<std::int32_t>(contacts.size()),
                                                overlaps.data(), static_cast<std::int32_t>(overlaps.size())});
            if (r.contactCount <= static_cast<std::int32_t>(contacts.size()) &&
                r.startOverlapCount <= static_cast<std::int32_t>(overlaps.size()))
                break;
            contacts.resize(static_cast<std::size_t>(std::max<std::int32_t>(r.contactCount, 16)));
            overlaps.resize(static_cast<std::size_t>(std::max<std::int32_t>(r.startOverlapCount, 16)));
        }
        FrameResult<T> f;
        f.position = r.position;
        // Only non-empty ranges: GCC 12 at -O3 warns (-Wnonnull) on the memmove of zero bytes into
        // the fresh vector's null storage that assign() would otherwise reach.
        if (r.contactCount > 0) f.contacts.assign(contacts.begin(), contacts.begin() + r.contactCount);
        if (r.startOverlapCount > 0)
            f.startOverlaps.assign(overlaps.begin(), overlaps.begin() + r.startOverlapCount);
        frames.push_back(std::move(f));
        start = r.position;
    }
    return frames;
}

/// The path that decided the production resolver's frames of a scene: the most exact one used.
template <class T>
detail::DecisionPath decisionPathOf(const Scene<T>& scene) {
    detail::DecisionPath worst = detail::DecisionPath::Fast;
    runFrames(scene, [&worst](const SweepInput<T>& in, const ResolveOutput<T>& out) {
        const SweepResult<T> r = resolveMove(in, out);
        worst = std::max(worst, detail::lastDecisionPath());
        return r;
    });
    return worst;
}

template <class T>
std::vector<FrameResult<T>> runImplementation(const Implementation& impl, const Scene<T>& scene) {
    switch (impl.kind) {
        case ImplementationKind::Twin:
            return runFrames(scene, [](const SweepInput<T>& in, const ResolveOutput<T>& out) {
                return bench::resolveMoveTwin(in, out);
            });
        case ImplementationKind::Grid:
            return runFrames(scene, [](const SweepInput<T>& in, const ResolveOutput<T>& out) {
                return bench::resolveMoveGrid(in, out);
            });
        case ImplementationKind::Core:
            return runScene(scene);
        case ImplementationKind::Seed:
            return oracle::resolveSceneSeed(scene);
        case ImplementationKind::SubstepFloat:
            return oracle::frameResults(oracle::resolveSceneSubstepFloat(scene, impl.substeps));
    }
    return {};
}

void record(CellStats& cell, const SceneVerdict& v, std::uint64_t caseIndex) {
    ++cell.scenes;
    const double positionScore = v.positionUlps == kNonFiniteUlps ? std::numeric_limits<double>::infinity()
                                                                  : static_cast<double>(v.positionUlps);
    for (std::size_t m = 0; m < kMetricCount; ++m) {
        if (!v.failed[m]) continue;
        ++cell.failures[m];
        const double score = m == static_cast<std::size_t>(Metric::Time) ? v.timeError : positionScore;
        mergeWorst(cell.worst[m], {true, score, caseIndex});
    }
    if (v.clipEligible) ++cell.clipEligible;
    if (v.cornerEligible) ++cell.cornerEligible;
    if (v.restingEligible) ++cell.restingEligible;
    cell.positionUlps.push_back(v.positionUlps);
    if (v.hasTime) cell.timeErrors.push_back(v.timeError);
}

/// The cells one worker fills: [implementation][family], and the coverage [family][scalar].
struct Shard {
    std::vector<std::vector<CellStats>> cells;
    std::vector<std::array<Coverage, 2>> coverage;
};

template <class T>
void auditScene(const std::vector<Implementation>& impls, const Family& family, std::size_t familyIndex,
                std::uint64_t seed, std::uint64_t caseIndex, Shard& shard) {
    const Scene<T> scene = generateScene<T>(family, seed, caseIndex);
    SceneJudge<T> judge(scene);
    constexpr bool kDouble = sizeof(T) == 8;

    // What the family covers, from the exact first frame.
    const FrameFacts<T>& first = judge.facts(0, scene.box.pos);
    Coverage& cov = shard.coverage[familyIndex][kDouble ? 1 : 0];
    ++cov.scenes;
    cov.hit += first.exact.contacts.empty() ? 0 : 1;
    cov.twoStep += std::any_of(first.exact.contacts.begin(), first.exact.contacts.end(),
                               [](const oracle::ExactContact& e) { return e.step == 2; })
                       ? 1
                       : 0;
    cov.tie += std::any_of(first.exact.contacts.begin(), first.exact.contacts.end(),
                           [](const oracle::ExactContact& e) { return e.tie; })
                   ? 1
                   : 0;
    cov.cornerClip += first.clipTiles.empty() ? 0 : 1;
    cov.cornerMiss += first.missTiles.empty() ? 0 : 1;
    cov.cornerPass += first.cornerPass ? 1 : 0;
    cov.startOverlap += first.exact.startOverlaps.empty() ? 0 : 1;
    cov.resting += first.restingRow >= 0 ? 1 : 0;
    const detail::DecisionPath path = decisionPathOf(scene);
    cov.filtered += path == detail::DecisionPath::Filtered ? 1 : 0;
    cov.exactPath += path == detail::DecisionPath::Exact ? 1 : 0;

    for (std::size_t r = 0; r < impls.size(); ++r) {
        const Implementation& impl = impls[r];
        if (impl.isDouble != kDouble) continue;
        CellStats& cell = shard.cells[r][familyIndex];
        record(cell, judge.judge(runImplementation(impl, scene)), caseIndex);
        if (impl.kind == ImplementationKind::Seed) {
            cell.epsilonMismatches.resize(kSeedEpsilons.size());
            for (std::size_t k = 0; k < kSeedEpsilons.size(); ++k) {
                const auto epsilon = static_cast<T>(kSeedEpsilons[k]);
                if (!judge.decisionsMatch(oracle::resolveSceneSeed(scene, epsilon)))
                    ++cell.epsilonMismatches[k];
            }
        }
    }
}

}  // namespace

AuditResult runAudit(const AuditConfig& config) {
    const auto started = std::chrono::steady_clock::now();
    AuditResult result;
    result.config = config;
    result.implementations = auditImplementations();
    result.families = auditFamilies();
    const std::size_t rows = result.implementations.size();
    const std::size_t columns = result.families.size();

    int jobs = config.jobs > 0 ? config.jobs : static_cast<int>(std::thread::hardware_concurrency());
    if (jobs < 1) jobs = 1;
    result.jobs = jobs;

    // Tasks interleave the families, so that progress advances evenly across them.
    const std::uint64_t total = config.cases * columns;
    std::atomic<std::uint64_t> next{0};
    std::atomic<std::uint64_t> done{0};
    std::vector<Shard> shards(static_cast<std::size_t>(jobs));
    std::vector<std::string> errors(static_cast<std::size_t>(jobs));  // each written by its worker only
    std::atomic<bool> failed{false};
    for (Shard& s : shards) {
        s.cells.assign(rows, std::vector<CellStats>(columns));
        s.coverage.assign(columns, {});
    }
    auto work = [&](std::size_t w) {
        try {
            for (std::uint64_t t; (t = next.fetch_add(1)) < total; done.fetch_add(1)) {
                const std::size_t f = static_cast<std::size_t>(t % columns);
                const std::uint64_t caseIndex = t / columns;
                const Family& family = result.families[f];
                if (family.floatToo)
                    auditScene<float>(result.implementations, family, f, config.seed, caseIndex, shards[w]);
                auditScene<double>(result.implementations, family, f, config.seed, caseIndex, shards[w]);
            }
        } catch (const std::exception& e) {
            errors[w] = e.what();
            failed.store(true);
            next.store(total);
        }
    };
    std::vector<std::thread> threads;
    for (int w = 0; w < jobs; ++w) threads.emplace_back(work, static_cast<std::size_t>(w));
    // Progress about twice a second, in steps of 50 ms so that a short run ends promptly.
    for (int tick = 0; done.load() < total && !failed.load(); ++tick) {
        if (config.progress && tick % 10 == 0) config.progress(done.load(), total);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    for (std::thread& t : threads) t.join();
    for (const std::string& e : errors)
        if (!e.empty()) throw std::runtime_error("audit worker failed: " + e);
    if (config.progress) config.progress(total, total);

    result.cells.assign(rows, std::vector<CellStats>(columns));
    result.coverage.assign(columns, {});
    for (const Shard& s : shards) {
        for (std::size_t r = 0; r < rows; ++r)
            for (std::size_t c = 0; c < columns; ++c) result.cells[r][c].merge(s.cells[r][c]);
        for (std::size_t c = 0; c < columns; ++c)
            for (std::size_t k = 0; k < 2; ++k) result.coverage[c][k].merge(s.coverage[c][k]);
    }
    for (auto& row : result.cells)
        for (CellStats& cell : row) {
            std::sort(cell.positionUlps.begin(), cell.positionUlps.end());
            std::sort(cell.timeErrors.begin(), cell.timeErrors.end());
        }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace tilesweep::audit
