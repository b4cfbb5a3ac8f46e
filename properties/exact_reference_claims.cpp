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
std::string matchesExactReferenceBitForBit(const Scene<T>& scene) {
    return diffFrames(resolveUnderTest(scene), oracle::resolveSceneExactRounded(scene));
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

template std::string matchesExactReferenceBitForBit<float>(const Scene<float>&);
template std::string matchesExactReferenceBitForBit<double>(const Scene<double>&);
template std::string placesContactsLikeTheExactReference<float>(const Scene<float>&);
template std::string placesContactsLikeTheExactReference<double>(const Scene<double>&);
template std::string exactReferenceAgreesWithSubsteps<float>(const Scene<float>&);
template std::string exactReferenceAgreesWithSubsteps<double>(const Scene<double>&);
template std::string sweepBoxMatchesTheReference<float>(const Scene<float>&);
template std::string sweepBoxMatchesTheReference<double>(const Scene<double>&);

}  // namespace tilesweep::properties
