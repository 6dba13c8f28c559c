#include "io/scene_export.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/file_extension.h"
#include "core/progress.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"

namespace veduta {

namespace {

ExportResult encode(const RenderScene &scene, const std::filesystem::path &out, ExportFormat format,
                    const ExportOptions &options, Progress &progress) {
    switch (format) {
    case ExportFormat::Obj: return writeObj(scene, out, options, progress);
    case ExportFormat::Gltf: return writeGltf(scene, out, false, options, progress);
    case ExportFormat::Glb: return writeGltf(scene, out, true, options, progress);
    case ExportFormat::Ply: return writePly(scene, out, options, progress);
    }
    throw std::invalid_argument("unknown export format");
}

// A folder or a device where a file goes would be removed, not replaced, if the set failed.
void checkNothingInTheWay(const std::vector<ExportFile> &files) {
    for (const ExportFile &file : files) {
        std::error_code error;
        auto status = std::filesystem::symlink_status(file.path, error);
        if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
            throw std::runtime_error(
                fmt::format("{}: cannot write it: something other than a file is there", file.path.string()));
    }
}

// A streamed file, each piece written as it comes; flushed to the disk before it is renamed.
void writeStreamed(const ExportFile &file) {
    writeFileAtomically(file.path, [&](const std::filesystem::path &temporary) {
        auto fail = [&] { return std::runtime_error(fmt::format("{}: {}", file.path.string(), std::strerror(errno))); };
        std::ofstream out(temporary, std::ios::binary);
        if (!out) throw fail();
        file.stream([&](std::string_view piece) {
            if (!out.write(piece.data(), std::streamsize(piece.size()))) throw fail();
        });
        out.close();
        if (!out) throw fail();
        int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
        bool synced = fd >= 0 && ::fsync(fd) == 0;
        if (fd >= 0) ::close(fd);
        if (!synced) throw fail();
    });
}

// The side files first, the main file (the first) last.
void writeAll(const std::vector<ExportFile> &files) {
    checkNothingInTheWay(files);
    std::vector<std::filesystem::path> paths;
    for (const ExportFile &file : files) paths.push_back(file.path);
    OutputSet set(paths);
    for (size_t i = files.size(); i-- > 0;) {
        const ExportFile &file = files[i];
        if (file.stream) {
            writeStreamed(file);
        } else {
            writeBytesAtomically(file.path, file.bytes.data(), file.bytes.size());
        }
    }
    set.commit();
}

}  // namespace

std::optional<ExportFormat> exportFormatForPath(const std::filesystem::path &path) {
    std::string extension = lowercaseExtension(path);
    if (extension == ".obj") return ExportFormat::Obj;
    if (extension == ".gltf") return ExportFormat::Gltf;
    if (extension == ".glb") return ExportFormat::Glb;
    if (extension == ".ply") return ExportFormat::Ply;
    return std::nullopt;
}

ExportStats exportScene(const RenderScene &scene, const std::filesystem::path &out, ExportFormat format,
                        const ExportOptions &options) {
    if (scene.materials.empty()) throw std::invalid_argument("a scene to export needs at least one material");
    Progress progress("export", scene.meshes.size() + scene.instances.size(), "meshes", options.progress);
    ExportResult result = encode(scene, out, format, options, progress);
    writeAll(result.files);
    progress.finish();
    result.stats.instances = scene.instances.size();
    result.stats.triangles = scene.effectiveTriangleCount();
    result.stats.files = result.files.size();
    return result.stats;
}

}  // namespace veduta
