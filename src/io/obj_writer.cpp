#include "io/obj_writer.h"

#include <string>
#include <utility>

#include <fmt/format.h>

#include "core/progress.h"
#include "io/export_georeference.h"
#include "io/export_images.h"
#include "io/export_materials.h"
#include "io/export_mesh_parts.h"
#include "io/export_text.h"
#include "scene/object_names.h"

namespace veduta {

namespace {

using Text = TextBuffer;

// Text is handed on in pieces of about this size.
constexpr size_t kPieceBytes = size_t(4) << 20;

// The geometry text, handed to the sink piece by piece: vertex numbers run on over the whole
// file, from 1.
class ObjText {
  public:
    ObjText(const RenderScene &scene, const ExportSink &sink) : scene_(scene), sink_(sink) {}

    void addObject(const std::string &name, const std::vector<MeshPart> &parts) {
        put(text_, "o {}\n", name);
        for (const MeshPart &part : parts) addPart(part);
        if (text_.size() >= kPieceBytes) flush();
    }

    Text &text() { return text_; }

    void flush() {
        sink_(std::string_view(text_.data(), text_.size()));
        text_.clear();
    }

  private:
    // Positions and normals share their numbers; texture coordinates, which not every part has,
    // are numbered on their own.
    void addPart(const MeshPart &part) {
        for (const Vec3f &p : part.positions) put(text_, "v {} {} {}\n", p.x, p.y, p.z);
        for (const Vec2f &t : part.uvs) put(text_, "vt {} {}\n", t.x, t.y);
        for (const Vec3f &n : part.normals) put(text_, "vn {} {} {}\n", n.x, n.y, n.z);
        put(text_, "usemtl {}\n", scene_.materials[part.material].name);
        bool uvs = !part.uvs.empty();
        for (size_t i = 0; i < part.indices.size(); i += 3) {
            put(text_, "f");
            for (size_t k = i; k < i + 3; ++k) {
                size_t v = first_ + part.indices[k];
                if (uvs) {
                    put(text_, " {}/{}/{}", v, firstUv_ + part.indices[k], v);
                } else {
                    put(text_, " {}//{}", v, v);
                }
            }
            put(text_, "\n");
        }
        first_ += part.positions.size();
        firstUv_ += part.uvs.size();
    }

    const RenderScene &scene_;
    const ExportSink &sink_;
    Text text_;
    size_t first_ = 1, firstUv_ = 1;
};

void mapLine(Text &out, const char *keyword, ExportImages &images, const Material &m, MapKind kind,
             const std::string &options = {}) {
    if (auto image = images.image(m, kind)) put(out, "{} {}{}\n", keyword, options, images.images()[*image].fileName);
}

// MTL's Phong model with the PBR extension (Pr roughness, Pm metallic) that Blender's importer
// reads; glass as a transmission filter (Tf), an index (Ni) and, for viewers that know only
// dissolve, an opacity (d) equal to what the pane reflects.
std::string mtlText(const RenderScene &scene, ExportImages &images) {
    Text out;
    put(out, "# veduta export\n");
    for (const Material &m : scene.materials) {
        Vec3f diffuse = m.glass ? m.glassTint : images.diffuseColor(m);
        Vec3f specular = m.glass ? Vec3f(1) : m.specular;
        put(out, "\nnewmtl {}\nKd {} {} {}\nKs {} {} {}\nNs {}\nPr {}\nPm 0\n", m.name, diffuse.x, diffuse.y, diffuse.z,
            specular.x, specular.y, specular.z, m.shininess, roughnessFromPhong(m));
        if (m.glass) {
            put(out, "Tf {} {} {}\nNi {}\nd {}\nillum 7\n", m.glassTint.x, m.glassTint.y, m.glassTint.z, m.ior,
                normalReflectance(m.ior));
            continue;
        }
        put(out, "illum 2\n");
        mapLine(out, "map_Kd", images, m, MapKind::Diffuse);
        mapLine(out, "map_Ks", images, m, MapKind::Specular);
        mapLine(out, "map_Bump", images, m, MapKind::Normal, fmt::format("-bm {} ", m.normalStrength));
        mapLine(out, "map_refl", images, m, MapKind::Reflection);
        mapLine(out, "map_d", images, m, MapKind::Opacity);
    }
    return fmt::to_string(out);
}

void streamObj(const RenderScene &scene, const std::string &mtl, Progress &progress, const ExportSink &sink) {
    ObjText obj(scene, sink);
    put(obj.text(), "# veduta export: Z up, metres\nmtllib {}\n", mtl);
    for (const BakedMesh &baked : scene.meshes) {
        obj.addObject(objectName(baked.objectId, baked.buildingId), meshParts(baked.mesh, scene.materials, {}));
        progress.advance();
    }
    InstanceCopies copies(scene);
    for (const Instance &instance : scene.instances) {
        obj.addObject(objectName(instance.objectId, instance.buildingId), copies.placed(instance));
        progress.advance();
    }
    obj.flush();
}

}  // namespace

ExportResult writeObj(const RenderScene &scene, const std::filesystem::path &out, const ExportOptions &options,
                      Progress &progress) {
    ExportResult result;
    std::filesystem::path mtl = out;
    mtl.replace_extension(".mtl");
    ExportImages images(scene, options.textureFiles, false, result.stats.notes);
    std::string materials = mtlText(scene, images);
    result.files.push_back({out, {}, [&scene, &progress, name = mtl.filename().string()](const ExportSink &sink) {
                                streamObj(scene, name, progress, sink);
                            }});
    result.files.push_back({mtl, std::move(materials), {}});
    for (const ExportedImage &image : images.images())
        result.files.push_back({out.parent_path() / image.fileName, imageBytes(image), {}});
    for (ExportFile &file : georeferenceSidecars(options.georeference, out, FileAxes::ZUp))
        result.files.push_back(std::move(file));
    result.stats.meshes = scene.meshes.size() + scene.instances.size();
    result.stats.textures = images.images().size();
    return result;
}

}  // namespace veduta
