#include "io/ply_writer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/progress.h"
#include "io/export_georeference.h"
#include "io/export_images.h"
#include "io/export_mesh_parts.h"
#include "io/export_text.h"
#include "io/output_files.h"

namespace veduta {

namespace {

static_assert(std::endian::native == std::endian::little, "PLY is written as the machine holds it");

constexpr size_t kPieceBytes = size_t(4) << 20;

template <typename T>
void append(std::string &out, const T &value) {
    out.append(reinterpret_cast<const char *>(&value), sizeof(T));
}

std::array<uint8_t, 3> srgb8(const Vec3f &linear) {
    auto channel = [](float v) { return uint8_t(std::lround(255 * std::clamp(linearToSrgb(v), 0.0f, 1.0f))); };
    return {channel(linear.x), channel(linear.y), channel(linear.z)};
}

struct PlyCounts {
    size_t vertices = 0, faces = 0;
    bool uvs = false;
};

void count(const std::vector<MeshPart> &parts, PlyCounts &counts) {
    for (const MeshPart &part : parts) {
        counts.vertices += part.positions.size();
        counts.faces += part.indices.size() / 3;
        counts.uvs = counts.uvs || !part.uvs.empty();
    }
}

// The whole file but its header, vertices before faces: the meshes are walked twice, since
// the faces of a million copies would not fit in memory beside their vertices.
class PlyBody {
  public:
    PlyBody(bool uvs, std::vector<std::array<uint8_t, 3>> colours, const ExportSink &sink) :
        uvs_(uvs), colours_(std::move(colours)), sink_(sink) {}

    void vertices(const std::vector<MeshPart> &parts) {
        for (const MeshPart &part : parts) {
            for (size_t v = 0; v < part.positions.size(); ++v) {
                append(bytes_, part.positions[v]);
                append(bytes_, part.normals[v]);
                if (uvs_) append(bytes_, part.uvs.empty() ? Vec2f{0, 0} : part.uvs[v]);
                append(bytes_, colours_[part.material]);
            }
        }
        flushIfFull();
    }

    void faces(const std::vector<MeshPart> &parts) {
        for (const MeshPart &part : parts) {
            for (size_t i = 0; i < part.indices.size(); i += 3) {
                append(bytes_, uint8_t(3));
                for (size_t k = i; k < i + 3; ++k) append(bytes_, uint32_t(first_ + part.indices[k]));
                append(bytes_, uint32_t(part.material));
            }
            first_ += part.positions.size();
        }
        flushIfFull();
    }

    void flush() {
        sink_(bytes_);
        bytes_.clear();
    }

  private:
    void flushIfFull() {
        if (bytes_.size() >= kPieceBytes) flush();
    }

    bool uvs_;
    std::vector<std::array<uint8_t, 3>> colours_;
    const ExportSink &sink_;
    std::string bytes_;
    size_t first_ = 0;
};

// Calls `use` with the parts of every mesh the scene draws: baked meshes as they are, instances
// as copies in world space (`placed`) or, where only their sizes and indices count, as their
// prototype's parts.
template <typename Use>
void forEachMesh(const RenderScene &scene, InstanceCopies &copies, bool placed, Use use) {
    for (const BakedMesh &baked : scene.meshes) use(meshParts(baked.mesh, scene.materials, {}));
    for (const Instance &instance : scene.instances) use(placed ? copies.placed(instance) : copies.local(instance));
}

std::string header(const RenderScene &scene, const PlyCounts &counts) {
    TextBuffer out;
    put(out, "ply\nformat binary_little_endian 1.0\ncomment veduta export: Z up, metres\n");
    for (size_t i = 0; i < scene.materials.size(); ++i)
        put(out, "comment material {} {}\n", i, scene.materials[i].name);
    put(out, "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n", counts.vertices);
    put(out, "property float nx\nproperty float ny\nproperty float nz\n");
    if (counts.uvs) put(out, "property float s\nproperty float t\n");
    put(out, "property uchar red\nproperty uchar green\nproperty uchar blue\n");
    put(out, "element face {}\nproperty list uchar uint vertex_indices\nproperty uint material_index\nend_header\n",
        counts.faces);
    return fmt::to_string(out);
}

}  // namespace

ExportResult writePly(const RenderScene &scene, const std::filesystem::path &out, const ExportOptions &options,
                      Progress &progress) {
    ExportResult result;
    ExportImages images(scene, options.textureFiles, false, result.stats.notes);
    std::vector<std::array<uint8_t, 3>> colours;
    for (const Material &m : scene.materials) colours.push_back(srgb8(m.glass ? m.glassTint : images.diffuseColor(m)));
    result.files.push_back({out, {}, [&scene, &progress, colours](const ExportSink &sink) {
                                InstanceCopies copies(scene);
                                PlyCounts counts;
                                forEachMesh(scene, copies, false, [&](const auto &parts) { count(parts, counts); });
                                sink(header(scene, counts));
                                PlyBody body(counts.uvs, colours, sink);
                                forEachMesh(scene, copies, true, [&](const auto &parts) {
                                    body.vertices(parts);
                                    progress.advance();
                                });
                                forEachMesh(scene, copies, false, [&](const auto &parts) { body.faces(parts); });
                                body.flush();
                            }});
    for (ExportFile &file : georeferenceSidecars(options.georeference, out, FileAxes::ZUp))
        result.files.push_back(std::move(file));
    result.stats.meshes = scene.meshes.size() + scene.instances.size();
    return result;
}

}  // namespace veduta
