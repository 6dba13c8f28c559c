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

// Files that one command writes together (an EXR and its PNG, six cube faces): all of them
// change, or none. Each is still written atomically by its own writer; an OutputSet made
// before the first keeps a link to every older file, and unless commit() is called, its
// destructor puts the older files back and removes the new ones, so a failure part-way
// through leaves the folder as it was.
class OutputSet {
  public:
    // Empty paths, outputs not asked for, are passed over.
    explicit OutputSet(std::vector<std::filesystem::path> files);
    ~OutputSet();
    OutputSet(const OutputSet &) = delete;
    OutputSet &operator=(const OutputSet &) = delete;

    // Every file is written: the older ones go.
    void commit();

  private:
    struct Entry {
        std::filesystem::path file, backup;  // backup empty: there was no older file
    };
    // The backup as a copy, where the file system has no hard links; a failure removes every
    // backup made so far before it is rethrown.
    void copyBackup(const Entry &entry);

    std::vector<Entry> entries_;
    bool committed_ = false;
};

}  // namespace veduta
