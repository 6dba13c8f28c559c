#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

#include "scene/cubemap.h"
#include "scene/cubemap_layout.h"

namespace veduta {
namespace {

using RadianceFunction = std::function<Vec3f(const Vec3f &)>;

// Smooth over the sphere, different in each channel and in every direction.
Vec3f smooth(const Vec3f &d) {
    float s = dot(d, normalize(Vec3f{0.3f, -0.5f, 0.8f})) + d.z * d.z;
    return {s + 1, 0.5f * d.x + 1, d.y * d.y};
}
constexpr float kSmoothGradientBound = 3;  // |∇| of each channel of `smooth` on the sphere is below this

Cubemap baked(int size, const RadianceFunction &f) {
    Cubemap cube(size);
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) cube.texel(face, x, y) = f(cube.direction(face, x + 0.5f, y + 0.5f));
        }
    }
    return cube;
}

float maxDifference(const Vec3f &a, const Vec3f &b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

float largestTexelDifference(const Cubemap &a, const Cubemap &b) {
    float largest = 0;
    for (int f = 0; f < kCubeFaceCount; ++f) {
        for (int y = 0; y < a.size(); ++y) {
            for (int x = 0; x < a.size(); ++x) {
                largest = std::max(largest, maxDifference(a.texel(f, x, y), b.texel(f, x, y)));
            }
        }
    }
    return largest;
}

float angleBetween(const Vec3f &a, const Vec3f &b) { return 2 * std::asin(std::min(1.0f, length(a - b) / 2)); }

TEST(Cubemap, FaceFramesAreOrthonormalAndLookOut) {
    for (int f = 0; f < kCubeFaceCount; ++f) {
        const CubeFaceFrame &frame = cubeFaceFrame(f);
        EXPECT_EQ(length(frame.forward), 1);
        EXPECT_EQ(length(frame.right), 1);
        EXPECT_EQ(length(frame.up), 1);
        EXPECT_EQ(dot(frame.forward, frame.right), 0);
        EXPECT_EQ(dot(frame.forward, frame.up), 0);
        // Seen from inside, as a camera looking out: right × up points back at the viewer.
        EXPECT_EQ(cross(frame.right, frame.up), -frame.forward) << cubeFaceName(f);
    }
    EXPECT_EQ(cubeFaceFrame(kEast).forward, Vec3f(1, 0, 0));
    EXPECT_EQ(cubeFaceFrame(kNorth).forward, Vec3f(0, 1, 0));
    EXPECT_EQ(cubeFaceFrame(kUp).forward, Vec3f(0, 0, 1));
    EXPECT_EQ(cubeFaceFrame(kSouth).forward, Vec3f(0, -1, 0));
    EXPECT_EQ(cubeFaceName(kWest), "west");
    EXPECT_EQ(cubeFaceName(kDown), "down");
}

// A cubemap whose texels hold their own directions, written as a cross: pixels side by side
// in the cross must look in nearly the same direction, also across the edges between faces.
TEST(Cubemap, CrossesHaveNoSeams) {
    constexpr int kSize = 16;
    Cubemap cube = baked(kSize, [](const Vec3f &d) { return d; });
    // Neighbouring texel centres are at most 2·atan(1/size) apart (at a face's centre).
    float limit = 2 * std::atan(1.0f / kSize) * 1.001f;
    for (bool vertical : {true, false}) {
        Image cross = crossFromCubemap(cube, vertical);
        auto directionAt = [&](int x, int y) { return Vec3f{cross.at(x, y)[0], cross.at(x, y)[1], cross.at(x, y)[2]}; };
        int pairsAcrossFaces = 0;
        for (int y = 0; y < cross.height; ++y) {
            for (int x = 0; x < cross.width; ++x) {
                Vec3f d = directionAt(x, y);
                if (length(d) == 0) continue;  // outside the cross
                for (auto [nx, ny] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
                    if (nx >= cross.width || ny >= cross.height || length(directionAt(nx, ny)) == 0) continue;
                    EXPECT_LT(angleBetween(d, directionAt(nx, ny)), limit)
                        << (vertical ? "vertical" : "horizontal") << " cross at " << x << "," << y;
                    if (nx / kSize != x / kSize || ny / kSize != y / kSize) ++pairsAcrossFaces;
                }
            }
        }
        // Five shared edges in either cross: up, west, east, down around north, and south
        // below down (vertical) or beside east (horizontal).
        EXPECT_EQ(pairsAcrossFaces, 5 * kSize) << (vertical ? "vertical" : "horizontal");
        // The faces are where docs/cubemap.md draws them.
        auto tileCentre = [&](int column, int row) {
            return directionAt(column * kSize + kSize / 2, row * kSize + kSize / 2);
        };
        EXPECT_GT(tileCentre(1, 1).y, 0.99f);                                   // north in the middle
        EXPECT_GT(tileCentre(1, 0).z, 0.99f);                                   // up above it
        EXPECT_LT(tileCentre(1, 2).z, -0.99f);                                  // down below it
        EXPECT_LT(tileCentre(0, 1).x, -0.99f);                                  // west on the left
        EXPECT_GT(tileCentre(2, 1).x, 0.99f);                                   // east on the right
        EXPECT_LT((vertical ? tileCentre(1, 3) : tileCentre(3, 1)).y, -0.99f);  // south
    }
}

TEST(Cubemap, LocateInvertsDirection) {
    Cubemap cube(7);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> position(0.0f, 7.0f);
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int i = 0; i < 200; ++i) {
            float x = position(rng), y = position(rng);
            CubeTexel t = cube.locate(cube.direction(face, x, y));
            EXPECT_EQ(t.face, face);
            EXPECT_NEAR(t.x, x, 1e-4f);
            EXPECT_NEAR(t.y, y, 1e-4f);
        }
    }
    // Directions off the unit sphere locate the same.
    CubeTexel t = cube.locate(Vec3f{5, -2, 1});
    EXPECT_EQ(t.face, kEast);
    EXPECT_NEAR(t.x, (2.0f / 5 + 1) * 3.5f, 1e-5f);  // right is −y
    EXPECT_NEAR(t.y, (1 - 1.0f / 5) * 3.5f, 1e-5f);
}

