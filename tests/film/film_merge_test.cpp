// mergeFilms: a single part unchanged, tiles assembled bit-exactly, sample ranges weighted by
// their counts (exact figures, and against one film that took all the samples), each check.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/hash.h"
#include "core/render_attributes.h"
#include "film/film.h"
#include "film/film_merge.h"
#include "film/passes.h"
#include "input_error.h"

namespace veduta {
namespace {

constexpr int kWidth = 12, kHeight = 8;

// How many samples pixel (x, y) takes in a film: varying, as adaptive sampling makes them.
using SampleCounts = std::function<uint32_t(int x, int y)>;

// A sample's radiance and first hit as a pure function of pixel and sample index, so that
// films over different sample ranges take the samples one film over all of them takes.
Vec3f radianceOf(int x, int y, uint32_t index) {
    auto channel = [&](uint32_t c) {
        return 10.0f * bitsToUnitFloat(hashValues({uint32_t(x), uint32_t(y), index, c}));
    };
    return {channel(0), channel(1), channel(2)};
}

FirstHit firstHitOf(int x, int y) {
    FirstHit hit;
    hit.hit = true;
    hit.position = {float(x), float(y), 0.25f};
    hit.normal = {0, 0, 1};
    hit.albedo = {0.5f, 0.25f, 0.125f};
    hit.depth = float(x + y) + 0.5f;
    hit.objectId = uint32_t(x);
    hit.materialId = 1;
    hit.instanceId = uint32_t(y);
    return hit;
}

// The developed film of `window` with samples offset … offset + counts(x, y) − 1 of each pixel.
LayeredImage renderPart(PixelWindow window, uint32_t offset, uint32_t samples, const SampleCounts &counts) {
    Film film(kWidth, kHeight, window);
    for (int y = window.y0; y < window.y1; ++y) {
        for (int x = window.x0; x < window.x1; ++x) {
            size_t pixel = film.pixelIndex(x, y);
            for (uint32_t i = 0; i < counts(x, y); ++i) {
                film.addSample(pixel, offset + i, radianceOf(x, y, offset + i), firstHitOf(x, y));
            }
            film.setFirstSample(pixel, firstHitOf(x, y));
        }
    }
    LayeredImage image = developFilm(film);
    image.metadata[kSamplesAttribute] = int(samples);
    image.metadata[kSampleOffsetAttribute] = int(offset);
    image.metadata[kSeedAttribute] = 7;
    image.metadata[kSceneHashAttribute] = std::string("0123456789abcdef");
    image.metadata[kRenderSecondsAttribute] = 1.5;
    image.metadata["RenderTime"] = blenderRenderTime(1.5);
    image.metadata["Software"] = std::string("veduta test");
    return image;
}

LayeredImage renderPart(PixelWindow window, uint32_t offset, uint32_t samples) {
    return renderPart(window, offset, samples, [samples](int, int) { return samples; });
}

const PixelWindow kFull{0, 0, kWidth, kHeight};

std::vector<uint32_t> bitsOf(const std::vector<float> &values) {
    std::vector<uint32_t> bits;
    for (float v : values) bits.push_back(std::bit_cast<uint32_t>(v));
    return bits;
}

void expectBitIdentical(const LayeredImage &a, const LayeredImage &b) {
    EXPECT_EQ(a.dataWindow, b.dataWindow);
    ASSERT_EQ(a.channels.size(), b.channels.size());
    for (const LayeredImage::Channel &c : a.channels) {
        ASSERT_NE(b.find(c.name), nullptr) << c.name;
        EXPECT_EQ(bitsOf(c.values), bitsOf(b.find(c.name)->values)) << c.name;
    }
}

// The message of the InputError mergeFilms throws, or "no error".
std::string mergeError(const std::vector<LayeredImage> &parts, const std::vector<std::string> &names) {
    return test::inputErrorOf([&] { mergeFilms(parts, names); });
}

TEST(FilmMerge, SinglePartComesBackBitIdentical) {
    // Counts 0 … 6, not powers of two; a pixel without samples keeps Combined 0 and alpha 1.
    LayeredImage part = renderPart(kFull, 5, 6, [](int x, int y) { return uint32_t(x + y) % 7; });
    LayeredImage merged = mergeFilms({part}, {"a.exr"});
    expectBitIdentical(merged, part);
    EXPECT_EQ(merged.metadata, part.metadata);
}

TEST(FilmMerge, TilesAreAssembledBitIdentical) {
    LayeredImage full = renderPart(kFull, 0, 3);
    std::vector<LayeredImage> tiles = {renderPart({0, 0, 5, 3}, 0, 3), renderPart({5, 0, 12, 3}, 0, 3),
                                       renderPart({0, 3, 12, 7}, 0, 3), renderPart({0, 7, 12, 8}, 0, 3)};
    LayeredImage merged = mergeFilms(tiles, {"a.exr", "b.exr", "c.exr", "d.exr"});
    expectBitIdentical(merged, full);
    EXPECT_EQ(std::get<int>(merged.metadata.at(kSamplesAttribute)), 3);
    EXPECT_EQ(std::get<double>(merged.metadata.at(kRenderSecondsAttribute)), 6.0);
    EXPECT_EQ(std::get<std::string>(merged.metadata.at("RenderTime")), "00:06.00");
}

// One pixel, two ranges with hand-computed means: weighted by all, even and odd sample counts.
TEST(FilmMerge, SampleRangesAreWeightedBySampleCounts) {
    auto part = [](int offset, int samples, float mean, float even, float odd) {
        LayeredImage image = renderPart({0, 0, 1, 1}, uint32_t(offset), uint32_t(samples));
        for (const char *c : {"R", "G", "B"}) {
            image.find(passChannel("Combined", c))->values = {mean};
            image.find(passChannel("CombinedEven", c))->values = {even};
            image.find(passChannel("CombinedOdd", c))->values = {odd};
            image.find(passChannel("DiffCol", c))->values = {mean};
        }
        return image;
    };
    // Samples 0, 1, 2 (even: 0, 2) and 3, 4 (even: 4), given in the wrong order.
    LayeredImage merged = mergeFilms({part(3, 2, 4.0f, 4.0f, 2.0f), part(0, 3, 1.0f, 1.0f, 1.0f)}, {"b.exr", "a.exr"});
    for (const char *c : {"R", "G", "B"}) {
        EXPECT_EQ(merged.find(passChannel("Combined", c))->values[0], (3 * 1.0f + 2 * 4.0f) / 5);
        EXPECT_EQ(merged.find(passChannel("DiffCol", c))->values[0], (3 * 1.0f + 2 * 4.0f) / 5);
        EXPECT_EQ(merged.find(passChannel("CombinedEven", c))->values[0], 2.0f);  // (2·1 + 1·4) / 3
        EXPECT_EQ(merged.find(passChannel("CombinedOdd", c))->values[0], 1.5f);   // (1·1 + 1·2) / 2
    }
    EXPECT_EQ(merged.find(passChannel("Combined", "A"))->values[0], 1.0f);
    EXPECT_EQ(merged.find(passChannel("SampleCount", "X"))->values[0], 5.0f);
    EXPECT_EQ(std::get<int>(merged.metadata.at(kSamplesAttribute)), 5);
    EXPECT_EQ(std::get<int>(merged.metadata.at(kSampleOffsetAttribute)), 0);
}

int64_t ulpsBetween(float a, float b) {
    // Both non-negative here, so the bit patterns are ordered like the values.
    return std::abs(int64_t(std::bit_cast<uint32_t>(a)) - int64_t(std::bit_cast<uint32_t>(b)));
}

// Two ranges against one film that took all their samples: the parts' means were rounded to
// float before the merge weighs them, so Combined, CombinedEven and CombinedOdd may differ by
// the one rounding; the derivation in docs/output.md bounds it by 1 ulp.
TEST(FilmMerge, TwoRangesAgreeWithOneFilmWithinOneUlp) {
    auto first = [](int x, int y) { return 1 + uint32_t(x * 3 + y) % 6; };
    auto second = [](int x, int y) { return 1 + uint32_t(x + 5 * y) % 7; };
    LayeredImage a = renderPart(kFull, 0, 6, first), b = renderPart(kFull, 6, 7, second);
    Film film(kWidth, kHeight, kFull);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            auto take = [&](uint32_t index) {
                film.addSample(film.pixelIndex(x, y), index, radianceOf(x, y, index), firstHitOf(x, y));
            };
            for (uint32_t i = 0; i < first(x, y); ++i) take(i);
            for (uint32_t i = 0; i < second(x, y); ++i) take(6 + i);
            film.setFirstSample(film.pixelIndex(x, y), firstHitOf(x, y));
        }
    }
    LayeredImage full = developFilm(film);
    LayeredImage merged = mergeFilms({a, b}, {"a.exr", "b.exr"});
    size_t values = 0, identical = 0;
    int64_t maxUlps = 0;
    for (const char *pass : {"Combined", "CombinedEven", "CombinedOdd"}) {
        for (const char *c : {"R", "G", "B"}) {
            const std::vector<float> &m = merged.find(passChannel(pass, c))->values;
            const std::vector<float> &f = full.find(passChannel(pass, c))->values;
            for (size_t p = 0; p < m.size(); ++p) {
                int64_t ulps = ulpsBetween(m[p], f[p]);
                maxUlps = std::max(maxUlps, ulps);
                identical += ulps == 0;
                ++values;
            }
        }
    }
    std::printf("two ranges vs one film: %zu of %zu radiance values bit-identical, max %lld ulp\n", identical, values,
                (long long)maxUlps);
    EXPECT_LE(maxUlps, 1);
    for (const char *pass : {"SampleCount", "Depth", "IndexOB", "IndexInstance", "Position", "Normal", "DiffCol"}) {
        for (const LayeredImage::Channel &c : full.channels) {
            if (!c.name.starts_with(passChannel(pass, ""))) continue;
            EXPECT_EQ(bitsOf(merged.find(c.name)->values), bitsOf(c.values)) << c.name;
        }
    }
}

