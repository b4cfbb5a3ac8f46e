// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/resolve.h"
#include "tilesweep/scene/scene.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

// A scene's frames through any resolver with tilesweep::resolveMove's signature (the baselines
// here, or resolveMove itself wrapped to watch it), each frame from the last one's position, with
// room for every list entry: what the audit and the twin adapter run the baselines with.
// (tilesweep::runScene is the same loop for resolveMove alone, refusing invalid input.)

namespace tilesweep::baselines {

/// Every frame of `scene` through `resolve(input, output)`, each starting where the last ended;
/// a frame whose lists did not fit is resolved again with room for all of them.
template <class T, class Resolve>
std::vector<FrameResult<T>> runFrames(const Scene<T>& scene, Resolve resolve) {
    std::vector<FrameResult<T>> frames;
    Vec2<T> start = scene.box.pos;
    std::vector<Contact<T>> contacts(16);
    std::vector<Cell> overlaps(16);
    for (const Vec2<T>& move : scene.moves) {
        const ResolveInput<T> input{scene.map.view(), {start, scene.box.size}, move};
        ResolveResult<T> r{};
        for (;;) {
            r = resolve(input, ResolveOutput<T>{contacts.data(), static_cast<std::int32_t>(contacts.size()),
                                                overlaps.data(), static_cast<std::int32_t>(overlaps.size())});
            if (r.contactCount <= static_cast<std::int32_t>(contacts.size()) &&
                r.startOverlapCount <= static_cast<std::int32_t>(overlaps.size()))
                break;
            contacts.resize(static_cast<std::size_t>(std::max<std::int32_t>(r.contactCount, 16)));
            overlaps.resize(static_cast<std::size_t>(std::max<std::int32_t>(r.startOverlapCount, 16)));
        }
        FrameResult<T> f;
        f.position = r.position;
        // Only non-empty ranges: GCC 12 at -O3 warns (-Wnonnull) on the memmove of zero bytes into
        // the fresh vector's null storage that assign() would otherwise reach.
        if (r.contactCount > 0) f.contacts.assign(contacts.begin(), contacts.begin() + r.contactCount);
        if (r.startOverlapCount > 0)
            f.startOverlaps.assign(overlaps.begin(), overlaps.begin() + r.startOverlapCount);
        frames.push_back(std::move(f));
        start = r.position;
    }
    return frames;
}

}  // namespace tilesweep::baselines
