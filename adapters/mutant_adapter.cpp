// SPDX-License-Identifier: MIT
// A deliberately broken resolver behind the protocol, to prove that `tilesweep check
// --resolver-cmd` holds an outside engine to each rule it enforces. Every mutation starts from the
// exact reference (oracle/exact), frame by frame from the position it itself returned, and breaks
// one rule of the contract, only in the frames where that rule has something to say; elsewhere it
// answers as the contract does. The rule each one breaks, and the claims that state that rule
// (properties/claims.h; [rule] is the safety rule of checks/frame_safety.h that
// obeysTheSafetyRules names):
//
//   round-nearest              positions rounded to nearest, not toward the start (nor down where
//                              the exception asks): matchesExactReferenceBitForBit
//   tie-prefers-x              an exact corner tie with both faces exposed or neither goes to x, not
//                              y (the scene is resolved transposed and transposed back; a scene
//                              with one-way tiles, whose rule is not symmetric, as the contract):
//                              matchesExactReferenceBitForBit
//   flipped-normal             the first contact on a solid tile has its normal along the motion
//                              [wellFormed]
//   time-past-one              the first contact's time is the value just above 1 [wellFormed]
//   contact-on-empty-cell      the first contact names the empty cell across the face it hit
//                              [wellFormed]
//   end-inside-tile            one ulp past a hit face, into a solid tile the box did not start in:
//                              neverEndsInsideATileItDidNotStartIn [endsInsideNewTile]
//   short-of-left-face         one ulp short (toward the start) of a tile's left face hit moving
//                              right: stopsJustTouching [leavesHitTileTouching]
//   short-of-right-face        likewise, a right face hit moving left
//   short-of-top-face          likewise, a top face hit moving down (landing)
//   short-of-bottom-face       likewise, a bottom face hit moving up (a ceiling)
//   past-end-positive          one ulp past the exact end on a free axis moving toward +infinity
//                              [staysWithinExactMotion]
//   past-end-negative          likewise toward -infinity, from an exact end that is not
//                              representable: the value just below it, which only a grid line
//                              would allow [staysWithinExactMotion]
//   behind-start               one ulp behind the start, against the motion, on a free axis moving
//                              toward -infinity [staysWithinExactMotion]
//   drifts-on-still-axis       one ulp off the start on an axis that does not move: zeroMoveChangesNothing
//                              [staysWithinExactMotion]
//   no-grid-line-exception     rounded toward the start where the exception asks for the value below
//                              the exact end [staysWithinExactMotion]
//   drops-start-overlap        the last started_overlapping cell left out: zeroMoveChangesNothing
//                              [startOverlaps]
//   lists-touched-as-overlap   solid tiles the box only touches at the start listed as overlapped
//                              [startOverlaps]
//   lists-one-way-overlap      one-way cells the box overlaps at the start listed: zeroMoveChangesNothing
//                              [startOverlaps]
//   platform-blocks-from-below a step moving up treats one-way tiles as solid:
//                              neverBlockedByAPlatformFromBelow
//   falls-through-platform     a box standing on a platform and moving down ignores platforms:
//                              neverFallsThroughAPlatformItStoodOn
//   time-one-ulp-late          the first contact's time one ulp later (earlier at 1):
//                              matchesExactReferenceBitForBit
//   missing-contact            the first contact of a frame of one step left out:
//                              matchesExactReferenceBitForBit, substepOracleFindsNoMissedContact
//   extra-contact              the last contact listed twice: matchesExactReferenceBitForBit
//   steps-reversed             the second step's contacts listed before the first's:
//                              matchesExactReferenceBitForBit
//   short-on-free-axis         one ulp short of the exact end on a free axis, toward the start (not
//                              the nearest value): matchesExactReferenceBitForBit; no safety rule
//                              forbids it
//
// A mutation that moves the box checks, exactly, that the new position enters no solid tile the box
// did not start in (end-inside-tile aside), so that it breaks its own rule and not that one. That
// geometry is this file's own, on the oracle's rationals, never checks/frame_safety.h: a fault
// planted in the judge cannot make a mutation hold back. adapters/CMakeLists.txt runs check on each
// mutation and names the claims that must fail (rule_breaker_test.sh).
//
// Variants (--variant) change what the contract leaves free; a checker must accept them:
//
//   reversed-overlaps          started_overlapping in reverse order (the contract allows any order)
//   hexfloat-numbers           every number a hexfloat string ("0x1.8p+3"), as scene files allow
//   long-decimal               every number in decimal with 9 (float) or 17 (double) significant
//                              digits, in exponent form: not the shortest, but it reads back the same
//   exact-decimal              every number in decimal with all its digits: its exact value
//
//     tilesweep_mutant_adapter --mutation NAME [--scalar float|double] < scenes.jsonl
//     tilesweep_mutant_adapter --variant NAME [--scalar float|double] < scenes.jsonl
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using namespace tilesweep;
using oracle::ExactBox;
using oracle::ExactFrame;
using oracle::ExactTileMap;
using oracle::Integer;
using oracle::Rational;

