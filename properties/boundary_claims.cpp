// SPDX-License-Identifier: MIT
#include "boundary_claims.h"

#include "c_types.h"

#include "tilesweep/mover.h"
#include "tilesweep/resolve.h"
#include "tilesweep/tilesweep.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace tilesweep::properties {
namespace {

/// Buffers larger than this are not tried (a box of thousands of tiles: the extreme family).
constexpr std::int32_t kLargestBufferTried = 4096;

template <class T>
bool sameBits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T>
bool sameContact(const Contact<T>& a, const Contact<T>& b) {
    return a.tile == b.tile && a.normal == b.normal && sameBits(a.time, b.time);
}

// The C API by scalar type: its types (c_types.h) and the calls the claims make.
template <class T>
struct CApi;
template <>
struct CApi<float> : detail::CTypes<float> {
    static ts_error create(const Desc* d, Map** m) { return ts_map_create_f(d, m); }
    static ts_error createOneWay(const Desc* d, const std::uint8_t* oneWay, Map** m) {
        return ts_map_create_one_way_f(d, oneWay, m);
    }
    static void destroy(Map* m) { ts_map_destroy_f(m); }
    static ts_error move(const Map* m, const Mover* v, Result* r, ContactC* c, std::int32_t n) {
        return ts_move_and_slide_f(m, v, r, c, n);
    }
    static ts_error setSolid(Map* m, std::int32_t i, std::int32_t j, int s) {
        return ts_map_set_solid_f(m, i, j, s);
    }
};
template <>
struct CApi<double> : detail::CTypes<double> {
    static ts_error create(const Desc* d, Map** m) { return ts_map_create_d(d, m); }
    static ts_error createOneWay(const Desc* d, const std::uint8_t* oneWay, Map** m) {
        return ts_map_create_one_way_d(d, oneWay, m);
    }
    static void destroy(Map* m) { ts_map_destroy_d(m); }
    static ts_error move(const Map* m, const Mover* v, Result* r, ContactC* c, std::int32_t n) {
        return ts_move_and_slide_d(m, v, r, c, n);
    }
    static ts_error setSolid(Map* m, std::int32_t i, std::int32_t j, int s) {
        return ts_map_set_solid_d(m, i, j, s);
    }
};

template <class T>
struct MapDeleter {
    void operator()(typename CApi<T>::Map* m) const { CApi<T>::destroy(m); }
};
template <class T>
using MapHandle = std::unique_ptr<typename CApi<T>::Map, MapDeleter<T>>;

template <class T>
typename CApi<T>::Desc descOf(const TileMapView<T>& v) {
    return {{v.origin.x, v.origin.y}, {v.tileSize.x, v.tileSize.y}, v.columns, v.rows, v.solid, nullptr};
}

template <class T>
typename CApi<T>::Mover moverOf(const Box<T>& box, Vec2<T> move) {
    return {{{box.pos.x, box.pos.y}, {box.size.x, box.size.y}}, {move.x, move.y}};
}

/// The flags moveAndSlide derives from a frame's contacts (mover.h).
struct Flags {
    bool blockedX = false, blockedY = false, onGround = false, onCeiling = false, onWall = false;
    int wallNormalX = 0;
};

template <class T>
Flags flagsOf(const Contact<T>* contacts, std::int32_t count) {
    Flags f;
    for (std::int32_t k = 0; k < count; ++k) {
        const Normal n = contacts[k].normal;
        if (n.x != 0) {
            f.blockedX = f.onWall = true;
            f.wallNormalX = n.x;
        }
        if (n.y != 0) f.blockedY = true;
        if (n.y < 0) f.onGround = true;
        if (n.y > 0) f.onCeiling = true;
    }
    return f;
}

template <class T>
std::string compareMove(const MoveResult<T>& got, const ResolveResult<T>& want, const Flags& flags) {
    const MoveStatus status = want.status == ResolveStatus::Blocked ? MoveStatus::Blocked : MoveStatus::Moved;
    if (got.status != status)
        return "status " + std::to_string(int(got.status)) + " != " + std::to_string(int(status));
    if (!sameBits(got.position.x, want.position.x) || !sameBits(got.position.y, want.position.y))
        return "position differs";
    if (got.contactCount != want.contactCount)
        return "contactCount " + std::to_string(got.contactCount) +
               " != " + std::to_string(want.contactCount);
    if (got.blockedX != flags.blockedX || got.blockedY != flags.blockedY || got.onGround != flags.onGround ||
        got.onCeiling != flags.onCeiling || got.onWall != flags.onWall ||
        got.wallNormalX != flags.wallNormalX)
        return "flags differ";
    return {};
}

template <class T>
std::string compareStored(const Contact<T>* got, const Contact<T>* want, std::int32_t count) {
    for (std::int32_t k = 0; k < count; ++k)
        if (!sameContact(got[k], want[k])) return "contact " + std::to_string(k) + " differs";
    return {};
}

/// One frame, every boundary; empty when all agree with `want` (room to spare).
template <class T>
std::string checkFrame(const Scene<T>& scene, const PreparedMap<T>& prepared,
                       const typename CApi<T>::Map* cmap, const Box<T>& box, Vec2<T> move,
                       const ResolveResult<T>& want, const std::vector<Contact<T>>& wanted) {
    const std::int32_t n = want.contactCount;
    const std::int32_t bound = maxContacts(box.size, scene.map.tileSize);
    const Flags flags = flagsOf(wanted.data(), n);
    const MoveInput<T> input{box, move};

    // resolveMove into exactly n.
    {
        std::vector<Contact<T>> exact(static_cast<std::size_t>(n) + 1);
        Cell overlaps[64];
        const ResolveResult<T> got =
            resolveMove<T>({scene.map.view(), box, move}, {exact.data(), n, overlaps, 64});
        if (got.status != want.status || got.contactCount != n ||
            !sameBits(got.position.x, want.position.x) || !sameBits(got.position.y, want.position.y))
            return "resolveMove into exactly " + std::to_string(n) + " contacts: a different result";
        if (std::string why = compareStored(exact.data(), wanted.data(), n); !why.empty())
            return "resolveMove into exactly " + std::to_string(n) + " contacts: " + why;
    }
    // moveAndSlide into exactly n, exactly the bound, and no buffer. Since 0.2 every call resolves
    // the frame and sets its flags from the steps, whatever the buffer; the contacts are stored
    // all or none: into a buffer of the bound directly, otherwise through the inline list of
    // kInlineContacts when they fit both it and the buffer (contactsStored says which).
    const auto storedWhen = [&](std::int32_t capacity) {
        return capacity >= bound || (n <= capacity && n <= kInlineContacts);
    };
    {
        std::vector<Contact<T>> exact(static_cast<std::size_t>(n) + 1);
        const MoveResult<T> got = moveAndSlide(prepared, input, exact.data(), n);
        const std::string at = "moveAndSlide into exactly " + std::to_string(n) + " contacts (bound " +
                               std::to_string(bound) + ")";
        if (std::string why = compareMove(got, want, flags); !why.empty()) return at + ": " + why;
        // A free move stores its (no) contacts whatever the buffer.
        if (n > 0 && got.contactsStored != storedWhen(n)) return at + ": contactsStored is wrong";
        if (got.contactsStored)
            if (std::string why = compareStored(exact.data(), wanted.data(), n); !why.empty())
                return at + ": " + why;
    }
    if (bound <= kLargestBufferTried) {
        std::vector<Contact<T>> full(static_cast<std::size_t>(bound));
        const MoveResult<T> got = moveAndSlide(prepared, input, full.data(), bound);
        const std::string at = "moveAndSlide into exactly maxContacts = " + std::to_string(bound);
        if (std::string why = compareMove(got, want, flags); !why.empty()) return at + ": " + why;
        if (!got.contactsStored) return at + ": contacts not stored";
        if (std::string why = compareStored(full.data(), wanted.data(), n); !why.empty())
            return at + ": " + why;
    }
    {
        const MoveResult<T> got = moveAndSlide(prepared, input);
        const std::string at = "moveAndSlide with no buffer (bound " + std::to_string(bound) + ")";
        if (std::string why = compareMove(got, want, flags); !why.empty()) return at + ": " + why;
    }
    if (cmap == nullptr) return {};
    // The C API: exactly n, exactly the bound, one below the bound of a wide box.
    using C = CApi<T>;
    const typename C::Mover mover = moverOf(box, move);
    const auto callC = [&](std::int32_t capacity, std::vector<typename C::ContactC>& buffer,
                           typename C::Result& result) {
        buffer.assign(static_cast<std::size_t>(capacity) + 1, typename C::ContactC{});
        return C::move(cmap, &mover, &result, buffer.data(), capacity);
    };
    const auto compareC = [&](ts_error code, const typename C::Result& r,
                              const std::vector<typename C::ContactC>& b,
                              const std::string& at) -> std::string {
        if (code != TS_OK) return at + ": " + ts_error_message(code);
        if (!sameBits(r.position.x, want.position.x) || !sameBits(r.position.y, want.position.y))
            return at + ": position differs";
        if (r.contact_count != n || r.status != (n > 0 ? TS_MOVE_BLOCKED : TS_MOVE_MOVED))
            return at + ": count or status differs";
        if ((r.on_ground != 0) != flags.onGround || (r.on_wall != 0) != flags.onWall ||
            (r.on_ceiling != 0) != flags.onCeiling || r.wall_normal_x != flags.wallNormalX)
            return at + ": flags differ";
        for (std::int32_t k = 0; r.contacts_stored != 0 && k < n; ++k) {
            const Contact<T>& w = wanted[static_cast<std::size_t>(k)];
            const auto& g = b[static_cast<std::size_t>(k)];
            if (g.i != w.tile.i || g.j != w.tile.j || g.nx != w.normal.x || g.ny != w.normal.y ||
                !sameBits(g.time, w.time))
                return at + ": contact " + std::to_string(k) + " differs";
        }
        return {};
    };
    std::vector<typename C::ContactC> buffer;
    typename C::Result result{};
    {
        const std::string at = "ts_move_and_slide into exactly " + std::to_string(n) + " contacts (bound " +
                               std::to_string(bound) + ")";
        const ts_error code = callC(n, buffer, result);
        if (n > 0 && (result.contacts_stored != 0) != storedWhen(n)) return at + ": contacts_stored is wrong";
        if (std::string why = compareC(code, result, buffer, at); !why.empty()) return why;
    }
    if (bound <= kLargestBufferTried) {
        const std::string at = "ts_move_and_slide into exactly ts_max_contacts = " + std::to_string(bound);
        const ts_error code = callC(bound, buffer, result);
        if (result.contacts_stored == 0) return at + ": contacts not stored";
        if (std::string why = compareC(code, result, buffer, at); !why.empty()) return why;
        const std::string below =
            "ts_move_and_slide into one below ts_max_contacts = " + std::to_string(bound);
        const ts_error short1 = callC(bound - 1, buffer, result);
        if (n > 0 && (result.contacts_stored != 0) != storedWhen(bound - 1))
            return below + ": contacts_stored is wrong";
        if (std::string why = compareC(short1, result, buffer, below); !why.empty()) return why;
    }
    return {};
}

}  // namespace

