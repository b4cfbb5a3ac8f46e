// SPDX-License-Identifier: MIT
#include "tilesweep/scene/file_write.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>
#include <system_error>

namespace tilesweep {

bool writeFileWhole(const std::string& path, const std::string& text, std::string& error) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (out.is_open()) out.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (out.is_open()) out.close();
        if (!out) {
            error = "cannot write '" + temporary + "': " + std::strerror(errno);
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            return false;
        }
    }
    std::error_code renameError;
    std::filesystem::rename(temporary, path, renameError);
    if (renameError) {
        error = "cannot rename '" + temporary + "' to '" + path + "': " + renameError.message();
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        return false;
    }
    return true;
}

}  // namespace tilesweep