TEST(Cubemap, TexelSolidAnglesSumToFourPi) {
    for (int size : {1, 3, 32, 512}) {
        Cubemap cube(size);
        double sum = 0;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) sum += cube.texelSolidAngle(x, y);
        }
        EXPECT_NEAR(kCubeFaceCount * sum, 4 * M_PI, 1e-4) << size;
    }
    // Small texels subtend their area on the face plane over (1 + a² + b²)^(3/2) at their
    // centres (a, b): the corner texel over five times less than the centre one.
    Cubemap cube(512);
    auto jacobian = [](double a, double b) { return std::pow(1 + a * a + b * b, 1.5); };
    double centre = 1.0 / 512, corner = 1 - 1.0 / 512;
    EXPECT_NEAR(cube.texelSolidAngle(256, 256) / cube.texelSolidAngle(0, 0),
                jacobian(corner, corner) / jacobian(centre, centre), 1e-4);
}

// Directions either side of every point along every edge, and around every corner, a tiny
// angle apart: a continuous lookup barely changes between them, a lookup with seams jumps
// by about the function's change over a texel.
float largestSeamExcess(const RadianceFunction &lookup) {
    constexpr float kEpsilon = 1e-5f;
    // The continuous lookup's own change over 2ε (its slope is a few times the function's).
    constexpr float kSlack = 20 * kSmoothGradientBound * kEpsilon;
    float excess = 0;
    auto compare = [&](const Vec3f &p, const Vec3f &q) {
        Vec3f a = normalize(p), b = normalize(q);
        float change = maxDifference(smooth(a), smooth(b));
        excess = std::max(excess, maxDifference(lookup(a), lookup(b)) - change - kSlack);
    };
    for (int face = 0; face < kCubeFaceCount; ++face) {
        const CubeFaceFrame &f = cubeFaceFrame(face);
        for (int side = 0; side < 4; ++side) {
            Vec3f out = side == 0 ? f.right : side == 1 ? -f.right : side == 2 ? f.up : -f.up;
            Vec3f along = side < 2 ? f.up : f.right;
            for (int i = 0; i <= 256; ++i) {
                float t = -1 + 2 * float(i) / 256;
                compare(f.forward + out * (1 - kEpsilon) + along * t, f.forward * (1 - kEpsilon) + out + along * t);
            }
        }
    }
    for (int corner = 0; corner < 8; ++corner) {
        Vec3f c{corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, corner & 4 ? 1.0f : -1.0f};
        Frame frame = Frame::fromNormal(normalize(c));
        Vec3f previous = c + frame.s * kEpsilon;
        for (int i = 1; i <= 24; ++i) {
            float phi = 2 * kPi * float(i) / 24;
            Vec3f p = c + (frame.s * std::cos(phi) + frame.t * std::sin(phi)) * kEpsilon;
            compare(p, previous);
            compare(p, c);
            previous = p;
        }
    }
    return excess;
}

