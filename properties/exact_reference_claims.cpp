// SPDX-License-Identifier: MIT
// The claims against the exact reference (claims.h): the resolver bit for bit, its contact
// positions too, sweepBox tile by tile, and the reference itself against the exact substep oracle.
#include "claim_support.h"
#include "claims.h"

#include "tilesweep/box_sweep.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/exact_sweep.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tilesweep::properties {

using namespace claim_support;

/// Decisions, positions, times and start overlaps equal the exact reference's, bit for bit.
template <class T>
std::string matchesExactReferenceBitForBit(const Scene<T>& scene, SceneResolver& resolver) {
    return diffFrames(framesFrom(resolver, scene), oracle::resolveSceneExactRounded(scene));
}

/// Every contact's position (Contact::position) equals the exact reference's, bit for bit, on
/// top of everything matchesExactReferenceBitForBit compares. tilesweep's own resolver, always:
/// the resolve protocol carries no contact position (an internal claim).
template <class T>
std::string placesContactsLikeTheExactReference(const Scene<T>& scene) {
    const std::vector<FrameResult<T>> got = runScene(scene);
    const std::vector<FrameResult<T>> want = oracle::resolveSceneExactRounded(scene);
    if (std::string decisions = diffFrames(got, want); !decisions.empty()) return decisions;
    for (std::size_t f = 0; f < got.size(); ++f)
        for (std::size_t k = 0; k < got[f].contacts.size(); ++k) {
            const Vec2<T> a = got[f].contacts[k].position;
            const Vec2<T> b = want[f].contacts[k].position;
            const std::string at =
                "frame " + std::to_string(f) + ": contact " + std::to_string(k) + " position ";
            if (!sameBits(a.x, b.x)) return at + "x " + hex(a.x) + " != " + hex(b.x);
            if (!sameBits(a.y, b.y)) return at + "y " + hex(a.y) + " != " + hex(b.y);
        }
    return {};
}

/// The same held against the exact reference instead of the resolver: an independent check of
/// the oracle the bit-for-bit claims trust, on the decisions where the substeps are conclusive
/// (an overlap seen at a substep is a contact that must have happened by then).
template <class T>
std::string exactReferenceAgreesWithSubsteps(const Scene<T>& scene) {
    return missedContactSeenBySubsteps(scene, oracle::resolveSceneExactRounded(scene));
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
            const BoxSweepResult<T> got = sweepBox<T>({scene.box, d, {x0, y0}, {x1, y1}, xExposed, yExposed});
            const oracle::ExactSweepOutput want = oracle::sweepTileExact(
                {oracle::toExact(scene.box), oracle::toExact(d), map.tileRect(i, j), xExposed, yExposed});
            const std::string at = "tile " + cellText({i, j}) + ": ";
            const BoxSweepStatus state =
                want.state == oracle::ExactSweepState::Blocks   ? BoxSweepStatus::Blocks
                : want.state == oracle::ExactSweepState::Misses ? BoxSweepStatus::Misses
                                                                : BoxSweepStatus::StartsOverlapping;
            if (got.status != state) return at + "sweepBox state differs from the reference";
            if (state != BoxSweepStatus::Blocks) continue;
            if (got.axis != want.axis) return at + "contact axis differs";
            const T time = oracle::fromRational<T>(want.time, oracle::Rounding::NearestEven);
            if (!sameBits(got.time, time)) return at + "time " + hex(got.time) + " != " + hex(time);
        }
    return {};
}

template std::string matchesExactReferenceBitForBit<float>(const Scene<float>&, SceneResolver&);
template std::string matchesExactReferenceBitForBit<double>(const Scene<double>&, SceneResolver&);
template std::string placesContactsLikeTheExactReference<float>(const Scene<float>&);
template std::string placesContactsLikeTheExactReference<double>(const Scene<double>&);
template std::string exactReferenceAgreesWithSubsteps<float>(const Scene<float>&);
template std::string exactReferenceAgreesWithSubsteps<double>(const Scene<double>&);
template std::string sweepBoxMatchesTheReference<float>(const Scene<float>&);
template std::string sweepBoxMatchesTheReference<double>(const Scene<double>&);

// ---- The claims of this file, with their properties (claim.h) ----------------------------------

