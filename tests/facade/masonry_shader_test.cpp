// Masonry shaded where it is looked up (masonry_shader.h) against the bake it stands in for
// (masonry_texture.h): the same stones, mortar and bevels at every texel centre, the walls' means
// for wide footprints, and the same values through the texture registry.
#include "facade/masonry_shader.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <vector>

#include "facade/brick_bond.h"
#include "io/image_library.h"
#include "thesis_figures.h"

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A 6 × 4 m brick wall with a window, in Fig. 5.7's bond.
struct BrickWall {
    WallFace face{rectangle(0, 0, 6, 4), {rectangle(2, 1, 3.2, 3)}};
    Masonry masonry = layBrickBond(parseBrickBond(thesis::kFigure5_7, "figure-5.7"), face, {0.125, 1871, 1});
};

Vec2d texelCentre(const MasonryTextures &t, int x, int row) {
    double top = t.origin.y + t.diffuse.height * t.texelSize;
    return {t.origin.x + (x + 0.5) * t.texelSize, top - (row + 0.5) * t.texelSize};
}

bool inOpening(const WallFace &face, Vec2d p) {
    for (const auto &o : face.openings)
        if (p.x > o[0].x && p.x < o[2].x && p.y > o[0].y && p.y < o[2].y) return true;
    return false;
}

TEST(MasonryShader, ShowsTheBakesStoneOrMortarAtEveryTexelCentre) {
    BrickWall wall;
    ASSERT_GT(wall.masonry.stones.size(), 1000u);
    // A texel whose centres never fall on the bond's edges (multiples of 1/32 cm): on an edge,
    // float texture coordinates may put a centre on either side.
    constexpr double kTexel = 0.0097;
    MasonryTextures baked = bakeMasonry(wall.masonry, wall.face, kTexel);
    MasonryShader shader({{wall.masonry, wall.face}});
    size_t texels = 0, same = 0, tiltedAlike = 0, tilted = 0;
    for (int row = 0; row < baked.diffuse.height; ++row)
        for (int x = 0; x < baked.diffuse.width; ++x) {
            Vec2d p = texelCentre(baked, x, row);
            if (inOpening(wall.face, p)) continue;
            ++texels;
            // A point sample (the footprint far below a joint) and one the texel's size.
            MasonrySample point = shader.shade(shader.uvOf(0, p), 1e-5f);
            const float *colour = baked.diffuse.at(x, row);
            same +=
                point.colour == Vec3f(colour[0], colour[1], colour[2]) && point.specular == *baked.specular.at(x, row);
            // On a stone, the bake's normals lean at its edges over a texel: so do the shader's at
            // a texel's footprint, the same way.
            if (*baked.specular.at(x, row) == 0) continue;  // mortar
            const float *n = baked.normal.at(x, row);
            Vec3f bakedNormal(n[0] * 2 - 1, n[1] * 2 - 1, n[2] * 2 - 1);
            Vec3f shaded = shader.shade(shader.uvOf(0, p), float(kTexel)).normal;
            bool bakedTilts = bakedNormal.z < 0.999f, shaderTilts = shaded.z < 0.999f;
            tilted += bakedTilts;
            tiltedAlike += bakedTilts && shaderTilts &&
                dot(Vec3f(bakedNormal.x, bakedNormal.y, 0), Vec3f(shaded.x, shaded.y, 0)) > 0;
        }
    std::printf("texel centres agreeing: %zu of %zu; stone texels leaning alike: %zu of %zu\n", same, texels,
                tiltedAlike, tilted);
    // Only texel centres on a stone's very edge may go either way.
    EXPECT_GT(double(same), 0.999 * double(texels)) << same << " of " << texels;
    EXPECT_GT(tilted, texels / 10);
    EXPECT_GT(double(tiltedAlike), 0.9 * double(tilted)) << tiltedAlike << " of " << tilted;
}

