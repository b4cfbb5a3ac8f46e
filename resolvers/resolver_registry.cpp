// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/resolver_registry.h"

#include "tilesweep/baselines/grid_resolve.h"
#include "tilesweep/baselines/run_frames.h"
#include "tilesweep/baselines/twin_resolve.h"
#include "tilesweep/resolvers/in_process_resolver.h"
#include "tilesweep/resolvers/library_resolver.h"
#include "tilesweep/resolvers/outside_resolver.h"

#if TILESWEEP_HAVE_ORACLE
#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/oracle/seed/seed_resolve.h"
#include "tilesweep/oracle/substep/substep_float.h"
#include "tilesweep/oracle/substep/substep_oracle.h"
#endif

#include <cstdint>
#include <string>

namespace tilesweep::resolvers {
namespace {

bool startsWith(const std::string& name, const char* prefix) { return name.rfind(prefix, 0) == 0; }

/// A resolver given as one function template, instantiated for both scalar types.
template <template <class> class Fn>
std::unique_ptr<SceneResolver> inBoth(const std::string& name) {
    return std::make_unique<InProcessResolver>(name, Fn<float>{}, Fn<double>{});
}

template <class T>
struct Core {
    std::vector<FrameResult<T>> operator()(const Scene<T>& s) const { return runScene(s); }
};
template <class T>
struct Twin {
    std::vector<FrameResult<T>> operator()(const Scene<T>& s) const {
        return baselines::runFrames(s, [](const ResolveInput<T>& in, const ResolveOutput<T>& out) {
            return baselines::resolveMoveTwin(in, out);
        });
    }
};
template <class T>
struct Grid {
    std::vector<FrameResult<T>> operator()(const Scene<T>& s) const {
        return baselines::runFrames(s, [](const ResolveInput<T>& in, const ResolveOutput<T>& out) {
            return baselines::resolveMoveGrid(in, out);
        });
    }
};

#if TILESWEEP_HAVE_ORACLE
template <class T>
struct Exact {
    std::vector<FrameResult<T>> operator()(const Scene<T>& s) const {
        return oracle::resolveSceneExactRounded(s);
    }
};
template <class T>
struct Seed {
    std::vector<FrameResult<T>> operator()(const Scene<T>& s) const { return oracle::resolveSceneSeed(s); }
};

/// N of "prefix:N" when `name` has that form with 1 <= N <= 2^20, else 0.
std::int64_t substepCount(const std::string& name, const std::string& prefix) {
    if (!startsWith(name, (prefix + ":").c_str())) return 0;
    const std::string digits = name.substr(prefix.size() + 1);
    if (digits.empty() || digits.size() > 7 || digits.find_first_not_of("0123456789") != std::string::npos)
        return 0;
    const std::int64_t n = std::stoll(digits);
    return n >= 1 && n <= (std::int64_t{1} << 20) ? n : 0;
}

template <class T>
FramesOf<T> substepExact(std::int64_t n) {
    return [n](const Scene<T>& s) { return oracle::frameResults(oracle::resolveSceneSubstep(s, n)); };
}
template <class T>
FramesOf<T> substepFloat(std::int64_t n) {
    return [n](const Scene<T>& s) { return oracle::frameResults(oracle::resolveSceneSubstepFloat(s, n)); };
}
#endif

std::string unknownName(const std::string& name) {
    return "unknown resolver '" + name +
           "': expected core, float, double"
#if TILESWEEP_HAVE_ORACLE
           ", exact, substep:N, substep-float:N (1 <= N <= 1048576), seed"
#endif
           ", twin, grid, lib:PATH (a shared library exporting ts_user_resolve_f or ts_user_resolve_d)"
           " or cmd:COMMAND (a process speaking tilesweep resolve's protocol)";
}

}  // namespace

std::unique_ptr<SceneResolver> makeResolver(const std::string& name, std::string& error,
                                            const OutsideOptions& outside) {
    error.clear();
    if (name == "core" || name == "float" || name == "double") return inBoth<Core>(name);
    if (name == "twin") return inBoth<Twin>(name);
    if (name == "grid") return inBoth<Grid>(name);
    if (startsWith(name, kCommandPrefix)) {
        const std::string command = name.substr(std::string(kCommandPrefix).size());
        if (command.empty()) {
            error = "cmd: needs a command";
            return nullptr;
        }
        return std::make_unique<OutsideResolver>(command, outside.timeoutSeconds);
    }
    if (startsWith(name, kLibraryPrefix)) {
        const std::string path = name.substr(std::string(kLibraryPrefix).size());
        LibraryLoad<float> inFloat = loadLibraryResolver<float>(path);
        LibraryLoad<double> inDouble = loadLibraryResolver<double>(path);
        if (!inFloat.resolve && !inDouble.resolve) {
            error = inFloat.error;
            return nullptr;
        }
        return std::make_unique<InProcessResolver>(name, std::move(inFloat.resolve),
                                                   std::move(inDouble.resolve));
    }
#if TILESWEEP_HAVE_ORACLE
    if (name == "exact") return inBoth<Exact>(name);
    if (name == "seed") return inBoth<Seed>(name);
    if (const std::int64_t n = substepCount(name, "substep"))
        return std::make_unique<InProcessResolver>(name, substepExact<float>(n), substepExact<double>(n));
    if (const std::int64_t n = substepCount(name, "substep-float"))
        return std::make_unique<InProcessResolver>(name, substepFloat<float>(n), substepFloat<double>(n));
#endif
    error = unknownName(name);
    return nullptr;
}

std::string checkResolverName(const std::string& name) {
    if (startsWith(name, kCommandPrefix)) return name.size() > 4 ? "" : "cmd: needs a command";
    std::string error;
    (void)makeResolver(name, error);
    return error;
}

std::string scalarForcedBy(const std::string& name) {
    return name == "float" || name == "double" ? name : "";
}

}  // namespace tilesweep::resolvers
