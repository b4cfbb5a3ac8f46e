// SPDX-License-Identifier: MIT
// The inexact game-style twin (tilesweep/baselines/twin_resolve.h) behind the resolver
// protocol: scene lines in on standard input, one result line per scene out, flushed per line
// (docs/contract.md, "tilesweep resolve"). What `tilesweep check --resolver-cmd` and `tilesweep audit
// --resolver-cmd` hold to the contract as "the move-and-slide a competent game developer writes".
//
//     tilesweep_twin_adapter [--scalar float|double] < scenes.jsonl
#include "tilesweep/baselines/run_frames.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/scene/scene.h"

#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace {

/// Every frame of a scene through the twin, each starting where the last ended.
template <class T>
std::vector<tilesweep::FrameResult<T>> runTwin(const tilesweep::Scene<T>& scene) {
    return tilesweep::baselines::runFrames(
        scene, [](const tilesweep::ResolveInput<T>& in, const tilesweep::ResolveOutput<T>& out) {
            return tilesweep::baselines::resolveMoveTwin<T>(in, out);
        });
}

template <class T>
int serve() {
    std::string line;
    while (std::getline(std::cin, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const tilesweep::SceneParse<T> parsed = tilesweep::parseScene<T>(line);
        try {
            std::cout << (parsed.scene ? tilesweep::formatFrames(runTwin(*parsed.scene))
                                       : tilesweep::formatError(parsed.error));
        } catch (const std::exception& e) {  // a NaN position cannot be printed as JSON
            std::cout << tilesweep::formatError(std::string("twin: ") + e.what());
        }
        std::cout << '\n' << std::flush;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    const bool useDouble =
        argc == 3 && std::strcmp(argv[1], "--scalar") == 0 && std::strcmp(argv[2], "double") == 0;
    if (argc != 1 && !(argc == 3 && std::strcmp(argv[1], "--scalar") == 0)) {
        std::fprintf(stderr, "usage: %s [--scalar float|double] < scenes.jsonl\n", argv[0]);
        return 2;
    }
    return useDouble ? serve<double>() : serve<float>();
}
