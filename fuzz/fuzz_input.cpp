#include "fuzz_input.h"

#include <unistd.h>
#include <fstream>

namespace veduta::fuzz {

namespace {

// Made at the first input, removed when the fuzzer exits normally.
struct ProcessFolder {
    std::filesystem::path path = std::filesystem::temp_directory_path() / ("veduta-fuzz-" + std::to_string(getpid()));
    ProcessFolder() { std::filesystem::create_directories(path / "empty"); }
    ~ProcessFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

}  // namespace

static const std::filesystem::path &processFolder() {
    static const ProcessFolder folder;
    return folder.path;
}

std::filesystem::path inputFile(const uint8_t *data, size_t size, std::string_view extension) {
    auto path = processFolder() / ("input" + std::string(extension));
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), std::streamsize(size));
    out.close();
    if (!out) throw std::runtime_error("fuzz: cannot write " + path.string());
    return path;
}

std::filesystem::path emptyFolder() { return processFolder() / "empty"; }

}  // namespace veduta::fuzz