enum class Change {
    RoundNearest,
    TiePrefersX,
    FlippedNormal,
    TimePastOne,
    ContactOnEmptyCell,
    EndInsideTile,
    ShortOfLeftFace,
    ShortOfRightFace,
    ShortOfTopFace,
    ShortOfBottomFace,
    PastEndPositive,
    PastEndNegative,
    BehindStart,
    DriftsOnStillAxis,
    NoGridLineException,
    DropsStartOverlap,
    ListsTouchedAsOverlap,
    ListsOneWayOverlap,
    PlatformBlocksFromBelow,
    FallsThroughPlatform,
    TimeOneUlpLate,
    MissingContact,
    ExtraContact,
    StepsReversed,
    ShortOnFreeAxis,
    // Variants: answers the contract allows.
    ReversedOverlaps,
    HexfloatNumbers,
    LongDecimal,
    ExactDecimal,
};

struct Named {
    const char* name;
    Change change;
    bool variant;
};

constexpr Named kChanges[] = {
    {"round-nearest", Change::RoundNearest, false},
    {"tie-prefers-x", Change::TiePrefersX, false},
    {"flipped-normal", Change::FlippedNormal, false},
    {"time-past-one", Change::TimePastOne, false},
    {"contact-on-empty-cell", Change::ContactOnEmptyCell, false},
    {"end-inside-tile", Change::EndInsideTile, false},
    {"short-of-left-face", Change::ShortOfLeftFace, false},
    {"short-of-right-face", Change::ShortOfRightFace, false},
    {"short-of-top-face", Change::ShortOfTopFace, false},
    {"short-of-bottom-face", Change::ShortOfBottomFace, false},
    {"past-end-positive", Change::PastEndPositive, false},
    {"past-end-negative", Change::PastEndNegative, false},
    {"behind-start", Change::BehindStart, false},
    {"drifts-on-still-axis", Change::DriftsOnStillAxis, false},
    {"no-grid-line-exception", Change::NoGridLineException, false},
    {"drops-start-overlap", Change::DropsStartOverlap, false},
    {"lists-touched-as-overlap", Change::ListsTouchedAsOverlap, false},
    {"lists-one-way-overlap", Change::ListsOneWayOverlap, false},
    {"platform-blocks-from-below", Change::PlatformBlocksFromBelow, false},
    {"falls-through-platform", Change::FallsThroughPlatform, false},
    {"time-one-ulp-late", Change::TimeOneUlpLate, false},
    {"missing-contact", Change::MissingContact, false},
    {"extra-contact", Change::ExtraContact, false},
    {"steps-reversed", Change::StepsReversed, false},
    {"short-on-free-axis", Change::ShortOnFreeAxis, false},
    {"reversed-overlaps", Change::ReversedOverlaps, true},
    {"hexfloat-numbers", Change::HexfloatNumbers, true},
    {"long-decimal", Change::LongDecimal, true},
    {"exact-decimal", Change::ExactDecimal, true},
};

// ---- Exact geometry on the map, independent of the checker under test (checks/) --------------

/// The largest integer <= q.
Integer floorOf(const Rational& q) {
    const Integer n = boost::multiprecision::numerator(q);
    const Integer d = boost::multiprecision::denominator(q);  // > 0
    Integer f = n / d;                                        // truncated toward zero
    if (n < 0 && f * d != n) f -= 1;
    return f;
}

