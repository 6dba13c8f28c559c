#include "facade/masonry_atlas.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "facade/brick_bond.h"
#include "thesis_figures.h"

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<AtlasWall> atlasWalls(const std::vector<Masonry> &masonry, const std::vector<WallFace> &faces) {
    std::vector<AtlasWall> walls;
    for (size_t i = 0; i < faces.size(); ++i) walls.push_back({&masonry[i], &faces[i]});
    return walls;
}

// The texel of `image` under (u, v) as Textures::lookup reads them: v up from the bottom row,
// wrapping periodically; `channel` of the nearest texel, or bilinear between the four around.
int wrap(int i, int n) { return ((i % n) + n) % n; }

float texel(const Image &image, int column, int rowFromBottom, int channel) {
    return image.at(wrap(column, image.width), image.height - 1 - wrap(rowFromBottom, image.height))[channel];
}

float nearest(const Image &image, Vec2f uv, int channel) {
    return texel(image, int(std::floor(uv.x * image.width)), int(std::floor(uv.y * image.height)), channel);
}

float bilinear(const Image &image, Vec2f uv, int channel) {
    double x = double(uv.x) * image.width - 0.5, y = double(uv.y) * image.height - 0.5;
    int column = int(std::floor(x)), row = int(std::floor(y));
    double fx = x - column, fy = y - row;
    return float((1 - fx) * (1 - fy) * texel(image, column, row, channel) +
                 fx * (1 - fy) * texel(image, column + 1, row, channel) +
                 (1 - fx) * fy * texel(image, column, row + 1, channel) +
                 fx * fy * texel(image, column + 1, row + 1, channel));
}

// Five walls in their own coordinates (not all from 0), with windows and gabled or octagonal
// openings whose edges fall on no texel boundary, and a blank pier; bricks of Fig. 5.7 at 1/8.
std::vector<WallFace> housesWalls() {
    std::vector<Vec2d> octagon;
    for (int i = 0; i < 8; ++i) {
        double a = (i + 0.5) * 2 * std::numbers::pi / 8;
        octagon.push_back({3.013 + 0.53 * std::cos(a), 4.71 + 0.53 * std::sin(a)});
    }
    return {
        {rectangle(0, 0, 5, 3),
         {rectangle(1.013, 0.9037, 1.987, 2.41),
          {{3.11, 0.77}, {4.07, 0.77}, {4.07, 2.03}, {3.59, 2.51}, {3.11, 2.03}}}},
        {rectangle(12.3, -0.4, 15.77, 6.1), {rectangle(12.91, 0.333, 13.87, 1.9), rectangle(13.2, 3.05, 15.1, 5.55)}},
        {{{0, 0}, {6, 0}, {6, 4}, {3, 6.5}, {0, 4}}, {octagon, rectangle(0.77, 0.61, 2.29, 3.3)}},
        {rectangle(-2, 0, -1.1, 3), {}},
        {rectangle(0.5, 0.5, 2.6, 1.7), {rectangle(1.01, 0.79, 2.03, 1.41)}},
    };
}

std::vector<Masonry> bricksOn(const std::vector<WallFace> &faces) {
    BrickBond bond = parseBrickBond(thesis::kFigure5_7, "fig5_7.txt");
    std::vector<Masonry> masonry;
    for (size_t i = 0; i < faces.size(); ++i) masonry.push_back(layBrickBond(bond, faces[i], {0.125, 3, uint32_t(i)}));
    return masonry;
}

constexpr size_t kLargeBudget = size_t(1) << 26;

