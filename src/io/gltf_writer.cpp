#include "io/gltf_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/axes.h"
#include "core/progress.h"
#include "io/export_georeference.h"
#include "io/export_images.h"
#include "io/export_json.h"
#include "io/export_materials.h"
#include "io/export_mesh_parts.h"
#include "io/export_text.h"
#include "scene/object_names.h"

namespace veduta {

namespace {

static_assert(sizeof(Vec3f) == 12 && sizeof(Vec2f) == 8, "attributes are copied as they lie in memory");

// The buffer views of vertex data and indices, one per kind, in this order in the buffer.
enum ViewKind { kPositions, kNormals, kUvs, kTangents, kIndices16, kIndices32, kViewKinds };
constexpr std::array<int, kViewKinds> kStride{12, 12, 8, 16, 0, 0};
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
// Indices fit 16 bits below this many vertices (65535 is the primitive restart value).
constexpr size_t kShortIndexVertices = 65535;
constexpr double kLumensPerWatt = 683;  // the photometric conversion glTF's lux and Blender's importer use
constexpr float kCameraNear = 0.1f;     // m; glTF cameras need one
constexpr float kOrthographicFar = 1e5f;

using Json = TextBuffer;

template <typename T>
void appendBytes(std::string &out, const std::vector<T> &values) {
    out.append(reinterpret_cast<const char *>(values.data()), values.size() * sizeof(T));
}

void padTo4(std::string &bytes, char pad) { bytes.append((4 - bytes.size() % 4) % 4, pad); }

// A float as the double it is, so that POSITION's min and max equal the data exactly.
std::string exact(float v) { return jsonNumber(double(v)); }

// A 3×4 affine transform as glTF's column-major 4×4 matrix.
std::string matrixJson(const Transform &t) {
    const auto &m = t.m;
    return fmt::format("[{},{},{},0,{},{},{},0,{},{},{},0,{},{},{},1]", m[0], m[4], m[8], m[1], m[5], m[9], m[2], m[6],
                       m[10], m[3], m[7], m[11]);
}

// A transform whose x, y and z axes are the columns given, placed at `origin`.
Transform fromAxes(const Vec3f &x, const Vec3f &y, const Vec3f &z, const Vec3f &origin) {
    return {{x.x, y.x, z.x, origin.x, x.y, y.y, z.y, origin.y, x.z, y.z, z.z, origin.z}};
}

struct Accessor {
    ViewKind view;
    size_t offset = 0;
    int componentType = kFloat;
    size_t count = 0;
    const char *type = "VEC3";
    std::string bounds;  // "min" and "max" members, POSITION only
};

// The document under construction: buffers, accessors, meshes and nodes as JSON text.
class GltfDocument {
  public:
    GltfDocument(const RenderScene &scene, ExportImages &images) : scene_(scene), images_(images) {}

    // A mesh of the parts that have triangles; none when no part has.
    std::optional<size_t> addMesh(const std::string &name, const std::vector<MeshPart> &parts) {
        Json primitives;
        for (const MeshPart &part : parts) {
            if (part.indices.empty()) continue;
            if (primitives.size()) put(primitives, ",");
            addPrimitive(primitives, part);
        }
        if (!primitives.size()) return std::nullopt;
        if (meshCount_++) put(meshes_, ",");
        put(meshes_, "{{\"name\":{},\"primitives\":[{}]}}", jsonString(name), fmt::to_string(primitives));
        return meshCount_ - 1;
    }

    // A node; `members` are its JSON members after the name.
    void addNode(const std::string &name, const std::string &members) {
        if (nodeCount_++) put(nodes_, ",");
        put(nodes_, "{{\"name\":{}{}}}", jsonString(name), members);
    }

    void addCamera(const Camera &camera) {
        Vec2f half = camera.halfExtent();
        if (camera.projection == Projection::Perspective) {
            cameras_ = fmt::format(
                "[{{\"name\":\"camera\",\"type\":\"perspective\",\"perspective\":{{\"aspectRatio\":{},\"yfov\":{},"
                "\"znear\":{}}}}}]",
                float(camera.width) / float(camera.height), 2 * std::atan(half.y), kCameraNear);
        } else {
            cameras_ = fmt::format(
                "[{{\"name\":\"camera\",\"type\":\"orthographic\",\"orthographic\":{{\"xmag\":{},\"ymag\":{},"
                "\"znear\":0,\"zfar\":{}}}}}]",
                half.x, half.y, kOrthographicFar);
        }
        // glTF cameras look down their −Z with +Y up.
        CameraAxes axes = camera.axes();
        Transform placed =
            fromAxes(zUpToYUp(axes.right), zUpToYUp(axes.up), zUpToYUp(-axes.forward), zUpToYUp(camera.position));
        addNode("camera", fmt::format(",\"camera\":0,\"matrix\":{}", matrixJson(placed)));
    }

