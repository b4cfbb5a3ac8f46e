// SPDX-License-Identifier: MIT
#pragma once

#include "tilesweep/detail/map_range.h"
#include "tilesweep/math.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <cstdint>

// The game-loop API: a map prepared once, then one call per mover per frame.
//
// It is the same resolver as resolveMove (resolve.h), bit for bit: same position, same
// contacts in the same order. What it adds is what a game loop asks every frame: plain float
// and double overloads (no template arguments at call sites), and a result that says what
// happened at a glance: the blocked axes, on ground / on a wall / on a ceiling, and the
// displacement with the blocked components removed. The flags come from the solver's steps
// (each step knows its contact axes, and the motion's sign gives the normal), so they are right
// with or without a contact buffer, for a box of any size. Contacts are optional: a buffer
// receives a frame's contacts all, or none (contactsStored says which), and a buffer of
// maxContacts(box size, tile size) entries always receives them. Each has its tile, normal, time
// and the box's position at the hit (Contact, resolve.h), which places a hit the box slid on
// from: a wall met on the way down, before sliding down it.
//
// Axes: x grows to the right and y grows downward (screen coordinates), so landing on a floor is
// the normal (0, -1) and sets onGround; hitting a face above sets onCeiling. A y-up game (y grows
// upward) that passes its coordinates unchanged gets the same exact results with the names
// swapped: what it calls the ground is onCeiling here and its ceilings are onGround (the tile
// grid then runs upward from the origin, row 0 at the bottom). clipVelocity needs no change: it
// zeroes whatever pushes into a face that was hit, whichever way is up.
//
// Usage (examples/platformer/platformer.cpp runs this loop; tests/header_recipes_test.cpp runs
// this recipe as written, and ctest checks it is this text):
//
//     auto map = tilesweep::prepareMap(view);  // once per map: validates it
//     if (!map.isValid()) return fail(tilesweep::describe(map.error()));
//     // every frame, every mover:
//     velocity.y += gravity * dt;
//     auto r = tilesweep::moveAndSlide(map, {player, velocity * dt});
//     player.pos = r.position;
//     velocity = tilesweep::clipVelocity(velocity, r);  // stops on floors, ceilings and walls

namespace tilesweep {

/// A tile map validated once by prepareMap and reused by every frame. It borrows the cells of
/// the view it was prepared from: they must outlive it (cells may change between frames; the
/// dimensions, origin and tile size may not).
template <class T>
class PreparedMap {
public:
    /// An empty, invalid map (error() is NotPrepared); use prepareMap.
    PreparedMap() noexcept = default;

    /// The map as resolveMove takes it.
    [[nodiscard]] const TileMapView<T>& view() const noexcept { return view_; }
    /// Why the map was refused, or MapError::None.
    [[nodiscard]] MapError error() const noexcept { return error_; }
    /// True when the map passed validateTileMap: moves through it can be resolved.
    [[nodiscard]] bool isValid() const noexcept { return error_ == MapError::None; }
    /// 1 / tile size, rounded: only for estimating cell ranges (always widened before use).
    [[nodiscard]] Vec2<double> inverseTileSize() const noexcept {
        return {range_.inverseTile[0], range_.inverseTile[1]};
    }
    /// This map with its one-way cells left out (TileMapView::withoutOneWay): the map to pass
    /// for a frame that drops through every platform. Prepare it once, beside the map; the
    /// choice is per call and costs the frame nothing.
    [[nodiscard]] PreparedMap withoutOneWay() const noexcept {
        PreparedMap map = *this;
        map.view_.oneWay = nullptr;
        return map;
    }
    /// Internal: the map's half of the resolver's range test, computed once here instead of
    /// every frame (src/range_admission.h reads it).
    [[nodiscard]] const detail::MapRange& mapRange() const noexcept { return range_; }

private:
    friend PreparedMap<float> prepareMap(const TileMapView<float>& map) noexcept;
    friend PreparedMap<double> prepareMap(const TileMapView<double>& map) noexcept;