/// The cells of one axis whose closed span may meet [lo, hi], with a cell of margin, clamped to
/// the map; empty when first > last.
std::pair<std::int64_t, std::int64_t> cellsNear(const Rational& lo, const Rational& hi,
                                                const Rational& origin, const Rational& tile,
                                                std::int32_t count) {
    const Integer first = floorOf((lo - origin) / tile) - 1;
    const Integer last = floorOf((hi - origin) / tile) + 1;
    if (last < 0 || first >= count) return {0, -1};
    return {first < 0 ? 0 : first.convert_to<std::int64_t>(),
            last >= count ? count - 1 : last.convert_to<std::int64_t>()};
}

enum class Meets : std::uint8_t { Overlaps, OnlyTouches };

/// The cells of `kind` that the box overlaps (their interiors meet), or that it touches without
/// overlapping; by row, then column.
std::vector<Cell> cellsMet(const ExactTileMap& map, const ExactBox& box, CellKind kind, Meets meets) {
    const oracle::ExactRect b = oracle::rectOf(box);
    const auto is = cellsNear(b.min.x, b.max.x, map.origin.x, map.tileSize.x, map.columns);
    const auto js = cellsNear(b.min.y, b.max.y, map.origin.y, map.tileSize.y, map.rows);
    std::vector<Cell> out;
    for (std::int64_t j = js.first; j <= js.second; ++j)
        for (std::int64_t i = is.first; i <= is.second; ++i) {
            if (map.kind(i, j) != kind) continue;
            const oracle::ExactRect t = map.tileRect(i, j);
            const bool closed =
                b.min.x <= t.max.x && b.max.x >= t.min.x && b.min.y <= t.max.y && b.max.y >= t.min.y;
            const bool open = oracle::overlaps(b, t);
            if (meets == Meets::Overlaps ? open : closed && !open)
                out.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
        }
    return out;
}

/// Whether the box at `pos` overlaps a solid tile it did not overlap at `start`.
template <class T>
bool entersNewSolid(const ExactTileMap& map, const Box<T>& start, Vec2<T> pos) {
    const std::vector<Cell> before = cellsMet(map, oracle::toExact(start), CellKind::Solid, Meets::Overlaps);
    for (const Cell c :
         cellsMet(map, oracle::toExact(Box<T>{pos, start.size}), CellKind::Solid, Meets::Overlaps))
        if (std::find(before.begin(), before.end(), c) == before.end()) return true;
    return false;
}

/// Whether the box stands on a one-way tile: the top of one lies exactly at its bottom, under
/// its open x span.
template <class T>
bool standsOnPlatform(const ExactTileMap& map, const Box<T>& box) {
    const oracle::ExactRect b = oracle::rectOf(oracle::toExact(box));
    for (const Cell c : cellsMet(map, oracle::toExact(box), CellKind::OneWay, Meets::OnlyTouches)) {
        const oracle::ExactRect t = map.tileRect(c.i, c.j);
        if (t.min.y == b.max.y && t.min.x < b.max.x && t.max.x > b.min.x) return true;
    }
    return false;
}

// ---- The mutations -----------------------------------------------------------------------------

template <class T>
T& along(Vec2<T>& v, int axis) {
    return axis == 0 ? v.x : v.y;
}

template <class T>
T along(const Vec2<T>& v, int axis) {
    return axis == 0 ? v.x : v.y;
}

template <class T>
bool hasContactOn(const FrameResult<T>& frame, int axis) {
    return std::any_of(frame.contacts.begin(), frame.contacts.end(),
                       [axis](const Contact<T>& c) { return (axis == 0 ? c.normal.x : c.normal.y) != 0; });
}

/// Moves the result one ulp on `axis` toward `target`, unless that enters a new solid tile;
/// whether it moved.
template <class T>
bool stepOneUlp(const ExactTileMap& map, const Box<T>& start, FrameResult<T>& frame, int axis, T target) {
    Vec2<T> moved = frame.position;
    along(moved, axis) = std::nextafter(along(moved, axis), target);
    if (entersNewSolid(map, start, moved)) return false;
    frame.position = moved;
    return true;
}

