// SPDX-License-Identifier: MIT
// The audit's driver: scenes from scene_families.cpp, each implementation run on them, each
// frame judged against the exact frame from the same start (scene_judge below), the figures
// gathered per (implementation, family) cell on worker threads with no shared mutable state
// (each worker owns its cells; the GMP rationals of the oracle are per-object), merged at the end.
#include "audit/audit.h"

#include "audit/scene_judge.h"
#include "frame_safety.h"  // checks/
#include "oracle/exact/exact_resolve.h"
#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/rational_convert.h"
#include "oracle/seed/seed_resolve.h"
#include "oracle/substep/substep_float.h"
#include "src/decision_path.h"

#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/twin_resolve.h"
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
        case Metric::Missed:
            return "missed-contact";
        case Metric::Extra:
            return "extra-contact";
        case Metric::Short:
            return "short";
        case Metric::Overshoot:
            return "overshoot";
        case Metric::NoAnswer:
            return "no-answer";
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

using namespace judge;

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
std::vector<FrameResult<T>> implementationFrames(const Implementation& impl, const Scene<T>& scene) {
    switch (impl.kind) {
        case ImplementationKind::Twin:
            return runFrames(scene, [](const SweepInput<T>& in, const ResolveOutput<T>& out) {
                return baselines::resolveMoveTwin(in, out);
            });
        case ImplementationKind::Grid:
            return runFrames(scene, [](const SweepInput<T>& in, const ResolveOutput<T>& out) {
                return baselines::resolveMoveGrid(in, out);
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
        record(cell, judge.judge(implementationFrames(impl, scene)), caseIndex);
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

template <class T>
std::vector<FrameResult<T>> runImplementation(const Implementation& impl, const Scene<T>& scene) {
    return implementationFrames(impl, scene);
}
template std::vector<FrameResult<float>> runImplementation<float>(const Implementation&, const Scene<float>&);
template std::vector<FrameResult<double>> runImplementation<double>(const Implementation&,
                                                                    const Scene<double>&);

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
