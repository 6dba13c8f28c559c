#include "facade/masonry_texture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {
namespace {

constexpr int kMortar = -1;
constexpr int kOpening = -2;

// Which stone (its index), mortar or opening lies under each texel's centre.
struct IdRaster {
    int width = 0;
    int height = 0;
    Vec2d origin;
    double texelSize = 0;
    std::vector<int> ids;

    double top() const { return origin.y + height * texelSize; }
    int &at(int x, int row) { return ids[size_t(row) * size_t(width) + size_t(x)]; }
    int at(int x, int row) const { return ids[size_t(row) * size_t(width) + size_t(x)]; }
};

// Sets the texels whose centres lie inside `polygon` (even-odd rule) to `id`: a scanline fill,
// so a stone costs its area in texels, not the wall's.
void fill(IdRaster &raster, const std::vector<Vec2d> &polygon, int id) {
    if (polygon.size() < 3) return;
    double low = polygon[0].y, high = polygon[0].y;
    for (const Vec2d &p : polygon) low = std::min(low, p.y), high = std::max(high, p.y);
    double s = raster.texelSize;
    int firstRow = std::max(0, int(std::floor((raster.top() - high) / s - 0.5)));
    int lastRow = std::min(raster.height - 1, int(std::ceil((raster.top() - low) / s - 0.5)));
    std::vector<double> crossings;
    for (int row = firstRow; row <= lastRow; ++row) {
        double y = raster.top() - (row + 0.5) * s;
        crossings.clear();
        for (size_t i = 0; i < polygon.size(); ++i) {
            Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            if ((a.y <= y) != (b.y <= y)) crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
        }
        std::sort(crossings.begin(), crossings.end());
        for (size_t i = 0; i + 1 < crossings.size(); i += 2) {
            // Columns whose centres x satisfy crossings[i] <= x < crossings[i + 1].
            int first = std::max(0, int(std::ceil((crossings[i] - raster.origin.x) / s - 0.5)));
            int last = std::min(raster.width - 1, int(std::ceil((crossings[i + 1] - raster.origin.x) / s - 0.5)) - 1);
            for (int x = first; x <= last; ++x) raster.at(x, row) = id;
        }
    }
}

IdRaster rasterise(const Masonry &masonry, const WallFace &face, double texelSize, size_t maxTexels) {
    if (!(texelSize > 0) || !std::isfinite(texelSize))
        throw std::invalid_argument(fmt::format("a masonry texel of {} m", texelSize));
    if (face.outline.size() < 3) throw std::invalid_argument("a wall face with fewer than three corners");
    Vec2d low = face.outline[0], high = face.outline[0];
    for (const Vec2d &p : face.outline) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    double columns = std::max(1.0, std::ceil((high.x - low.x) / texelSize));
    double rows = std::max(1.0, std::ceil((high.y - low.y) / texelSize));
    if (columns * rows > double(maxTexels))
        throw std::invalid_argument(
            fmt::format("a {:.0f} × {:.0f} masonry texture is more than {} texels", columns, rows, maxTexels));
    IdRaster raster{int(columns), int(rows), low, texelSize, {}};
    raster.ids.assign(size_t(raster.width) * size_t(raster.height), kMortar);
    for (size_t i = 0; i < masonry.stones.size(); ++i) fill(raster, masonry.stones[i].outline, int(i));
    for (const auto &opening : face.openings) fill(raster, opening, kOpening);
    return raster;
}

// For every stone texel, its chamfer (3-4) distance in texels from the nearest texel that is not
// of the same stone: how far in from the stone's edge it lies, for the bevel.
std::vector<float> distancesFromStoneEdges(const IdRaster &raster) {
    constexpr float kFar = std::numeric_limits<float>::max() / 4;
    int w = raster.width, h = raster.height;
    std::vector<float> distance(raster.ids.size(), kFar);
    auto index = [w](int x, int row) { return size_t(row) * size_t(w) + size_t(x); };
    auto differs = [&](int x, int row, int id) {
        return x >= 0 && x < w && row >= 0 && row < h && raster.at(x, row) != id;
    };
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            int id = raster.at(x, row);
            if (id < 0 || differs(x - 1, row, id) || differs(x + 1, row, id) || differs(x, row - 1, id) ||
                differs(x, row + 1, id))
                distance[index(x, row)] = 0;
        }
    auto relax = [&](int x, int row, int dx, int drow, float step) {
        int nx = x + dx, nrow = row + drow;
        if (nx < 0 || nx >= w || nrow < 0 || nrow >= h) return;
        float &d = distance[index(x, row)];
        d = std::min(d, distance[index(nx, nrow)] + step);
    };
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            relax(x, row, -1, 0, 3), relax(x, row, 0, -1, 3), relax(x, row, -1, -1, 4), relax(x, row, 1, -1, 4);
        }
    for (int row = h - 1; row >= 0; --row)
        for (int x = w - 1; x >= 0; --x) {
            relax(x, row, 1, 0, 3), relax(x, row, 0, 1, 3), relax(x, row, 1, 1, 4), relax(x, row, -1, 1, 4);
        }
    for (float &d : distance) d /= 3;
    return distance;
}

