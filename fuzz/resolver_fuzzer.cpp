// SPDX-License-Identifier: MIT
// Fuzz target for the resolver: bytes are decoded into a map of up to 32 x 32 cells, a box and a
// displacement, in float or in double, with any bit pattern for every scalar (NaN, infinities,
// subnormals, huge values) mixed with values a collision cares about (small integers, tile
// multiples, their neighbours one to three ulps away). resolveMove must then either refuse the
// input (exactly when isValid says it is invalid) or return a result that obeys the contract's
// safety rules, checked exactly by frame_safety.h. A truncated list must not change the result.
//
// Input layout (missing bytes read as zero): 1 byte scalar type (bit 0: double), 1 byte
// columns, 1 byte rows, ceil(columns*rows/8) bytes of solid bits, then 10 scalars (origin,
// tile size, box position, box size, displacement), then 1 byte of list capacities.
#include "frame_safety.h"  // checks/
#include "fuzz_check.h"

#include "tilesweep/resolve.h"
#include "tilesweep/tile_map.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using namespace tilesweep;

constexpr std::int32_t kMaxSide = 32;  // cells per map side; keeps one input well under a millisecond

/// Reads the input front to back; past its end every byte is zero.
class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) noexcept : data_(data), size_(size) {}

    std::uint8_t byte() noexcept { return at_ < size_ ? data_[at_++] : std::uint8_t{0}; }

    template <class U>
    U word() noexcept {
        U value = 0;
        for (std::size_t k = 0; k < sizeof(U); ++k)
            value = static_cast<U>(static_cast<U>(value << 8) | byte());
        return value;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

template <class T>
using BitsOf = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;

template <class T>
T fromBits(BitsOf<T> bits) noexcept {
    T value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

/// Values at the edges of T's range, and a few that tile arithmetic trips on.
template <class T>
T specialValue(std::uint8_t pick) noexcept {
    using L = std::numeric_limits<T>;
    const T table[] = {L::quiet_NaN(),
                       -L::quiet_NaN(),
                       L::signaling_NaN(),
                       L::infinity(),
                       -L::infinity(),
                       T(0),
                       -T(0),
                       L::denorm_min(),
                       -L::denorm_min(),
                       L::min(),
                       -L::min(),
                       L::max(),
                       L::lowest(),
                       L::epsilon(),
                       T(1) / T(3),
                       T(0.1),
                       std::ldexp(T(1), L::digits),
                       std::ldexp(T(1), L::digits) + T(2),
                       std::ldexp(T(1), L::max_exponent - 2),
                       std::ldexp(T(1), L::min_exponent - 1)};
    return table[pick % (sizeof table / sizeof table[0])];
}

/// One scalar: a tag byte chooses how the bytes after it are read.
template <class T>
T decodeScalar(ByteReader& in) {
    const std::uint8_t tag = in.byte();
    switch (tag % 8) {
        case 0:  // any bit pattern
            return fromBits<T>(in.word<BitsOf<T>>());
        case 1:  // a small integer
            return static_cast<T>(static_cast<std::int8_t>(in.byte()));
        case 2:  // a fixed-point value with 8 fraction bits
            return static_cast<T>(static_cast<std::int16_t>(in.word<std::uint16_t>())) / T(256);
        case 3:
            return specialValue<T>(in.byte());
        case 4: {  // a multiple of 4 (a tile edge, often), nudged by -3..3 ulps
            T value = static_cast<T>(static_cast<std::int8_t>(in.byte())) * T(4);
            const int steps = in.byte() % 7 - 3;
            const T toward =
                steps < 0 ? -std::numeric_limits<T>::infinity() : std::numeric_limits<T>::infinity();
            for (int k = 0; k < (steps < 0 ? -steps : steps); ++k) value = std::nextafter(value, toward);
            return value;
        }
        case 5: {  // a small integer scaled by any power of two: far from the origin, or tiny
            const T mantissa = static_cast<T>(static_cast<std::int8_t>(in.byte()));
            return std::ldexp(mantissa,
                              static_cast<int>(static_cast<std::int16_t>(in.word<std::uint16_t>()) % 1200));
        }
        default:  // a small multiple of 16: the usual tile size
            return static_cast<T>(static_cast<std::int8_t>(in.byte())) * T(16);
    }
}

template <class T>
Vec2<T> decodeVec2(ByteReader& in) {
    const T x = decodeScalar<T>(in);
    return {x, decodeScalar<T>(in)};
}

template <class T>
std::string hexfloat(T value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", static_cast<double>(value));
    return buffer;
}

template <class T>
std::string describeInput(const ResolveInput<T>& in, const std::vector<std::uint8_t>& solid) {
    std::string text = std::string(sizeof(T) == 4 ? "float" : "double") + " map " +
                       std::to_string(in.map.columns) + "x" + std::to_string(in.map.rows) + " origin (" +
                       hexfloat(in.map.origin.x) + ", " + hexfloat(in.map.origin.y) + ") tile (" +
                       hexfloat(in.map.tileSize.x) + ", " + hexfloat(in.map.tileSize.y) + ") box (" +
                       hexfloat(in.box.pos.x) + ", " + hexfloat(in.box.pos.y) + ", " +
                       hexfloat(in.box.size.x) + ", " + hexfloat(in.box.size.y) + ") d (" +
                       hexfloat(in.displacement.x) + ", " + hexfloat(in.displacement.y) + ") rows";
    for (std::int32_t j = 0; j < in.map.rows; ++j) {
        text += ' ';
        for (std::int32_t i = 0; i < in.map.columns; ++i)
            text += solid[static_cast<std::size_t>(j * in.map.columns + i)] != 0 ? '#' : '.';
    }
    return text;
}

/// Caller-owned lists of exactly the given capacities, on the heap, so that AddressSanitizer
/// catches a write past either one; capacity 0 passes null pointers.
template <class T>
struct Lists {
    std::vector<Contact<T>> contacts;
    std::vector<Cell> overlaps;

    Lists(std::int32_t contactCapacity, std::int32_t overlapCapacity)
        : contacts(static_cast<std::size_t>(contactCapacity)),
          overlaps(static_cast<std::size_t>(overlapCapacity)) {}

    ResolveOutput<T> output() noexcept {
        return {contacts.empty() ? nullptr : contacts.data(), static_cast<std::int32_t>(contacts.size()),
                overlaps.empty() ? nullptr : overlaps.data(), static_cast<std::int32_t>(overlaps.size())};
    }
};

template <class T>
void fuzzResolver(ByteReader& in) {
    constexpr const char* kTarget = "fuzz_resolver";
    const std::int32_t columns = in.byte() % (kMaxSide + 1);
    const std::int32_t rows = in.byte() % (kMaxSide + 1);
    std::vector<std::uint8_t> solid(static_cast<std::size_t>(columns * rows));
    for (std::size_t k = 0; k < solid.size(); k += 8) {
        const std::uint8_t bits = in.byte();
        for (std::size_t b = 0; b < 8 && k + b < solid.size(); ++b) solid[k + b] = (bits >> b) & 1u;
    }
    TileMapView<T> map{{}, {}, columns, rows, solid.empty() ? nullptr : solid.data()};
    map.origin = decodeVec2<T>(in);
    map.tileSize = decodeVec2<T>(in);
    ResolveInput<T> input{map, {}, {}};
    input.box.pos = decodeVec2<T>(in);
    input.box.size = decodeVec2<T>(in);
    input.displacement = decodeVec2<T>(in);
    const std::uint8_t capacities = in.byte();

    Lists<T> small(capacities & 7, (capacities >> 4) & 7);
    const ResolveResult<T> first = resolveMove(input, small.output());
    const Vec2<T> start = input.box.pos;

    if (!isValid(input)) {
        const bool startFinite = std::isfinite(start.x) && std::isfinite(start.y);
        const Vec2<T> expected = startFinite ? start : Vec2<T>{0, 0};
        if (first.status != ResolveStatus::InvalidInput || first.contactCount != 0 ||
            first.startOverlapCount != 0 || !fuzz::sameBits(first.position.x, expected.x) ||
            !fuzz::sameBits(first.position.y, expected.y))
            fuzz::failCheck(kTarget, "invalid input not refused with the start position and no lists",
                            describeInput(input, solid));
        return;
    }
    if (!std::isfinite(first.position.x) || !std::isfinite(first.position.y))
        fuzz::failCheck(kTarget, "non-finite final position", describeInput(input, solid));
    // A map whose edges are not all representable is outside the resolver's contract (callers
    // run validateTileMap first): it must not crash or produce a NaN, and that is all.
    if (validateTileMap(map) != MapError::None) return;
    if (first.status == ResolveStatus::InvalidInput)
        fuzz::failCheck(kTarget, "valid input refused", describeInput(input, solid));

    // With room for every list entry, the result must be the same; then check it.
    Lists<T> full(first.contactCount, first.startOverlapCount);
    const ResolveResult<T> r = resolveMove(input, full.output());
    if (r.status != first.status || r.contactCount != first.contactCount ||
        r.startOverlapCount != first.startOverlapCount || !fuzz::sameBits(r.position.x, first.position.x) ||
        !fuzz::sameBits(r.position.y, first.position.y))
        fuzz::failCheck(kTarget, "result depends on the list capacities", describeInput(input, solid));

    const checks::MapEdges<T> edges = checks::computeEdges(map);
    checks::SafetyScratch scratch;
    const checks::FrameRecord<T> frame{
        map, input.box, input.displacement, r, full.contacts.data(), full.overlaps.data()};
    const checks::SafetyViolation violation = checks::checkFrameSafety(frame, edges, scratch);
    if (violation) fuzz::failCheck(kTarget, violation.detail, describeInput(input, solid));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    if ((in.byte() & 1) != 0)
        fuzzResolver<double>(in);
    else
        fuzzResolver<float>(in);
    return 0;
}