TEST(Cubemap, LookupIsContinuousAcrossEdgesAndCorners) {
    Cubemap cube = baked(32, smooth);
    EXPECT_LE(largestSeamExcess([&](const Vec3f &d) { return cube.lookup(d); }), 0.0f);
    // The test can fail: the nearest texel jumps at every edge.
    float nearestExcess = largestSeamExcess([&](const Vec3f &d) {
        CubeTexel t = cube.locate(d);
        return cube.texel(t.face, int(t.x), int(t.y));
    });
    EXPECT_GT(nearestExcess, 0.05f);
}

TEST(Cubemap, LookupInterpolatesBetweenTexelCentres) {
    Cubemap cube = baked(32, smooth);
    // At a texel centre it returns the texel itself.
    EXPECT_LT(maxDifference(cube.lookup(cube.direction(kNorth, 10.5f, 20.5f)), cube.texel(kNorth, 10, 20)), 1e-5f);
    // Inside a face it stays within the bilinear error of the function, h²·|f''|/8 with a
    // texel size h ≤ 2/32 and second derivatives of `smooth` below 8. Within a texel of an
    // edge, taps from the neighbouring face sit up to 1/32 (half a texel) along the edge from
    // where the weights put them, which adds up to that distance times the gradient.
    const float interiorBound = 0.0625f * 0.0625f, edgeBound = interiorBound + kSmoothGradientBound / 32;
    float interiorError = 0, edgeError = 0;
    std::mt19937 rng(5);
    std::normal_distribution<float> normal;
    for (int i = 0; i < 100000; ++i) {
        Vec3f d = normalize(Vec3f{normal(rng), normal(rng), normal(rng)});
        CubeTexel t = cube.locate(d);
        bool nearEdge = std::min({t.x, t.y, 32 - t.x, 32 - t.y}) < 1;
        float error = maxDifference(cube.lookup(d), smooth(d));
        (nearEdge ? edgeError : interiorError) = std::max(nearEdge ? edgeError : interiorError, error);
    }
    std::printf("[ lookup   ] largest error inside faces %.5f, within a texel of an edge %.5f\n", interiorError,
                edgeError);
    EXPECT_LT(interiorError, interiorBound);
    EXPECT_LT(edgeError, edgeBound);
}