// How far each texel stands out of the mortar, in metres: a stone's depth, falling to the mortar
// over the bevel at its edges, and the relief's height where it has one.
std::vector<double> heights(const IdRaster &raster, const Masonry &masonry, double bevel) {
    // Where half a texel spans the bevel, even a texel at a stone's edge (distance 0, its centre
    // half a texel in) stands at the full depth: the distances change nothing and are not made.
    const bool distances = bevel > 0.5 * raster.texelSize;
    std::vector<float> distance = distances ? distancesFromStoneEdges(raster) : std::vector<float>();
    std::vector<double> height(raster.ids.size(), 0.0);
    for (size_t i = 0; i < height.size(); ++i) {
        int id = raster.ids[i];
        if (id < 0) continue;
        double inset = ((distances ? distance[i] : 0.0f) + 0.5) * raster.texelSize;
        height[i] = masonry.stones[size_t(id)].depth * (bevel > 0 ? std::min(1.0, inset / bevel) : 1.0);
    }
    if (masonry.relief)
        for (int row = 0; row < raster.height; ++row)
            for (int x = 0; x < raster.width; ++x)
                height[size_t(row) * size_t(raster.width) + size_t(x)] += reliefHeightAt(
                    *masonry.relief,
                    {raster.origin.x + (x + 0.5) * raster.texelSize, raster.top() - (row + 0.5) * raster.texelSize});
    return height;
}

void writeNormals(const IdRaster &raster, const std::vector<double> &height, Image &normal) {
    int w = raster.width, h = raster.height;
    auto heightAt = [&](int x, int row) {
        x = std::clamp(x, 0, w - 1), row = std::clamp(row, 0, h - 1);
        return height[size_t(row) * size_t(w) + size_t(x)];
    };
    double twoTexels = 2 * raster.texelSize;
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            double alongSlope = (heightAt(x + 1, row) - heightAt(x - 1, row)) / twoTexels;
            double upSlope = (heightAt(x, row - 1) - heightAt(x, row + 1)) / twoTexels;  // rows run down
            Vec3f n = normalize(Vec3f(float(-alongSlope), float(-upSlope), 1.0f));
            float *out = normal.at(x, row);
            out[0] = n.x * 0.5f + 0.5f, out[1] = n.y * 0.5f + 0.5f, out[2] = n.z * 0.5f + 0.5f;
        }
}

}  // namespace

double reliefHeightAt(const MasonryRelief &relief, Vec2d p) {
    const Image &image = *relief.heights;
    double column = (p.x - relief.origin.x) / relief.cellSize;
    double fromTop = image.height - (p.y - relief.origin.y) / relief.cellSize;
    if (column < 0 || fromTop < 0 || column > image.width || fromTop > image.height) return 0;
    double x = std::clamp(column - 0.5, 0.0, image.width - 1.0), y = std::clamp(fromTop - 0.5, 0.0, image.height - 1.0);
    int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
    double fx = x - x0, fy = y - y0;
    auto at = [&](int cx, int cy) { return double(image.pixels[size_t(cy) * size_t(image.width) + size_t(cx)]); };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

MasonryTextures bakeMasonry(const Masonry &masonry, const WallFace &face, double texelSize, const MasonryLook &look,
                            size_t maxTexels) {
    IdRaster raster = rasterise(masonry, face, texelSize, maxTexels);
    MasonryTextures textures{raster.origin, texelSize, Image(raster.width, raster.height, 4),
                             Image(raster.width, raster.height, 3), Image(raster.width, raster.height, 1)};
    for (int row = 0; row < raster.height; ++row)
        for (int x = 0; x < raster.width; ++x) {
            int id = raster.at(x, row);
            const Vec3f &colour = id >= 0 ? masonry.stones[size_t(id)].colour : masonry.mortarColour;
            float *diffuse = textures.diffuse.at(x, row);
            diffuse[0] = colour.x, diffuse[1] = colour.y, diffuse[2] = colour.z;
            diffuse[3] = id == kOpening ? 0.0f : 1.0f;
            *textures.specular.at(x, row) = id >= 0 ? look.stoneSpecular : look.mortarSpecular;
        }
    writeNormals(raster, heights(raster, masonry, look.bevel), textures.normal);
    return textures;
}

}  // namespace veduta
