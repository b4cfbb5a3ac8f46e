// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/library_resolver.h"

#include "tilesweep/resolver_lib.h"

#include <algorithm>
#include <dlfcn.h>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace tilesweep::resolvers {
namespace {

/// The C API's types for T.
template <class T>
struct CTypes;
template <>
struct CTypes<float> {
    using SceneT = ts_scene_f;
    using FrameT = ts_frame_out_f;
    using ContactT = ts_contact_f;
    using VecT = ts_vec2_f;
    using Function = ts_user_resolve_f_fn;
    static constexpr const char* kName = TS_USER_RESOLVE_F_NAME;
};
template <>
struct CTypes<double> {
    using SceneT = ts_scene_d;
    using FrameT = ts_frame_out_d;
    using ContactT = ts_contact_d;
    using VecT = ts_vec2_d;
    using Function = ts_user_resolve_d_fn;
    static constexpr const char* kName = TS_USER_RESOLVE_D_NAME;
};

/// Room each frame gets at first: enough for the scenes of the suite; a frame that needs more
/// says so (TS_USER_NEEDS_ROOM) and the call is made again.
constexpr std::int32_t kFirstContactRoom = 64;
constexpr std::int32_t kFirstOverlapRoom = 64;
/// The most room a frame is given: a library asking for more is refusing the scene.
constexpr std::int32_t kMostRoom = std::int32_t{1} << 24;

template <class T>
std::vector<FrameResult<T>> resolveThrough(typename CTypes<T>::Function function, const Scene<T>& scene) {
    using C = CTypes<T>;
    typename C::SceneT in{};
    in.map.origin = {scene.map.origin.x, scene.map.origin.y};
    in.map.tile_size = {scene.map.tileSize.x, scene.map.tileSize.y};
    in.map.columns = scene.map.columns;
    in.map.rows = scene.map.rows;
    in.map.solid = scene.map.solid.data();
    in.map.allocator = nullptr;
    in.one_way = scene.map.oneWay.empty() ? nullptr : scene.map.oneWay.data();
    in.box.pos = {scene.box.pos.x, scene.box.pos.y};
    in.box.size = {scene.box.size.x, scene.box.size.y};
    std::vector<typename C::VecT> moves;
    moves.reserve(scene.moves.size());
    for (const Vec2<T>& m : scene.moves) moves.push_back({m.x, m.y});
    in.moves = moves.data();
    in.move_count = static_cast<std::int32_t>(moves.size());

    const std::size_t count = moves.size();
    std::vector<std::int32_t> contactRoom(count, kFirstContactRoom);
    std::vector<std::int32_t> overlapRoom(count, kFirstOverlapRoom);
    std::vector<std::vector<typename C::ContactT>> contacts(count);
    std::vector<std::vector<ts_cell>> overlaps(count);
    std::vector<typename C::FrameT> out(count);
    for (;;) {
        for (std::size_t k = 0; k < count; ++k) {
            contacts[k].assign(static_cast<std::size_t>(contactRoom[k]), {});
            overlaps[k].assign(static_cast<std::size_t>(overlapRoom[k]), {});
            out[k] = {};
            out[k].contacts = contacts[k].data();
            out[k].contact_capacity = contactRoom[k];
            out[k].start_overlaps = overlaps[k].data();
            out[k].start_overlap_capacity = overlapRoom[k];
        }
        const int status = function(&in, out.data());
        if (status == TS_USER_OK) break;
        if (status != TS_USER_NEEDS_ROOM)
            throw std::runtime_error(std::string(C::kName) + " refused the scene (returned " +
                                     std::to_string(status) + ")");
        bool grew = false;
        for (std::size_t k = 0; k < count; ++k) {
            const std::int32_t needContacts = out[k].contact_count;
            const std::int32_t needOverlaps = out[k].start_overlap_count;
            if (needContacts > kMostRoom || needOverlaps > kMostRoom)
                throw std::runtime_error(std::string(C::kName) +
                                         " asked for more than 2^24 contacts or cells");
            if (needContacts > contactRoom[k]) contactRoom[k] = needContacts, grew = true;
            if (needOverlaps > overlapRoom[k]) overlapRoom[k] = needOverlaps, grew = true;
        }
        if (!grew)
            throw std::runtime_error(std::string(C::kName) +
                                     " returned TS_USER_NEEDS_ROOM without asking for more room");
    }

    std::vector<FrameResult<T>> frames(count);
    for (std::size_t k = 0; k < count; ++k) {
        const typename C::FrameT& f = out[k];
        if (f.contact_count < 0 || f.contact_count > f.contact_capacity || f.start_overlap_count < 0 ||
            f.start_overlap_count > f.start_overlap_capacity)
            throw std::runtime_error(std::string(C::kName) + ": frame " + std::to_string(k) +
                                     " has a count outside its room without returning TS_USER_NEEDS_ROOM");
        frames[k].position = {f.position.x, f.position.y};
        for (std::int32_t c = 0; c < f.contact_count; ++c) {
            const typename C::ContactT& contact = f.contacts[c];
            frames[k].contacts.push_back(
                {Cell{contact.i, contact.j}, Normal{contact.nx, contact.ny}, contact.time, {}});
        }
        for (std::int32_t c = 0; c < f.start_overlap_count; ++c)
            frames[k].startOverlaps.push_back(Cell{f.start_overlaps[c].i, f.start_overlaps[c].j});
    }
    return frames;
}

}  // namespace

template <class T>
LibraryLoad<T> loadLibraryResolver(const std::string& path) {
    using C = CTypes<T>;
    LibraryLoad<T> load;
    // A path without a slash would be searched for on the library path; this one is a file.
    const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
    void* library = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
        const char* why = dlerror();
        load.error = "cannot load '" + path + "': " + (why ? why : "dlopen failed");
        return load;
    }
    dlerror();
    void* symbol = dlsym(library, C::kName);
    if (symbol == nullptr) {
        load.error = "'" + path + "' does not export " + C::kName +
                     " (include/tilesweep/resolver_lib.h; declare it extern \"C\" in C++)";
        return load;
    }
    const auto function = reinterpret_cast<typename C::Function>(symbol);
    load.resolve = [function](const Scene<T>& scene) { return resolveThrough<T>(function, scene); };
    return load;
}

template LibraryLoad<float> loadLibraryResolver<float>(const std::string&);
template LibraryLoad<double> loadLibraryResolver<double>(const std::string&);

}  // namespace tilesweep::resolvers
