// SPDX-License-Identifier: MIT
// Replays inputs through a fuzz target without libFuzzer, so that any compiler (g++ included)
// can run the seed corpus and the saved regressions as an ordinary test, the way fmt's fuzzers
// ship a plain main. Arguments are files or directories (every regular file in them, in name
// order); a failing check aborts the process, which fails the test.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

void replayFile(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (!file.good() && !file.eof()) {
        std::fprintf(stderr, "replay: cannot read %s\n", path.c_str());
        std::exit(2);
    }
    std::fprintf(stderr, "replay: %s\n", path.c_str());
    // A copy on the heap of exactly the input's size, so that AddressSanitizer catches a read
    // past its end, as it would under libFuzzer.
    std::vector<std::uint8_t> input(bytes.begin(), bytes.end());
    LLVMFuzzerTestOneInput(input.empty() ? nullptr : input.data(), input.size());
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t replayed = 0;
    for (int a = 1; a < argc; ++a) {
        const fs::path target(argv[a]);
        if (fs::is_directory(target)) {
            std::vector<fs::path> files;
            for (const auto& entry : fs::directory_iterator(target))
                if (entry.is_regular_file() && entry.path().filename().string().front() != '.')
                    files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            for (const fs::path& file : files) replayFile(file);
            replayed += files.size();
        } else if (fs::is_regular_file(target)) {
            replayFile(target);
            ++replayed;
        } else {
            std::fprintf(stderr, "replay: no such file or directory: %s\n", argv[a]);
            return 2;
        }
    }
    std::printf("replay: %zu inputs passed\n", replayed);
    return 0;
}
