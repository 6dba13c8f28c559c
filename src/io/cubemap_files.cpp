#include "io/cubemap_files.h"

#include <array>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "io/image_library.h"
#include "scene/cubemap_layout.h"

namespace veduta {

namespace {

constexpr std::array<const char *, kCubeFaceCount> kAxisNames{"+x", "-x", "+y", "-y", "+z", "-z"};

void replaceAll(std::string &text, const std::string &placeholder, const std::string &value) {
    for (size_t at = text.find(placeholder); at != std::string::npos; at = text.find(placeholder, at + value.size())) {
        text.replace(at, placeholder.size(), value);
    }
}

}  // namespace

bool isFacePattern(const std::filesystem::path &file) {
    std::string name = file.string();
    return name.find("{face}") != std::string::npos || name.find("{axis}") != std::string::npos;
}

std::filesystem::path faceFile(const std::filesystem::path &pattern, int face) {
    std::string name = pattern.string();
    replaceAll(name, "{face}", std::string(cubeFaceName(face)));
    replaceAll(name, "{axis}", kAxisNames[size_t(face)]);
    return name;
}

Cubemap readCubemap(const std::filesystem::path &file, const std::string &colorSpace, int faceSize) {
    ImageLibrary &library = imageLibrary();
    if (isFacePattern(file)) {
        std::array<Image, kCubeFaceCount> faces;
        for (int f = 0; f < kCubeFaceCount; ++f) faces[size_t(f)] = library.read(faceFile(file, f), colorSpace);
        return cubemapFromFaces(faces);
    }
    Image image = library.read(file, colorSpace);
    if (image.width == 2 * image.height) {
        return cubemapFromLatLong(image, faceSize > 0 ? faceSize : std::max(1, image.width / 4));
    }
    return cubemapFromCross(image);
}

void writeCubemap(const Cubemap &cubemap, const std::filesystem::path &file, CubemapLayout layout) {
    ImageLibrary &library = imageLibrary();
    switch (layout) {
    case CubemapLayout::Faces: {
        std::array<Image, kCubeFaceCount> faces = facesFromCubemap(cubemap);
        std::vector<std::filesystem::path> files;
        for (int f = 0; f < kCubeFaceCount; ++f) files.push_back(faceFile(file, f));
        OutputSet outputs(files);
        for (int f = 0; f < kCubeFaceCount; ++f) library.write(files[size_t(f)], faces[size_t(f)]);
        outputs.commit();
        return;
    }
    case CubemapLayout::VerticalCross: library.write(file, crossFromCubemap(cubemap, true)); return;
    case CubemapLayout::HorizontalCross: library.write(file, crossFromCubemap(cubemap, false)); return;
    case CubemapLayout::LatLong: library.write(file, latLongFromCubemap(cubemap, 4 * cubemap.size())); return;
    }
}

}  // namespace veduta