const std::vector<std::string> kTwo = {"a.exr", "b.exr"};

TEST(FilmMerge, DifferentImageSizesAreAnError) {
    LayeredImage b = renderPart(kFull, 4, 4);
    b.fullWidth = 13;
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), b}, kTwo), "b.exr: is a 13x8 image, a.exr is 12x8");
}

TEST(FilmMerge, DifferentChannelsAreAnError) {
    LayeredImage b = renderPart(kFull, 4, 4);
    std::erase_if(b.channels, [](const LayeredImage::Channel &c) { return c.name == "ViewLayer.IndexMA.X"; });
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), b}, kTwo),
              "b.exr: lacks the channel ViewLayer.IndexMA.X that a.exr has");
    b = renderPart(kFull, 4, 4);
    b.addChannel("ViewLayer.Extra.X");
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), b}, kTwo), "b.exr: has a channel ViewLayer.Extra.X, a.exr has not");
}

TEST(FilmMerge, DifferentScenesAndSeedsAreAnError) {
    LayeredImage b = renderPart(kFull, 4, 4);
    b.metadata[kSceneHashAttribute] = std::string("fedcba9876543210");
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), b}, kTwo),
              "b.exr: has a different veduta.sceneHash from a.exr: not the same render");
    b = renderPart(kFull, 4, 4);
    b.metadata[kSeedAttribute] = 8;
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), b}, kTwo),
              "b.exr: has a different veduta.seed from a.exr: not the same render");
}