    // The sun as a directional light (which shines down its node's −Z), in lux: veduta's
    // irradiance in W/m² times 683 lm/W, the brightest channel as intensity, the channels over
    // it as colour.
    void addSun(const Sun &sun) {
        if (!sun.enabled()) return;
        float strongest = maxComponent(sun.irradiance);
        Vec3f colour = sun.irradiance / strongest;
        lights_ = fmt::format("[{{\"name\":\"sun\",\"type\":\"directional\",\"color\":{},\"intensity\":{}}}]",
                              jsonArray(colour), jsonNumber(strongest * kLumensPerWatt));
        Vec3f z = normalize(zUpToYUp(sun.direction));
        Vec3f helper = std::abs(z.y) < 0.9f ? Vec3f{0, 1, 0} : Vec3f{1, 0, 0};
        Vec3f x = normalize(cross(helper, z));
        Vec3f y = cross(z, x);
        addNode("sun",
                fmt::format(",\"extensions\":{{\"KHR_lights_punctual\":{{\"light\":0}}}},\"matrix\":{}",
                            matrixJson(fromAxes(x, y, z, Vec3f{0, 0, 0}))));
    }

    // The whole document: JSON and the binary buffer (without images for .gltf, which refers to
    // them by name; with them for .glb). `bin` is the .bin's name, empty for .glb.
    std::pair<std::string, std::string> finish(const std::string &bin, const std::string &extras) {
        std::string materials = materialsJson();  // registers the images
        std::string buffer;
        std::array<std::optional<size_t>, kViewKinds> viewIndex;
        Json views;
        size_t viewCount = 0;
        auto addView = [&](const std::string &bytes, int stride, int target) {
            padTo4(buffer, '\0');
            if (viewCount++) put(views, ",");
            put(views, "{{\"buffer\":0,\"byteOffset\":{},\"byteLength\":{}", buffer.size(), bytes.size());
            if (stride) put(views, ",\"byteStride\":{}", stride);
            if (target) put(views, ",\"target\":{}", target);
            put(views, "}}");
            buffer += bytes;
            return viewCount - 1;
        };
        for (int kind = 0; kind < kViewKinds; ++kind) {
            if (views_[kind].empty()) continue;
            viewIndex[kind] =
                addView(views_[kind], kStride[kind], kind >= kIndices16 ? kElementArrayBuffer : kArrayBuffer);
        }
        Json imagesJson;
        for (const ExportedImage &image : images_.images()) {
            if (imagesJson.size()) put(imagesJson, ",");
            if (bin.empty()) {
                size_t view = addView(imageBytes(image), 0, 0);
                put(imagesJson, "{{\"bufferView\":{},\"mimeType\":\"{}\"}}", view, image.mimeType);
            } else {
                put(imagesJson, "{{\"uri\":{}}}", jsonString(uriEscaped(image.fileName)));
            }
        }
        padTo4(buffer, '\0');

        Json doc;
        put(doc, "{{\"asset\":{{\"version\":\"2.0\",\"generator\":\"veduta\",\"extras\":{{\"veduta\":{}}}}}", extras);
        std::string used = extensionsUsed();
        if (!used.empty()) put(doc, ",\"extensionsUsed\":[{}]", used);
        put(doc, ",\"scene\":0,\"scenes\":[{{\"name\":\"veduta_scene\",\"extras\":{{\"veduta\":{}}},\"nodes\":[",
            extras);
        for (size_t i = 0; i < nodeCount_; ++i) put(doc, "{}{}", i ? "," : "", i);
        put(doc, "]}}],\"nodes\":[{}]", fmt::to_string(nodes_));
        if (meshCount_) put(doc, ",\"meshes\":[{}]", fmt::to_string(meshes_));
        put(doc, ",\"materials\":[{}]", materials);
        if (imagesJson.size()) {
            put(doc,
                ",\"images\":[{}],\"samplers\":[{{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,"
                "\"wrapT\":10497}}],\"textures\":[",
                fmt::to_string(imagesJson));
            for (size_t i = 0; i < images_.images().size(); ++i)
                put(doc, "{}{{\"sampler\":0,\"source\":{}}}", i ? "," : "", i);
            put(doc, "]");
        }
        if (!cameras_.empty()) put(doc, ",\"cameras\":{}", cameras_);
        if (!lights_.empty()) put(doc, ",\"extensions\":{{\"KHR_lights_punctual\":{{\"lights\":{}}}}}", lights_);
        if (!accessors_.empty()) {
            put(doc, ",\"accessors\":[");
            for (size_t i = 0; i < accessors_.size(); ++i) {
                const Accessor &a = accessors_[i];
                put(doc,
                    "{}{{\"bufferView\":{},\"byteOffset\":{},\"componentType\":{},\"count\":{},\"type\":\"{}\"{}}}",
                    i ? "," : "", *viewIndex[a.view], a.offset, a.componentType, a.count, a.type, a.bounds);
            }
            put(doc, "]");
        }
        if (viewCount) {
            put(doc, ",\"bufferViews\":[{}],\"buffers\":[{{\"byteLength\":{}", fmt::to_string(views), buffer.size());
            if (!bin.empty()) put(doc, ",\"uri\":{}", jsonString(uriEscaped(bin)));
            put(doc, "}}]");
        }
        put(doc, "}}");
        return {fmt::to_string(doc), std::move(buffer)};
    }

