// SPDX-License-Identifier: MIT
// A deliberately broken resolver behind the protocol, to prove that `tilesweep check
// --resolver-cmd` catches and shrinks what an outside engine gets wrong. Both mutants start
// from the exact reference (oracle/exact), so each differs from the contract in one rule only:
//
//   --mutation round-nearest   final positions rounded to nearest, not toward the start (nor
//                              down where the contract's exception asks): a box can end a
//                              sub-ulp inside the tile it stopped at, or past its exact motion
//   --mutation tie-prefers-x   on an exact corner tie with both faces exposed or neither, the
//                              contact axis is x instead of y (the scene is resolved transposed,
//                              where the default axis is the other one, and transposed back)
//
//     tilesweep_mutant_adapter --mutation round-nearest [--scalar float|double] < scenes.jsonl
#include "tilesweep/oracle/exact/exact_geometry.h"
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/exact/rational_convert.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace tilesweep;

enum class Mutation { RoundNearest, TiePrefersX };

template <class T>
std::vector<FrameResult<T>> roundNearest(const Scene<T>& scene) {
    const oracle::ExactTileMap map = oracle::toExact(scene.map);
    std::vector<FrameResult<T>> frames;
    Box<T> box = scene.box;
    for (const Vec2<T>& move : scene.moves) {
        const oracle::ExactFrame exact =
            oracle::resolveFrameExact(map, oracle::toExact(box), oracle::toExact(move));
        FrameResult<T> frame = oracle::roundFrame<T>(exact);  // decisions and times as the contract's
        frame.position = {oracle::fromRational<T>(exact.position.x, oracle::Rounding::NearestEven),
                          oracle::fromRational<T>(exact.position.y, oracle::Rounding::NearestEven)};
        if (exact.position.x == exact.start.x) frame.position.x = box.pos.x;  // keep -0 as the contract does
        if (exact.position.y == exact.start.y) frame.position.y = box.pos.y;
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

template <class T>
int serve(Mutation mutation) {
    std::string line;
    while (std::getline(std::cin, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const SceneParse<T> parsed = parseScene<T>(line);
        if (!parsed.scene) {
            std::cout << formatError(parsed.error) << '\n' << std::flush;
            continue;
        }
        const auto frames =
            mutation == Mutation::RoundNearest ? roundNearest(*parsed.scene) : tiePrefersX(*parsed.scene);
        std::cout << formatFrames(frames) << '\n' << std::flush;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    std::string mutation;
    std::string scalar = "float";
    for (int k = 1; k + 1 < argc; k += 2) {
        if (std::strcmp(argv[k], "--mutation") == 0) mutation = argv[k + 1];
        if (std::strcmp(argv[k], "--scalar") == 0) scalar = argv[k + 1];
    }
    if ((mutation != "round-nearest" && mutation != "tie-prefers-x") ||
        (scalar != "float" && scalar != "double")) {
        std::fprintf(stderr, "usage: %s --mutation round-nearest|tie-prefers-x [--scalar float|double]\n",
                     argv[0]);
        return 2;
    }
    const Mutation m = mutation == "round-nearest" ? Mutation::RoundNearest : Mutation::TiePrefersX;
    return scalar == "double" ? serve<double>(m) : serve<float>(m);
}
