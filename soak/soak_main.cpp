// SPDX-License-Identifier: MIT
// tilesweep_soak: a long run of the resolver as a game drives it. Random walkers with gravity,
// jumps and dashes (now and then a dash of dozens of tiles in one frame) move through generated
// levels of platforms, walls and pits, one resolveMove per walker per frame, each frame starting
// where the last one ended. Every frame is checked exactly against the safety rules
// (../checks/frame_safety.h): the box never ends inside a tile it did not start in, stops
// touching what it hits, never moves past the exact end but where the contract's rounding rule
// asks for one ulp more, and, since a walker never starts inside a tile, never reports a start
// overlap; so over a whole run no walker ever gets into a wall. A walker
// standing still on a floor must keep its exact position frame after frame (resting contact does
// not drift). Memory must stay flat: the resident set size is printed at the start and the end.
//
//   tilesweep_soak [--seconds S] [--ticks N] [--seed N] [--walkers N] [--scalar float|double]
//
// A tick is one frame of every walker. --ticks stops after N ticks (or S seconds, whichever comes
// first), which makes a run reproducible: the same seed and ticks give the same frames.
//
// Exit status 1 when any frame broke a rule, 2 on bad arguments.
#include "frame_safety.h"
#include "fuzz_check.h"

#include "tilesweep/resolve.h"
#include "tilesweep/scenarios/levels.h"
#include "tilesweep/tile_map.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace tilesweep;

constexpr std::int32_t kColumns = scenarios::kLevelColumns;
constexpr std::int32_t kRows = scenarios::kLevelRows;
constexpr std::int64_t kTicksPerLevel = 4000;  // a new level (and new walkers) this often
constexpr std::int32_t kListCapacity = 256;    // contacts or overlaps of one small box
constexpr int kMaxReportedViolations = 10;

struct Options {
    double seconds = 60;
    std::uint64_t ticks = 0;  // 0: no limit
    std::uint64_t seed = 1;
    int walkers = 64;
    bool useDouble = false;
};

struct Counters {
    std::uint64_t frames = 0;
    std::uint64_t ticks = 0;
    std::uint64_t levels = 0;
    std::uint64_t contacts = 0;
    std::uint64_t restingChecks = 0;
    std::uint64_t restingWithoutContact = 0;  // resting, but the gravity step did not reach the floor
    std::uint64_t bigDashes = 0;
    std::uint64_t violations = 0;
    std::uint64_t roundedDown = 0;  ///< frames where the rounding rule's exception rounded an axis down
};

/// A /proc/self/status field in kB ("VmRSS", "VmHWM"), or -1.
long readStatusKb(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    const std::size_t length = std::strlen(field);
    while (std::getline(status, line))
        if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':')
            return std::strtol(line.c_str() + length + 1, nullptr, 10);
    return -1;
}

template <class T>
struct Level {
    std::vector<std::uint8_t> solid;
    TileMapView<T> map;
    checks::MapEdges<T> edges;
};

template <class T>
struct Walker {
    Box<T> box{};
    T vx = 0;
    T vy = 0;
    T speed = 0;         // walking speed, length units per frame
    int direction = 0;   // -1, 0 (standing still) or 1
    int modeFrames = 0;  // frames left before the walker picks a new direction
    int dashFrames = 0;
    bool grounded = false;  // the last frame landed on or pressed into a floor
    bool resting = false;   // the last frame had no x motion and ended on a floor
};

template <class T>
class Soak {
public:
    Soak(const Options& options, Counters& counters)
        : options_(options),
          counters_(counters),
          random_(options.seed),
          walkers_(static_cast<std::size_t>(options.walkers)) {}

    void newLevel() {
        ++counters_.levels;
        Level<T>& level = level_;
        // The level's cells, tile size and origin from the scenario library (same draws, same order).
        scenarios::PlatformLevel<T> built = scenarios::buildPlatformLevel<T>(random_);
        level.solid = std::move(built.solid);
        level.map = {built.origin, {built.tile, built.tile}, kColumns, kRows, level.solid.data()};
        if (validateTileMap(level.map) != MapError::None) level.map.origin = {T(0), T(0)};
        level.edges = checks::computeEdges(level.map);

        for (Walker<T>& walker : walkers_) spawn(walker);
    }

