// SPDX-License-Identifier: MIT
// Instructions per frame, counted rather than timed: every side-by-side scenario of the
// benchmarks (tilesweep/scenarios/frames.h: kSideBySideScenarios) through tilesweep (on its
// prepared map, and on the bare view), the lean twin, the lean grid and the dividing twin, in float and
// double. Run under callgrind, the program zeroes the counters before each scenario's frames and dumps them
// after, named
// "<impl> <scenario><T>[/speed] <frames>"; scripts/instructions.sh divides each dump's instruction count by
// its frames. An instruction count does not depend on the machine's load, so it is the measure to compare on
// a shared machine, and the one that says where a ratio of run times comes from.
//
//   valgrind --tool=callgrind tilesweep_frame_instructions [FRAMES [FILTER]]
//
// Outside valgrind the client requests do nothing, and the program just runs the frames.
#include "frame_scenarios.h"
#include "side_by_side.h"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(name) (void)(name)
#endif

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using tilesweep::bench::FrameKind;
using tilesweep::bench::FrameScenario;

using tilesweep::bench::Impl;

const char* nameOf(Impl impl) {
    switch (impl) {
        case Impl::Tilesweep:
            return "Tilesweep";
        case Impl::TilesweepView:
            return "TilesweepView";
        case Impl::Twin:
            return "Twin";
        case Impl::Grid:
            return "Grid";
        case Impl::TwinDividing:
            return "TwinDividing";
        case Impl::TwinLibm:
            return "TwinLibm";
    }
    return "?";
}

/// `frames` frames of `s` (cycling through its kFrameCount) through `impl`; returns a checksum
/// of the end positions, so that no frame can be optimized away.
template <class T, Impl I>
[[gnu::noinline]] double runFrames(const FrameScenario<T>& s, std::size_t frames) {
    const tilesweep::TileMapView<T> view = s.map.view();
    tilesweep::Contact<T> contacts[64];
    tilesweep::Cell overlaps[64];
    const tilesweep::ResolveOutput<T> out{contacts, 64, overlaps, 64};
    const tilesweep::bench::PerMap<T> perMap(view);
    double sum = 0;
    std::size_t k = 0;
    for (std::size_t n = 0; n < frames; ++n) {
        const tilesweep::ResolveInput<T> in{view, s.boxes[k], s.moves[k]};
        const tilesweep::ResolveResult<T> r = tilesweep::bench::resolveWith<T, I>(in, out, perMap);
        sum += static_cast<double>(r.position.x) + static_cast<double>(r.position.y);
        k = (k + 1) & (tilesweep::bench::kFrameCount - 1);
    }
    return sum;
}

template <class T, Impl I>
void count(const FrameScenario<T>& s, const std::string& label, std::size_t frames) {
    const std::string name = std::string(nameOf(I)) + " " + label + " " + std::to_string(frames);
    CALLGRIND_ZERO_STATS;
    const double sum = runFrames<T, I>(s, frames);
    CALLGRIND_DUMP_STATS_AT(name.c_str());
    std::printf("%s checksum %.17g\n", name.c_str(), sum);
}

template <class T>
void countScenario(FrameKind kind, int speedArg, const char* scalar, std::size_t frames,
                   const std::string& filter) {
    std::string label = std::string(tilesweep::bench::nameOf(kind)) + "<" + scalar + ">";
    if (speedArg > 0) label += "/" + std::to_string(speedArg);
    if (label.find(filter) == std::string::npos) return;
    const FrameScenario<T> s = tilesweep::bench::makeFrameScenario<T>(kind, speedArg / 2.0);
    count<T, Impl::Tilesweep>(s, label, frames);
    count<T, Impl::TilesweepView>(s, label, frames);
    count<T, Impl::Twin>(s, label, frames);
    count<T, Impl::Grid>(s, label, frames);
    count<T, Impl::TwinDividing>(s, label, frames);
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t frames = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 65536;
    const std::string filter = argc > 2 ? argv[2] : "";
    if (frames == 0) {
        std::fprintf(stderr, "usage: tilesweep_frame_instructions [FRAMES > 0 [FILTER]]\n");
        return 2;
    }
    for (const tilesweep::bench::SideBySideScenario& e : tilesweep::bench::kSideBySideScenarios) {
        countScenario<float>(e.kind, e.speedArg, "float", frames, filter);
        countScenario<double>(e.kind, e.speedArg, "double", frames, filter);
    }
    return 0;
}