TEST(MasonryAtlas, TheTexturesEdgeMatchesEveryOpeningWithinATexel) {
    std::vector<WallFace> faces = housesWalls();
    std::vector<Masonry> masonry = bricksOn(faces);
    const double s = 0.02;
    MasonryAtlas atlas = bakeMasonryAtlas(atlasWalls(masonry, faces), s, {}, kLargeBudget);
    ASSERT_DOUBLE_EQ(atlas.layout.texelSize, s);
    // The walls lie at different places: no two regions share their corner.
    for (size_t i = 0; i < faces.size(); ++i)
        for (size_t j = i + 1; j < faces.size(); ++j)
            EXPECT_TRUE(atlas.layout.regions[i].x != atlas.layout.regions[j].x ||
                        atlas.layout.regions[i].y != atlas.layout.regions[j].y);
    int samples = 0;
    for (size_t wall = 0; wall < faces.size(); ++wall)
        for (const std::vector<Vec2d> &opening : faces[wall].openings)
            for (size_t i = 0; i < opening.size(); ++i) {
                Vec2d a = opening[i], b = opening[(i + 1) % opening.size()];
                double edge = length(b - a);
                Vec2d along = (b - a) * (1 / edge);
                Vec2d out{along.y, -along.x};  // counter-clockwise: the outside is on the right
                bool axisParallel = along.x == 0 || along.y == 0;
                // From two texels past each corner, every third of a texel along the edge.
                for (double t = 2 * s; t <= edge - 2 * s; t += s / 3) {
                    Vec2d p = a + along * t;
                    Vec2f in = atlas.uvOf(wall, p - out * s), beyond = atlas.uvOf(wall, p + out * s);
                    EXPECT_EQ(nearest(atlas.diffuse, in, 3), 0.0f) << wall << " " << p.x << "," << p.y;
                    EXPECT_EQ(nearest(atlas.diffuse, beyond, 3), 1.0f) << wall << " " << p.x << "," << p.y;
                    // The renderer's cut-out threshold (Material::opacityMap) under a bilinear lookup;
                    // along a jamb, sill or lintel it reads no texel from the other side at all.
                    float tolerance = axisParallel ? 1e-4f : 0.1f;
                    EXPECT_LT(bilinear(atlas.diffuse, in, 3), tolerance) << wall << " " << p.x << "," << p.y;
                    EXPECT_GT(bilinear(atlas.diffuse, beyond, 3), 1 - tolerance) << wall << " " << p.x << "," << p.y;
                    ++samples;
                }
            }
    EXPECT_GT(samples, 3000);
}

TEST(MasonryAtlas, EachRegionHoldsItsWallsOwnBakeTexelForTexel) {
    std::vector<WallFace> faces = housesWalls();
    std::vector<Masonry> masonry = bricksOn(faces);
    MasonryLook look{0.07f, 0.01f, 0.01};
    MasonryAtlas atlas = bakeMasonryAtlas(atlasWalls(masonry, faces), 0.03, look, kLargeBudget);
    for (size_t wall = 0; wall < faces.size(); ++wall) {
        const AtlasRegion &region = atlas.layout.regions[wall];
        MasonryTextures own = bakeMasonry(masonry[wall], faces[wall], 0.03, look);
        ASSERT_EQ(region.width, own.diffuse.width);
        ASSERT_EQ(region.height, own.diffuse.height);
        EXPECT_EQ(region.origin, own.origin);
        for (int row = 0; row < region.height; ++row)
            for (int x = 0; x < region.width; ++x) {
                for (int c = 0; c < 4; ++c)
                    ASSERT_EQ(atlas.diffuse.at(region.x + x, region.y + row)[c], own.diffuse.at(x, row)[c]);
                for (int c = 0; c < 3; ++c)
                    ASSERT_EQ(atlas.normal.at(region.x + x, region.y + row)[c], own.normal.at(x, row)[c]);
                ASSERT_EQ(*atlas.specular.at(region.x + x, region.y + row), *own.specular.at(x, row));
            }
    }
}

// Walls of one colour each (a stone and the mortar), the stones reaching the walls' edges, one
// opening running out of its wall's right edge.
struct ColouredWalls {
    std::vector<WallFace> faces;
    std::vector<Masonry> masonry;
};

ColouredWalls colouredWalls() {
    ColouredWalls walls;
    for (int i = 0; i < 6; ++i) {
        double w = 1.3 + 0.45 * i, h = 2.9 - 0.31 * i;
        WallFace face{rectangle(0, 0, w, h), {}};
        if (i == 2) face.openings.push_back({{w - 0.4, 0.5}, {w + 0.2, 0.5}, {w + 0.2, 1.0}, {w - 0.4, 1.0}});
        Vec3f mortar(0.1f * float(i), 0.5f, 0.02f), stone(0.05f + 0.1f * float(i), 0.9f, 0.7f);
        Masonry masonry{{{rectangle(-0.1, h * 0.6, w * 0.7, h + 0.1), stone, 0.02}}, mortar, 0.01};
        walls.faces.push_back(face);
        walls.masonry.push_back(masonry);
    }
    return walls;
}

