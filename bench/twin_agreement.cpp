// SPDX-License-Identifier: MIT
// How often the inexact twin (and the swept-bounds grid resolver) decide differently from
// tilesweep, on the benchmarks' own frames (frame_scenarios.h): the share of frames on which
// they disagree, for every scenario.
//
//   tilesweep_twin_agreement            # every scenario, float and double
//
// Then the lean twin against the first one (resolveMoveTwinLibm, std::floor/std::ceil of a
// quotient per cell): the frames on which they decide differently or end at different
// positions, on the benchmarks' frames (16-px tiles: a power of two, where the two must agree)
// and on five property families (tiles of 4 to 32 px, 12 and 24 among them).
//
// Per frame and implementation, against tilesweep::resolveMove (which matches the exact
// reference bit for bit):
//   decisions differ  the contact count, or any contact's tile or normal (in order), or the
//                     start-overlap list differs;
//   positions differ  the final position differs in any bit (-0 == 0); tilesweep rounds toward
//                     the start (docs/contract.md "Positions"), plain arithmetic to nearest, so most
//                     of these are one ulp apart: "> 1 ulp" counts the rest;
//   ends inside       the final box overlaps (open, evaluated exactly) a solid tile it did not
//                     overlap at the start: the failure the contract's rounding rule rules out.
#include "frame_scenarios.h"

#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/scenarios/families.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

namespace {

using tilesweep::Box;
using tilesweep::Cell;
using tilesweep::Contact;
using tilesweep::ResolveInput;
using tilesweep::ResolveOutput;
using tilesweep::ResolveResult;
using tilesweep::TileMapView;
using tilesweep::Vec2;
namespace tb = tilesweep::bench;

constexpr std::int32_t kCapacity = 64;

/// One frame's full output.
template <class T>
struct FrameOutput {
    ResolveResult<T> result;
    Contact<T> contacts[kCapacity];
    Cell overlaps[kCapacity];
};

template <class T, class Resolve>
void runFrame(const ResolveInput<T>& in, FrameOutput<T>& f, Resolve resolve) {
    f.result = resolve(in, ResolveOutput<T>{f.contacts, kCapacity, f.overlaps, kCapacity});
}

template <class T>
bool sameDecisions(const FrameOutput<T>& a, const FrameOutput<T>& b) {
    if (a.result.contactCount != b.result.contactCount) return false;
    if (a.result.startOverlapCount != b.result.startOverlapCount) return false;
    const std::int32_t n = a.result.contactCount < kCapacity ? a.result.contactCount : kCapacity;
    for (std::int32_t k = 0; k < n; ++k)
        if (a.contacts[k].tile != b.contacts[k].tile || a.contacts[k].normal != b.contacts[k].normal)
            return false;
    const std::int32_t m = a.result.startOverlapCount < kCapacity ? a.result.startOverlapCount : kCapacity;
    for (std::int32_t k = 0; k < m; ++k)
        if (a.overlaps[k] != b.overlaps[k]) return false;
    return true;
}

/// Whether the box at `pos` overlaps a solid tile it did not overlap at the start. Edges and
/// sums are formed in long double (64-bit significand on x86), where the sums of these
/// scenarios (below 2^22, least bit no finer than 2^-40) are exact.
template <class T>
bool endsInside(const TileMapView<T>& map, const Box<T>& start, Vec2<T> pos) {
    using L = long double;
    const auto overlaps = [&](L x, L y, std::int64_t i, std::int64_t j) {
        const L x0 = L(map.origin.x) + L(i) * L(map.tileSize.x),
                y0 = L(map.origin.y) + L(j) * L(map.tileSize.y);
        return x < x0 + L(map.tileSize.x) && x + L(start.size.x) > x0 && y < y0 + L(map.tileSize.y) &&
               y + L(start.size.y) > y0;
    };
    const auto cellOf = [](L v, L o, L t) { return static_cast<std::int64_t>(std::floor((v - o) / t)); };
    const std::int64_t i0 = cellOf(L(pos.x), L(map.origin.x), L(map.tileSize.x)) - 1;
    const std::int64_t j0 = cellOf(L(pos.y), L(map.origin.y), L(map.tileSize.y)) - 1;
    const std::int64_t i1 = cellOf(L(pos.x) + L(start.size.x), L(map.origin.x), L(map.tileSize.x)) + 1;
    const std::int64_t j1 = cellOf(L(pos.y) + L(start.size.y), L(map.origin.y), L(map.tileSize.y)) + 1;
    for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t i = i0; i <= i1; ++i)
            if (map.isSolid(i, j) && overlaps(L(pos.x), L(pos.y), i, j) &&
                !overlaps(L(start.pos.x), L(start.pos.y), i, j))
                return true;
    return false;
}