/// The map a frame is resolved on: the scene's, except where the mutation changes which tiles block.
template <class T>
ExactTileMap mapOfFrame(Change change, const ExactTileMap& map, const Box<T>& start, Vec2<T> move) {
    if (change == Change::PlatformBlocksFromBelow && move.y < 0) {
        ExactTileMap solidified = map;
        for (CellKind& cell : solidified.cells)
            if (cell == CellKind::OneWay) cell = CellKind::Solid;
        return solidified;
    }
    if (change == Change::FallsThroughPlatform && move.y > 0 && standsOnPlatform(map, start))
        return map.withoutOneWay();
    return map;
}

/// Applies the mutation to one frame resolved under the contract (`frame`, from `exact`).
template <class T>
void mutateFrame(Change change, const ExactTileMap& map, const Box<T>& start, Vec2<T> move,
                 const ExactFrame& exact, FrameResult<T>& frame) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    const auto startOf = [&](int axis) { return along(start.pos, axis); };
    switch (change) {
        case Change::RoundNearest:
            frame.position = {oracle::fromRational<T>(exact.position.x, oracle::Rounding::NearestEven),
                              oracle::fromRational<T>(exact.position.y, oracle::Rounding::NearestEven)};
            if (exact.position.x == exact.start.x)
                frame.position.x = start.pos.x;  // keep -0 as the contract does
            if (exact.position.y == exact.start.y) frame.position.y = start.pos.y;
            break;
        case Change::FlippedNormal:
            // On a solid tile: a one-way tile's flipped normal would also leave its only face.
            for (Contact<T>& c : frame.contacts)
                if (map.kind(c.tile.i, c.tile.j) == CellKind::Solid) {
                    c.normal = {static_cast<std::int8_t>(-c.normal.x), static_cast<std::int8_t>(-c.normal.y)};
                    break;
                }
            break;
        case Change::TimePastOne:
            if (!frame.contacts.empty()) frame.contacts.front().time = std::nextafter(T(1), T(2));
            break;
        case Change::ContactOnEmptyCell:
            // The normal points out of the hit face: the cell across it is tile + normal.
            if (!frame.contacts.empty()) {
                Contact<T>& c = frame.contacts.front();
                const Cell across{c.tile.i + c.normal.x, c.tile.j + c.normal.y};
                if (map.kind(across.i, across.j) == CellKind::Empty) c.tile = across;
            }
            break;
        case Change::EndInsideTile:
            // One ulp through a hit face always overlaps the hit tile on that axis; keep it when
            // the box then overlaps some solid tile it did not start in (it may have slid past).
            for (auto c = frame.contacts.rbegin(); c != frame.contacts.rend(); ++c) {
                const int axis = c->normal.x != 0 ? 0 : 1;
                const int motion = -(axis == 0 ? c->normal.x : c->normal.y);
                Vec2<T> moved = frame.position;
                along(moved, axis) = std::nextafter(along(moved, axis), motion > 0 ? inf : -inf);
                if (entersNewSolid(map, start, moved)) {
                    frame.position = moved;
                    break;
                }
            }
            break;
        case Change::ShortOfLeftFace:
        case Change::ShortOfRightFace:
        case Change::ShortOfTopFace:
        case Change::ShortOfBottomFace: {
            const Normal face = change == Change::ShortOfLeftFace    ? Normal{-1, 0}
                                : change == Change::ShortOfRightFace ? Normal{1, 0}
                                : change == Change::ShortOfTopFace   ? Normal{0, -1}
                                                                     : Normal{0, 1};
            const int axis = face.x != 0 ? 0 : 1;
            const bool hit = std::any_of(frame.contacts.begin(), frame.contacts.end(),
                                         [face](const Contact<T>& c) { return c.normal == face; });
            // Only where the box moved on that axis: short of the start would also move backward.
            if (hit && along(frame.position, axis) != startOf(axis))
                stepOneUlp(map, start, frame, axis, startOf(axis));
            break;
        }
        case Change::PastEndPositive:
        case Change::PastEndNegative: {
            // Only where the contract rounded toward the start: one ulp past that is the value
            // just past the exact end, where the exception (when it applies) is already. Toward
            // -infinity, only where the exact end is not representable: the value just below it
            // is then what the exception would ask for, were there a grid line, and there is none.
            const int sign = change == Change::PastEndPositive ? 1 : -1;
            for (int axis = 0; axis < 2; ++axis) {
                const Rational& e = axis == 0 ? exact.position.x : exact.position.y;
                const T q = along(frame.position, axis);
                if (along(move, axis) * T(sign) > 0 && !hasContactOn(frame, axis) &&
                    oracle::roundToward<T>(e, startOf(axis)) == q &&
                    (sign > 0 || oracle::toRational(q) != e) &&
                    stepOneUlp(map, start, frame, axis, sign > 0 ? inf : -inf))
                    break;
            }
            break;
        }
        case Change::BehindStart:
            for (int axis = 0; axis < 2; ++axis) {
                if (!(along(move, axis) < 0) || hasContactOn(frame, axis)) continue;
                Vec2<T> moved = frame.position;
                along(moved, axis) = std::nextafter(startOf(axis), inf);
                if (!entersNewSolid(map, start, moved)) {
                    frame.position = moved;
                    break;
                }
            }
            break;
        case Change::DriftsOnStillAxis:
            for (int axis = 0; axis < 2; ++axis)
                if (along(move, axis) == 0 &&
                    (stepOneUlp(map, start, frame, axis, inf) || stepOneUlp(map, start, frame, axis, -inf)))
                    break;
            break;
        case Change::NoGridLineException:
            // Where the contract rounded down past the exact end, round toward the start instead.
            for (int axis = 0; axis < 2; ++axis) {
                if (!(along(move, axis) < 0) || hasContactOn(frame, axis)) continue;
                const Rational& e = axis == 0 ? exact.position.x : exact.position.y;
                const T back = oracle::roundToward<T>(e, startOf(axis));
                if (back == along(frame.position, axis)) continue;
                Vec2<T> moved = frame.position;
                along(moved, axis) = back;
                if (!entersNewSolid(map, start, moved)) frame.position = moved;
            }
            break;
        case Change::DropsStartOverlap:
            if (!frame.startOverlaps.empty()) frame.startOverlaps.pop_back();
            break;
        case Change::ListsTouchedAsOverlap:
            for (const Cell c : cellsMet(map, oracle::toExact(start), CellKind::Solid, Meets::OnlyTouches))
                frame.startOverlaps.push_back(c);
            break;
        case Change::ListsOneWayOverlap:
            for (const Cell c : cellsMet(map, oracle::toExact(start), CellKind::OneWay, Meets::Overlaps))
                frame.startOverlaps.push_back(c);
            break;
        case Change::PlatformBlocksFromBelow:
            // Resolved with platforms as solid: the start overlaps are still the solid tiles'.
            frame.startOverlaps = cellsMet(map, oracle::toExact(start), CellKind::Solid, Meets::Overlaps);
            break;
        case Change::TimeOneUlpLate:
            if (!frame.contacts.empty()) {
                T& t = frame.contacts.front().time;
                t = std::nextafter(t, t < 1 ? T(2) : T(0));
            }
            break;
        case Change::MissingContact:
            // Only in a frame of one step: what is left is hit at the same time, so the frame's
            // first contact is not later, only one is missing (or all, after a single hit).
            if (!frame.contacts.empty() &&
                std::all_of(exact.contacts.begin(), exact.contacts.end(),
                            [](const oracle::ExactContact& c) { return c.step == 1; }))
                frame.contacts.erase(frame.contacts.begin());
            break;
        case Change::ExtraContact:
            if (!frame.contacts.empty()) frame.contacts.push_back(frame.contacts.back());
            break;
        case Change::StepsReversed: {
            // roundFrame keeps the exact frame's contacts in order, so exact.contacts[k] is frame's k.
            std::vector<Contact<T>> second;
            std::vector<Contact<T>> first;
            for (std::size_t k = 0; k < frame.contacts.size(); ++k)
                (exact.contacts[k].step == 2 ? second : first).push_back(frame.contacts[k]);
            if (!second.empty() && !first.empty()) {
                second.insert(second.end(), first.begin(), first.end());
                frame.contacts = second;
            }
            break;
        }
        case Change::ShortOnFreeAxis:
            // Only where the contract rounded toward the start: where it rounded down instead, one
            // ulp toward the start is the rounding the grid-line exception forbids.
            for (int axis = 0; axis < 2; ++axis) {
                const Rational& e = axis == 0 ? exact.position.x : exact.position.y;
                if (along(move, axis) != 0 && !hasContactOn(frame, axis) &&
                    along(frame.position, axis) != startOf(axis) &&
                    oracle::roundToward<T>(e, startOf(axis)) == along(frame.position, axis) &&
                    stepOneUlp(map, start, frame, axis, startOf(axis)))
                    break;
            }
            break;
        case Change::ReversedOverlaps:
            std::reverse(frame.startOverlaps.begin(), frame.startOverlaps.end());
            break;
        case Change::TiePrefersX:           // whole scenes (tiePrefersX)
        case Change::FallsThroughPlatform:  // the map only (mapOfFrame)
        case Change::HexfloatNumbers:       // the output only (formatted)
        case Change::LongDecimal:
        case Change::ExactDecimal:
            break;
    }
}

