// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/frame_stats.h"
#include "tilesweep/math.h"
#include "tilesweep/tile_map.h"

#include <cstdint>

// One frame of move-and-slide through a tile map, exactly as docs/contract.md defines it.
//
// The box moves by `displacement` over the frame; "time" is the fraction of the frame elapsed,
// in [0, 1]. At most two steps: the first contact (every tile hit at that earliest time is taken
// at once) zeroes the motion on its contact axes, and the rest of the motion slides on. Every
// decision (hit or miss, which tiles, contact axis, normal) is exact; the final position is the
// exact one rounded toward the start, per axis, except that an axis moving toward minus infinity
// rounds down when rounding back would carry the box's far edge over a grid line (docs/contract.md,
// "Positions"). So the box never ends inside a tile it did not start inside, stops touching a
// face it hits or less than an ulp short, and never moves past the exact motion but by less
// than an ulp on such an axis.
//
// Usage, one frame per game tick (tilesweep/mover.h wraps this for a game loop: a prepared map,
// float and double overloads, on-ground and wall flags, contact lists never cut short):
//
//     tilesweep::TileMapView<float> map{{0, 0}, {16, 16}, columns, rows, cells};
//     if (tilesweep::validateTileMap(map) != tilesweep::MapError::None) return;  // once per map
//     tilesweep::Contact<float> contacts[16];
//     tilesweep::Cell overlaps[16];
//     tilesweep::ResolveOutput<float> out{contacts, 16, overlaps, 16};
//     auto result = tilesweep::resolveMove({map, player, velocity * dt}, out);
//     if (result.status != tilesweep::ResolveStatus::InvalidInput) player.pos = result.position;
//     bool onGround = result.blockedY && velocity.y > 0;       // y grows downward
//     for (int k = 0; k < result.contactCount && k < 16; ++k)  // beyond 16: some, unspecified
//         hits.push_back(contacts[k].tile);
//
// tests/header_recipes_test.cpp runs this recipe as written (ctest checks it is this text).

namespace tilesweep {

/// Outcome of a resolve. `Blocked` means at least one contact was recorded.
enum class ResolveStatus : std::uint8_t { Moved, Blocked, InvalidInput };

/// One tile hit during a frame.
template <class T>
struct Contact {
    Cell tile;      ///< the cell that was hit
    Normal normal;  ///< points out of the tile face that was hit, against the motion
    T time;         ///< fraction of the whole frame elapsed at the hit: the exact one, in [0, 1),
                    ///< rounded to nearest (so 1 for a hit within half an ulp of the frame end)
    /// The box's position (its min corner, as Box::pos) at the hit, where the time alone cannot
    /// place it once the path bends. On the normal's axis the box stops at the hit, so that
    /// coordinate is the result's position there (rounded by the contract's rule). On the other
    /// axis: when the box slides on along it after the hit (a first-step hit on one axis only,
    /// the other still moving), start + s * displacement at the exact hit time s, rounded to
    /// nearest, ties to even (the start itself when s = 0); otherwise (a second-step hit, a
    /// corner hit on both axes, an axis that does not move) the result's position there too.
    Vec2<T> position;
};

/// What one frame moves: the box from its position by `displacement` through `map`.
template <class T>
struct ResolveInput {
    TileMapView<T> map;    ///< the grid; assumed to have passed validateTileMap
    Box<T> box;            ///< the box at the start of the frame; size > 0, all finite
    Vec2<T> displacement;  ///< the motion over the whole frame, finite; zero is valid
};

/// Caller-owned storage for the lists a resolve produces (the library never allocates).
template <class T>
struct ResolveOutput {
    Contact<T>* contacts = nullptr;  ///< receives up to contactCapacity contacts
    std::int32_t contactCapacity = 0;
    Cell* startOverlaps = nullptr;  ///< receives up to startOverlapCapacity cells
    std::int32_t startOverlapCapacity = 0;
    FrameStats* stats = nullptr;  ///< optional: receives how the frame was decided (frame_stats.h)
};

/// The result of one frame.
template <class T>
struct ResolveResult {
    ResolveStatus status = ResolveStatus::InvalidInput;
    Vec2<T> position{};                  ///< final box position; the start position on InvalidInput
    std::int32_t contactCount = 0;       ///< contacts in the frame; more than capacity means truncated
    std::int32_t startOverlapCount = 0;  ///< solid cells the box overlapped at the start, likewise
    bool blockedX = false;               ///< some tile stopped the motion on x (a contact with axis x, normal
                                         ///< (-sign(displacement.x), 0)); known from the steps, with or
                                         ///< without a contact buffer
    bool blockedY = false;               ///< likewise on y: normal (0, -sign(displacement.y))
};

/// True when the input can be resolved: finite values, box size > 0, map header sane
/// (finite origin, tile sizes > 0, non-negative dimensions, cells present).
template <class T>
[[nodiscard]] bool isValid(const ResolveInput<T>& input) noexcept;

/// Resolves one frame. Contacts are listed step by step in the order they happen, and within
/// a step by row, then column; start overlaps by row, then column. On invalid input returns
/// ResolveStatus::InvalidInput with the start position (zero motion) and no lists.
template <class T>
[[nodiscard]] ResolveResult<T> resolveMove(const ResolveInput<T>& input,
                                           const ResolveOutput<T>& output) noexcept;

/// resolveMove<float> without the template argument, so that a braced input works:
/// resolveMove({map, box, displacement}, output).
[[nodiscard]] ResolveResult<float> resolveMove(const ResolveInput<float>& input,
                                               const ResolveOutput<float>& output) noexcept;
/// resolveMove<double> without the template argument.
[[nodiscard]] ResolveResult<double> resolveMove(const ResolveInput<double>& input,
                                                const ResolveOutput<double>& output) noexcept;

// The names before this scheme (<Op>Input, <Op>Result, <Op>Status for resolveMove, moveAndSlide
// and sweepBox alike), kept for one release; a use gets a deprecation warning.
using Status [[deprecated("use tilesweep::ResolveStatus")]] = ResolveStatus;
template <class T>
using SweepInput [[deprecated("use tilesweep::ResolveInput")]] = ResolveInput<T>;
template <class T>
using SweepResult [[deprecated("use tilesweep::ResolveResult")]] = ResolveResult<T>;

extern template bool isValid<float>(const ResolveInput<float>&) noexcept;
extern template bool isValid<double>(const ResolveInput<double>&) noexcept;
extern template ResolveResult<float> resolveMove<float>(const ResolveInput<float>&,
                                                        const ResolveOutput<float>&) noexcept;
extern template ResolveResult<double> resolveMove<double>(const ResolveInput<double>&,
                                                          const ResolveOutput<double>&) noexcept;

}  // namespace tilesweep