TEST(MasonryAtlas, GuttersRepeatTheirOwnWallsEdgeAndNeverCarryAnotherWallsColour) {
    ColouredWalls walls = colouredWalls();
    MasonryAtlas atlas = bakeMasonryAtlas(atlasWalls(walls.masonry, walls.faces), 0.02, {}, kLargeBudget);
    const MasonryAtlasLayout &layout = atlas.layout;
    std::vector<int> owner(size_t(layout.width) * size_t(layout.height), -1);
    int transparentGutter = 0;
    for (size_t wall = 0; wall < walls.faces.size(); ++wall) {
        const AtlasRegion &r = layout.regions[wall];
        const Masonry &m = walls.masonry[wall];
        for (int row = r.y - kAtlasGutter; row < r.y + r.height + kAtlasGutter; ++row)
            for (int x = r.x - kAtlasGutter; x < r.x + r.width + kAtlasGutter; ++x) {
                owner[size_t(row) * size_t(layout.width) + size_t(x)] = int(wall);
                int edgeX = std::clamp(x, r.x, r.x + r.width - 1), edgeRow = std::clamp(row, r.y, r.y + r.height - 1);
                const float *d = atlas.diffuse.at(x, row);
                for (int c = 0; c < 4; ++c) EXPECT_EQ(d[c], atlas.diffuse.at(edgeX, edgeRow)[c]);
                for (int c = 0; c < 3; ++c) EXPECT_EQ(atlas.normal.at(x, row)[c], atlas.normal.at(edgeX, edgeRow)[c]);
                EXPECT_EQ(*atlas.specular.at(x, row), *atlas.specular.at(edgeX, edgeRow));
                Vec3f colour(d[0], d[1], d[2]), stone = m.stones[0].colour;
                bool own = (colour.x == m.mortarColour.x && colour.y == m.mortarColour.y) ||
                    (colour.x == stone.x && colour.y == stone.y);
                EXPECT_TRUE(own) << wall << " at " << x << "," << row;
                bool inGutter = x < r.x || x >= r.x + r.width || row < r.y || row >= r.y + r.height;
                transparentGutter += inGutter && d[3] == 0.0f;
            }
    }
    // The opening that leaves its wall's right edge is transparent in the gutter too: 0.5 m at
    // 2 cm per texel, 25 rows, times the gutter's width.
    EXPECT_EQ(transparentGutter, 25 * kAtlasGutter);
    // What no wall owns is transparent black with a flat normal.
    int unused = 0;
    for (int row = 0; row < layout.height; ++row)
        for (int x = 0; x < layout.width; ++x) {
            if (owner[size_t(row) * size_t(layout.width) + size_t(x)] >= 0) continue;
            ++unused;
            for (int c = 0; c < 4; ++c) EXPECT_EQ(atlas.diffuse.at(x, row)[c], 0.0f);
            EXPECT_EQ(atlas.normal.at(x, row)[0], 0.5f);
            EXPECT_EQ(atlas.normal.at(x, row)[1], 0.5f);
            EXPECT_EQ(atlas.normal.at(x, row)[2], 1.0f);
            EXPECT_EQ(*atlas.specular.at(x, row), 0.0f);
        }
    EXPECT_GT(unused, 0);
}

