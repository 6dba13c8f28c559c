// The public sample data in ../shared/data (see its MANIFEST.md), which sits beside a
// developer's checkout but not beside a clean clone: tests that read it skip without it.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "test_paths.h"

namespace veduta::test {

// ../shared/data/<relative> beside the source tree, or nullopt when it is not there.
inline std::optional<std::filesystem::path> sharedDataFile(std::string_view relative) {
    std::filesystem::path file = sourceDir() / "../shared/data" / relative;
    if (!std::filesystem::exists(file)) return std::nullopt;
    return file;
}

}  // namespace veduta::test