TEST(FilmMerge, MissingAttributeIsAnError) {
    LayeredImage a = renderPart(kFull, 0, 4);
    a.metadata.erase(kSampleOffsetAttribute);
    EXPECT_EQ(mergeError({a}, {"a.exr"}), "a.exr: has no veduta.sampleOffset attribute; is it a veduta render?");
}

TEST(FilmMerge, OverlappingSampleRangesAreAnError) {
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), renderPart(kFull, 2, 4)}, kTwo),
              "b.exr: its samples [2, 6) overlap the samples [0, 4) of a.exr");
}

TEST(FilmMerge, GapBetweenSampleRangesIsAnError) {
    EXPECT_EQ(mergeError({renderPart(kFull, 6, 2), renderPart(kFull, 0, 4)}, kTwo),
              "a.exr: its samples [6, 8) do not continue the samples [0, 4) of b.exr: samples [4, 6) are in none of "
              "the files");
}

TEST(FilmMerge, OverlappingTilesAreAnError) {
    EXPECT_EQ(mergeError({renderPart({0, 0, 7, 8}, 0, 4), renderPart({6, 0, 12, 8}, 0, 4)}, kTwo),
              "b.exr: its data window 6 0 12 8 overlaps the data window 0 0 7 8 of a.exr");
}

TEST(FilmMerge, UncoveredPixelsAreAnError) {
    EXPECT_EQ(mergeError({renderPart({0, 0, 5, 8}, 0, 4), renderPart({6, 0, 12, 8}, 0, 4)}, kTwo),
              "a.exr: the tiles leave 8 of the 96 pixels of their bounding box 0 0 12 8 uncovered");
}

TEST(FilmMerge, TilesWithDifferentSampleRangesAreAnError) {
    EXPECT_EQ(mergeError({renderPart({0, 0, 6, 8}, 0, 4), renderPart({6, 0, 12, 8}, 0, 8)}, kTwo),
              "b.exr: its tile has the samples [0, 8), the tile of a.exr has [0, 4)");
}

TEST(FilmMerge, DifferentFirstSampleDataAreAnError) {
    LayeredImage b = renderPart(kFull, 4, 4);
    b.find(passChannel("Depth", "Z"))->values[2 * kWidth + 3] = 100.0f;
    EXPECT_EQ(mergeError({renderPart(kFull, 0, 4), b}, kTwo),
              "b.exr: ViewLayer.Depth.Z at pixel 3 2 is 100, in a.exr it is 5.5: they come from different scenes");
}

}  // namespace
}  // namespace veduta
