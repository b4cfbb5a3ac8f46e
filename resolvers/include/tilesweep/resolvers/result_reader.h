// SPDX-License-Identifier: MIT
#pragma once

// Reading a result line of `tilesweep resolve` (docs/contract.md, "tilesweep resolve") back into
// frames, as an outside resolver prints it:
//
//     {"frames": [{"pos": [x, y], "contacts": [{"tile": [i, j], "normal": [0, -1], "t": 0.25}],
//                  "started_overlapping": [[i, j]]}]}
//
// Every number is rounded once, straight from its text to T (a JSON number, or a hexfloat
// string such as "0x1.8p+3"), never through double first, so a float printed in its shortest
// form reads back to the same bits. The reader is strict: it is the judge of a process that
// may print anything, and whatever it cannot read exactly is the resolver's failure.

#include "tilesweep/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tilesweep::resolvers {

/// A result line read: the frames, or why the line is not a valid answer.
template <class T>
struct ResultParse {
    std::optional<std::vector<FrameResult<T>>> frames;
    std::string error;  ///< empty when `frames` is set
};

/// Reads one result line for a scene of `frameCount` frames. An `{"error": ...}` line, malformed
/// JSON, a missing or ill-typed field, a non-finite or unreadable number, a normal that is not
/// one of the four axis normals, or a frame count other than `frameCount` is an error. Unknown
/// fields are ignored. Never throws.
template <class T>
[[nodiscard]] ResultParse<T> parseResultLine(std::string_view line, std::size_t frameCount);

extern template ResultParse<float> parseResultLine<float>(std::string_view, std::size_t);
extern template ResultParse<double> parseResultLine<double>(std::string_view, std::size_t);

}  // namespace tilesweep::resolvers