/// Whether a and b are more than one ulp apart on some axis.
template <class T>
bool fartherThanUlp(Vec2<T> a, Vec2<T> b) {
    const auto far = [](T u, T v) {
        return v < std::nextafter(u, -std::numeric_limits<T>::infinity()) ||
               v > std::nextafter(u, std::numeric_limits<T>::infinity());
    };
    return far(a.x, b.x) || far(a.y, b.y);
}

struct Counts {
    long frames = 0;
    long blocked = 0;  ///< frames tilesweep reports a contact in
    long twinDecisions = 0, twinPositions = 0, twinUlp = 0, twinInside = 0;
    long gridDecisions = 0, gridPositions = 0, gridUlp = 0, gridInside = 0;
    long tilesweepInside = 0;

    void add(const Counts& c) {
        frames += c.frames;
        blocked += c.blocked;
        twinDecisions += c.twinDecisions;
        twinPositions += c.twinPositions;
        twinUlp += c.twinUlp;
        twinInside += c.twinInside;
        gridDecisions += c.gridDecisions;
        gridPositions += c.gridPositions;
        gridUlp += c.gridUlp;
        gridInside += c.gridInside;
        tilesweepInside += c.tilesweepInside;
    }
};

template <class T>
Counts countScenario(tb::FrameKind kind, int speedArg) {
    const tb::FrameScenario<T> s = tb::makeFrameScenario<T>(kind, speedArg / 2.0);
    const TileMapView<T> view = s.map.view();
    static FrameOutput<T> exact, twin, grid;
    Counts c;
    for (std::size_t k = 0; k < s.boxes.size(); ++k) {
        const ResolveInput<T> in{view, s.boxes[k], s.moves[k]};
        runFrame(in, exact, [](const ResolveInput<T>& i, const ResolveOutput<T>& o) {
            return tilesweep::resolveMove(i, o);
        });
        runFrame(in, twin, [](const ResolveInput<T>& i, const ResolveOutput<T>& o) {
            return tilesweep::baselines::resolveMoveTwin(i, o);
        });
        runFrame(in, grid, [](const ResolveInput<T>& i, const ResolveOutput<T>& o) {
            return tilesweep::baselines::resolveMoveGrid(i, o);
        });
        ++c.frames;
        c.blocked += exact.result.contactCount > 0;
        c.twinDecisions += !sameDecisions(exact, twin);
        c.gridDecisions += !sameDecisions(exact, grid);
        c.twinPositions += exact.result.position != twin.result.position;
        c.gridPositions += exact.result.position != grid.result.position;
        c.twinUlp += fartherThanUlp(exact.result.position, twin.result.position);
        c.gridUlp += fartherThanUlp(exact.result.position, grid.result.position);
        c.tilesweepInside += endsInside(view, s.boxes[k], exact.result.position);
        c.twinInside += endsInside(view, s.boxes[k], twin.result.position);
        c.gridInside += endsInside(view, s.boxes[k], grid.result.position);
    }
    return c;
}

