// Writing a file so that it appears whole or not at all: the content goes to a temporary
// beside the target, which is renamed over the target only when complete. A failed or
// interrupted run never leaves a damaged file or destroys an older good one.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <vector>

namespace veduta {

// Calls `write` with the temporary's path (same folder, same extension), then renames it to
// `file`. Removes the temporary and rethrows if `write` throws or the rename fails.
void writeFileAtomically(const std::filesystem::path &file,
                         const std::function<void(const std::filesystem::path &temporary)> &write);

// Writes bytes already in memory to `path` and flushes them to the disk, checking every write,
// the flush and the close: a full disk shows as an error here, not as a short file later.
// Errors name `file`, the target the user knows, rather than a temporary.
void writeWholeFile(const std::filesystem::path &path, const void *data, size_t size,
                    const std::filesystem::path &file);
// The same for a file made of pieces, written one after the other without copying them together.
void writeWholeFile(const std::filesystem::path &path, const std::vector<std::span<const std::byte>> &pieces,
                    const std::filesystem::path &file);

// writeFileAtomically for bytes already in memory.
void writeBytesAtomically(const std::filesystem::path &file, const void *data, size_t size);
void writeBytesAtomically(const std::filesystem::path &file, const std::vector<std::span<const std::byte>> &pieces);

}  // namespace veduta
