#include "io/export_images.h"

#include <fmt/format.h>
#include <unistd.h>

#include "core/file_extension.h"
#include "core/input_file.h"
#include "io/image_library.h"

namespace veduta {

namespace {

TextureId mapOf(const Material &m, MapKind kind) {
    switch (kind) {
    case MapKind::Diffuse: return m.diffuseMap;
    case MapKind::Specular: return m.specularMap;
    case MapKind::Normal: return m.normalMap;
    case MapKind::Reflection: return m.reflectionMap;
    case MapKind::Opacity: return m.opacityMap;
    }
    return kNoTexture;
}

const char *kindName(MapKind kind) {
    switch (kind) {
    case MapKind::Diffuse: return "diffuse";
    case MapKind::Specular: return "specular";
    case MapKind::Normal: return "normal";
    case MapKind::Reflection: return "reflection";
    case MapKind::Opacity: return "opacity";
    }
    return "";
}

std::string mimeType(const std::filesystem::path &file) {
    std::string extension = lowercaseExtension(file);
    if (extension == ".png") return "image/png";
    if (extension == ".jpg" || extension == ".jpeg") return "image/jpeg";
    return {};
}

// The texture registry names a procedural texture's fingerprint so (images/oiio_textures.cpp);
// nothing else tells it from an image made in memory.
bool isProcedural(const Textures &textures, TextureId id) {
    return textures.fingerprint(id).starts_with("procedural:");
}

// A map in a format glTF does not take, as PNG, through the image plugin. A colour map is read
// in linear values and written with the sRGB transfer glTF expects of base colours; a data map
// (normal) is read as if it were sRGB, so that the same transfer gives its values back unchanged.
std::string pngOf(const std::filesystem::path &source, MapKind kind) {
    Image image = imageLibrary().read(source, kind == MapKind::Diffuse ? "" : "sRGB");
    std::filesystem::path png = std::filesystem::temp_directory_path() /
        fmt::format("veduta-export-{}-{}.png", ::getpid(), source.stem().string());
    try {
        imageLibrary().write(png, image);
        std::string bytes = readInputFile(png);
        std::filesystem::remove(png);
        return bytes;
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(png, ignored);
        throw;
    }
}

}  // namespace

std::string imageBytes(const ExportedImage &image) {
    return image.converted.empty() ? readInputFile(image.source) : image.converted;
}

ExportImages::ExportImages(const RenderScene &scene, const TextureFiles &files, bool pngOrJpegOnly,
                           ExportNotes &notes) :
    scene_(scene), files_(files), pngOrJpegOnly_(pngOrJpegOnly), notes_(notes) {}

std::optional<size_t> ExportImages::image(const Material &material, MapKind kind, bool formatHasSlot) {
    TextureId id = mapOf(material, kind);
    if (id == kNoTexture) return std::nullopt;
    if (!formatHasSlot) {
        note(material, kind, "the format has no slot for it");
        return std::nullopt;
    }
    auto file = files_.find(id);
    if (file == files_.end()) {
        bool procedural = scene_.textures && isProcedural(*scene_.textures, id);
        note(material, kind, procedural ? "procedural texture" : "texture made in memory, no file");
        return std::nullopt;
    }
    const std::filesystem::path &source = file->second;
    if (auto found = bySource_.find(source); found != bySource_.end()) return found->second;
    std::string mime = mimeType(source);
    if (pngOrJpegOnly_ && mime.empty()) {
        images_.push_back({source, uniqueName(source, ".png"), "image/png", pngOf(source, kind)});
    } else {
        images_.push_back({source, uniqueName(source, source.extension().string()), mime, {}});
    }
    bySource_.emplace(source, images_.size() - 1);
    return images_.size() - 1;
}

std::string ExportImages::uniqueName(const std::filesystem::path &source, const std::string &extension) {
    std::string name = source.stem().string() + extension;
    for (int n = 2; names_.count(name); ++n) name = fmt::format("{}_{}{}", source.stem().string(), n, extension);
    names_.insert(name);
    return name;
}

Vec3f ExportImages::diffuseColor(const Material &material) {
    if (material.diffuseMap == kNoTexture || image(material, MapKind::Diffuse)) return material.diffuse;
    if (!scene_.textures) return material.diffuse;
    return material.diffuse * textureMean(*scene_.textures, material.diffuseMap);
}

void ExportImages::note(const Material &material, MapKind kind, const std::string &why) {
    std::string reason = kind == MapKind::Diffuse ? fmt::format("materials keep only their mean colour: {}", why)
                                                  : fmt::format("materials lose their {} map: {}", kindName(kind), why);
    if (noted_.emplace(reason, material.name).second) ++notes_[reason];
}

Vec3f textureMean(const Textures &textures, TextureId id) {
    float mean[3] = {1, 1, 1};
    textures.lookup(id, {0.5f, 0.5f}, 1.0f, mean, 3);
    if (textures.channels(id) < 3) mean[1] = mean[2] = mean[0];
    return {mean[0], mean[1], mean[2]};
}

}  // namespace veduta
