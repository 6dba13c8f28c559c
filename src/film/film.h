// The film: what a render accumulates for each pixel of its window. Sums of radiance (all
// samples, and the even-numbered ones apart, for noise estimates and denoisers), sums of the
// first hit's normal and albedo, the sample count, and the data of each pixel's first sample:
// depth, position and ids, unfiltered; and, when asked for, Cryptomatte's counts of what every
// sample met first. passes.h develops it into Blender's passes; a checkpoint stores it exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/layered_image.h"
#include "core/vecmath.h"
#include "film/cryptomatte.h"

namespace veduta {

// What a camera ray met first (cut-outs are looked through, panes of glass are not).
struct FirstHit {
    bool hit = false;         // false: the ray left the scene, everything else is zero
    Vec3f position;           // world space
    Vec3f normal;             // the shading normal (normal-mapped), facing the camera, world space
    Vec3f albedo;             // the diffuse colour k_d · diffuse map; black for glass
    float depth = 0;          // along the camera's view axis, as Blender's Z pass
    uint32_t objectId = 0;    // the scene file's object id
    uint32_t materialId = 0;  // 1 + the material's index in the scene (0: background)
    uint32_t buildingId = 0;  // the object's building, 0 if none
    uint32_t instanceId = 0;  // 1 + the index of the <instance> it belongs to, 0 if none
};

// One accumulation buffer, as a checkpoint sees it: a name and raw bytes.
struct FilmBuffer {
    std::string name;
    std::span<std::byte> bytes;
};

class Film {
  public:
    // A film for `window` of an image fullWidth × fullHeight pixels.
    Film(int fullWidth, int fullHeight, PixelWindow window);

    int fullWidth() const { return fullWidth_; }
    int fullHeight() const { return fullHeight_; }
    const PixelWindow &window() const { return window_; }
    size_t pixelCount() const { return count_.size(); }
    // The index of full-image pixel (x, y), which must lie in the window.
    size_t pixelIndex(int x, int y) const {
        return size_t(y - window_.y0) * size_t(window_.width()) + size_t(x - window_.x0);
    }

    // One sample of a pixel. `sampleIndex` is the sample's number in the pixel's sequence,
    // whose parity picks the half buffer. Radiance is summed in double, in the order samples
    // come, so that resuming continues exactly the sums an uninterrupted render makes.
    void addSample(size_t pixel, uint32_t sampleIndex, const Vec3f &radiance, const FirstHit &first);
    // The data passes (depth, position, ids) of the pixel's first sample.
    void setFirstSample(size_t pixel, const FirstHit &first);

    uint32_t sampleCount(size_t pixel) const { return count_[pixel]; }
    uint32_t evenSampleCount(size_t pixel) const { return evenCount_[pixel]; }
    // Sums over the pixel's samples: all of them, and the even-numbered ones.
    Vec3d radianceSum(size_t pixel) const { return {sum_[3 * pixel], sum_[3 * pixel + 1], sum_[3 * pixel + 2]}; }
    Vec3d evenRadianceSum(size_t pixel) const {
        return {evenSum_[3 * pixel], evenSum_[3 * pixel + 1], evenSum_[3 * pixel + 2]};
    }
    Vec3f normalSum(size_t pixel) const { return at3(normalSum_, pixel); }
    Vec3f albedoSum(size_t pixel) const { return at3(albedoSum_, pixel); }
    float depth(size_t pixel) const { return depth_[pixel]; }
    Vec3f position(size_t pixel) const { return at3(position_, pixel); }
    uint32_t objectId(size_t pixel) const { return ids_[pixel * 4 + 0]; }
    uint32_t materialId(size_t pixel) const { return ids_[pixel * 4 + 1]; }
    uint32_t buildingId(size_t pixel) const { return ids_[pixel * 4 + 2]; }
    uint32_t instanceId(size_t pixel) const { return ids_[pixel * 4 + 3]; }

    // Cryptomatte: from now on every sample's first hit is counted per pixel, `ranks` slots for
    // objects and as many for materials (24 · ranks bytes a pixel). For a fresh film.
    void enableCryptomatte(int ranks);
    int cryptomatteRanks() const { return cryptomatteRanks_; }
    // A pixel's slots of one kind: the keys its samples met first, in the order they were first
    // met, and how many samples met each; a slot with count 0 is empty. Keys met once every slot
    // is taken are not counted (as in Cycles), so that the film stays a fixed size.
    std::span<const uint64_t> cryptomatteKeys(size_t pixel, CryptomatteKind kind) const {
        return {&cryptomatteKeys_[slotsOf(pixel, kind)], size_t(cryptomatteRanks_)};
    }
    std::span<const uint32_t> cryptomatteCounts(size_t pixel, CryptomatteKind kind) const {
        return {&cryptomatteCounts_[slotsOf(pixel, kind)], size_t(cryptomatteRanks_)};
    }

    // Every buffer the film's state consists of, in a fixed order.
    std::vector<FilmBuffer> buffers();

  private:
    static Vec3f at3(const std::vector<float> &v, size_t i) { return {v[3 * i], v[3 * i + 1], v[3 * i + 2]}; }
    size_t slotsOf(size_t pixel, CryptomatteKind kind) const {
        return (pixel * 2 + size_t(kind)) * size_t(cryptomatteRanks_);
    }
    void countCryptomatte(size_t pixel, CryptomatteKind kind, uint64_t key);

    int fullWidth_, fullHeight_;
    PixelWindow window_;
    std::vector<double> sum_, evenSum_;
    std::vector<float> normalSum_, albedoSum_;
    std::vector<uint32_t> count_, evenCount_;
    std::vector<float> depth_, position_;
    std::vector<uint32_t> ids_;  // object, material, building, instance
    int cryptomatteRanks_ = 0;
    std::vector<uint64_t> cryptomatteKeys_;
    std::vector<uint32_t> cryptomatteCounts_;
};

}  // namespace veduta