template <class T>
std::string storesContactsAtExactCapacity(const Scene<T>& scene) {
    const PreparedMap<T> prepared = prepareMap(scene.map.view());
    if (!prepared.isValid()) return {};
    using C = CApi<T>;
    const typename C::Desc desc = descOf(scene.map.view());
    typename C::Map* raw = nullptr;
    const std::vector<std::uint8_t>& oneWay = scene.map.oneWay;
    const ts_error made =
        oneWay.empty() ? C::create(&desc, &raw) : C::createOneWay(&desc, oneWay.data(), &raw);
    if (made != TS_OK) return "ts_map_create refused a map prepareMap accepted";
    const MapHandle<T> cmap(raw);
    Box<T> box = scene.box;
    std::vector<Contact<T>> plenty(kLargestBufferTried);
    Cell overlaps[64];
    for (std::size_t f = 0; f < scene.moves.size(); ++f) {
        const Vec2<T> move = scene.moves[f];
        const ResolveResult<T> want =
            resolveMove<T>({scene.map.view(), box, move}, {plenty.data(), kLargestBufferTried, overlaps, 64});
        if (want.status == ResolveStatus::InvalidInput || want.contactCount > kLargestBufferTried) return {};
        const std::vector<Contact<T>> wanted(plenty.begin(), plenty.begin() + want.contactCount);
        if (std::string why = checkFrame(scene, prepared, cmap.get(), box, move, want, wanted); !why.empty())
            return "frame " + std::to_string(f) + ": " + why;
        box.pos = want.position;
    }
    return {};
}

