// What one `veduta export` is given besides the scene, and what it hands back: the files to
// write and what they hold. The writers (gltf_writer.h, obj_writer.h, ply_writer.h) encode
// into memory; scene_export.h writes the files, all or none.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geodesy/georeference.h"
#include "scene/textures.h"

namespace veduta {

// The image files that a scene's maps were read from, by texture id: what the scene
// description names (RenderScene holds only ids). Maps missing here were made in memory.
using TextureFiles = std::map<TextureId, std::filesystem::path>;

struct ExportOptions {
    std::optional<Georeference> georeference;  // none: the scene is in local metres only
    TextureFiles textureFiles;
    bool progress = false;  // a progress line on a terminal
};

// Takes the next piece of a file's content.
using ExportSink = std::function<void(std::string_view piece)>;

// A file an export writes: whole in memory until it is written, or, for OBJ and PLY geometry,
// which instances copied out make far larger than the scene, produced piece by piece as it is
// written.
struct ExportFile {
    std::filesystem::path path;
    std::string bytes;
    std::function<void(const ExportSink &sink)> stream;  // when set, the content instead of `bytes`
};

// What was left out, counted by reason ("materials keep only their mean colour: procedural
// texture"); each reason is said once with its count.
using ExportNotes = std::map<std::string, size_t>;

struct ExportStats {
    size_t meshes = 0;     // meshes in the file: baked meshes and prototypes (OBJ, PLY: every copy)
    size_t instances = 0;  // prototype placements (OBJ, PLY: written out as copies)
    size_t triangles = 0;  // as drawn, every instance counted
    size_t files = 0;      // files written: the main file and its side files
    size_t textures = 0;   // image files referenced (copied beside the file or embedded)
    ExportNotes notes;
};

// The files of one export and what they hold.
struct ExportResult {
    std::vector<ExportFile> files;  // the main file first
    ExportStats stats;
};

}  // namespace veduta