TEST(MasonryShader, AFootprintOfManyJointsGivesTheWallsMean) {
    BrickWall wall;
    MasonryTextures baked = bakeMasonry(wall.masonry, wall.face, 0.005);
    Vec3f sum(0.0f);
    size_t count = 0;
    for (int row = 0; row < baked.diffuse.height; ++row)
        for (int x = 0; x < baked.diffuse.width; ++x) {
            if (inOpening(wall.face, texelCentre(baked, x, row))) continue;
            const float *c = baked.diffuse.at(x, row);
            sum += Vec3f(c[0], c[1], c[2]);
            ++count;
        }
    Vec3f bakedMean = sum * (1.0f / float(count));
    MasonryShader shader({{wall.masonry, wall.face}});
    MasonrySample mean = shader.shade(shader.uvOf(0, {1, 1}), 1.0f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean.colour[k], bakedMean[k], 0.01f * bakedMean[k]) << k;
    EXPECT_EQ(mean.normal, Vec3f(0, 0, 1));
    // Footprints under a stone (the bond's bricks are 25 × 6.25 cm) leave joints to the pixel's
    // samples; between one stone and four, a blend: nearer the mean the wider the footprint.
    Vec2f uv = shader.uvOf(0, {0.5, 0.5});
    float point = length(shader.shade(uv, 0.0f).colour - mean.colour);
    EXPECT_EQ(shader.shade(uv, 0.1f).colour, shader.shade(uv, 0.0f).colour);
    float blended = length(shader.shade(uv, 0.25f).colour - mean.colour);
    EXPECT_LT(blended, point);
    EXPECT_GT(blended, 0.0f);
}

TEST(MasonryShader, WallsStackedInTheTextureKeepTheirOwnMasonry) {
    BrickWall a, b;
    b.masonry.mortarColour = {0.9f, 0.1f, 0.1f};
    b.masonry.stones.clear();
    MasonryShader both({{a.masonry, a.face}, {b.masonry, b.face}});
    MasonryShader first({{a.masonry, a.face}});
    for (Vec2d p : {Vec2d{0.3, 0.2}, Vec2d{5.9, 3.9}, Vec2d{4.1, 1.7}}) {
        EXPECT_EQ(both.shade(both.uvOf(0, p), 1e-5f).colour, first.shade(first.uvOf(0, p), 1e-5f).colour);
        EXPECT_EQ(both.shade(both.uvOf(1, p), 1e-5f).colour, Vec3f(0.9f, 0.1f, 0.1f));
    }
    EXPECT_NE(both.fingerprint(), first.fingerprint());
}

