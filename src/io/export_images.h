// Which of a material's maps an export can reference as image files, and what it says about
// the others. RenderScene holds maps as texture ids; the files they were read from come from
// the scene description (ExportOptions::textureFiles). Maps computed where they are looked up
// (procedural masonry) or made in memory (baked masonry atlases) have no file: a diffuse one
// is written as its mean colour, and every map left out is counted in the notes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "io/export_job.h"
#include "scene/render_scene.h"

namespace veduta {

enum class MapKind { Diffuse, Specular, Normal, Reflection, Opacity };

// An image file the export references, under a name of its own beside the output.
struct ExportedImage {
    std::filesystem::path source;
    std::string fileName;
    std::string mimeType;   // image/png or image/jpeg; empty for other formats
    std::string converted;  // the PNG made of a source in another format; empty: the source as it is
};

// The bytes the export writes for the image: its PNG conversion or the source file.
std::string imageBytes(const ExportedImage &image);

class ExportImages {
  public:
    // `pngOrJpegOnly`: glTF, which allows no other format; maps in others (EXR, TIFF) are
    // converted to PNG through the image plugin. The notes go to `notes`.
    ExportImages(const RenderScene &scene, const TextureFiles &files, bool pngOrJpegOnly, ExportNotes &notes);

    // The image of the material's map of that kind, or none (counted in the notes when the
    // material has such a map). `formatHasSlot` false: the format has nowhere to put it.
    std::optional<size_t> image(const Material &material, MapKind kind, bool formatHasSlot = true);
    // The diffuse colour to write: the material's, times its map's mean when the map is not
    // exported, so that the surface keeps its overall colour.
    Vec3f diffuseColor(const Material &material);

    const std::vector<ExportedImage> &images() const { return images_; }

  private:
    void note(const Material &material, MapKind kind, const std::string &why);
    std::string uniqueName(const std::filesystem::path &source, const std::string &extension);

    const RenderScene &scene_;
    const TextureFiles &files_;
    bool pngOrJpegOnly_;
    ExportNotes &notes_;
    std::vector<ExportedImage> images_;
    std::map<std::filesystem::path, size_t> bySource_;
    std::set<std::string> names_;
    std::set<std::pair<std::string, std::string>> noted_;  // (reason, material)
};

// A texture's mean over its whole period, in three channels.
Vec3f textureMean(const Textures &textures, TextureId id);

}  // namespace veduta