  private:
    size_t addAccessor(ViewKind view, int componentType, size_t count, const char *type, std::string bounds = {}) {
        accessors_.push_back({view, views_[view].size(), componentType, count, type, std::move(bounds)});
        return accessors_.size() - 1;
    }

    template <typename T>
    size_t addAttribute(ViewKind view, const std::vector<T> &values, const char *type, std::string bounds = {}) {
        size_t accessor = addAccessor(view, kFloat, values.size(), type, std::move(bounds));
        appendBytes(views_[view], values);
        return accessor;
    }

    size_t addIndices(const std::vector<uint32_t> &indices, size_t vertices) {
        if (vertices < kShortIndexVertices) {
            std::vector<uint16_t> shorts(indices.begin(), indices.end());
            size_t accessor = addAccessor(kIndices16, kUnsignedShort, indices.size(), "SCALAR");
            appendBytes(views_[kIndices16], shorts);
            return accessor;
        }
        size_t accessor = addAccessor(kIndices32, kUnsignedInt, indices.size(), "SCALAR");
        appendBytes(views_[kIndices32], indices);
        return accessor;
    }

    static std::string positionBounds(const std::vector<Vec3f> &positions) {
        Vec3f low = positions.front(), high = positions.front();
        for (const Vec3f &p : positions) {
            low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
        }
        return fmt::format(",\"min\":[{},{},{}],\"max\":[{},{},{}]", exact(low.x), exact(low.y), exact(low.z),
                           exact(high.x), exact(high.y), exact(high.z));
    }

    void addPrimitive(Json &out, const MeshPart &part) {
        put(out, "{{\"attributes\":{{\"POSITION\":{}",
            addAttribute(kPositions, part.positions, "VEC3", positionBounds(part.positions)));
        put(out, ",\"NORMAL\":{}", addAttribute(kNormals, part.normals, "VEC3"));
        if (!part.uvs.empty()) put(out, ",\"TEXCOORD_0\":{}", addAttribute(kUvs, part.uvs, "VEC2"));
        if (!part.tangents.empty()) put(out, ",\"TANGENT\":{}", addAttribute(kTangents, part.tangents, "VEC4"));
        put(out, "}},\"indices\":{},\"material\":{},\"mode\":4}}", addIndices(part.indices, part.positions.size()),
            part.material);
    }

    std::string materialsJson() {
        Json out;
        for (const Material &m : scene_.materials) {
            if (out.size()) put(out, ",");
            materialJson(out, m);
            glass_ = glass_ || m.glass;
        }
        return fmt::to_string(out);
    }

    void materialJson(Json &out, const Material &m) {
        Vec3f base = m.glass ? m.glassTint : images_.diffuseColor(m);
        base = {std::clamp(base.x, 0.0f, 1.0f), std::clamp(base.y, 0.0f, 1.0f), std::clamp(base.z, 0.0f, 1.0f)};
        put(out,
            "{{\"name\":{},\"doubleSided\":true,\"pbrMetallicRoughness\":{{\"baseColorFactor\":[{},{},{},1],"
            "\"metallicFactor\":0,\"roughnessFactor\":{}",
            jsonString(m.name), base.x, base.y, base.z, roughnessFromPhong(m));
        if (m.glass) {
            put(out,
                "}},\"extensions\":{{\"KHR_materials_transmission\":{{\"transmissionFactor\":1}},"
                "\"KHR_materials_ior\":{{\"ior\":{}}}}}}}",
                std::max(m.ior, 1.0f));
            return;
        }
        if (auto image = images_.image(m, MapKind::Diffuse)) put(out, ",\"baseColorTexture\":{{\"index\":{}}}", *image);
        put(out, "}}");
        if (auto image = images_.image(m, MapKind::Normal))
            put(out, ",\"normalTexture\":{{\"index\":{},\"scale\":{}}}", *image, m.normalStrength);
        for (MapKind kind : {MapKind::Specular, MapKind::Reflection, MapKind::Opacity}) images_.image(m, kind, false);
        put(out, "}}");
    }