TEST(MasonryAtlas, UvMapsPutEachWallsCornersAtItsRegionsTexelCorners) {
    // Sizes in whole texels of 1/32 m, so the faces' corners are the regions' corners.
    const double s = 1.0 / 32;
    std::vector<WallFace> faces{{rectangle(2, 1, 4, 4), {}},
                                {rectangle(-7.5, 0.25, -3, 2.5), {}},
                                {rectangle(100, 50, 101.5, 56), {}},
                                {rectangle(0, 0, 3.1, 1.7), {}}};
    std::vector<Masonry> masonry(faces.size());
    MasonryAtlas atlas = bakeMasonryAtlas(atlasWalls(masonry, faces), s, {}, kLargeBudget);
    const double w = atlas.layout.width, h = atlas.layout.height;
    for (size_t wall = 0; wall < 3; ++wall) {
        const AtlasRegion &r = atlas.layout.regions[wall];
        Vec2d low = faces[wall].outline[0], high = faces[wall].outline[2];
        EXPECT_EQ(r.width, int((high.x - low.x) / s));
        EXPECT_EQ(r.height, int((high.y - low.y) / s));
        Vec2f lowUv = atlas.uvOf(wall, low), highUv = atlas.uvOf(wall, high);
        EXPECT_NEAR(lowUv.x, r.x / w, 1e-7);
        EXPECT_NEAR(lowUv.y, (h - r.y - r.height) / h, 1e-7);  // the bottom edge of its lowest row
        EXPECT_NEAR(highUv.x, (r.x + r.width) / w, 1e-7);
        EXPECT_NEAR(highUv.y, (h - r.y) / h, 1e-7);  // the top edge of its top row
    }
    // A wall not a whole number of texels: its region is rounded up, the high corner inside its last texel.
    const AtlasRegion &r = atlas.layout.regions[3];
    EXPECT_EQ(r.width, 100);  // 3.1 m / (1/32 m) = 99.2
    EXPECT_EQ(r.height, 55);  // 1.7 m → 54.4
    Vec2f highUv = atlas.uvOf(3, {3.1, 1.7});
    EXPECT_NEAR(highUv.x * w, r.x + 99.2, 1e-3);
    EXPECT_NEAR(highUv.y * h, h - r.y - 55 + 54.4, 1e-3);
}

bool slotsOverlap(const AtlasRegion &a, const AtlasRegion &b) {
    int g = kAtlasGutter;
    return a.x - g < b.x + b.width + g && b.x - g < a.x + a.width + g && a.y - g < b.y + b.height + g &&
        b.y - g < a.y + a.height + g;
}

// Forty walls of assorted sizes, plain mortar with a window each.
std::vector<WallFace> streetWalls() {
    std::vector<WallFace> faces;
    for (int i = 0; i < 40; ++i) {
        double w = 1.5 + 0.9 * (i % 7), h = 2.5 + 0.7 * (i % 5);
        faces.push_back({rectangle(0, 0, w, h), {rectangle(0.5, 0.6, 1.2, 1.9)}});
    }
    return faces;
}

TEST(MasonryAtlas, PackedRegionsWithTheirGuttersNeverOverlapAndStayInTheAtlas) {
    std::vector<WallFace> faces = streetWalls();
    std::vector<Masonry> masonry(faces.size());
    MasonryAtlasLayout layout = layOutMasonryAtlas(atlasWalls(masonry, faces), 0.04, kLargeBudget);
    ASSERT_EQ(layout.regions.size(), faces.size());
    double used = 0;
    for (size_t i = 0; i < layout.regions.size(); ++i) {
        const AtlasRegion &a = layout.regions[i];
        EXPECT_GE(a.x - kAtlasGutter, 0);
        EXPECT_GE(a.y - kAtlasGutter, 0);
        EXPECT_LE(a.x + a.width + kAtlasGutter, layout.width);
        EXPECT_LE(a.y + a.height + kAtlasGutter, layout.height);
        used += double(a.width + 2 * kAtlasGutter) * double(a.height + 2 * kAtlasGutter);
        for (size_t j = i + 1; j < layout.regions.size(); ++j)
            EXPECT_FALSE(slotsOverlap(a, layout.regions[j])) << i << " and " << j;
    }
    // Shelves waste little: the regions fill most of the atlas.
    EXPECT_GT(used / (double(layout.width) * layout.height), 0.75);
}