    /// One frame for every walker.
    void tick() {
        ++counters_.ticks;
        if (counters_.ticks % kTicksPerLevel == 0) newLevel();
        for (Walker<T>& walker : walkers_) step(walker);
    }

private:
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }
    bool chance(double p) { return uniform(0, 1) < p; }

    T tile() const { return level_.map.tileSize.x; }

    /// Places a walker in an empty cell with an empty cell below it (the box fits in the two).
    void spawn(Walker<T>& walker) {
        const T size = tile();
        walker.box.size = {static_cast<T>(size * static_cast<T>(uniform(0.3, 0.9))),
                           static_cast<T>(size * static_cast<T>(uniform(0.3, 1.8)))};
        for (;;) {
            const auto i = static_cast<std::int32_t>(uniform(1, kColumns - 1));
            const auto j = static_cast<std::int32_t>(uniform(1, kRows - 2));
            if (level_.map.isSolid(i, j) || level_.map.isSolid(i, j + 1)) continue;
            const auto ui = static_cast<std::size_t>(i);
            const auto uj = static_cast<std::size_t>(j);
            // A small fraction of a tile in from the cell's corner, so that it does not touch.
            walker.box.pos = {level_.edges.x[ui] + size * T(0.05), level_.edges.y[uj] + size * T(0.05)};
            break;
        }
        walker.vx = walker.vy = 0;
        walker.speed = size * static_cast<T>(uniform(0.05, 0.25));
        walker.direction = 0;
        walker.modeFrames = 0;
        walker.dashFrames = 0;
        walker.grounded = walker.resting = false;
    }

    /// Chooses the walker's displacement for this frame: walking, standing, jumping, dashing.
    Vec2<T> control(Walker<T>& walker) {
        const T size = tile();
        if (--walker.modeFrames <= 0) {
            walker.direction = static_cast<int>(uniform(0, 3)) - 1;  // often stands still
            walker.modeFrames = static_cast<int>(uniform(10, 200));
        }
        if (walker.dashFrames > 0) {
            --walker.dashFrames;
        } else {
            walker.vx = static_cast<T>(walker.direction) * walker.speed;
            if (chance(0.004)) {  // dash: a few frames of high speed
                walker.dashFrames = static_cast<int>(uniform(3, 10));
                walker.vx = static_cast<T>(chance(0.5) ? 1 : -1) * size * static_cast<T>(uniform(0.5, 2.5));
            } else if (chance(0.0005)) {  // one frame through half the level: must not tunnel
                ++counters_.bigDashes;
                walker.dashFrames = 1;
                walker.vx = static_cast<T>(chance(0.5) ? 1 : -1) * size * static_cast<T>(uniform(10, 60));
                walker.vy = size * static_cast<T>(uniform(-30, 30));
            }
        }
        if (walker.grounded && chance(0.02)) walker.vy = -size * static_cast<T>(uniform(0.3, 0.6));  // jump
        const T gravity = size * T(0.022);
        const T terminal = size * T(0.9);
        walker.vy = walker.vy + gravity;
        if (walker.vy > terminal && walker.dashFrames == 0) walker.vy = terminal;
        return {walker.vx, walker.vy};
    }

    void step(Walker<T>& walker) {
        const Vec2<T> d = control(walker);
        const ResolveInput<T> input{level_.map, walker.box, d};
        const ResolveResult<T> r = resolveMove(input, {contacts_, kListCapacity, overlaps_, kListCapacity});
        ++counters_.frames;

        std::string violation;
        const std::uint64_t roundedDownBefore = scratch_.roundedDown;
        if (r.contactCount > kListCapacity || r.startOverlapCount > kListCapacity) {
            violation = "list longer than " + std::to_string(kListCapacity);
        } else {
            const checks::FrameRecord<T> frame{level_.map, walker.box, d, r, contacts_, overlaps_};
            violation = checks::checkFrameSafety(frame, level_.edges, scratch_).detail;
        }
        bool floor = false;
        if (violation.empty()) {
            for (std::int32_t k = 0; k < r.contactCount; ++k) floor = floor || contacts_[k].normal.y == -1;
            if (r.startOverlapCount != 0) violation = "a walker started inside a tile";
        }
        if (violation.empty() && walker.resting && d.x == 0 && d.y > 0) {
            ++counters_.restingChecks;
            // The position must not change. A floor contact is not required: a box that came to
            // rest less than an ulp above the floor (the touching position is not representable
            // far from the origin) under a gravity step smaller than that gap meets nothing.
            if (!fuzz::sameBits(r.position.x, walker.box.pos.x) ||
                !fuzz::sameBits(r.position.y, walker.box.pos.y))
                violation = "resting contact drifted";
            if (!floor) ++counters_.restingWithoutContact;
        }
        if (!violation.empty()) {
            report(violation, walker, d, r);
            spawn(walker);
            return;
        }
        if (scratch_.roundedDown != roundedDownBefore) ++counters_.roundedDown;  // the walker goes on

        counters_.contacts += static_cast<std::uint64_t>(r.contactCount);
        walker.box.pos = r.position;
        walker.grounded = floor;
        walker.resting = floor && d.x == 0;
        for (std::int32_t k = 0; k < r.contactCount; ++k) {
            const Normal n = contacts_[k].normal;
            if (n.y != 0) walker.vy = 0;
            if (n.x != 0) {
                walker.vx = 0;
                walker.dashFrames = 0;
            }
        }
    }

    void report(const std::string& violation, const Walker<T>& walker, Vec2<T> d, const ResolveResult<T>& r) {
        if (++counters_.violations > kMaxReportedViolations) return;
        std::fprintf(stderr,
                     "soak: VIOLATION at tick %llu: %s\n  map origin (%a, %a) tile %a; box (%a, %a, %a, %a) "
                     "d (%a, %a) -> (%a, %a), %d contacts\n",
                     static_cast<unsigned long long>(counters_.ticks), violation.c_str(),
                     static_cast<double>(level_.map.origin.x), static_cast<double>(level_.map.origin.y),
                     static_cast<double>(tile()), static_cast<double>(walker.box.pos.x),
                     static_cast<double>(walker.box.pos.y), static_cast<double>(walker.box.size.x),
                     static_cast<double>(walker.box.size.y), static_cast<double>(d.x),
                     static_cast<double>(d.y), static_cast<double>(r.position.x),
                     static_cast<double>(r.position.y), r.contactCount);
    }

    const Options& options_;
    Counters& counters_;
    std::mt19937_64 random_;
    std::vector<Walker<T>> walkers_;
    Level<T> level_;
    Contact<T> contacts_[kListCapacity];
    Cell overlaps_[kListCapacity];
    checks::SafetyScratch scratch_;
};

