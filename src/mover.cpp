// SPDX-License-Identifier: MIT
#include "tilesweep/mover.h"

#include "frame_solve.h"
#include "move_result.h"
#include "range_admission.h"
#include "validity.h"

#include <cmath>
#include <limits>

// The game-loop calls: prepareMap, maxContacts and moveAndSlide, over resolveMove.

namespace tilesweep {
using detail::isFinite;
using detail::isPositive;
using detail::moveResultOf;
using detail::refusedMove;

namespace {

template <class T>
void prepare(const TileMapView<T>& map, MapError& error, detail::MapRange& range,
             TileMapView<T>& view) noexcept {
    error = validateTileMap(map);
    view = map;
    if (error == MapError::None) range = detail::mapRangeOf(map);
}

/// The input by reference, not a box and a displacement by value: a Vec2<double> by value arrives
/// in two registers, and storing them apart to read them back as one vector stalls the store
/// forwarding, which would make a prepared frame slower than a bare resolveMove call.
template <class T>
ResolveResult<T> resolveOnPrepared(const PreparedMap<T>& map, const MoveInput<T>& input,
                                   const ResolveOutput<T>& output) noexcept {
    if (!map.isValid()) {
        ResolveResult<T> invalid;
        invalid.status = ResolveStatus::InvalidInput;
        invalid.position = isFinite(input.box.pos) ? input.box.pos : Vec2<T>{0, 0};
        return invalid;
    }
    return detail::resolveFrame(map.view(), input, output, detail::ContactPositions::Placed, &map.mapRange());
}

/// floor(fl(size / tile)) + 2 on one axis, in int64, saturated far above INT32_MAX.
template <class T>
std::int64_t cellsAlong(T size, T tile) noexcept {
    const double q = std::floor(static_cast<double>(size) / static_cast<double>(tile));
    // Division in double of float inputs is the float quotient's bound or larger: both round
    // monotonically, so floor(fl_double(w/t)) >= floor(w/t) holds either way.
    if (!(q < 0x1p40)) return std::int64_t{1} << 40;
    return static_cast<std::int64_t>(q) + 2;
}

template <class T>
std::int32_t maxContactsOf(Vec2<T> box, Vec2<T> tile) noexcept {
    if (!isPositive(box) || !isPositive(tile)) return 0;
    const std::int64_t n = cellsAlong(box.x, tile.x) + cellsAlong(box.y, tile.y);
    return n > std::numeric_limits<std::int32_t>::max() ? std::numeric_limits<std::int32_t>::max()
                                                        : static_cast<std::int32_t>(n);
}

/// Inlined into each moveAndSlide overload (gnu::always_inline): a call of its own would cost
/// every frame the saved registers and a copy of the result. (A batch does not come here: its
/// loop solves its frames inline, move_range.cpp.)
template <class T>
[[gnu::always_inline]] inline MoveResult<T> moveAndSlideOf(const PreparedMap<T>& map,
                                                           const MoveInput<T>& input, Contact<T>* contacts,
                                                           std::int32_t capacity) noexcept {
    // The map was checked once, by prepareMap; the box and the move are checked by the resolver,
    // whose InvalidInput is refused below. Every move goes to the resolver, free ones too: its
    // fast path finds a move whose swept cells are empty after the frame's set-up (free_move.h),
    // where a test here, before the set-up, would cost a move that is not free more than it
    // saves a free one.
    if (!map.isValid()) return refusedMove(input, MoveStatus::InvalidInput);
    // A caller without a buffer gets no contacts, so the resolver stores none (capacity 0). A
    // buffer of maxContacts takes the contacts directly; a smaller one has them go to the stack,
    // copied out when they all fit, so that the caller's buffer holds all of them or is left as
    // it was. The flags never depend on either: they come from the steps. (The bound takes two
    // divisions and two floors: only a caller with a buffer pays for them.)
    const bool wanted = contacts != nullptr && capacity > 0;
    const bool direct = wanted && capacity >= maxContactsOf(input.box.size, map.view().tileSize);
    Contact<T> local[kInlineContacts];
    Contact<T>* buffer = !wanted ? nullptr : direct ? contacts : local;
    const std::int32_t bufferCapacity = !wanted ? 0 : direct ? capacity : kInlineContacts;
    // The contacts' positions only when the caller may receive the contacts.
    const ResolveResult<T> s = detail::resolveFrame(
        map.view(), input, ResolveOutput<T>{buffer, bufferCapacity},
        wanted ? detail::ContactPositions::Placed : detail::ContactPositions::Skipped, &map.mapRange());
    if (s.status == ResolveStatus::InvalidInput) return refusedMove(input, MoveStatus::InvalidInput);
    MoveResult<T> r = moveResultOf(s, input.displacement);
    if (direct) {
        r.contactsStored = s.contactCount <= capacity;  // always: maxContacts proves it
#if defined(TILESWEEP_FAULT_INLINE_LIMIT_EXCLUSIVE)     // deliberate fault: exactly the inline limit is not
                                                        // copied
    } else if (contacts != nullptr && s.contactCount <= capacity && s.contactCount < kInlineContacts) {
#else
    } else if (contacts != nullptr && s.contactCount <= capacity && s.contactCount <= kInlineContacts) {
#endif
        for (std::int32_t k = 0; k < s.contactCount; ++k) contacts[k] = local[k];
        r.contactsStored = true;
    }
    return r;
}

}  // namespace

PreparedMap<float> prepareMap(const TileMapView<float>& map) noexcept {
    PreparedMap<float> p;
    prepare(map, p.error_, p.range_, p.view_);
    return p;
}

PreparedMap<double> prepareMap(const TileMapView<double>& map) noexcept {
    PreparedMap<double> p;
    prepare(map, p.error_, p.range_, p.view_);
    return p;
}

ResolveResult<float> resolveMove(const PreparedMap<float>& map, const MoveInput<float>& input,
                                 const ResolveOutput<float>& output) noexcept {
    return resolveOnPrepared(map, input, output);
}
ResolveResult<double> resolveMove(const PreparedMap<double>& map, const MoveInput<double>& input,
                                  const ResolveOutput<double>& output) noexcept {
    return resolveOnPrepared(map, input, output);
}
std::int32_t maxContacts(Vec2<float> boxSize, Vec2<float> tileSize) noexcept {
    return maxContactsOf(boxSize, tileSize);
}

std::int32_t maxContacts(Vec2<double> boxSize, Vec2<double> tileSize) noexcept {
    return maxContactsOf(boxSize, tileSize);
}

MoveResult<float> moveAndSlide(const PreparedMap<float>& map, const MoveInput<float>& input,
                               Contact<float>* contacts, std::int32_t contactCapacity) noexcept {
    return moveAndSlideOf(map, input, contacts, contactCapacity);
}

MoveResult<double> moveAndSlide(const PreparedMap<double>& map, const MoveInput<double>& input,
                                Contact<double>* contacts, std::int32_t contactCapacity) noexcept {
    return moveAndSlideOf(map, input, contacts, contactCapacity);
}

}  // namespace tilesweep
