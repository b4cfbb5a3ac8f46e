// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/audit/scene_families.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

// The tolerance audit (`tilesweep audit`): every implementation of the resolver held against the
// exact reference (oracle/exact) over the scenario families of scene_families.h, frame by frame.
//
// Each frame of an implementation is judged against the exact frame that starts from the same
// position, so a multi-frame scene that drifts early is still judged fairly later: the exact
// reference is re-run from the implementation's own start when it differs from the reference
// trajectory. The figures (all per scene: a scene counts once whichever of its frames failed):
//
//   decision   the multiset of (tile, normal) contacts differs from the exact one
//   inexact    anything differs from the contract's rounded result, bit for bit (position,
//              contacts in order with their times, start overlaps)
//   tunnel     the box ends entirely beyond a tile that the exact frame stops at, on the axis of
//              that contact (its trailing edge at or past the tile's far face)
//   inside     the box ends strictly overlapping a solid tile it did not overlap at its start
//   clip-miss  the exact frame's first step hits a tile by clipping its corner (it enters on one
//              axis, not a tie, and the overlap window would close on the other axis before the
//              frame ends, so that unstopped it would pass the corner and come out), and the
//              implementation reports no contact with that tile
//   corner-hit the straight move's swept bounds overlap a tile whose overlap set I is empty
//              (the contract's corner miss, a path exactly through a corner point included), the
//              exact frame never touches it, and the implementation reports a contact with it
//   snag       the frame starts resting on a floor (the box's bottom on the top of a solid
//              tile it overlaps on x, whose cell above is empty) and the implementation reports
//              an x contact on a tile of that floor row that the exact frame does not
//   non-finite the implementation returned an infinite or NaN position
//   missed-contact  the exact frame hits a (tile, normal) that the implementation does not report
//   extra-contact   the implementation reports a (tile, normal) that the exact frame does not hit
//              (a different tile or normal is both: one missed, one extra)
//   short      on an axis the exact frame stops on (a contact's axis), the box ends farther back
//              than the contract's position: it stops short of touching by more than rounding
//   overshoot  on some axis the box ends beyond the contract's position in the direction of the
//              frame's motion (past the exact end by more than rounding; on a contact axis that
//              is a push into the tile), or moves on an axis that did not move
//   no-answer  (outside resolvers) the resolver gave no usable answer: a crash, a hang, garbage,
//              an error line, or the wrong number of frames
//   position   the largest error of the final position against the contract's (the exact one
//              rounded toward the start), per axis, in ulps of the scalar type at the magnitude of
//              the expected coordinate, floored at the tile size: |got - want| / ulp(max(|want|,
//              tile)), rounded up; 0 exactly when bit-equal as numbers
//   time       the largest |t - t_contract| over the contacts both report for the same tile, in
//              fractions of the frame, t_contract being the exact time rounded to nearest
//
// The seed algorithm is also re-run with each epsilon of kSeedEpsilons (see seed_resolve.h):
// the smallest |epsilon| at which its decisions match on every scene of a family is reported,
// or "none" when no epsilon in the list makes them all match.

namespace tilesweep::audit {

/// The tolerances the seed algorithm is re-run with, in fractions of the move, smallest first
/// (each with both signs: + accepts near misses, - rejects near hits).
inline const std::vector<double> kSeedEpsilons = {0,    1e-7,  -1e-7, 1e-6,  -1e-6, 1e-5, -1e-5,
                                                  1e-4, -1e-4, 1e-3,  -1e-3, 1e-2,  -1e-2};

/// The per-scene failure figures, in report order; Position and Time select the worst scene of
/// a cell by the size of the error rather than by a count.
enum class Metric : std::uint8_t {
    Decision,
    Inexact,
    Tunnel,
    Inside,
    ClipMiss,
    CornerHit,
    Snag,
    NonFinite,
    Missed,
    Extra,
    Short,
    Overshoot,
    NoAnswer,
    Position,
    Time,
    PlatformFall,   ///< ends with its bottom below the top of a one-way tile the exact frame lands on
                    ///< (sinking into it by any amount, or falling through it)
    PlatformBlock,  ///< stopped by a one-way tile the exact frame passes (from below, the side, inside)
    PlatformSnag    ///< stopped on x by a one-way tile of the platform it starts standing on
};
constexpr std::size_t kMetricCount = 18;

/// The short name of a metric ("decision", "tunnel", ...).
[[nodiscard]] const char* metricName(Metric m);

/// How an implementation resolves.
enum class ImplementationKind : std::uint8_t {
    Core,          ///< tilesweep's production resolver
    Seed,          ///< the seed article's algorithm
    SubstepFloat,  ///< N substeps in plain float
    Twin,          ///< game-style swept AABB walking cells in path order (tilesweep/baselines/twin_resolve.h)
    Grid,          ///< game-style swept AABB scanning the swept bounds (tilesweep/baselines/grid_resolve.h)
};

/// One row of the report.
struct Implementation {
    std::string name;  ///< "core-float", "seed-double", "substep16-float", ...
    ImplementationKind kind = ImplementationKind::Core;
    bool isDouble = false;      ///< the scalar type it runs in
    std::int64_t substeps = 0;  ///< N, for SubstepFloat
};

/// Every implementation of the audit, in report order.
[[nodiscard]] std::vector<Implementation> auditImplementations();

/// The name of an implementation's resolver in the registry (resolvers/resolver_registry.h):
/// "core", "seed", "substep-float:N", "twin" or "grid".
[[nodiscard]] std::string resolverName(const Implementation& impl);

/// The worst scene of a cell for one metric: the case with the largest score (the position
/// error in ulps for most metrics), the lowest case index on a tie.
struct WorstCase {
    bool found = false;
    double score = 0;
    std::uint64_t caseIndex = 0;

