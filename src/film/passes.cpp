#include "film/passes.h"

#include <array>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "core/check.h"

namespace veduta {

namespace {

struct Pass {
    const char *name;
    std::vector<const char *> channels;
};

// Every pass developFilm writes, in order.
const Pass kPasses[] = {{"Combined", {"R", "G", "B", "A"}},
                        {"CombinedEven", {"R", "G", "B"}},
                        {"CombinedOdd", {"R", "G", "B"}},
                        {"Depth", {"Z"}},
                        {"Normal", {"X", "Y", "Z"}},
                        {"DiffCol", {"R", "G", "B"}},
                        {"Position", {"X", "Y", "Z"}},
                        {"IndexOB", {"X"}},
                        {"IndexMA", {"X"}},
                        {"IndexBuilding", {"X"}},
                        {"IndexInstance", {"X"}},
                        {"SampleCount", {"X"}}};

// The pass's channels, one vector per channel. Taken only once every channel is added: adding a
// channel may move the others.
std::vector<std::vector<float> *> channelsOf(LayeredImage &image, const Pass &pass) {
    std::vector<std::vector<float> *> channels;
    for (const char *c : pass.channels) channels.push_back(&image.find(passChannel(pass.name, c))->values);
    return channels;
}

template <typename V>
void store(const std::vector<std::vector<float> *> &channels, size_t pixel, const V &v, double scale) {
    (*channels[0])[pixel] = float(double(v.x) * scale);
    (*channels[1])[pixel] = float(double(v.y) * scale);
    (*channels[2])[pixel] = float(double(v.z) * scale);
}

double inverse(uint32_t count) { return count ? 1.0 / double(count) : 0.0; }

}  // namespace

std::string passChannel(const std::string &pass, const std::string &channel) {
    return fmt::format("{}.{}.{}", kViewLayer, pass, channel);
}

LayeredImage developFilm(const Film &film) {
    LayeredImage image;
    image.fullWidth = film.fullWidth();
    image.fullHeight = film.fullHeight();
    image.dataWindow = film.window();
    for (const Pass &pass : kPasses) {
        for (const char *c : pass.channels) image.addChannel(passChannel(pass.name, c));
    }
    auto [combined, even, odd, depth, normal, albedo, position, ids, materials, buildings, instances, samples] = [&] {
        std::array<std::vector<std::vector<float> *>, std::size(kPasses)> all;
        for (size_t i = 0; i < all.size(); ++i) all[i] = channelsOf(image, kPasses[i]);
        return all;
    }();

    for (size_t p = 0; p < film.pixelCount(); ++p) {
        uint32_t n = film.sampleCount(p), nEven = film.evenSampleCount(p);
        Vec3d sum = film.radianceSum(p), evenSum = film.evenRadianceSum(p);
        store(combined, p, sum, inverse(n));
        // Alpha is 1: the background is part of the image, as in Blender's non-transparent film.
        (*combined[3])[p] = 1.0f;
        store(even, p, evenSum, inverse(nEven));
        store(odd, p, Vec3d{sum.x - evenSum.x, sum.y - evenSum.y, sum.z - evenSum.z}, inverse(n - nEven));
        store(normal, p, film.normalSum(p), inverse(n));
        store(albedo, p, film.albedoSum(p), inverse(n));
        bool background = film.materialId(p) == 0;
        (*depth[0])[p] = background ? kBackgroundDepth : film.depth(p);
        store(position, p, film.position(p), 1.0);
        (*ids[0])[p] = float(film.objectId(p));
        (*materials[0])[p] = float(film.materialId(p));
        (*buildings[0])[p] = float(film.buildingId(p));
        (*instances[0])[p] = float(film.instanceId(p));
        (*samples[0])[p] = float(n);
    }
    return image;
}

RgbaImage combinedImage(const Film &film) { return combinedImage(developFilm(film)); }

RgbaImage combinedImage(const LayeredImage &image) {
    const char *names[4] = {"R", "G", "B", "A"};
    RgbaImage rgba(image.dataWindow.width(), image.dataWindow.height());
    for (int c = 0; c < 4; ++c) {
        const LayeredImage::Channel *channel = image.find(passChannel("Combined", names[c]));
        VEDUTA_CHECK(channel, "the image has no Combined pass");
        for (size_t p = 0; p < channel->values.size(); ++p) rgba.pixels()[p * 4 + size_t(c)] = channel->values[p];
    }
    return rgba;
}

}  // namespace veduta