TEST(MasonryAtlas, ATightBudgetCoarsensAllWallsAlikeToTheFirstLadderStepThatFits) {
    std::vector<WallFace> faces = streetWalls();
    std::vector<Masonry> masonry = bricksOn(faces);
    std::vector<AtlasWall> walls = atlasWalls(masonry, faces);
    const double asked = 0.01;
    const size_t budget = 300000;
    MasonryAtlas atlas = bakeMasonryAtlas(walls, asked, {}, budget);
    const MasonryAtlasLayout &layout = atlas.layout;
    EXPECT_LE(size_t(layout.width) * size_t(layout.height), budget);
    EXPECT_EQ(atlas.diffuse.pixels.size(), size_t(layout.width) * size_t(layout.height) * 4);
    ASSERT_GT(layout.texelSize, asked);
    ASSERT_LT(layout.texelSize, kCoarsestAtlasTexel);
    // A step of the ladder, and the one below it does not fit.
    double step = kAtlasTexelSteps * std::log2(layout.texelSize / asked);
    EXPECT_NEAR(step, std::round(step), 1e-9);
    MasonryAtlasLayout finer =
        layOutMasonryAtlas(walls, asked * std::exp2((std::round(step) - 1) / kAtlasTexelSteps), kLargeBudget);
    EXPECT_GT(size_t(finer.width) * size_t(finer.height), budget);
    // All walls at the one texel size.
    for (size_t i = 0; i < faces.size(); ++i) {
        EXPECT_EQ(layout.regions[i].width, int(std::ceil(faces[i].outline[2].x / layout.texelSize)));
        EXPECT_EQ(layout.regions[i].height, int(std::ceil(faces[i].outline[2].y / layout.texelSize)));
    }
    // The same walls give the same atlas.
    MasonryAtlas again = bakeMasonryAtlas(walls, asked, {}, budget);
    EXPECT_EQ(again.layout.texelSize, layout.texelSize);
    EXPECT_EQ(again.diffuse.pixels, atlas.diffuse.pixels);
    EXPECT_EQ(again.normal.pixels, atlas.normal.pixels);
    EXPECT_EQ(again.specular.pixels, atlas.specular.pixels);
    for (size_t i = 0; i < faces.size(); ++i) {
        EXPECT_EQ(again.layout.regions[i].x, layout.regions[i].x);
        EXPECT_EQ(again.layout.regions[i].y, layout.regions[i].y);
    }
}

TEST(MasonryAtlas, RefusesOnlyWhenEvenATexelPerTenCentimetresDoesNotFit) {
    std::vector<WallFace> faces = streetWalls();
    std::vector<Masonry> masonry(faces.size());
    std::vector<AtlasWall> walls = atlasWalls(masonry, faces);
    MasonryAtlasLayout coarsest = layOutMasonryAtlas(walls, kCoarsestAtlasTexel, kLargeBudget);
    size_t needed = size_t(coarsest.width) * size_t(coarsest.height);
    MasonryAtlasLayout fits = layOutMasonryAtlas(walls, 0.001, needed);
    EXPECT_LE(size_t(fits.width) * size_t(fits.height), needed);
    EXPECT_LE(fits.texelSize, kCoarsestAtlasTexel);
    EXPECT_THROW(layOutMasonryAtlas(walls, 0.001, needed - 1), std::length_error);
    EXPECT_THROW(layOutMasonryAtlas(walls, 0.5, 1000), std::length_error);
    EXPECT_THROW(layOutMasonryAtlas(walls, 0.01, 0), std::length_error);
    EXPECT_THROW(layOutMasonryAtlas(walls, 0.0, kLargeBudget), std::invalid_argument);
    EXPECT_THROW(layOutMasonryAtlas(walls, std::nan(""), kLargeBudget), std::invalid_argument);
    EXPECT_THROW(layOutMasonryAtlas({{nullptr, &faces[0]}}, 0.01, kLargeBudget), std::invalid_argument);
    WallFace line{{{0, 0}, {1, 0}}, {}};
    EXPECT_THROW(layOutMasonryAtlas({{&masonry[0], &line}}, 0.01, kLargeBudget), std::invalid_argument);
    WallFace far{{{0, 0}, {std::numeric_limits<double>::infinity(), 0}, {0, 1}}, {}};
    EXPECT_THROW(layOutMasonryAtlas({{&masonry[0], &far}}, 0.01, kLargeBudget), std::invalid_argument);
    MasonryAtlasLayout none = layOutMasonryAtlas({}, 0.01, 0);
    EXPECT_EQ(none.width, 0);
    EXPECT_TRUE(none.regions.empty());
}