    std::string extensionsUsed() const {
        std::string out;
        if (glass_) out += "\"KHR_materials_transmission\",\"KHR_materials_ior\"";
        if (!lights_.empty()) out += std::string(out.empty() ? "" : ",") + "\"KHR_lights_punctual\"";
        return out;
    }

    // A file name as a URI reference: what is not unreserved is percent-encoded.
    static std::string uriEscaped(const std::string &name) {
        std::string out;
        for (unsigned char c : name) {
            if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
                out += char(c);
            } else {
                out += fmt::format("%{:02X}", c);
            }
        }
        return out;
    }

    const RenderScene &scene_;
    ExportImages &images_;
    std::array<std::string, kViewKinds> views_;
    std::vector<Accessor> accessors_;
    Json meshes_, nodes_;
    size_t meshCount_ = 0, nodeCount_ = 0;
    std::string cameras_, lights_;
    bool glass_ = false;
};

// GLB: a 12-byte header, the JSON chunk padded with spaces, the binary chunk with zeros.
std::string glbBytes(std::string json, const std::string &bin) {
    padTo4(json, ' ');
    auto word = [](std::string &out, uint32_t value) { out.append(reinterpret_cast<const char *>(&value), 4); };
    std::string out;
    size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
    word(out, 0x46546C67);  // "glTF"
    word(out, 2);
    word(out, uint32_t(total));
    word(out, uint32_t(json.size()));
    word(out, 0x4E4F534A);  // "JSON"
    out += json;
    if (!bin.empty()) {
        word(out, uint32_t(bin.size()));
        word(out, 0x004E4942);  // "BIN"
        out += bin;
    }
    return out;
}

std::string prototypeName(const RenderScene &scene, const Instance &instance) {
    if (instance.materialOverride == kNoMaterial) return fmt::format("prototype_{}", instance.prototype);
    return fmt::format("prototype_{}/{}", instance.prototype, scene.materials.at(instance.materialOverride).name);
}

}  // namespace

ExportResult writeGltf(const RenderScene &scene, const std::filesystem::path &out, bool binary,
                       const ExportOptions &options, Progress &progress) {
    ExportResult result;
    ExportImages images(scene, options.textureFiles, true, result.stats.notes);
    GltfDocument doc(scene, images);
    PartOptions parts;
    parts.transform = kZUpToYUp;
    parts.flipV = true;
    // Tangents serve normal maps, and only those the file references.
    for (const Material &m : scene.materials) parts.tangents.push_back(!m.glass && images.image(m, MapKind::Normal));
    for (const BakedMesh &baked : scene.meshes) {
        std::string name = objectName(baked.objectId, baked.buildingId);
        if (auto mesh = doc.addMesh(name, meshParts(baked.mesh, scene.materials, parts))) {
            doc.addNode(name, fmt::format(",\"mesh\":{}", *mesh));
            ++result.stats.meshes;
        }
        progress.advance();
    }
    std::map<std::pair<PrototypeId, MaterialId>, std::optional<size_t>> prototypeMeshes;
    for (const Instance &instance : scene.instances) {
        auto key = std::make_pair(instance.prototype, instance.materialOverride);
        auto found = prototypeMeshes.find(key);
        if (found == prototypeMeshes.end()) {
            parts.materialOverride = instance.materialOverride;
            std::optional<size_t> mesh =
                doc.addMesh(prototypeName(scene, instance),
                            meshParts(scene.prototypes.at(instance.prototype), scene.materials, parts));
            result.stats.meshes += mesh ? 1 : 0;
            found = prototypeMeshes.emplace(key, mesh).first;
        }
        // The prototype's vertices are already Y up: turn them back, place, turn again.
        if (found->second)
            doc.addNode(objectName(instance.objectId, instance.buildingId),
                        fmt::format(",\"mesh\":{},\"matrix\":{}", *found->second,
                                    matrixJson(kZUpToYUp * instance.objectToWorld * kYUpToZUp)));
        progress.advance();
    }
    doc.addCamera(scene.camera);
    doc.addSun(scene.sun);

    std::string extras = georeferenceJson(options.georeference, FileAxes::YUp);
    std::filesystem::path bin = out;
    bin.replace_extension(".bin");
    auto [json, buffer] = doc.finish(binary ? std::string() : bin.filename().string(), extras);
    if (binary) {
        result.files.push_back({out, glbBytes(std::move(json), buffer), {}});
    } else {
        result.files.push_back({out, std::move(json), {}});
        if (!buffer.empty()) result.files.push_back({bin, std::move(buffer), {}});
        for (const ExportedImage &image : images.images())
            result.files.push_back({out.parent_path() / image.fileName, imageBytes(image), {}});
    }
    for (ExportFile &file : georeferenceSidecars(options.georeference, out, FileAxes::YUp))
        result.files.push_back(std::move(file));
    result.stats.textures = images.images().size();
    return result;
}

}  // namespace veduta