/// Every frame of a scene, each from the position the previous one returned, mutated.
template <class T>
std::vector<FrameResult<T>> resolveMutated(const Scene<T>& scene, Change change) {
    const ExactTileMap map = oracle::toExact(scene.map);
    std::vector<FrameResult<T>> frames;
    Box<T> box = scene.box;
    for (const Vec2<T>& move : scene.moves) {
        const ExactFrame exact = oracle::resolveFrameExact(mapOfFrame(change, map, box, move),
                                                           oracle::toExact(box), oracle::toExact(move));
        FrameResult<T> frame = oracle::roundFrame<T>(exact);
        mutateFrame(change, map, box, move, exact, frame);
        box.pos = frame.position;
        frames.push_back(std::move(frame));
    }
    return frames;
}

template <class T>
Scene<T> transposed(const Scene<T>& scene) {
    Scene<T> t = scene;
    t.map.origin = {scene.map.origin.y, scene.map.origin.x};
    t.map.tileSize = {scene.map.tileSize.y, scene.map.tileSize.x};
    t.map.columns = scene.map.rows;
    t.map.rows = scene.map.columns;
    for (std::int32_t j = 0; j < scene.map.rows; ++j)
        for (std::int32_t i = 0; i < scene.map.columns; ++i)
            t.map.solid[static_cast<std::size_t>(i * t.map.columns + j)] =
                scene.map.solid[static_cast<std::size_t>(j * scene.map.columns + i)];
    t.box = {{scene.box.pos.y, scene.box.pos.x}, {scene.box.size.y, scene.box.size.x}};
    for (Vec2<T>& m : t.moves) m = {m.y, m.x};
    return t;
}

