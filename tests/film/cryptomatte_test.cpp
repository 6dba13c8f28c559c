// Cryptomatte: ids as the specification and Blender compute them, the manifest, and the layers a
// render develops: coverage from every sample's first hit, the same for any thread count and tile
// size, and sample ranges that merge into the single render.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include "core/murmur_hash.h"
#include "core/render_attributes.h"
#include "film/cryptomatte.h"
#include "film/film_merge.h"
#include "film/passes.h"
#include "io/checkpoint_file.h"
#include "render/renderer.h"
#include "test_scenes.h"

namespace veduta {
namespace {

TEST(MurmurHash3, MatchesTheReferenceImplementation) {
    // Values of Appleby's MurmurHash3_x86_32 with seed 0 (as Python's mmh3.hash prints them).
    EXPECT_EQ(murmurHash3(""), 0u);
    EXPECT_EQ(murmurHash3("hello"), 0x248bfa47u);
    EXPECT_EQ(murmurHash3("The quick brown fox jumps over the lazy dog"), 0x2e4ff723u);
    EXPECT_EQ(murmurHash3("", 1), 0x514e28b7u);
}

TEST(Cryptomatte, IdsAreTheSpecificationsExamples) {
    // The manifest of the specification's example: {"bunny":"13851a76", "default":"42c9679f"}.
    EXPECT_EQ(cryptomatteHex(cryptomatteIdBits("bunny")), "13851a76");
    EXPECT_EQ(cryptomatteHex(cryptomatteIdBits("default")), "42c9679f");
    EXPECT_EQ(cryptomatteHex(cryptomatteIdBits("bunny_porcelain_mat")), "b24b26d4");
    EXPECT_EQ(std::bit_cast<uint32_t>(cryptomatteId("bunny")), 0x13851a76u);
}

TEST(Cryptomatte, IdsAreNeverDenormalInfiniteOrNan) {
    int clamped = 0;
    for (int i = 0; i < 4000; ++i) {
        std::string name = fmt::format("object_{}", i);
        uint32_t hash = murmurHash3(name), bits = cryptomatteIdBits(name);
        uint32_t exponent = (hash >> 23) & 0xffu;
        float id = std::bit_cast<float>(bits);
        ASSERT_TRUE(std::isnormal(id)) << name;
        if (exponent == 0 || exponent == 255) {
            EXPECT_EQ(bits, hash ^ (1u << 23)) << name;  // exponent 0 → 1, 255 → 254
            ++clamped;
        } else {
            EXPECT_EQ(bits, hash) << name;
        }
    }
    EXPECT_GT(clamped, 0);  // about 2 in 256 names
}

TEST(Cryptomatte, MetadataKeyIsTheTypeNamesHash) {
    std::string key = cryptomatteHex(murmurHash3("ViewLayer.CryptoObject")).substr(0, 7);
    EXPECT_EQ(cryptomatteMetadataPrefix("ViewLayer.CryptoObject"), "cryptomatte/" + key + "/");
    EXPECT_EQ(cryptomatteChannel(CryptomatteKind::Object, 0, false), "ViewLayer.CryptoObject00.R");
    EXPECT_EQ(cryptomatteChannel(CryptomatteKind::Material, 3, true), "ViewLayer.CryptoMaterial01.A");
}

TEST(Cryptomatte, ManifestRoundTrips) {
    std::map<std::string, std::string> manifest{{"plain", "13851a76"},
                                                {"a \"quoted\" \\ name", "42c9679f"},
                                                {std::string("tab\there"), "00000001"},
                                                {"a value another file wrote", "not \"hex\""}};
    std::string json = manifestJson(manifest);
    EXPECT_EQ(json.find('\t'), std::string::npos);
    EXPECT_EQ(parseManifest(json), manifest);
    EXPECT_EQ(parseManifest("{}"), (std::map<std::string, std::string>{}));
    EXPECT_THROW(parseManifest("{\"a\":"), std::runtime_error);
}

// Other writers escape what veduta writes as it is: a \u escape is a code point, kept as UTF-8.
TEST(Cryptomatte, ManifestReadsUnicodeEscapesAsUtf8) {
    EXPECT_EQ(parseManifest(R"({"Stra\u00dfe \u20ac":"0000002a"})"),
              (std::map<std::string, std::string>{{"Straße €", "0000002a"}}));
    EXPECT_THROW(parseManifest(R"({"a\u00zz":"0000002a"})"), std::runtime_error);
    EXPECT_THROW(parseManifest(R"({"a\u00)"), std::runtime_error);
}

TEST(Cryptomatte, RanksByWeightThenId) {
    std::vector<CryptomatteEntry> ranked = rankEntries({{7, 1}, {3, 5}, {9, 5}, {1, 2}}, 3);
    ASSERT_EQ(ranked.size(), 3u);
    EXPECT_EQ(ranked[0].idBits, 3u);
    EXPECT_EQ(ranked[1].idBits, 9u);
    EXPECT_EQ(ranked[2].idBits, 1u);
}

Film renderWithCryptomatte(const RenderScene &scene, RenderOptions options = {}, int threads = 2) {
    Film film = makeFilm(scene, options);
    film.enableCryptomatte(kDefaultCryptomatteRanks);
    RenderStats stats;
    Bvh bvh(scene);
    tbb::task_arena(threads).execute([&] { renderFilm(scene, bvh, options, film, stats); });
    return film;
}

LayeredImage developAll(const Film &film, const RenderScene &scene) {
    DevelopOptions options;
    options.passes = allPasses();
    options.naming = cryptomatteNaming(scene);
    return developFilm(film, options);
}

// Coverage of `name` at pixel p over every rank.
float coverageOf(const LayeredImage &image, CryptomatteKind kind, const std::string &name, size_t p) {
    float id = cryptomatteId(name), coverage = 0;
    for (int rank = 0; image.find(cryptomatteChannel(kind, rank, false)); ++rank) {
        if (std::bit_cast<uint32_t>(image.find(cryptomatteChannel(kind, rank, false))->values[p]) ==
            std::bit_cast<uint32_t>(id))
            coverage += image.find(cryptomatteChannel(kind, rank, true))->values[p];
    }
    return coverage;
}

float coverageSum(const LayeredImage &image, CryptomatteKind kind, size_t p) {
    float sum = 0;
    for (int rank = 0; image.find(cryptomatteChannel(kind, rank, true)); ++rank) {
        sum += image.find(cryptomatteChannel(kind, rank, true))->values[p];
    }
    return sum;
}

// Two walls meeting at x = 0, which the 21-pixel-wide image shows through the centres of its
// column 10; every sample hits one of them.
TEST(CryptomatteRender, SplitsTheBoundaryPixelsBetweenTwoObjects) {
    RenderScene scene = test::sceneFromXml(R"(<scene version="1">
  <camera position="0 -10 0" look_at="0 0 0" fov="20" resolution="21 7"/>
  <render spp="256"/>
  <material name="red" diffuse="0.6 0.1 0.1"/>
  <material name="blue" diffuse="0.1 0.1 0.6"/>
  <box size="20 1 40" translate="-10 0 -20" material="red" id="1"/>
  <box size="20 1 40" translate="10 0 -20" material="blue" id="2" building="4"/>
</scene>)");
    Film film = renderWithCryptomatte(scene);
    LayeredImage image = developAll(film, scene);
    for (int y = 0; y < 7; ++y) {
        for (int x = 0; x < 21; ++x) {
            size_t p = size_t(y) * 21 + size_t(x);
            float left = coverageOf(image, CryptomatteKind::Object, "object_1", p);
            float right = coverageOf(image, CryptomatteKind::Object, "building_4/object_2", p);
            EXPECT_NEAR(left + right, 1.0f, 1e-6f) << x << " " << y;
            EXPECT_NEAR(coverageSum(image, CryptomatteKind::Material, p), 1.0f, 1e-6f);
            EXPECT_EQ(coverageOf(image, CryptomatteKind::Material, "red", p), left);
            if (x <= 7) {
                EXPECT_EQ(left, 1.0f) << x;
            } else if (x >= 13) {
                EXPECT_EQ(right, 1.0f) << x;
            } else if (x == 10) {
                // The filter is symmetric: half the samples of the middle column land on each side.
                EXPECT_NEAR(left, 0.5f, 0.06f);
            } else if (x == 9) {
                EXPECT_GT(left, right);
            }
        }
    }
    auto manifest = storedManifest(image, CryptomatteKind::Object);
    EXPECT_EQ(manifest.size(), 2u);
    EXPECT_EQ(manifest["building_4/object_2"], cryptomatteHex(cryptomatteIdBits("building_4/object_2")));
}

RenderScene smallDefaultScene(uint32_t tileSize = 16) {
    SceneDescription d = test::defaultSceneAt(48, 27, 16);
    d.settings.tileSize = tileSize;
    return buildRenderScene(d);
}

TEST(CryptomatteRender, CoverageIsAtMostOneAndTheSameForAnyThreadsAndTiles) {
    RenderScene scene = smallDefaultScene(16);
    LayeredImage a = developAll(renderWithCryptomatte(scene, {}, 2), scene);
    LayeredImage b = developAll(renderWithCryptomatte(smallDefaultScene(3), {}, 1), scene);
    size_t partial = 0;
    for (size_t p = 0; p < a.dataWindow.area(); ++p) {
        float sum = coverageSum(a, CryptomatteKind::Object, p);
        ASSERT_LE(sum, 1.0f + 1e-6f);
        if (sum < 1.0f - 1e-6f) ++partial;  // the sky covers the rest
    }
    EXPECT_GT(partial, 0u);
    for (const LayeredImage::Channel &c : a.channels) {
        if (!isCryptomatteChannel(c.name)) continue;
        const std::vector<float> &other = b.find(c.name)->values;
        for (size_t p = 0; p < c.values.size(); ++p) {
            ASSERT_EQ(std::bit_cast<uint32_t>(c.values[p]), std::bit_cast<uint32_t>(other[p])) << c.name << " " << p;
        }
    }
}

TEST(CryptomatteRender, ResumingFromACheckpointKeepsTheCounts) {
    RenderScene scene = smallDefaultScene();
    Bvh bvh(scene);
    test::ScratchFolder folder("cryptomatte_checkpoint");
    std::filesystem::path file = folder.path() / "render.checkpoint";
    RenderOptions options;
    options.passSamples = 4;
    options.afterPass = [&](Film &film, const RenderStats &stats) {
        if (stats.samplesDone == 8) writeCheckpoint(file, {}, film, stats);
    };
    LayeredImage whole = developAll(renderWithCryptomatte(scene, options), scene);
    Film film = makeFilm(scene, {});
    film.enableCryptomatte(kDefaultCryptomatteRanks);
    RenderStats stats;
    readCheckpoint(file, {}, film, stats);
    ASSERT_EQ(stats.samplesDone, 8u);
    renderFilm(scene, bvh, {}, film, stats);
    LayeredImage resumed = developAll(film, scene);
    for (const LayeredImage::Channel &c : whole.channels) {
        if (!isCryptomatteChannel(c.name)) continue;
        for (size_t p = 0; p < c.values.size(); ++p) {
            ASSERT_EQ(std::bit_cast<uint32_t>(c.values[p]), std::bit_cast<uint32_t>(resumed.find(c.name)->values[p]))
                << c.name << " " << p;
        }
    }
}

void addMergeMetadata(LayeredImage &image, uint32_t offset, uint32_t samples) {
    image.metadata[kSceneHashAttribute] = std::string("test");
    image.metadata[kSeedAttribute] = 0;
    image.metadata[kRenderSecondsAttribute] = 1.0;
    image.metadata[kSampleOffsetAttribute] = int(offset);
    image.metadata[kSamplesAttribute] = int(samples);
}

TEST(CryptomatteRender, SampleRangesMergeIntoTheSingleRender) {
    RenderScene scene = smallDefaultScene();
    Film whole = renderWithCryptomatte(scene);
    LayeredImage single = developAll(whole, scene);
    std::vector<LayeredImage> parts;
    for (uint32_t offset : {0u, 8u}) {
        RenderScene half = smallDefaultScene();
        half.settings.samplesPerPixel = 8;
        RenderOptions options;
        options.sampleOffset = offset;
        parts.push_back(developAll(renderWithCryptomatte(half, options), scene));
        addMergeMetadata(parts.back(), offset, 8);
    }
    LayeredImage merged = mergeFilms(parts, {"first.exr", "second.exr"});
    for (CryptomatteKind kind : kCryptomatteKinds) {
        EXPECT_EQ(storedManifest(merged, kind), storedManifest(single, kind));
        size_t compared = 0;
        for (size_t p = 0; p < whole.pixelCount(); ++p) {
            // Exact where the pixel met fewer ids than it has slots: then no id was dropped.
            if (whole.cryptomatteCounts(p, kind).back() > 0) continue;
            ++compared;
            for (int rank = 0; rank < kDefaultCryptomatteRanks; ++rank) {
                for (bool coverage : {false, true}) {
                    std::string name = cryptomatteChannel(kind, rank, coverage);
                    ASSERT_EQ(std::bit_cast<uint32_t>(merged.find(name)->values[p]),
                              std::bit_cast<uint32_t>(single.find(name)->values[p]))
                        << name << " at " << p;
                }
            }
        }
        EXPECT_GT(compared, whole.pixelCount() * 9 / 10);
    }
}

}  // namespace
}  // namespace veduta