template <class T>
std::string reportsEachCErrorByItsCause(const Scene<T>& scene) {
    using C = CApi<T>;
    constexpr int digits = std::numeric_limits<T>::digits;
    const TileMapView<T> view = scene.map.view();
    std::vector<std::uint8_t> cells(view.solid, view.solid + static_cast<std::size_t>(view.columns) *
                                                                 static_cast<std::size_t>(view.rows));
    typename C::Desc base = descOf(view);
    if (cells.empty()) {
        cells.assign(1, 0);
        base.columns = 1;
        base.rows = 1;
    }
    base.solid = cells.data();
    const auto expect = [](ts_error got, ts_error want, const char* field,
                           const std::string& cause) -> std::string {
        if (got != want)
            return cause + ": got " + std::to_string(int(got)) + " (" + ts_error_message(got) + "), want " +
                   std::to_string(int(want)) + " (" + ts_error_message(want) + ")";
        if (std::strstr(ts_error_message(got), field) == nullptr)
            return cause + ": the message '" + ts_error_message(got) + "' does not name " + field;
        return {};
    };
    const auto create = [](typename C::Desc d) {
        typename C::Map* m = nullptr;
        const ts_error code = C::create(&d, &m);
        C::destroy(m);
        return code;
    };
    std::string why;
    const auto check = [&why](std::string result) {
        if (why.empty()) why = std::move(result);
    };
    typename C::Map* out = nullptr;
    check(expect(C::create(nullptr, &out), TS_ERROR_NULL_ARGUMENT, "NULL", "a NULL map description"));
    typename C::Desc d = base;
    d.origin.x = std::numeric_limits<T>::quiet_NaN();
    check(expect(create(d), TS_ERROR_MAP_NON_FINITE_ORIGIN, "map.origin", "origin.x NaN"));
    d = base;
    d.origin.y = -std::numeric_limits<T>::infinity();
    check(expect(create(d), TS_ERROR_MAP_NON_FINITE_ORIGIN, "map.origin", "origin.y -inf"));
    d = base;
    d.tile_size.y = 0;
    check(expect(create(d), TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE, "map.tile_size", "tile_size.y 0"));
    d = base;
    d.tile_size.x = -d.tile_size.x;
    check(expect(create(d), TS_ERROR_MAP_NON_POSITIVE_TILE_SIZE, "map.tile_size", "tile_size.x negative"));
    d = base;
    d.rows = -1;
    check(expect(create(d), TS_ERROR_MAP_NEGATIVE_DIMENSIONS, "rows", "rows -1"));
    d = base;
    d.columns = 65536;
    d.rows = 32768;  // 2^31 cells, one past the limit; refused before a cell is read
    check(expect(create(d), TS_ERROR_MAP_TOO_LARGE, "cells", "2^31 cells"));
    // origin = tile * 2^(digits + 2): the next edge, tile * (2^(digits + 2) + 1), needs more
    // than `digits` bits whatever the tile's odd part.
    const T farX = std::ldexp(base.tile_size.x, digits + 2);
    const T farY = std::ldexp(base.tile_size.y, digits + 2);
    if (std::isfinite(farX)) {
        d = base;
        d.origin.x = farX;
        check(expect(create(d), TS_ERROR_MAP_UNREPRESENTABLE_EDGE_X, "origin.x", "an edge on x past digits"));
    }
    if (std::isfinite(farY)) {
        d = base;
        d.origin.y = farY;
        check(expect(create(d), TS_ERROR_MAP_UNREPRESENTABLE_EDGE_Y, "origin.y", "an edge on y past digits"));
    }
    typename C::Map* raw = nullptr;
    if (C::create(&base, &raw) != TS_OK) return why.empty() ? "ts_map_create refused the scene's map" : why;
    const MapHandle<T> map(raw);
    check(expect(C::setSolid(map.get(), base.columns, 0, 1), TS_ERROR_CELL_OUT_OF_RANGE, "cell",
                 "cell i = columns"));
    check(expect(C::setSolid(map.get(), 0, -1, 1), TS_ERROR_CELL_OUT_OF_RANGE, "cell", "cell j = -1"));
    typename C::Result result{};
    typename C::Mover mover = moverOf(scene.box, scene.moves.front());
    check(expect(C::move(map.get(), nullptr, &result, nullptr, 0), TS_ERROR_NULL_ARGUMENT, "NULL",
                 "a NULL mover"));
    mover.displacement.y = std::numeric_limits<T>::quiet_NaN();
    check(expect(C::move(map.get(), &mover, &result, nullptr, 0), TS_ERROR_INVALID_INPUT, "mover",
                 "a NaN displacement"));
    mover = moverOf(scene.box, scene.moves.front());
    mover.box.size.x = 0;
    check(expect(C::move(map.get(), &mover, &result, nullptr, 0), TS_ERROR_INVALID_INPUT, "mover",
                 "a box size 0"));
    // A box 70 tiles wide (maxContacts 75) moving into a solid cell, with 74 entries.
    if (cells.size() >= 2 && base.columns >= 2) {
        std::vector<std::uint8_t> one(cells.size(), 0);
        one[1] = 1;  // cell (1, 0)
        typename C::Desc wide = base;
        wide.solid = one.data();
        typename C::Map* wr = nullptr;
        if (C::create(&wide, &wr) == TS_OK) {
            const MapHandle<T> wideMap(wr);
            const T tx = base.tile_size.x;
            const T ty = base.tile_size.y;
            const typename C::Mover w{{{base.origin.x + tx - 70 * tx - tx / 2, base.origin.y}, {70 * tx, ty}},
                                      {tx, T(0)}};
            // Since 0.2 a short buffer is no error: the frame and its flags come back, the
            // contacts are stored when they fit (contacts_stored), and with no buffer none are.
            std::vector<typename C::ContactC> buffer(80);
            const ts_error code = C::move(wideMap.get(), &w, &result, buffer.data(), 74);
            if (code != TS_OK || result.on_wall == 0 || result.contacts_stored == 0 ||
                result.contact_count != 1)
                check("a box 70 tiles wide with 74 entries: got " + std::to_string(code) + " (" +
                      ts_error_message(code) + "), on_wall " + std::to_string(result.on_wall) + ", stored " +
                      std::to_string(result.contacts_stored) +
                      ", want TS_OK, on the wall, its one contact stored");
            const ts_error none = C::move(wideMap.get(), &w, &result, nullptr, 0);
            if (none != TS_OK || result.on_wall == 0 || result.contacts_stored != 0)
                check("a box 70 tiles wide with no buffer: got " + std::to_string(none) +
                      ", want TS_OK, on the wall, no contact stored");
        }
    }
    return why;
}