double percent(long part, long whole) {
    return whole > 0 ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

void printRow(const char* name, const Counts& c) {
    std::printf("%-26s %7ld %6.2f%% | %8.4f%% %8.3f%% %8.4f%% %5ld | %8.4f%% %8.3f%% %8.4f%% %5ld | %5ld\n",
                name, c.frames, percent(c.blocked, c.frames), percent(c.twinDecisions, c.frames),
                percent(c.twinPositions, c.frames), percent(c.twinUlp, c.frames), c.twinInside,
                percent(c.gridDecisions, c.frames), percent(c.gridPositions, c.frames),
                percent(c.gridUlp, c.frames), c.gridInside, c.tilesweepInside);
}

template <class T>
void report(const char* scalar, tb::FrameKind kind, int speedArg, Counts& total) {
    const Counts c = countScenario<T>(kind, speedArg);
    char name[64];
    if (speedArg > 0) {
        std::snprintf(name, sizeof name, "%s<%s>/%d", tb::nameOf(kind), scalar, speedArg);
    } else {
        std::snprintf(name, sizeof name, "%s<%s>", tb::nameOf(kind), scalar);
    }
    printRow(name, c);
    total.add(c);
}

/// The lean twin against the first twin, frame by frame.
struct LibmCounts {
    long frames = 0;
    long decisions = 0;  ///< frames whose contacts or start overlaps differ
    long positions = 0;  ///< frames whose final positions differ in any bit
};

/// One frame through both; returns the lean twin's result.
template <class T>
ResolveResult<T> compareWithLibm(const ResolveInput<T>& in, LibmCounts& c) {
    static FrameOutput<T> lean, libm;
    runFrame(in, lean, [](const ResolveInput<T>& i, const ResolveOutput<T>& o) {
        return tilesweep::baselines::resolveMoveTwin(i, o);
    });
    runFrame(in, libm, [](const ResolveInput<T>& i, const ResolveOutput<T>& o) {
        return tilesweep::baselines::resolveMoveTwinLibm(i, o);
    });
    ++c.frames;
    c.decisions += !sameDecisions(lean, libm);
    c.positions += lean.result.position != libm.result.position;
    return lean.result;
}

/// The side-by-side scenarios' frames.
template <class T>
LibmCounts libmOnFrames(tb::FrameKind kind, int speedArg) {
    const tb::FrameScenario<T> s = tb::makeFrameScenario<T>(kind, speedArg / 2.0);
    LibmCounts c;
    for (std::size_t k = 0; k < s.boxes.size(); ++k)
        (void)compareWithLibm<T>({s.map.view(), s.boxes[k], s.moves[k]}, c);
    return c;
}

/// `scenes` scenes of a property family, each frame from where the lean twin ended the last.
template <class T>
LibmCounts libmOnFamily(tilesweep::scenarios::Family family, std::uint64_t scenes) {
    LibmCounts c;
    for (std::uint64_t seed = 0; seed < scenes; ++seed) {
        const tilesweep::Scene<T> scene = tilesweep::scenarios::buildScene<T>(family, seed).scene;
        Vec2<T> start = scene.box.pos;
        for (const Vec2<T>& move : scene.moves)
            start = compareWithLibm<T>({scene.map.view(), {start, scene.box.size}, move}, c).position;
    }
    return c;
}

void printLibmRow(const char* name, const LibmCounts& c) {
    std::printf("%-26s %8ld | %8ld %8ld\n", name, c.frames, c.decisions, c.positions);
}

}  // namespace

int main() {
    std::printf("Against tilesweep::resolveMove, %zu frames per scenario (speed arg = 2 x tiles/frame).\n",
                tb::kFrameCount);
    std::printf("%-26s %7s %7s | %9s %9s %9s %5s | %9s %9s %9s %5s | %5s\n", "scenario", "frames", "blocked",
                "twin dec", "twin pos", "> 1 ulp", "in", "grid dec", "grid pos", "> 1 ulp", "in", "ts in");
    Counts all[2];
    for (const tb::SideBySideScenario& e : tb::kSideBySideScenarios)
        report<float>("float", e.kind, e.speedArg, all[0]);
    for (const tb::SideBySideScenario& e : tb::kSideBySideScenarios)
        report<double>("double", e.kind, e.speedArg, all[1]);
    printRow("all float", all[0]);
    printRow("all double", all[1]);

    std::printf("\nThe lean twin against the first twin (libm), frames that differ:\n");
    std::printf("%-26s %8s | %8s %8s\n", "scenes", "frames", "decision", "position");
    LibmCounts frames[2];
    for (const tb::SideBySideScenario& e : tb::kSideBySideScenarios) {
        const LibmCounts f = libmOnFrames<float>(e.kind, e.speedArg);
        const LibmCounts d = libmOnFrames<double>(e.kind, e.speedArg);
        frames[0].frames += f.frames;
        frames[0].decisions += f.decisions;
        frames[0].positions += f.positions;
        frames[1].frames += d.frames;
        frames[1].decisions += d.decisions;
        frames[1].positions += d.positions;
    }
    printLibmRow("benchmark frames<float>", frames[0]);
    printLibmRow("benchmark frames<double>", frames[1]);
    using tilesweep::scenarios::Family;
    constexpr std::uint64_t kFamilyScenes = 20000;
    for (const Family family :
         {Family::Random, Family::CornerPass, Family::CornerTie, Family::SeamLanding, Family::FarSubUlp}) {
        char row[64];
        std::snprintf(row, sizeof row, "%s<float>", tilesweep::scenarios::familyName(family));
        printLibmRow(row, libmOnFamily<float>(family, kFamilyScenes));
        std::snprintf(row, sizeof row, "%s<double>", tilesweep::scenarios::familyName(family));
        printLibmRow(row, libmOnFamily<double>(family, kFamilyScenes));
    }
    return 0;
}
