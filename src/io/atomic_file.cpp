#include "io/atomic_file.h"

#include <stdexcept>

#include <fmt/format.h>
#include <unistd.h>

namespace veduta {

void writeFileAtomically(const std::filesystem::path &file,
                         const std::function<void(const std::filesystem::path &temporary)> &write) {
    if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path());
    std::filesystem::path temporary =
        file.parent_path() / fmt::format(".{}.tmp{}{}", file.stem().string(), getpid(), file.extension().string());
    try {
        write(temporary);
        std::filesystem::rename(temporary, file);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

}  // namespace veduta