template <class T>
std::vector<FrameResult<T>> tiePrefersX(const Scene<T>& scene) {
    // A one-way tile's rule is not symmetric under the transposition: such scenes as the contract.
    if (std::find(scene.map.oneWay.begin(), scene.map.oneWay.end(), std::uint8_t{1}) !=
        scene.map.oneWay.end())
        return oracle::resolveSceneExactRounded(scene);
    const std::vector<oracle::ExactFrame> exact = oracle::resolveSceneExact(transposed(scene));
    std::vector<FrameResult<T>> frames;
    for (const oracle::ExactFrame& e : exact) {
        const FrameResult<T> t = oracle::roundFrame<T>(e);
        FrameResult<T> f;
        f.position = {t.position.y, t.position.x};
        // Back to this scene's axes, each step's hits again by row, then column.
        std::vector<std::size_t> order(t.contacts.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return std::make_tuple(e.contacts[a].step, t.contacts[a].tile.i, t.contacts[a].tile.j) <
                   std::make_tuple(e.contacts[b].step, t.contacts[b].tile.i, t.contacts[b].tile.j);
        });
        for (const std::size_t k : order) {
            const Contact<T>& c = t.contacts[k];
            f.contacts.push_back(
                {{c.tile.j, c.tile.i}, {c.normal.y, c.normal.x}, c.time, {c.position.y, c.position.x}});
        }
        for (const Cell c : t.startOverlaps) f.startOverlaps.push_back({c.j, c.i});
        std::sort(f.startOverlaps.begin(), f.startOverlaps.end(),
                  [](Cell a, Cell b) { return std::tie(a.j, a.i) < std::tie(b.j, b.i); });
        frames.push_back(std::move(f));
    }
    return frames;
}

