// SPDX-License-Identifier: MIT
// The safety claims (claims.h): what any sound resolver holds whatever its rounding, with no
// allowance: never inside a tile it did not start in, never into a wall, stopped touching, every
// rule of checks/frame_safety.h, no contact the substeps see missed; and bad input refused.
#include "claim_support.h"
#include "claims.h"

#include <cmath>
#include <limits>

namespace tilesweep::properties {

using namespace claim_support;

/// At the end of every frame, the box overlaps no solid tile it did not overlap at the frame's
/// start: docs/contract.md's promise, with no allowance (the amended rounding rule keeps it).
template <class T>
std::string neverEndsInsideATileItDidNotStartIn(const Scene<T>& scene, SceneResolver& resolver) {
    const CheckedFrames<T> c = checkedFrames(scene, resolver);
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
std::string neverGetsIntoAWall(const Scene<T>& scene, SceneResolver& resolver) {
    const CheckedFrames<T> c = checkedFrames(scene, resolver);
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
std::string stopsJustTouching(const Scene<T>& scene, SceneResolver& resolver) {
    const CheckedFrames<T> c = checkedFrames(scene, resolver);
    for (std::size_t f = 0; f < c.frames.size(); ++f)
        if (std::string why = checks::checkHitTilesLeftTouching(recordOf(scene, c, f), c.edges); !why.empty())
            return "frame " + std::to_string(f) + ": " + why;
    return {};
}

/// Every frame obeys every safety rule of checks/frame_safety.h: well formed, the exact start
/// overlaps, no new overlap at the end, hit tiles left touching, and the position between the
/// start and the exact end, or one ulp below it exactly where the rounding rule says.
template <class T>
std::string obeysTheSafetyRules(const Scene<T>& scene, SceneResolver& resolver) {
    const CheckedFrames<T> c = checkedFrames(scene, resolver);
    checks::SafetyScratch scratch;
    for (std::size_t f = 0; f < c.frames.size(); ++f)
        if (const checks::SafetyViolation v =
                checks::checkFrameSafety(recordOf(scene, c, f), c.edges, scratch))
            return "frame " + std::to_string(f) + ": " + checks::ruleName(v.rule) + ": " + v.detail;
    return {};
}

/// Whenever the exact 64-substep oracle sees an overlap at substep k, the resolver hit something
/// no later than k/64 in that frame.
template <class T>
std::string substepOracleFindsNoMissedContact(const Scene<T>& scene, SceneResolver& resolver) {
    return missedContactSeenBySubsteps(scene, framesFrom(resolver, scene));
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
            const ResolveResult<T> r =
                resolveMove<T>({s.map.view(), s.box, s.moves.back()}, {contacts, 8, overlaps, 8});
            const std::string at = std::string(fields[field]) + " = " + hex(bad) + ": ";
            if (r.status != ResolveStatus::InvalidInput) return at + "not refused as InvalidInput";
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

template std::string neverEndsInsideATileItDidNotStartIn<float>(const Scene<float>&, SceneResolver&);
template std::string neverEndsInsideATileItDidNotStartIn<double>(const Scene<double>&, SceneResolver&);
template std::string neverGetsIntoAWall<float>(const Scene<float>&, SceneResolver&);
template std::string neverGetsIntoAWall<double>(const Scene<double>&, SceneResolver&);
template std::string stopsJustTouching<float>(const Scene<float>&, SceneResolver&);
template std::string stopsJustTouching<double>(const Scene<double>&, SceneResolver&);
template std::string obeysTheSafetyRules<float>(const Scene<float>&, SceneResolver&);
template std::string obeysTheSafetyRules<double>(const Scene<double>&, SceneResolver&);
template std::string substepOracleFindsNoMissedContact<float>(const Scene<float>&, SceneResolver&);
template std::string substepOracleFindsNoMissedContact<double>(const Scene<double>&, SceneResolver&);
template std::string badInputIsRejected<float>(const Scene<float>&);
template std::string badInputIsRejected<double>(const Scene<double>&);

// ---- The claims of this file, with their properties (claim.h) ----------------------------------

template <class T>
std::vector<Claim<T>> safetyClaims() {
    using S = ClaimScope;
    const bool isDouble = std::is_same_v<T, double>;
    return {
        {"neverEndsInsideATileItDidNotStartIn",
         &neverEndsInsideATileItDidNotStartIn<T>,
         S::Safety,
         nullptr,
         {{"neverEndsInsideATileItDidNotStartIn", Family::Mixed, {{"hit", 0.2}, {"rounded-down", 0.002}}},
          // Float far edges all take the fast path, whose range test has no slack: the float
          // range test's edge has its own family and floor (decidesRangeEdgeScenesExactly).
          {"farEdgesNeverEndInsideATile", Family::FarEdge,
           isDouble ? std::vector<CoverageFloor>{{"rounded-down", 0.05}, {"fallback", 0.05}}
                    : std::vector<CoverageFloor>{{"rounded-down", 0.05}}},
          {"roundingNearFarCornersStaysOutOfHitTiles",
           Family::FarSubUlp,
           {{"far-origin", 0.9}, {"fallback", 0.05}}}}},
        {"stopsJustTouching",
         &stopsJustTouching<T>,
         S::Safety,
         nullptr,
         {{"stopsJustTouching", Family::Mixed, {{"hit", 0.2}}}}},
        {"obeysTheSafetyRules",
         &obeysTheSafetyRules<T>,
         S::Safety,
         nullptr,
         {{"obeysTheSafetyRules", Family::Mixed, {{"hit", 0.2}}},
          {"farEdgesObeyTheSafetyRules", Family::FarEdge, {{"rounded-down", 0.05}}},
          {"extremeScenesObeyTheSafetyRules", Family::Extreme, {{"empty-map", 0.2}, {"huge-move", 0.3}}},
          {"platformScenesObeyTheSafetyRules",
           Family::Platforms,
           {{"one-way-hit", 0.05}, {"starts-in-one-way", 0.05}}}}},
        {"neverGetsIntoAWall",
         &neverGetsIntoAWall<T>,
         S::Safety,
         nullptr,
         {{"neverGetsIntoAWall", Family::FarEdge, {{"rounded-down", 0.05}}}}},
        {"substepOracleFindsNoMissedContact",
         &substepOracleFindsNoMissedContact<T>,
         S::Safety,
         nullptr,
         {{"substepOracleFindsNoMissedContact", Family::Mixed, {{"hit", 0.2}}},
          {"substepOracleSeesEveryPlatformLanding", Family::PlatformLanding, {{"one-way-hit", 0.3}}}}},
        // Bad input: inputs the other families seldom make.
        {"badInputIsRejected",
         &aboutTilesweep<T, &badInputIsRejected<T>>,
         S::Internal,
         nullptr,
         {{"badInputIsRejected", Family::Mixed, {}}}},
    };
}

template std::vector<Claim<float>> safetyClaims<float>();
template std::vector<Claim<double>> safetyClaims<double>();

}  // namespace tilesweep::properties
