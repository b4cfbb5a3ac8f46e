// SPDX-License-Identifier: MIT
// The audit's driver: scenes from scene_families.cpp, each implementation run on them
// (implementation_runner.cpp), each frame judged against the exact frame from the same start
// (scene_judge.h), the figures gathered per (implementation, family) cell on worker threads
// (parallel_tasks.h) with no shared mutable state (each worker owns its cells; the GMP rationals
// of the oracle are per-object), merged at the end (audit_result.cpp).
#include "tilesweep/audit/audit.h"

#include "parallel_tasks.h"
#include "scene_judge.h"

#include "tilesweep/baselines/run_frames.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/seed/seed_resolve.h"
#include "tilesweep/resolvers/resolver_registry.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace tilesweep::audit {
namespace {

using namespace judge;
using baselines::runFrames;

/// The path that decided the production resolver's frames of a scene: the most exact one used.
template <class T>
DecisionPath decisionPathOf(const Scene<T>& scene) {
    DecisionPath worst = DecisionPath::Fast;
    runFrames(scene, [&worst](const ResolveInput<T>& in, const ResolveOutput<T>& out) {
        FrameStats stats;
        ResolveOutput<T> counted = out;
        counted.stats = &stats;
        const ResolveResult<T> r = resolveMove(in, counted);
        worst = std::max(worst, stats.path);
        return r;
    });
    return worst;
}

void record(CellStats& cell, const SceneVerdict& v, std::uint64_t caseIndex) {
    ++cell.scenes;
    const double positionScore = v.positionUlps == kNonFiniteUlps ? std::numeric_limits<double>::infinity()
                                                                  : static_cast<double>(v.positionUlps);
    for (std::size_t m = 0; m < kMetricCount; ++m) {
        if (!v.failed[m]) continue;
        ++cell.failures[m];
        const double score = m == static_cast<std::size_t>(Metric::Time) ? v.timeError : positionScore;
        cell.worst[m].merge({true, score, caseIndex});
    }
    if (v.clipEligible) ++cell.clipEligible;
    if (v.cornerEligible) ++cell.cornerEligible;
    if (v.restingEligible) ++cell.restingEligible;
    cell.positionUlps.push_back(v.positionUlps);
    if (v.hasTime) cell.timeErrors.push_back(v.timeError);
}

/// The cells one worker fills: [implementation][family], and the coverage [family][scalar]; the
/// worker's own resolver of each implementation.
struct Shard {
    std::vector<std::vector<CellStats>> cells;
    std::vector<std::array<Coverage, 2>> coverage;
    std::vector<std::unique_ptr<resolvers::SceneResolver>> resolvers;
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
    const DecisionPath path = decisionPathOf(scene);
    cov.filtered += path == DecisionPath::Filtered ? 1 : 0;
    cov.exactPath += path == DecisionPath::Exact ? 1 : 0;

    for (std::size_t r = 0; r < impls.size(); ++r) {
        const Implementation& impl = impls[r];
        if (impl.isDouble != kDouble) continue;
        CellStats& cell = shard.cells[r][familyIndex];
        resolvers::Answer<T> answer = resolvers::resolveOne(*shard.resolvers[r], scene);
        if (!answer.answered())
            throw std::runtime_error(impl.name + " could not resolve a scene: " + answer.failure);
        record(cell, judge.judge(answer.frames), caseIndex);
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

    std::vector<Shard> shards(static_cast<std::size_t>(jobs));
    for (Shard& s : shards) {
        s.cells.assign(rows, std::vector<CellStats>(columns));
        s.coverage.assign(columns, {});
        for (const Implementation& impl : result.implementations) {
            std::string error;
            s.resolvers.push_back(resolvers::makeResolver(resolverName(impl), error));
            if (!s.resolvers.back()) throw std::logic_error(impl.name + ": " + error);
        }
    }
    // Tasks interleave the families, so that progress advances evenly across them.
    const std::uint64_t total = config.cases * columns;
    ParallelTasks tasks;
    tasks.workers = jobs;
    tasks.tasks = total;
    tasks.units = total;
    tasks.name = "audit";
    tasks.progress = config.progress;
    tasks.run = [&](std::size_t w, std::size_t t) -> std::uint64_t {
        const std::size_t f = t % columns;
        const std::uint64_t caseIndex = t / columns;
        const Family& family = result.families[f];
        if (family.floatToo)
            auditScene<float>(result.implementations, family, f, config.seed, caseIndex, shards[w]);
        auditScene<double>(result.implementations, family, f, config.seed, caseIndex, shards[w]);
        return 1;
    };
    runParallelTasks(tasks);

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