TEST(Cubemap, TexelsAcrossAnEdgeComeFromTheNeighbouringFace) {
    Cubemap cube(4);
    cube.texel(kEast, 0, 1) = Vec3f(1.0f);   // east's left edge meets north's right edge
    cube.texel(kUp, 3, 3) = Vec3f(3.0f);     // the up face's corner above north's and east's
    cube.texel(kNorth, 3, 0) = Vec3f(2.0f);  // north's top-right corner
    cube.texel(kEast, 0, 0) = Vec3f(1.0f);   // east's top-left corner
    EXPECT_EQ(cube.texelAcrossEdges(kNorth, 4, 1), Vec3f(1.0f));
    EXPECT_EQ(cube.texelAcrossEdges(kEast, -1, 1), Vec3f(0.0f));  // north's (3, 1) is black
    EXPECT_EQ(cube.texelAcrossEdges(kNorth, 3, -1), Vec3f(3.0f));
    // Past north's top-right corner: the mean of north's, east's and up's corner texels.
    EXPECT_EQ(cube.texelAcrossEdges(kNorth, 4, -1), Vec3f(2.0f));
}

// Round trips through the layouts.

std::array<Image, kCubeFaceCount> randomFaces(int size) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> value(0.0f, 100.0f);
    std::array<Image, kCubeFaceCount> faces;
    for (Image &face : faces) {
        face = Image(size, size, 3);
        for (float &v : face.pixels) v = value(rng);
    }
    return faces;
}

TEST(CubemapLayout, FacesThroughCrossesComeBackBitIdentical) {
    std::array<Image, kCubeFaceCount> faces = randomFaces(8);
    Cubemap cube = cubemapFromFaces(faces);
    for (bool vertical : {true, false}) {
        Image cross = crossFromCubemap(cube, vertical);
        EXPECT_EQ(cross.width, vertical ? 24 : 32);
        EXPECT_EQ(cross.height, vertical ? 32 : 24);
        std::array<Image, kCubeFaceCount> back = facesFromCubemap(cubemapFromCross(cross));
        for (int f = 0; f < kCubeFaceCount; ++f) {
            EXPECT_EQ(back[size_t(f)].pixels, faces[size_t(f)].pixels)
                << cubeFaceName(f) << (vertical ? " vertical" : " horizontal");
        }
    }
}

TEST(CubemapLayout, ExtraChannelsAreIgnoredAndNegativeOrNanSamplesBecomeZero) {
    std::array<Image, kCubeFaceCount> faces;
    for (Image &face : faces) face = Image(2, 2, 4);
    float *p = faces[kUp].at(1, 0);
    p[0] = -1e-6f;
    p[1] = std::nanf("");
    p[2] = 2;
    p[3] = 7;  // alpha
    Cubemap cube = cubemapFromFaces(faces);
    EXPECT_EQ(cube.texel(kUp, 1, 0), Vec3f(0, 0, 2));
}

TEST(CubemapLayout, LatLongFollowsBlendersEquirectangularMapping) {
    auto expectDirection = [](float u, float v, Vec3f expected) {
        Vec3f d = latLongDirection(u, v);
        EXPECT_LT(length(d - expected), 1e-6f) << u << "," << v;
        Vec2f back = latLongPosition(d);
        if (std::abs(expected.z) < 0.5f) {
            EXPECT_NEAR(back.x, u, 1e-6f) << u << "," << v;
        }
        EXPECT_NEAR(back.y, v, 1e-6f) << u << "," << v;
    };
    expectDirection(0.5f, 0.5f, {1, 0, 0});    // centre: east
    expectDirection(0.75f, 0.5f, {0, -1, 0});  // right of centre: south
    expectDirection(0.25f, 0.5f, {0, 1, 0});   // left of centre: north
    expectDirection(0.5f, 0.0f, {0, 0, 1});    // top row: up
    expectDirection(0.5f, 1.0f, {0, 0, -1});
    expectDirection(0.5f, 0.25f, {std::sqrt(0.5f), 0, std::sqrt(0.5f)});
}

Image latLongOf(int width, const RadianceFunction &f) {
    Image image(width, width / 2, 3);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < width; ++x) {
            Vec3f v = f(latLongDirection((x + 0.5f) / float(width), (y + 0.5f) / float(image.height)));
            image.at(x, y)[0] = v.x;
            image.at(x, y)[1] = v.y;
            image.at(x, y)[2] = v.z;
        }
    }
    return image;
}