    TileMapView<T> view_{};
    MapError error_ = MapError::NotPrepared;
    detail::MapRange range_{};  // with the tile reciprocals (inverseTileSize)
};

/// Validates `map` once (validateTileMap: O(columns + rows)) and keeps it for every frame.
[[nodiscard]] PreparedMap<float> prepareMap(const TileMapView<float>& map) noexcept;
/// Validates `map` once (validateTileMap: O(columns + rows)) and keeps it for every frame.
[[nodiscard]] PreparedMap<double> prepareMap(const TileMapView<double>& map) noexcept;

/// One mover's frame: its box at the start and the motion it wants over the frame.
template <class T>
struct MoveInput {
    Box<T> box;            ///< position and size (> 0) at the start of the frame, finite
    Vec2<T> displacement;  ///< motion over the whole frame (velocity * dt), finite; zero is valid
};

/// resolveMove (resolve.h) through a prepared map: the same result, bit for bit, as
/// resolveMove({map.view(), input.box, input.displacement}, output), with the map's share of each
/// frame's checks done once by prepareMap. This is the call for a game that resolves many frames
/// through one map and wants resolveMove's lists. A map that failed prepareMap gives
/// ResolveStatus::InvalidInput.
[[nodiscard]] ResolveResult<float> resolveMove(const PreparedMap<float>& map, const MoveInput<float>& input,
                                               const ResolveOutput<float>& output) noexcept;
/// The same in double.
[[nodiscard]] ResolveResult<double> resolveMove(const PreparedMap<double>& map,
                                                const MoveInput<double>& input,
                                                const ResolveOutput<double>& output) noexcept;

/// How a move ended.
enum class MoveStatus : std::uint8_t {
    Moved,         ///< nothing was hit: the box moved the whole way
    Blocked,       ///< at least one tile was hit: see the flags and contactCount
    InvalidInput,  ///< non-finite value, size <= 0, or a map that failed prepareMap: nothing moved
    /// Never returned since 0.2 (a frame is resolved whatever the buffer; see contactsStored).
    /// Kept for one release so that code naming it still compiles.
    ContactBufferTooSmall,
};

/// What happened to one mover in one frame. The flags come from the solver's steps, whether or
/// not the caller asked for the contacts themselves.
template <class T>
struct MoveResult {
    Vec2<T> position{};  ///< where the box ends; its start position unless Moved/Blocked
    MoveStatus status = MoveStatus::InvalidInput;
    bool blockedX = false;               ///< a tile stopped the motion on x (same as onWall)
    bool blockedY = false;               ///< a tile stopped the motion on y (onGround or onCeiling)
    bool onGround = false;               ///< a floor was hit: a contact with normal (0, -1) (y down)
    bool onCeiling = false;              ///< a ceiling was hit: a contact with normal (0, 1)
    bool onWall = false;                 ///< a wall was hit: a contact with normal (1, 0) or (-1, 0)
    std::int8_t wallNormalX = 0;         ///< the wall's normal on x: 1 (wall on the left), -1 (right), 0
    bool contactsStored = false;         ///< the caller's buffer holds all contactCount contacts
    std::int32_t contactCount = 0;       ///< tiles hit this frame, stored or not
    std::int32_t startOverlapCount = 0;  ///< solid tiles the box overlapped at the start (it may
                                         ///< leave them; they never block)
    /// The frame's displacement with the blocked components set to zero (b2ClipVector against
    /// the contact normals): the motion the box still had on the axes it slid along. Exact: each
    /// component is the input's or zero.
    Vec2<T> clippedDisplacement{};
};

/// `velocity` with the components that push into a face this frame hit set to zero: x when
/// onWall and it points into the wall, y when onGround and it points down, or onCeiling and it
/// points up. A game calls it after every move instead of zeroing by hand (a hand-written rule
/// that forgets onCeiling sticks the player to ceilings).
template <class T>
[[nodiscard]] constexpr Vec2<T> clipVelocity(Vec2<T> velocity, const MoveResult<T>& result) noexcept {
    if ((result.wallNormalX < 0 && velocity.x > 0) || (result.wallNormalX > 0 && velocity.x < 0))
        velocity.x = 0;
    if ((result.onGround && velocity.y > 0) || (result.onCeiling && velocity.y < 0)) velocity.y = 0;
    return velocity;
}

/// The contacts the game-loop calls resolve into on the stack when the caller's buffer is
/// smaller than maxContacts, so that they store all of a frame's contacts or none. A frame with more
/// contacts than this (a box over 30 tiles on a side) and no buffer of maxContacts entries is
/// still resolved, flags and all; only its contacts are not stored.
inline constexpr std::int32_t kInlineContacts = 64;

/// The most contacts one frame can record for a box of this size in tiles of this size:
/// (floor(w/tw) + 2) + (floor(h/th) + 2), saturated at INT32_MAX; 0 for a size that is not
/// finite and > 0 (such a move is invalid and records none). A contact buffer this large is
/// never too small. Why (docs/contract.md, "One frame through a map"): a frame has at most two
/// steps. The tiles hit in a step with contact axis x all enter at the step's time s on x, so
/// they lie in the one column across the box's leading x face, in rows that overlap the box's
/// open y extent just after s: an open interval of h/th cells meets at most ceil(h/th) + 1 open
/// rows. Likewise the y-axis tiles of a step lie in one row, at most ceil(w/tw) + 1 of them. If
/// the first step zeroes both axes there is no second step; if it zeroes only x (only x-axis
/// tiles, <= ceil(h/th) + 1), the second step moves on y alone, so every tile it hits has contact
/// axis y (<= ceil(w/tw) + 1); the same with the axes swapped. So a frame records at most
/// ceil(w/tw) + ceil(h/th) + 2 contacts. The bound uses floor(fl(w/tw)) + 2 >= ceil(w/tw) + 1,
/// true for the rounded quotient because rounding is monotonic and integers are representable.
/// tests/mover_test.cpp holds the resolver to it (a property over random scenes).
[[nodiscard]] std::int32_t maxContacts(Vec2<float> boxSize, Vec2<float> tileSize) noexcept;
/// The same bound in double.
[[nodiscard]] std::int32_t maxContacts(Vec2<double> boxSize, Vec2<double> tileSize) noexcept;

/// Resolves one mover's frame (the same position and contacts as resolveMove, each contact with
/// its time and the box's position at the hit). `contacts` is
/// optional: when it holds at least maxContacts entries, or at least contactCount and the frame
/// has at most kInlineContacts, the contacts are stored in resolveMove's order (step by step,
/// then by row, then column) and contactsStored is set; otherwise none are stored. Never throws;
/// invalid input gives MoveStatus::InvalidInput with the start position.
[[nodiscard]] MoveResult<float> moveAndSlide(const PreparedMap<float>& map, const MoveInput<float>& input,
                                             Contact<float>* contacts = nullptr,
                                             std::int32_t contactCapacity = 0) noexcept;
/// The same in double.
[[nodiscard]] MoveResult<double> moveAndSlide(const PreparedMap<double>& map, const MoveInput<double>& input,
                                              Contact<double>* contacts = nullptr,
                                              std::int32_t contactCapacity = 0) noexcept;

}  // namespace tilesweep
