#include "facade/masonry_texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Stone stone(std::vector<Vec2d> outline, Vec3f colour, double depth = 0.01) {
    return {std::move(outline), colour, depth};
}

// Whether p lies inside the polygon (even-odd), exactly as the definition says.
bool inside(const std::vector<Vec2d> &polygon, Vec2d p) {
    bool in = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        Vec2d a = polygon[i], b = polygon[j];
        if ((a.y <= p.y) != (b.y <= p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

Vec2d texelCentre(const MasonryTextures &t, int x, int row) {
    double top = t.origin.y + t.diffuse.height * t.texelSize;
    return {t.origin.x + (x + 0.5) * t.texelSize, top - (row + 0.5) * t.texelSize};
}

TEST(MasonryTexture, EachTexelShowsTheStoneOrTheMortarUnderItsCentre) {
    WallFace face{rectangle(0, 0, 2, 1), {}};
    Masonry masonry{{stone(rectangle(0.1, 0.1, 0.9, 0.4), {0.6f, 0.2f, 0.1f})}, {0.3f, 0.3f, 0.3f}, 0.01};
    MasonryTextures t = bakeMasonry(masonry, face, 0.01);
    ASSERT_EQ(t.diffuse.width, 200);
    ASSERT_EQ(t.diffuse.height, 100);
    int brickTexels = 0;
    for (int row = 0; row < 100; ++row)
        for (int x = 0; x < 200; ++x) {
            const float *d = t.diffuse.at(x, row);
            bool onBrick = inside(masonry.stones[0].outline, texelCentre(t, x, row));
            EXPECT_FLOAT_EQ(d[0], onBrick ? 0.6f : 0.3f) << x << "," << row;
            EXPECT_FLOAT_EQ(d[3], 1.0f);
            EXPECT_FLOAT_EQ(*t.specular.at(x, row), onBrick ? 0.04f : 0.0f);
            brickTexels += onBrick;
        }
    EXPECT_EQ(brickTexels, 80 * 30);
    // The top row is the top of the wall: the brick (y 0.1 to 0.4) is in rows 60 to 89.
    EXPECT_FLOAT_EQ(t.diffuse.at(50, 60)[0], 0.6f);
    EXPECT_FLOAT_EQ(t.diffuse.at(50, 59)[0], 0.3f);
    EXPECT_FLOAT_EQ(t.diffuse.at(50, 89)[0], 0.6f);
    EXPECT_FLOAT_EQ(t.diffuse.at(50, 90)[0], 0.3f);
}

TEST(MasonryTexture, TheOpeningsEdgeIsWithinATexelOfTheOpening) {
    // An arched-looking opening with slanted sides at no texel boundary, and a brick through it
    // that the texture must not show inside the hole.
    std::vector<Vec2d> opening{{1.013, 0.5037}, {1.987, 0.5037}, {1.987, 1.61}, {1.5, 1.93}, {1.013, 1.61}};
    WallFace face{rectangle(0, 0, 3, 2.2), {opening}};
    Masonry masonry{{stone(rectangle(0.5, 1.0, 2.5, 1.3), {0.7f, 0.3f, 0.2f})}, {0.4f, 0.4f, 0.4f}, 0.01};
    double s = 0.02;
    MasonryTextures t = bakeMasonry(masonry, face, s);
    int holeTexels = 0;
    for (int row = 0; row < t.diffuse.height; ++row)
        for (int x = 0; x < t.diffuse.width; ++x) {
            Vec2d centre = texelCentre(t, x, row);
            bool inHole = t.diffuse.at(x, row)[3] == 0.0f;
            EXPECT_EQ(inHole, inside(opening, centre)) << x << "," << row;
            holeTexels += inHole;
            // Every texel of the hole lies within a texel's diagonal of the opening itself.
            if (inHole) {
                bool near = false;
                for (double dx : {-s, 0.0, s})
                    for (double dy : {-s, 0.0, s}) near |= inside(opening, {centre.x + dx, centre.y + dy});
                EXPECT_TRUE(near);
            }
        }
    // The hole's area in texels agrees with the opening's to within its outline's length in texels.
    double area = 0.974 * (1.61 - 0.5037) + 0.5 * 0.974 * (1.93 - 1.61);
    double perimeter = 2 * (1.61 - 0.5037) + 0.974 + 2 * std::hypot(0.487, 0.32);
    EXPECT_NEAR(holeTexels * s * s, area, perimeter * s);
}

TEST(MasonryTexture, NormalsLeanOutOfTheStonesEdgesTheOpenGLWay) {
    WallFace face{rectangle(0, 0, 1, 1), {}};
    Masonry masonry{{stone(rectangle(0.2, 0.2, 0.8, 0.8), {0.5f, 0.5f, 0.5f}, 0.02)}, {0.2f, 0.2f, 0.2f}, 0.01};
    MasonryTextures t = bakeMasonry(masonry, face, 0.01);
    auto normal = [&](int x, int row) {
        const float *n = t.normal.at(x, row);
        return Vec3f(n[0] * 2 - 1, n[1] * 2 - 1, n[2] * 2 - 1);
    };
    // In the mortar far from the stone and on the stone's face: straight out.
    EXPECT_NEAR(normal(5, 5).z, 1.0f, 1e-6);
    EXPECT_NEAR(normal(50, 50).z, 1.0f, 1e-6);
    // At the left edge (x = 0.2, column 20) the face leans left, at the right edge right; at the
    // top edge (y = 0.8, row 20) up: green grows upwards (OpenGL), as Material::normalMap reads it.
    EXPECT_LT(normal(20, 50).x, -0.1f);
    EXPECT_GT(normal(79, 50).x, 0.1f);
    EXPECT_GT(normal(50, 20).y, 0.1f);
    EXPECT_LT(normal(50, 79).y, -0.1f);
    for (int row = 0; row < 100; ++row)
        for (int x = 0; x < 100; ++x) EXPECT_NEAR(length(normal(x, row)), 1.0f, 1e-5);
}

TEST(MasonryTexture, RefusesTexturesPastItsLimitAndTexelsOfNoSize) {
    WallFace face{rectangle(0, 0, 10, 10), {}};
    Masonry masonry;
    EXPECT_THROW(bakeMasonry(masonry, face, 0.001, {}, 1000000), std::invalid_argument);
    EXPECT_NO_THROW(bakeMasonry(masonry, face, 0.01, {}, 1000000));
    EXPECT_THROW(bakeMasonry(masonry, face, 0.0), std::invalid_argument);
    EXPECT_THROW(bakeMasonry(masonry, face, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace veduta
