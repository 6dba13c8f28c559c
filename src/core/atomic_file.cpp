#include "core/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace veduta {

namespace {

// A hidden file beside `file` for this process, with its extension: ".name.tmp1234.exr".
std::filesystem::path siblingName(const std::filesystem::path &file, const char *kind) {
    return file.parent_path() /
        fmt::format(".{}.{}{}{}", file.stem().string(), kind, getpid(), file.extension().string());
}

}  // namespace

void writeFileAtomically(const std::filesystem::path &file,
                         const std::function<void(const std::filesystem::path &temporary)> &write) {
    if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path());
    std::filesystem::path temporary = siblingName(file, "tmp");
    try {
        write(temporary);
        std::filesystem::rename(temporary, file);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void writeWholeFile(const std::filesystem::path &path, const void *data, size_t size,
                    const std::filesystem::path &file) {
    writeWholeFile(path, {std::span(static_cast<const std::byte *>(data), size)}, file);
}

void writeWholeFile(const std::filesystem::path &path, const std::vector<std::span<const std::byte>> &pieces,
                    const std::filesystem::path &file) {
    auto fail = [&](int error) {
        return std::runtime_error(fmt::format("{}: {}", file.string(), std::strerror(error)));
    };
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw fail(errno);
    for (std::span<const std::byte> piece : pieces) {
        const std::byte *bytes = piece.data();
        size_t size = piece.size();
        while (size > 0) {
            ssize_t written = ::write(fd, bytes, size);
            if (written < 0 && errno == EINTR) continue;
            if (written <= 0) {
                int error = written < 0 ? errno : ENOSPC;
                ::close(fd);
                throw fail(error);
            }
            bytes += written;
            size -= size_t(written);
        }
    }
    // The rename that follows must not publish a file whose blocks never reached the disk.
    if (::fsync(fd) != 0) {
        int error = errno;
        ::close(fd);
        throw fail(error);
    }
    if (::close(fd) != 0) throw fail(errno);
}

void writeBytesAtomically(const std::filesystem::path &file, const void *data, size_t size) {
    writeBytesAtomically(file, {std::span(static_cast<const std::byte *>(data), size)});
}

void writeBytesAtomically(const std::filesystem::path &file, const std::vector<std::span<const std::byte>> &pieces) {
    writeFileAtomically(file, [&](const std::filesystem::path &temporary) { writeWholeFile(temporary, pieces, file); });
}

OutputSet::OutputSet(std::vector<std::filesystem::path> files) {
    for (std::filesystem::path &file : files) {
        if (file.empty()) continue;  // an output not asked for
        Entry entry{std::move(file), {}};
        std::error_code error;
        if (std::filesystem::is_regular_file(entry.file, error)) {
            // A hard link costs no copy; a file system without links gets a copy.
            entry.backup = siblingName(entry.file, "old");
            std::filesystem::create_hard_link(entry.file, entry.backup, error);
            if (error) copyBackup(entry);
        }
        entries_.push_back(std::move(entry));
    }
}

void OutputSet::copyBackup(const Entry &entry) {
    try {
        std::filesystem::copy_file(entry.file, entry.backup, std::filesystem::copy_options::overwrite_existing);
    } catch (...) {
        // No destructor runs for a set whose constructor throws: its backups go here.
        std::error_code ignored;
        std::filesystem::remove(entry.backup, ignored);
        for (const Entry &made : entries_)
            if (!made.backup.empty()) std::filesystem::remove(made.backup, ignored);
        throw;
    }
}

OutputSet::~OutputSet() {
    std::error_code ignored;
    for (const Entry &entry : entries_) {
        if (committed_) {
            if (!entry.backup.empty()) std::filesystem::remove(entry.backup, ignored);
        } else if (entry.backup.empty()) {
            std::filesystem::remove(entry.file, ignored);
        } else if (std::filesystem::equivalent(entry.backup, entry.file, ignored)) {
            // Never replaced. rename() of one hard link over another of the same file does
            // nothing and leaves both names.
            std::filesystem::remove(entry.backup, ignored);
        } else {
            std::filesystem::rename(entry.backup, entry.file, ignored);
        }
    }
}

void OutputSet::commit() { committed_ = true; }

}  // namespace veduta
