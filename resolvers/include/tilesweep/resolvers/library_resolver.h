// SPDX-License-Identifier: MIT
#pragma once

// A user's resolver from a shared library (include/tilesweep/resolver_lib.h), the resolver the
// registry names lib:PATH (`tilesweep resolve --resolver lib:PATH`): each scene is handed to the library's
// ts_user_resolve_f or ts_user_resolve_d with the C API's types, and its frames come back as
// FrameResult. `tilesweep check --resolver-lib PATH` runs that command as an outside resolver,
// so the library lives in a child process and a crash in it costs one scene, not the run.
//
//     LibraryLoad<float> loaded = loadLibraryResolver<float>("./libmine.so");
//     if (!loaded.resolve) fail(loaded.error);   // cannot open, or no ts_user_resolve_f
//     frames = loaded.resolve(scene);             // throws std::runtime_error when it refuses

#include "tilesweep/resolvers/in_process_resolver.h"

#include <string>

namespace tilesweep::resolvers {

/// The resolver of a library, or why there is none.
template <class T>
struct LibraryLoad {
    FramesOf<T> resolve;  ///< empty when the library could not be used
    std::string error;    ///< why not: dlopen's or dlsym's message
};

/// Opens `path` (dlopen; it stays loaded) and finds ts_user_resolve_f (float) or
/// ts_user_resolve_d (double).
template <class T>
[[nodiscard]] LibraryLoad<T> loadLibraryResolver(const std::string& path);

/// The prefix of a resolver name that names a library: "lib:PATH".
inline constexpr const char* kLibraryResolverPrefix = "lib:";

extern template LibraryLoad<float> loadLibraryResolver<float>(const std::string&);
extern template LibraryLoad<double> loadLibraryResolver<double>(const std::string&);

}  // namespace tilesweep::resolvers