template <class T>
void run(const Options& options, Counters& counters, long& rssStartKb) {
    Soak<T> soak(options, counters);
    soak.newLevel();
    for (int warm = 0; warm < 100; ++warm) soak.tick();  // let the scratch lists reach their size
    rssStartKb = readStatusKb("VmRSS");
    const auto start = std::chrono::steady_clock::now();
    const auto budget = std::chrono::duration<double>(options.seconds);
    while (std::chrono::steady_clock::now() - start < budget &&
           (options.ticks == 0 || counters.ticks < options.ticks))
        soak.tick();
}

bool parseOptions(int argc, char** argv, Options& options) {
    for (int a = 1; a < argc; a += 2) {  // every option takes a value
        const std::string arg = argv[a];
        const char* value = a + 1 < argc ? argv[a + 1] : nullptr;
        if (value == nullptr) return false;
        if (arg == "--seconds") {
            options.seconds = std::strtod(value, nullptr);
        } else if (arg == "--ticks") {
            options.ticks = std::strtoull(value, nullptr, 10);
        } else if (arg == "--seed") {
            options.seed = std::strtoull(value, nullptr, 10);
        } else if (arg == "--walkers") {
            options.walkers = std::atoi(value);
        } else if (arg == "--scalar") {
            if (std::strcmp(value, "float") != 0 && std::strcmp(value, "double") != 0) return false;
            options.useDouble = std::strcmp(value, "double") == 0;
        } else {
            return false;
        }
    }
    return options.seconds >= 0 && options.walkers > 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    if (!parseOptions(argc, argv, options)) {
        std::fprintf(stderr,
                     "usage: tilesweep_soak [--seconds S] [--ticks N] [--seed N] [--walkers N] [--scalar "
                     "float|double]\n");
        return 2;
    }
    Counters counters;
    long rssStart = -1;
    const auto start = std::chrono::steady_clock::now();
    if (options.useDouble)
        run<double>(options, counters, rssStart);
    else
        run<float>(options, counters, rssStart);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const long rssEnd = readStatusKb("VmRSS");
    const long rssPeak = readStatusKb("VmHWM");

    std::printf("soak: %s, seed %llu, %d walkers, %.1f s\n", options.useDouble ? "double" : "float",
                static_cast<unsigned long long>(options.seed), options.walkers, elapsed);
    std::printf(
        "soak: %llu frames (%llu ticks, %llu levels), %.0f frames/s\n",
        static_cast<unsigned long long>(counters.frames), static_cast<unsigned long long>(counters.ticks),
        static_cast<unsigned long long>(counters.levels), static_cast<double>(counters.frames) / elapsed);
    std::printf(
        "soak: %llu contacts, %llu resting frames checked for drift (%llu of them hovering a "
        "sub-ulp gap above the floor), %llu long dashes\n",
        static_cast<unsigned long long>(counters.contacts),
        static_cast<unsigned long long>(counters.restingChecks),
        static_cast<unsigned long long>(counters.restingWithoutContact),
        static_cast<unsigned long long>(counters.bigDashes));
    std::printf("soak: RSS %ld kB at start, %ld kB at end, peak %ld kB\n", rssStart, rssEnd, rssPeak);
    std::printf(
        "soak: %llu frames rounded an axis down, past the exact end by less than an ulp, where "
        "rounding back would have carried the far edge over a grid line (docs/contract.md, Positions)\n",
        static_cast<unsigned long long>(counters.roundedDown));
    std::printf("soak: %llu violations\n", static_cast<unsigned long long>(counters.violations));
    return counters.violations == 0 ? 0 : 1;
}