TEST(CubemapLayout, LatLongBecomesTheCubeOfTheSameFunction) {
    // Smooth functions survive resampling up to the filters' error: bilinear h²·|f''|/8 with
    // h = 2π/512 in the panorama, and the 4×4 box over a texel, (2/32)²·|f''|/24.
    Cubemap cube = cubemapFromLatLong(latLongOf(512, smooth), 32);
    Cubemap expected = baked(32, smooth);
    EXPECT_LT(largestTexelDifference(cube, expected), 3e-3f);
    // Not symmetric by accident: a map mirrored east–west comes out different.
    Cubemap mirrored = cubemapFromLatLong(latLongOf(512, [](const Vec3f &d) { return smooth({-d.x, d.y, d.z}); }), 32);
    EXPECT_GT(maxDifference(mirrored.texel(kEast, 16, 16), expected.texel(kEast, 16, 16)), 0.1f);
}

TEST(CubemapLayout, CubeThroughLatLongComesBackClose) {
    Cubemap cube = baked(32, smooth);
    Image latLong = latLongFromCubemap(cube, 256);
    EXPECT_EQ(latLong.height, 128);
    Cubemap back = cubemapFromLatLong(latLong, 32);
    // Three filters in a row (cube bilinear, panorama box, panorama bilinear), each within
    // h²·|f''|/8 for h ≤ 2/32 and |f''| < 8.
    EXPECT_LT(largestTexelDifference(back, cube), 3 * 0.0625f * 0.0625f);
}

// Validation: each error names what is wrong.

void expectLayoutError(const std::function<void()> &convert, const std::string &mention, const std::string &mention2) {
    try {
        convert();
        ADD_FAILURE() << "no LayoutError; expected one mentioning " << mention;
    } catch (const LayoutError &e) {
        std::string message = e.what();
        EXPECT_NE(message.find(mention), std::string::npos) << message;
        EXPECT_NE(message.find(mention2), std::string::npos) << message;
    }
}

TEST(CubemapLayout, BadFacesAreErrorsNamingTheFace) {
    std::array<Image, kCubeFaceCount> faces = randomFaces(8);
    faces[kNorth] = Image(8, 4, 3);
    expectLayoutError([&] { cubemapFromFaces(faces); }, "face 'north' is 8x4", "square");
    faces = randomFaces(8);
    faces[kWest] = Image(4, 4, 3);
    expectLayoutError([&] { cubemapFromFaces(faces); }, "face 'west' is 4x4", "face 'east' is 8x8");
    faces = randomFaces(8);
    faces[kUp] = Image(8, 8, 1);
    expectLayoutError([&] { cubemapFromFaces(faces); }, "face 'up' has 1 channel", "3");
    faces = randomFaces(8);
    faces[kDown] = Image();
    expectLayoutError([&] { cubemapFromFaces(faces); }, "face 'down' is empty", "0x0");
}

TEST(CubemapLayout, BadCrossesAndLatLongsAreErrors) {
    expectLayoutError([] { cubemapFromCross(Image(30, 30, 3)); }, "cross image is 30x30", "3:4");
    expectLayoutError([] { cubemapFromCross(Image(31, 41, 3)); }, "cross image is 31x41", "4:3");
    expectLayoutError([] { cubemapFromCross(Image(12, 16, 2)); }, "cross image has 2 channels", "RGB");
    expectLayoutError([] { cubemapFromLatLong(Image(30, 20, 3), 8); }, "lat-long image is 30x20", "twice as wide");
    expectLayoutError([] { cubemapFromLatLong(Image(40, 20, 3), 0); }, "face size is 0", "positive");
    expectLayoutError([] { latLongFromCubemap(Cubemap(4), 33); }, "width is 33", "even");
    // A good cross of either orientation is taken.
    EXPECT_EQ(cubemapFromCross(Image(12, 16, 3)).size(), 4);
    EXPECT_EQ(cubemapFromCross(Image(16, 12, 3)).size(), 4);
}

}  // namespace
}  // namespace veduta
