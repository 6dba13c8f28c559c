#include "scene/cubemap.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

// Every face is seen from the centre looking out, so right × up = −forward on all six. The
// up face's up is south and the down face's north so that both meet the north face's top and
// bottom edges, the crosses' middle column (docs/cubemap.md).
constexpr std::array<CubeFaceFrame, kCubeFaceCount> kFrames{{
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},   // east
    {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // west
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    // north
    {{0, -1, 0}, {-1, 0, 0}, {0, 0, 1}},  // south
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   // up
    {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},   // down
}};

constexpr std::array<std::string_view, kCubeFaceCount> kNames{"east", "west", "north", "south", "up", "down"};

// A face coordinate in [−1, 1] as a texel position in [0, size). NaN (a zero direction)
// becomes 0 so that callers can always index with the result.
float texelPosition(float coordinate, int size) {
    float p = (coordinate + 1) * 0.5f * float(size);
    return p >= 0 ? std::min(p, std::nextafter(float(size), 0.0f)) : 0.0f;
}

// Driscoll's antiderivative of the solid angle over the face plane at distance 1:
// ∫∫ (1 + a² + b²)^(−3/2) da db = atan(a·b / √(1 + a² + b²)).
double solidAngleAntiderivative(double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1)); }

Vec3f lerp(float t, const Vec3f &a, const Vec3f &b) { return a * (1 - t) + b * t; }

}  // namespace

const CubeFaceFrame &cubeFaceFrame(int face) { return kFrames[size_t(face)]; }

std::string_view cubeFaceName(int face) { return kNames[size_t(face)]; }

Vec3f cubeDirection(int size, int face, float x, float y) {
    const CubeFaceFrame &f = kFrames[size_t(face)];
    float a = cubeFaceCoordinate(x, size), b = -cubeFaceCoordinate(y, size);
    return normalize(f.forward + f.right * a + f.up * b);
}

CubeTexel cubeLocate(int size, const Vec3f &d) {
    float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    int axis = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    int face = 2 * axis + (d[axis] < 0 ? 1 : 0);
    const CubeFaceFrame &f = kFrames[size_t(face)];
    float inverseDepth = 1 / std::abs(d[axis]);
    float a = dot(d, f.right) * inverseDepth, b = dot(d, f.up) * inverseDepth;
    return {face, texelPosition(a, size), texelPosition(-b, size)};
}

double cubeTexelSolidAngle(int size, int x, int y) {
    // Signs do not matter: the solid angle is symmetric in a and b.
    double a0 = 2.0 * x / size - 1, a1 = 2.0 * (x + 1) / size - 1;
    double b0 = 2.0 * y / size - 1, b1 = 2.0 * (y + 1) / size - 1;
    return solidAngleAntiderivative(a0, b0) - solidAngleAntiderivative(a0, b1) - solidAngleAntiderivative(a1, b0) +
        solidAngleAntiderivative(a1, b1);
}

Cubemap::Cubemap(int size) : size_(size) {
    for (auto &face : faces_) face.assign(size_t(size) * size_t(size), Vec3f(0.0f));
}

Vec3f Cubemap::direction(int face, float x, float y) const { return cubeDirection(size_, face, x, y); }

CubeTexel Cubemap::locate(const Vec3f &direction) const { return cubeLocate(size_, direction); }

float Cubemap::texelSolidAngle(int x, int y) const { return float(cubeTexelSolidAngle(size_, x, y)); }

Vec3f Cubemap::texelAcrossEdges(int face, int x, int y) const {
    bool outsideX = x < 0 || x >= size_, outsideY = y < 0 || y >= size_;
    if (!outsideX && !outsideY) return texel(face, x, y);
    int insideX = std::clamp(x, 0, size_ - 1), insideY = std::clamp(y, 0, size_ - 1);
    if (outsideX && outsideY) {
        return (texel(face, insideX, insideY) + texelAcrossEdges(face, x, insideY) +
                texelAcrossEdges(face, insideX, y)) /
            3.0f;
    }
    // The texel's centre lies on the face's plane one texel beyond the edge. Folded over the
    // edge onto the neighbouring face, the same distance from the edge, it lands on the
    // centre of the texel that adjoins (insideX, insideY) there, well clear of rounding.
    const CubeFaceFrame &f = kFrames[size_t(face)];
    float a = cubeFaceCoordinate(float(x) + 0.5f, size_), b = -cubeFaceCoordinate(float(y) + 0.5f, size_);
    float beyond = std::max(std::abs(a), std::abs(b)) - 1;
    Vec3f folded = f.forward * (1 - beyond) + f.right * std::clamp(a, -1.0f, 1.0f) + f.up * std::clamp(b, -1.0f, 1.0f);
    CubeTexel t = locate(folded);
    return texel(t.face, int(t.x), int(t.y));
}

Vec3f Cubemap::lookup(const Vec3f &direction) const {
    // Bilinear between texel centres; taps past a face's edge come from the neighbouring
    // faces (texelAcrossEdges), so both sides of an edge blend the same texels with the same
    // weights and the result is continuous across edges and corners.
    CubeTexel t = locate(direction);
    float px = t.x - 0.5f, py = t.y - 0.5f;
    int x0 = int(std::floor(px)), y0 = int(std::floor(py));
    float fx = px - float(x0), fy = py - float(y0);
    Vec3f top = lerp(fx, texelAcrossEdges(t.face, x0, y0), texelAcrossEdges(t.face, x0 + 1, y0));
    Vec3f bottom = lerp(fx, texelAcrossEdges(t.face, x0, y0 + 1), texelAcrossEdges(t.face, x0 + 1, y0 + 1));
    return lerp(fy, top, bottom);
}

}  // namespace veduta
