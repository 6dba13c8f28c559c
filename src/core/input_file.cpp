#include "core/input_file.h"

#include <fstream>

#include <fmt/format.h>

#include "core/error.h"

namespace veduta {

namespace {

std::string bytesText(uint64_t bytes) {
    if (bytes < (uint64_t(1) << 20)) return fmt::format("{} bytes", bytes);
    if (bytes < (uint64_t(1) << 30)) return fmt::format("{:.1f} MiB", double(bytes) / double(1 << 20));
    return fmt::format("{:.1f} GiB", double(bytes) / double(1 << 30));
}

}  // namespace

void checkInputFile(const std::filesystem::path &file) {
    FileLoc loc{file.string(), 0, 0};
    std::error_code error;
    std::filesystem::file_status status = std::filesystem::status(file, error);
    if (!std::filesystem::exists(status)) throw InputError(loc, "cannot open file");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(loc, "is not a regular file (a directory or a device); veduta reads only files");
}

std::string readInputFile(const std::filesystem::path &file, uint64_t limit) {
    checkInputFile(file);
    FileLoc loc{file.string(), 0, 0};
    std::error_code error;
    uint64_t size = std::filesystem::file_size(file, error);
    if (error) throw InputError(loc, fmt::format("cannot read file ({})", error.message()));
    if (size > limit)
        throw InputError(
            loc, fmt::format("is {}; veduta reads files of this kind up to {}", bytesText(size), bytesText(limit)));
    std::ifstream in(file, std::ios::binary);
    std::string text(size, '\0');
    if (!in || !in.read(text.data(), std::streamsize(size))) throw InputError(loc, "cannot read file");
    return text;
}

}  // namespace veduta