// A wall may ask for a coarser texel than the atlas's (farther from the camera, or facing away):
// its region shrinks by that factor, up to the coarsest texel, its map stays true, and a tight
// budget coarsens every wall by the same step.
TEST(MasonryAtlas, EachWallTakesItsOwnTexelUpToTheCoarsest) {
    std::vector<WallFace> faces{{rectangle(0, 0, 4, 3), {}}, {rectangle(0, 0, 4, 3), {}}, {rectangle(0, 0, 4, 3), {}}};
    std::vector<Masonry> masonry(faces.size());
    std::vector<AtlasWall> walls = atlasWalls(masonry, faces);
    walls[1].texelScale = 4;
    walls[2].texelScale = 1000;
    MasonryAtlasLayout layout = layOutMasonryAtlas(walls, 0.01, kLargeBudget);
    EXPECT_DOUBLE_EQ(layout.texelSize, 0.01);
    EXPECT_DOUBLE_EQ(layout.regions[0].texelSize, 0.01);
    EXPECT_DOUBLE_EQ(layout.regions[1].texelSize, 0.04);
    EXPECT_DOUBLE_EQ(layout.regions[2].texelSize, kCoarsestAtlasTexel);
    EXPECT_EQ(layout.regions[0].width, 400);
    EXPECT_EQ(layout.regions[1].width, 100);
    EXPECT_EQ(layout.regions[2].width, 40);
    for (size_t i = 0; i < 3; ++i) {
        // A wall metre is 1 / texel columns: the map's scale in atlas widths.
        EXPECT_NEAR(layout.regions[i].uv.scale.x * layout.width, 1 / layout.regions[i].texelSize, 1e-9) << i;
        Vec2f corner = layout.regions[i].uv({0, 3});
        EXPECT_NEAR(corner.x * layout.width, layout.regions[i].x, 1e-3) << i;
        EXPECT_NEAR((1 - corner.y) * layout.height, layout.regions[i].y, 1e-3) << i;
    }
    // Room for the three only at twice the texel: the coarse wall, already at the coarsest, stays.
    size_t budget = size_t((200 + 8) * (150 + 8) + (50 + 8) * (38 + 8) + (40 + 8) * (30 + 8)) * 2;
    MasonryAtlasLayout tight = layOutMasonryAtlas(walls, 0.01, budget);
    EXPECT_GT(tight.texelSize, 0.01);
    EXPECT_LE(size_t(tight.width) * size_t(tight.height), budget);
    EXPECT_DOUBLE_EQ(tight.regions[1].texelSize, 4 * tight.texelSize);
    EXPECT_DOUBLE_EQ(tight.regions[2].texelSize, kCoarsestAtlasTexel);
    walls[1].texelScale = 0.5;
    EXPECT_THROW(layOutMasonryAtlas(walls, 0.01, kLargeBudget), std::invalid_argument);
    walls[1].texelScale = std::nan("");
    EXPECT_THROW(layOutMasonryAtlas(walls, 0.01, kLargeBudget), std::invalid_argument);
}

TEST(MasonryAtlas, AWallWithoutStonesIsBakedAsMortarWithItsOpeningsCut) {
    std::vector<WallFace> faces{{rectangle(0, 0, 2, 2), {rectangle(0.5, 0.5, 1.5, 1.5)}}};
    std::vector<Masonry> masonry{{{}, Vec3f(0.6f, 0.55f, 0.5f), 0.01}};
    MasonryAtlas atlas = bakeMasonryAtlas(atlasWalls(masonry, faces), 0.0625, {}, kLargeBudget);
    const AtlasRegion &r = atlas.layout.regions[0];
    ASSERT_EQ(r.width, 32);
    int holes = 0;
    for (int row = r.y; row < r.y + r.height; ++row)
        for (int x = r.x; x < r.x + r.width; ++x) {
            const float *d = atlas.diffuse.at(x, row);
            EXPECT_EQ(d[0], 0.6f);
            EXPECT_EQ(d[2], 0.5f);
            holes += d[3] == 0.0f;
        }
    EXPECT_EQ(holes, 16 * 16);
    EXPECT_EQ(nearest(atlas.diffuse, atlas.uvOf(0, {1.0, 1.0}), 3), 0.0f);
    EXPECT_EQ(nearest(atlas.diffuse, atlas.uvOf(0, {0.2, 1.0}), 3), 1.0f);
}

}  // namespace
}  // namespace veduta
