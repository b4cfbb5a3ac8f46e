// SPDX-License-Identifier: MIT
#include "resolvers.h"

#include "library_resolver.h"

#include <cstdint>
#include <string>

#if TILESWEEP_HAVE_ORACLE
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/seed/seed_resolve.h"
#include "tilesweep/oracle/substep/substep_float.h"
#include "tilesweep/oracle/substep/substep_oracle.h"
#endif
#if TILESWEEP_HAVE_AUDIT
#include "tilesweep/audit/audit.h"
#endif

namespace tilesweep::cli {
namespace {

#if TILESWEEP_HAVE_ORACLE
/// N of "prefix:N" when `name` has that form with 1 <= N <= 2^20, else 0.
std::int64_t substepCount(const std::string& name, const std::string& prefix) {
    if (name.rfind(prefix + ":", 0) != 0) return 0;
    const std::string digits = name.substr(prefix.size() + 1);
    if (digits.empty() || digits.size() > 7 || digits.find_first_not_of("0123456789") != std::string::npos)
        return 0;
    const std::int64_t n = std::stoll(digits);
    return n >= 1 && n <= (std::int64_t{1} << 20) ? n : 0;
}

template <class T, class Frames>
std::vector<FrameResult<T>> framesOf(const Frames& substepFrames) {
    std::vector<FrameResult<T>> out;
    for (const auto& f : substepFrames) out.push_back(f.frame);
    return out;
}
#endif

}  // namespace

template <class T>
Resolver<T> findResolver(const std::string& name) {
    if (name == "core" || name == "float" || name == "double") return &runScene<T>;
    if (name.rfind(kLibraryResolverPrefix, 0) == 0)
        return loadLibraryResolver<T>(name.substr(std::string(kLibraryResolverPrefix).size())).resolve;
#if TILESWEEP_HAVE_ORACLE
    if (name == "exact") return &oracle::resolveSceneExactRounded<T>;
    if (name == "seed") return [](const Scene<T>& s) { return oracle::resolveSceneSeed<T>(s); };
    if (const std::int64_t n = substepCount(name, "substep"))
        return [n](const Scene<T>& s) { return framesOf<T>(oracle::resolveSceneSubstep<T>(s, n)); };
    if (const std::int64_t n = substepCount(name, "substep-float"))
        return [n](const Scene<T>& s) { return framesOf<T>(oracle::resolveSceneSubstepFloat<T>(s, n)); };
#endif
#if TILESWEEP_HAVE_AUDIT
    // The game-style baselines (bench/), so that `tilesweep check --resolver-cmd` can hold them.
    if (name == "twin" || name == "grid") {
        audit::Implementation impl;
        impl.name = name;
        impl.kind = name == "twin" ? audit::ImplementationKind::Twin : audit::ImplementationKind::Grid;
        impl.isDouble = sizeof(T) == 8;
        return [impl](const Scene<T>& s) { return audit::runImplementation<T>(impl, s); };
    }
#endif
    return {};
}

std::string checkResolverName(const std::string& name) {
    if (name.rfind(kLibraryResolverPrefix, 0) == 0) {
        const std::string path = name.substr(std::string(kLibraryResolverPrefix).size());
        const LibraryLoad<float> inFloat = loadLibraryResolver<float>(path);
        if (inFloat.resolve || loadLibraryResolver<double>(path).resolve) return {};
        return inFloat.error;
    }
    if (findResolver<float>(name)) return {};
    return "unknown resolver '" + name +
           "': expected core, float, double"
#if TILESWEEP_HAVE_ORACLE
           ", exact, substep:N, substep-float:N (1 <= N <= 1048576) or seed"
#endif
#if TILESWEEP_HAVE_AUDIT
           ", twin or grid"
#endif
           ", or lib:PATH (a shared library exporting ts_user_resolve_f or ts_user_resolve_d)";
}

std::string scalarForcedBy(const std::string& name) {
    return name == "float" || name == "double" ? name : "";
}

template Resolver<float> findResolver<float>(const std::string&);
template Resolver<double> findResolver<double>(const std::string&);

}  // namespace tilesweep::cli