TEST(MasonryShader, AFootprintOverTheWholeTextureGivesTheMeanOfAllWallsByArea) {
    // What the preview colours a building's masonry with (preview.cpp's previewAlbedo).
    BrickWall a, b;
    b.masonry.mortarColour = {0.9f, 0.1f, 0.1f};
    b.masonry.stones.clear();
    b.face.outline = rectangle(0, 0, 12, 4);  // twice a's area less the opening, and the opening
    MasonryShader both({{a.masonry, a.face}, {b.masonry, b.face}});
    Vec3f meanA = both.shade(both.uvOf(0, {1, 1}), 1.0f).colour, meanB = both.shade(both.uvOf(1, {1, 1}), 1.0f).colour;
    EXPECT_EQ(meanB, Vec3f(0.9f, 0.1f, 0.1f));
    double areaA = 6 * 4 - 1.2 * 2, areaB = 12 * 4 - 1.2 * 2;
    Vec3f expected = (meanA * float(areaA) + meanB * float(areaB)) * float(1 / (areaA + areaB));
    MasonrySample whole = both.shade({0.5f, 0.5f}, 1e6f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(whole.colour[k], expected[k], 1e-5f) << k;
    EXPECT_EQ(whole.normal, Vec3f(0, 0, 1));
    // Under the whole texture, a wide footprint still gives its own wall's mean.
    EXPECT_EQ(both.shade(both.uvOf(0, {1, 1}), 5.0f).colour, meanA);
}

TEST(MasonryShader, AWallGivenAsARecipeIsLaidWhenALookupFirstReachesItOnceForAllThreads) {
    BrickWall wall;
    std::atomic<int> laid[2] = {0, 0};
    auto recipe = [&](int w, uint64_t hash) {
        return MasonryRecipe{[&laid, &wall, w](const WallFace &) {
                                 ++laid[w];
                                 return wall.masonry;
                             },
                             hash};
    };
    MasonryShader given({{wall.masonry, wall.face}, {wall.masonry, wall.face}});
    MasonryShader shader({{{}, wall.face, recipe(0, 1)}, {{}, wall.face, recipe(1, 2)}});
    EXPECT_EQ(laid[0] + laid[1], 0);
    // Many threads reach the second wall at once: it is laid once, and every one of them sees it
    // as the wall given laid.
    std::vector<std::thread> threads;
    std::atomic<int> differing{0};
    for (int t = 0; t < 8; ++t)
        threads.emplace_back([&, t] {
            for (int k = 0; k < 200; ++k) {
                Vec2d p{0.01 + 0.0297 * (k + t), 0.02 + 0.0193 * (k * t % 200)};
                for (float footprint : {1e-5f, 0.01f, 0.3f})
                    differing += shader.shade(shader.uvOf(1, p), footprint).colour !=
                        given.shade(given.uvOf(1, p), footprint).colour;
            }
        });
    for (std::thread &thread : threads) thread.join();
    EXPECT_EQ(laid[0], 0);
    EXPECT_EQ(laid[1], 1);
    EXPECT_EQ(differing, 0);
    // The recipe's hash stands for the stones it will lay.
    MasonryShader same({{{}, wall.face, recipe(0, 1)}, {{}, wall.face, recipe(1, 2)}});
    MasonryShader other({{{}, wall.face, recipe(0, 1)}, {{}, wall.face, recipe(1, 3)}});
    EXPECT_EQ(same.fingerprint(), shader.fingerprint());
    EXPECT_NE(other.fingerprint(), shader.fingerprint());
    EXPECT_NE(given.fingerprint(), shader.fingerprint());
}

TEST(MasonryShader, TheTextureRegistryAnswersWithTheShadersMaps) {
    BrickWall wall;
    int laid = 0;
    MasonryRecipe recipe{[&](const WallFace &) {
                             ++laid;
                             return wall.masonry;
                         },
                         1};
    auto shader = std::make_shared<const MasonryShader>(std::vector<ShadedWall>{{{}, wall.face, recipe}});
    std::shared_ptr<Textures> textures =
        imageLibrary().makeTextures(std::filesystem::temp_directory_path() / "veduta-masonry-shader-test");
    TextureId diffuse = textures->add(std::make_shared<MasonryTexture>(shader, MasonryMap::Diffuse));
    TextureId normal = textures->add(std::make_shared<MasonryTexture>(shader, MasonryMap::Normal));
    TextureId specular = textures->add(std::make_shared<MasonryTexture>(shader, MasonryMap::Specular));
    EXPECT_EQ(laid, 0) << "registering the maps laid the wall";
    EXPECT_EQ(textures->channels(diffuse), 3);
    EXPECT_EQ(textures->channels(specular), 1);
    EXPECT_NE(textures->fingerprint(diffuse), textures->fingerprint(normal));
    for (float footprint : {0.001f, 0.05f, 2.0f}) {
        Vec2f uv = shader->uvOf(0, {1.13, 0.41});
        MasonrySample sample = shader->shade(uv, footprint);
        float out[3];
        textures->lookup(diffuse, uv, footprint, out, 3);
        EXPECT_EQ(Vec3f(out[0], out[1], out[2]), sample.colour) << footprint;
        textures->lookup(normal, uv, footprint, out, 3);
        EXPECT_NEAR(out[0], sample.normal.x * 0.5f + 0.5f, 1e-6f);
        textures->lookup(specular, uv, footprint, out, 1);
        EXPECT_EQ(out[0], sample.specular);
    }
}

}  // namespace
}  // namespace veduta
