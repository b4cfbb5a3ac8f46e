// SPDX-License-Identifier: MIT
// Running a scene's frames through the production resolver, tilesweep::resolveMove.
#include "tilesweep/scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace tilesweep {
namespace {

// Room for a typical frame (a box on a floor touches two or three tiles); a frame that needs
// more is resolved again with room for all of it, so this only saves allocations.
constexpr std::size_t kInitialCapacity = 16;

}  // namespace

template <class T>
std::vector<FrameResult<T>> runScene(const Scene<T>& scene) {
    std::vector<FrameResult<T>> frames;
    frames.reserve(scene.moves.size());
    const TileMapView<T> map = scene.map.view();
    Box<T> box = scene.box;
    // Reused across frames; resolveMove writes into them and reports how many it needed.
    std::vector<Contact<T>> contacts(kInitialCapacity);
    std::vector<Cell> startOverlaps(kInitialCapacity);

    for (std::size_t k = 0; k < scene.moves.size(); ++k) {
        const ResolveInput<T> input{map, box, scene.moves[k]};
        ResolveResult<T> result;
        for (;;) {
            const ResolveOutput<T> output{contacts.data(), static_cast<std::int32_t>(contacts.size()),
                                          startOverlaps.data(),
                                          static_cast<std::int32_t>(startOverlaps.size())};
            result = resolveMove(input, output);
            if (result.status == ResolveStatus::InvalidInput || result.contactCount < 0 ||
                result.startOverlapCount < 0)
                throw std::invalid_argument("runScene: the resolver refused frame " + std::to_string(k) +
                                            " as invalid input");
            const auto contactCount = static_cast<std::size_t>(result.contactCount);
            const auto overlapCount = static_cast<std::size_t>(result.startOverlapCount);
            if (contactCount <= contacts.size() && overlapCount <= startOverlaps.size()) break;
            // Truncated: the counts are the full sizes, so one more call with room for them
            // completes the lists (resolveMove is a pure function of its input).
            if (contactCount > contacts.size()) contacts.resize(contactCount);
            if (overlapCount > startOverlaps.size()) startOverlaps.resize(overlapCount);
        }

        FrameResult<T> frame;
        frame.position = result.position;
        frame.contacts.assign(contacts.begin(), contacts.begin() + result.contactCount);
        frame.startOverlaps.assign(startOverlaps.begin(), startOverlaps.begin() + result.startOverlapCount);
        frames.push_back(std::move(frame));
        box.pos = result.position;  // the next frame starts where this one ended (rounded)
    }
    return frames;
}

template std::vector<FrameResult<float>> runScene<float>(const Scene<float>&);
template std::vector<FrameResult<double>> runScene<double>(const Scene<double>&);

}  // namespace tilesweep