// ---- Writing ---------------------------------------------------------------------------------

/// A number as the variant writes it: a hexfloat string, or decimal with 9 or 17 significant
/// digits, or with every digit of its exact value (trailing zeros dropped).
template <class T>
std::string numberText(T value, Change change) {
    const auto v = static_cast<double>(value);  // exact: a float promotes without rounding
    char buffer[1200];
    if (change == Change::HexfloatNumbers) {
        std::snprintf(buffer, sizeof buffer, "\"%a\"", v);
        return buffer;
    }
    const int digits = change == Change::LongDecimal ? std::numeric_limits<T>::max_digits10 : 1100;
    std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, v);
    std::string text = buffer;
    if (change == Change::ExactDecimal) {  // 1100 digits hold any double exactly: drop the zeros
        const std::size_t e = text.find('e');
        std::size_t end = text.find_last_not_of('0', e - 1);
        if (text[end] == '.') --end;
        text.erase(end + 1, e - end - 1);
    }
    return text;
}

template <class T>
std::string formatted(const std::vector<FrameResult<T>>& frames, Change change) {
    if (change != Change::HexfloatNumbers && change != Change::LongDecimal && change != Change::ExactDecimal)
        return formatFrames(frames);
    const auto pair = [](long a, long b) { return "[" + std::to_string(a) + ", " + std::to_string(b) + "]"; };
    std::string out = "{\"frames\": [";
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const FrameResult<T>& frame = frames[f];
        out += f == 0 ? "" : ", ";
        out += "{\"pos\": [" + numberText(frame.position.x, change) + ", " +
               numberText(frame.position.y, change) + "], \"contacts\": [";
        for (std::size_t k = 0; k < frame.contacts.size(); ++k) {
            const Contact<T>& c = frame.contacts[k];
            out += k == 0 ? "" : ", ";
            out += "{\"tile\": " + pair(c.tile.i, c.tile.j) +
                   ", \"normal\": " + pair(c.normal.x, c.normal.y) +
                   ", \"t\": " + numberText(c.time, change) + "}";
        }
        out += "], \"started_overlapping\": [";
        for (std::size_t k = 0; k < frame.startOverlaps.size(); ++k)
            out += (k == 0 ? "" : ", ") + pair(frame.startOverlaps[k].i, frame.startOverlaps[k].j);
        out += "]}";
    }
    return out + "]}";
}

template <class T>
int serve(Change change) {
    std::string line;
    while (std::getline(std::cin, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const SceneParse<T> parsed = parseScene<T>(line);
        if (!parsed.scene) {
            std::cout << formatError(parsed.error) << '\n' << std::flush;
            continue;
        }
        const auto frames = change == Change::TiePrefersX ? tiePrefersX(*parsed.scene)
                                                          : resolveMutated(*parsed.scene, change);
        std::cout << formatted(frames, change) << '\n' << std::flush;
    }
    return 0;
}

int usage(const char* self) {
    std::fprintf(stderr, "usage: %s --mutation NAME | --variant NAME [--scalar float|double]\n", self);
    for (const bool variant : {false, true}) {
        std::fprintf(stderr, "  %s:", variant ? "variants" : "mutations");
        for (const Named& n : kChanges)
            if (n.variant == variant) std::fprintf(stderr, " %s", n.name);
        std::fprintf(stderr, "\n");
    }
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    std::string mutation;
    std::string variant;
    std::string scalar = "float";
    for (int k = 1; k + 1 < argc; k += 2) {
        if (std::strcmp(argv[k], "--mutation") == 0) mutation = argv[k + 1];
        if (std::strcmp(argv[k], "--variant") == 0) variant = argv[k + 1];
        if (std::strcmp(argv[k], "--scalar") == 0) scalar = argv[k + 1];
    }
    const bool isVariant = !variant.empty();
    if (mutation.empty() == variant.empty() || (scalar != "float" && scalar != "double"))
        return usage(argv[0]);
    const std::string& name = isVariant ? variant : mutation;
    for (const Named& n : kChanges)
        if (name == n.name && n.variant == isVariant)
            return scalar == "double" ? serve<double>(n.change) : serve<float>(n.change);
    return usage(argv[0]);
}
