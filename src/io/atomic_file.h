// Writing a file so that it appears whole or not at all: the content goes to a temporary
// beside the target, which is renamed over the target only when complete. A failed or
// interrupted run never leaves a damaged file or destroys an older good one.
#pragma once

#include <filesystem>
#include <functional>

namespace veduta {

// Calls `write` with the temporary's path (same folder, same extension), then renames it to
// `file`. Removes the temporary and rethrows if `write` throws or the rename fails.
void writeFileAtomically(const std::filesystem::path &file,
                         const std::function<void(const std::filesystem::path &temporary)> &write);

}  // namespace veduta