    /// Keeps the worse of this and `other` (the larger score; the lower case index on a tie).
    void merge(const WorstCase& other);
};

/// The figures of one implementation on one family.
struct CellStats {
    std::uint64_t scenes = 0;
    std::array<std::uint64_t, kMetricCount> failures{};  ///< scenes that failed each metric
    std::uint64_t clipEligible = 0;                      ///< scenes whose exact first step clips a corner
    std::uint64_t cornerEligible = 0;         ///< scenes with a corner-missed tile in the swept bounds
    std::uint64_t restingEligible = 0;        ///< scenes with a frame that starts resting on a floor
    std::vector<std::uint64_t> positionUlps;  ///< per scene, the largest error; kNonFiniteUlps if not finite
    std::vector<double> timeErrors;           ///< per scene with a shared contact, the largest error
    std::vector<std::uint64_t> epsilonMismatches;  ///< per kSeedEpsilons entry (seed rows only)
    std::array<WorstCase, kMetricCount> worst{};

    /// Adds another shard's figures (the vectors are concatenated; sort before reading).
    void merge(const CellStats& other);
};

/// The position error recorded for a non-finite position.
constexpr std::uint64_t kNonFiniteUlps = ~std::uint64_t{0};

/// Which cases of a family (run through the exact reference) exercise which rule: what the
/// family covers, counted on the first frame.
struct Coverage {
    std::uint64_t scenes = 0;
    std::uint64_t hit = 0;           ///< some contact
    std::uint64_t twoStep = 0;       ///< a contact in the second step (a slide that hits)
    std::uint64_t tie = 0;           ///< a contact decided by the tie rule
    std::uint64_t cornerClip = 0;    ///< a first-step contact that clips a corner
    std::uint64_t cornerMiss = 0;    ///< a corner-missed tile in the swept bounds
    std::uint64_t cornerPass = 0;    ///< a path exactly through a tile's corner point
    std::uint64_t startOverlap = 0;  ///< the box starts overlapping a solid tile
    std::uint64_t resting = 0;       ///< the box starts resting on a floor
    std::uint64_t filtered = 0;      ///< the resolver's fast path needed an exact refinement (some frame)
    std::uint64_t exactPath = 0;     ///< the resolver fell back to the exact lattice (some frame)

    void merge(const Coverage& other);
};

/// What to run.
struct AuditConfig {
    std::uint64_t cases = 5000;     ///< scenes per family (per scalar type)
    std::uint64_t seed = 20261122;  ///< the seed every scene derives from
    int jobs = 0;                   ///< worker threads; 0: all cores
    std::string commandLine;        ///< recorded in the report, for rerunning it
    /// Called from the coordinating thread about twice a second: (cases done, cases in all).
    std::function<void(std::uint64_t, std::uint64_t)> progress;
};

/// Everything an audit found.
struct AuditResult {
    AuditConfig config;
    std::vector<Implementation> implementations;
    std::vector<Family> families;
    std::vector<std::vector<CellStats>> cells;      ///< [implementation][family]; sorted vectors
    std::vector<std::array<Coverage, 2>> coverage;  ///< [family][0 float, 1 double]
    double seconds = 0;
    int jobs = 1;

    /// The cell of an implementation and a family, by name; throws std::out_of_range.
    [[nodiscard]] const CellStats& cell(const std::string& implementation, const std::string& family) const;
};

/// Runs the audit on `config.jobs` threads. Deterministic for a given seed and case count.
[[nodiscard]] AuditResult runAudit(const AuditConfig& config);

/// Writes report.md, report.json (scripts/plots.py draws the charts from it) and
/// worst/<implementation>__<family>.jsonl (the worst scene of every failing cell, one line per
/// failing metric, replayable with `tilesweep resolve`) into `directory`, creating it. Throws
/// std::runtime_error on I/O failure.
void writeAuditReport(const AuditResult& result, const std::string& directory);

/// The seed's verdict on a family: the smallest |epsilon| of kSeedEpsilons with no decision
/// mismatch, as text ("0", "1e-05", "-1e-04"), or "none".
[[nodiscard]] std::string smallestFixingEpsilon(const CellStats& cell);

}  // namespace tilesweep::audit
