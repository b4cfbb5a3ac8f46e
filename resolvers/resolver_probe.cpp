// SPDX-License-Identifier: MIT
#include "tilesweep/resolvers/resolver_probe.h"

#include "tilesweep/resolvers/resolver_process.h"
#include "tilesweep/resolvers/result_reader.h"
#include "tilesweep/scene/scene.h"

#include <vector>

namespace tilesweep::resolvers {
namespace {

/// The known scene: a 12 px box 4 px down falls 40 px onto the floor of a 6 x 4 map of 16 px
/// tiles. Every resolver meets this in its first minute of use.
constexpr const char* kProbeScene =
    R"({"name": "probe: a box falls onto the floor", "map": {"origin": [0, 0], "tile": [16, 16], )"
    R"("rows": ["......", "......", "......", "######"]}, "box": [20, 4, 12, 12], "move": [0, 40]})";

template <class T>
std::string probeLine() {
    return formatScene(*parseScene<T>(kProbeScene).scene);
}

}  // namespace

std::string knownSceneLine() { return probeLine<float>(); }

namespace {

template <class T>
std::string judgeAnswer(const ResolverReply& reply, const char* scalar) {
    if (!reply.failure.empty()) return reply.failure;
    const ResultParse<T> parsed = parseResultLine<T>(reply.line, 1);
    if (parsed.frames) return {};
    return std::string("its answer to a valid ") + scalar + " scene is not a result line (" + parsed.error +
           "): '" + reply.line.substr(0, 200) + "'";
}

}  // namespace

std::string probeResolver(const std::string& command, double timeoutSeconds, bool inFloat, bool inDouble) {
    std::vector<std::string> lines;
    if (inFloat) lines.push_back(probeLine<float>());
    if (inDouble) lines.push_back(probeLine<double>());
    ResolverProcess process(command, timeoutSeconds);
    const std::vector<ResolverReply> replies = process.exchange(lines);
    std::size_t k = 0;
    if (inFloat)
        if (std::string why = judgeAnswer<float>(replies[k++], "float"); !why.empty()) return why;
    if (inDouble)
        if (std::string why = judgeAnswer<double>(replies[k], "double"); !why.empty()) return why;
    return {};
}

}  // namespace tilesweep::resolvers