template std::string storesContactsAtExactCapacity<float>(const Scene<float>&);
template std::string storesContactsAtExactCapacity<double>(const Scene<double>&);
template std::string reportsEachCErrorByItsCause<float>(const Scene<float>&);
template std::string reportsEachCErrorByItsCause<double>(const Scene<double>&);

// ---- The claims of this file, with their properties (claim.h) ----------------------------------

template <class T>
std::vector<Claim<T>> boundaryClaims() {
    using S = ClaimScope;
    return {
        // Capacity boundaries: buffers of exactly the count and the bound, the inline limit, the
        // wide path at its bound; and the same on every kind of scene.
        {"storesContactsAtExactCapacity",
         &aboutTilesweep<T, &storesContactsAtExactCapacity<T>>,
         S::Internal,
         nullptr,
         {{"storesContactsAtExactCapacity",
           Family::Capacity,
           {{"bound-inline-limit", 0.15}, {"bound-wide", 0.15}, {"many-contacts", 0.3}}},
          {"storesEveryFramesContactsAtExactCapacity", Family::Mixed, {{"hit", 0.2}, {"two-step", 0.005}}}}},
        // Every C error code from its own cause, through C.
        {"reportsEachCErrorByItsCause",
         &aboutTilesweep<T, &reportsEachCErrorByItsCause<T>>,
         S::Internal,
         nullptr,
         {{"reportsEachCErrorByItsCause", Family::Mixed, {{"edge-causes-built", 0.9}}}}},
    };
}

template std::vector<Claim<float>> boundaryClaims<float>();
template std::vector<Claim<double>> boundaryClaims<double>();

}  // namespace tilesweep::properties
