#include "film/film.h"

namespace veduta {

namespace {

template <typename T>
FilmBuffer bufferOf(std::string name, std::vector<T> &values) {
    return {std::move(name), std::as_writable_bytes(std::span<T>(values))};
}

}  // namespace

Film::Film(int fullWidth, int fullHeight, PixelWindow window) :
    fullWidth_(fullWidth), fullHeight_(fullHeight), window_(window) {
    size_t n = window.area();
    sum_.assign(n * 3, 0.0);
    evenSum_.assign(n * 3, 0.0);
    normalSum_.assign(n * 3, 0.0f);
    albedoSum_.assign(n * 3, 0.0f);
    count_.assign(n, 0);
    evenCount_.assign(n, 0);
    depth_.assign(n, 0.0f);
    position_.assign(n * 3, 0.0f);
    ids_.assign(n * 4, 0);
}

void Film::addSample(size_t pixel, uint32_t sampleIndex, const Vec3f &radiance, const FirstHit &first) {
    double *sum = &sum_[pixel * 3];
    sum[0] += double(radiance.x);
    sum[1] += double(radiance.y);
    sum[2] += double(radiance.z);
    if (sampleIndex % 2 == 0) {
        double *even = &evenSum_[pixel * 3];
        even[0] += double(radiance.x);
        even[1] += double(radiance.y);
        even[2] += double(radiance.z);
        ++evenCount_[pixel];
    }
    for (int c = 0; c < 3; ++c) {
        normalSum_[pixel * 3 + size_t(c)] += first.normal[c];
        albedoSum_[pixel * 3 + size_t(c)] += first.albedo[c];
    }
    ++count_[pixel];
    // A sample that met nothing covers no id: the pixel's coverages then sum to less than 1.
    if (cryptomatteRanks_ > 0 && first.hit) {
        countCryptomatte(pixel, CryptomatteKind::Object, cryptomatteObjectKey(first.objectId, first.buildingId));
        countCryptomatte(pixel, CryptomatteKind::Material, first.materialId);
    }
}

void Film::enableCryptomatte(int ranks) {
    cryptomatteRanks_ = ranks;
    cryptomatteKeys_.assign(pixelCount() * 2 * size_t(ranks), 0);
    cryptomatteCounts_.assign(pixelCount() * 2 * size_t(ranks), 0);
}

void Film::countCryptomatte(size_t pixel, CryptomatteKind kind, uint64_t key) {
    size_t first = slotsOf(pixel, kind);
    for (size_t slot = first; slot < first + size_t(cryptomatteRanks_); ++slot) {
        if (cryptomatteCounts_[slot] == 0) cryptomatteKeys_[slot] = key;
        if (cryptomatteKeys_[slot] == key) {
            ++cryptomatteCounts_[slot];
            return;
        }
    }
}

void Film::setFirstSample(size_t pixel, const FirstHit &first) {
    depth_[pixel] = first.depth;
    for (int c = 0; c < 3; ++c) position_[pixel * 3 + size_t(c)] = first.position[c];
    uint32_t *ids = &ids_[pixel * 4];
    ids[0] = first.objectId;
    ids[1] = first.materialId;
    ids[2] = first.buildingId;
    ids[3] = first.instanceId;
}

std::vector<FilmBuffer> Film::buffers() {
    std::vector<FilmBuffer> all{
        bufferOf("radiance", sum_),     bufferOf("even radiance", evenSum_), bufferOf("normal", normalSum_),
        bufferOf("albedo", albedoSum_), bufferOf("samples", count_),         bufferOf("even samples", evenCount_),
        bufferOf("depth", depth_),      bufferOf("position", position_),     bufferOf("ids", ids_)};
    if (cryptomatteRanks_ > 0) {
        all.push_back(bufferOf("cryptomatte keys", cryptomatteKeys_));
        all.push_back(bufferOf("cryptomatte counts", cryptomatteCounts_));
    }
    return all;
}

}  // namespace veduta
