// SPDX-License-Identifier: MIT
#pragma once

#include <string>

// Writing a file whole or not at all, for the tools that write reports, pictures and corpus files
// (the property suite, the command-line tool). Part of the `tilesweep_scene` target (scene/).

namespace tilesweep {

/// Writes `text` to `path` through `path`.tmp and a rename, so that a reader never sees half a
/// file and a failed write leaves any previous file as it was. On failure returns false with a
/// message naming the file in `error`, and removes the temporary file. The directory must exist.
[[nodiscard]] bool writeFileWhole(const std::string& path, const std::string& text, std::string& error);

}  // namespace tilesweep