template <class T>
std::vector<Claim<T>> exactReferenceClaims() {
    using S = ClaimScope;
    const bool isDouble = std::is_same_v<T, double>;
    // In double, the code only double frames reach (productError's aLow * bLow term, the
    // remainder test of roundTimeToDouble) on purpose: refinements on inputs of full precision.
    std::vector<CoverageFloor> fineBits = {
        {"time-tie", 0.05}, {"reaches-at-end", 0.05}, {"lattice-wide", 0.05}, {"lattice-192", 0.03}};
    if (isDouble) fineBits.push_back({"full-precision-refined", 0.15});
    return {
        {"matchesExactReferenceBitForBit",
         &matchesExactReferenceBitForBit<T>,
         S::BitForBit,
         nullptr,
         {
             // The floors say what a run must have seen for its pass to mean something.
             {"matchesExactReferenceBitForBit",
              Family::Mixed,
              {{"hit", 0.2},
               {"miss", 0.1},
               {"tie", 0.03},
               {"touch-at-0", 0.03},
               {"two-step", 0.005},
               {"family:corner-pass", 0.05},
               {"seam", 0.02},
               {"far-origin", 0.03}}},
             // The corner, tie and far-origin families must reach the band where the fast path
             // cannot decide alone ("fallback": a filtered refinement or the exact lattice).
             {"decidesCornerPassesExactly",
              Family::CornerPass,
              {{"hit", 0.1}, {"miss", 0.1}, {"fallback", 0.05}}},
             {"settlesCornerTiesByExposedFace", Family::CornerTie, {{"tie", 0.3}, {"fallback", 0.05}}},
             // About 18.6% hits on average, 14.4% in the worst of 4,700 rounds.
             {"broadphaseOffersEveryBlockingTile", Family::Random, {{"hit", 0.10}, {"two-step", 0.02}}},
             // The rounding rule's family: the exception must change the result in a good share.
             {"roundsFarEdgesByTheAmendedRule", Family::FarEdge, {{"rounded-down", 0.05}, {"hit", 0.2}}},
             // In double, exact ties whose filter error lies in the band's upper half
             // (filter_band_family.h): what a halved bound decides wrongly.
             {"decidesTiesInsideTheFilterBand", Family::FilterBand,
              isDouble
                  ? std::vector<CoverageFloor>{{"tie", 0.5}, {"fallback", 0.5}, {"filter-upper-half", 0.5}}
                  : std::vector<CoverageFloor>{{"tie", 0.5}, {"fallback", 0.5}}},
             {"decidesFineBitsExactly", Family::FineBits, fineBits},
             // Empty maps and huge moves: inputs the other families seldom make.
             {"handlesEmptyMapsAndHugeMovesExactly",
              Family::Extreme,
              {{"empty-map", 0.2}, {"huge-move", 0.3}}},
             {"neverTunnelsAtHighSpeed", Family::HighSpeed, {{"hit", 0.5}}},
             // Corner entries one ulp off a tie, whose products differ by less than the filter's
             // bound: the refinement decides a nonzero sign. (Float frames hold every product
             // exactly in double: no refinement there, the same claim.)
             {"decidesNearTiesInsideTheFilterBand", Family::NearTie,
              isDouble ? std::vector<CoverageFloor>{{"near-tie-refined", 0.1},
                                                    {"full-precision-refined", 0.1},
                                                    {"hit", 0.5}}
                       : std::vector<CoverageFloor>{{"hit", 0.5}}},
             // The tiny end of the range: scenes scaled by powers of two near the least normal.
             {"decidesTinyScenesExactly", Family::TinyScale, {{"tiny", 0.5}, {"hit", 0.1}}},
             // The edge of the float range test (range-edge): spans 52 to 57
             // (range_edge_family.h); the scenes four binades past it catch a test that much too
             // generous.
             {"decidesRangeEdgeScenesExactly", Family::RangeEdge,
              isDouble ? std::vector<CoverageFloor>{{"hit", 0.9}}
                       : std::vector<CoverageFloor>{{"range-boundary", 0.6}, {"hit", 0.9}}},
             // One-way platforms (platform_family.h): landing on them at every speed and on
             // exact corners, jumping up through them, walking along them across seams, and
             // platforms among solid tiles.
             {"landsOnPlatformsExactly",
              Family::PlatformLanding,
              {{"one-way-hit", 0.3},
               {"one-way-tie", 0.03},
               {"one-way-fast", 0.1},
               {"in-one-way", 0.1},
               {"far-origin", 0.1}}},
             {"jumpsThroughPlatformsExactly",
              Family::PlatformJump,
              {{"in-one-way", 0.3}, {"one-way-hit", 0.15}, {"starts-in-one-way", 0.1}}},
             {"walksAlongPlatformsExactly",
              Family::PlatformWalk,
              {{"on-platform", 0.75}, {"one-way-seam", 0.1}}},
             {"decidesPlatformsAmongSolidTilesExactly",
              Family::Platforms,
              {{"one-way-hit", 0.05}, {"starts-in-one-way", 0.05}}},
         }},
        // Contact positions: the one new number (a step-1 hit the box slides on from, after
        // t = 0, at a coordinate T cannot hold) must be reached: about 45%, 36% and 17% at 2,000
        // cases.
        {"placesContactsLikeTheExactReference",
         &aboutTilesweep<T, &placesContactsLikeTheExactReference<T>>,
         S::Internal,
         nullptr,
         {{"placesContactsLikeTheExactReference",
           Family::Mixed,
           {{"hit", 0.2},
            {"hit-then-slide", 0.2},
            {"late-hit-then-slide", 0.15},
            {"hit-then-slide-rounded", 0.05}}}}},
        {"exactReferenceAgreesWithSubsteps",
         &aboutTilesweep<T, &exactReferenceAgreesWithSubsteps<T>>,
         S::Internal,
         nullptr,
         {{"exactReferenceAgreesWithSubsteps", Family::Mixed, {{"hit", 0.2}, {"touch-at-0", 0.03}}}}},
        {"sweepBoxMatchesTheReference",
         &aboutTilesweep<T, &sweepBoxMatchesTheReference<T>>,
         S::Internal,
         nullptr,
         {{"sweepBoxMatchesTheReference", Family::Mixed, {{"hit", 0.2}, {"tie", 0.03}}}}},
    };
}

template std::vector<Claim<float>> exactReferenceClaims<float>();
template std::vector<Claim<double>> exactReferenceClaims<double>();

}  // namespace tilesweep::properties
