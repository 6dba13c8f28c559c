#include "facade/masonry_atlas.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "core/check.h"

namespace veduta {
namespace {

// A face's bounding rectangle: the domain bakeMasonry bakes.
struct Extent {
    Vec2d low, high;
};

Extent extentOf(const AtlasWall &wall, size_t index) {
    if (!wall.masonry || !wall.face)
        throw std::invalid_argument(fmt::format("atlas wall {} has no masonry or face", index));
    const std::vector<Vec2d> &outline = wall.face->outline;
    if (outline.size() < 3)
        throw std::invalid_argument(fmt::format("atlas wall {} has fewer than three corners", index));
    Extent extent{outline[0], outline[0]};
    for (const Vec2d &p : outline) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw std::invalid_argument(fmt::format("atlas wall {} has a corner that is not finite", index));
        extent.low = {std::min(extent.low.x, p.x), std::min(extent.low.y, p.y)};
        extent.high = {std::max(extent.high.x, p.x), std::max(extent.high.y, p.y)};
    }
    return extent;
}

// The texels along a span at `texelSize`, exactly as bakeMasonry counts them; in double, so that a
// span far too fine for any budget is refused rather than overflowing.
double texelsAlong(double span, double texelSize) { return std::max(1.0, std::ceil(span / texelSize)); }

// A region with its gutter, and where its top left corner goes.
struct Slot {
    int64_t width = 0, height = 0;
    int64_t x = 0, y = 0;
};

// A wall's texel when the atlas's is `texelSize` (see Texel per wall in the header).
double wallTexel(const AtlasWall &wall, double texelSize) {
    return std::max(texelSize, std::min(texelSize * wall.texelScale, kCoarsestAtlasTexel));
}

// The shelf packing of the walls at `texelSize`, or nothing when it exceeds `maxTexels`.
std::optional<MasonryAtlasLayout> pack(const std::vector<AtlasWall> &walls, const std::vector<Extent> &extents,
                                       double texelSize, size_t maxTexels) {
    const double budget = double(maxTexels);
    std::vector<Slot> slots(extents.size());
    std::vector<double> texels(extents.size());
    double area = 0;
    for (size_t i = 0; i < extents.size(); ++i) {
        texels[i] = wallTexel(walls[i], texelSize);
        double width = texelsAlong(extents[i].high.x - extents[i].low.x, texels[i]) + 2 * kAtlasGutter;
        double height = texelsAlong(extents[i].high.y - extents[i].low.y, texels[i]) + 2 * kAtlasGutter;
        area += width * height;
        if (area > budget) return std::nullopt;
        slots[i].width = int64_t(width), slots[i].height = int64_t(height);
    }
    std::vector<size_t> order(slots.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return slots[a].height > slots[b].height; });
    int64_t widest = 0;
    for (const Slot &slot : slots) widest = std::max(widest, slot.width);
    const int64_t shelfWidth = std::max(widest, int64_t(std::ceil(std::sqrt(area))));
    int64_t x = 0, shelfTop = 0, shelfHeight = 0, atlasWidth = 0;
    for (size_t i : order) {
        if (x + slots[i].width > shelfWidth) shelfTop += shelfHeight, x = 0, shelfHeight = 0;
        // Tallest first: a shelf is as high as its first slot.
        if (x == 0) shelfHeight = slots[i].height;
        slots[i].x = x, slots[i].y = shelfTop;
        x += slots[i].width;
        atlasWidth = std::max(atlasWidth, x);
    }
    const int64_t atlasHeight = shelfTop + shelfHeight;
    if (atlasWidth > INT_MAX || atlasHeight > INT_MAX || double(atlasWidth) * double(atlasHeight) > budget)
        return std::nullopt;

    MasonryAtlasLayout layout{texelSize, int(atlasWidth), int(atlasHeight), {}};
    const double w = double(atlasWidth), h = double(atlasHeight);
    for (size_t i = 0; i < slots.size(); ++i) {
        AtlasRegion region;
        region.x = int(slots[i].x) + kAtlasGutter, region.y = int(slots[i].y) + kAtlasGutter;
        region.width = int(slots[i].width) - 2 * kAtlasGutter, region.height = int(slots[i].height) - 2 * kAtlasGutter;
        region.texelSize = texels[i];
        region.origin = extents[i].low;
        // Column x + (p.x − origin.x) / s; and from the bottom row up, the region's bottom lies
        // h − (y + height) rows above the atlas's bottom.
        region.uv.scale = {1 / (texels[i] * w), 1 / (texels[i] * h)};
        region.uv.offset = {region.x / w - region.origin.x * region.uv.scale.x,
                            (h - region.y - region.height) / h - region.origin.y * region.uv.scale.y};
        layout.regions.push_back(region);
    }
    return layout;
}

// Copies `from` (a wall's image) into its region of `to`, and its edge texels into the gutter.
void copyWithGutter(const Image &from, const AtlasRegion &region, Image &to) {
    VEDUTA_CHECK(from.width == region.width && from.height == region.height && from.channels == to.channels,
                 "a baked wall differs from its atlas region");
    const size_t channels = size_t(from.channels), rowLength = size_t(from.width) * channels;
    for (int row = -kAtlasGutter; row < region.height + kAtlasGutter; ++row) {
        const float *source = from.at(0, std::clamp(row, 0, from.height - 1));
        float *target = to.at(region.x, region.y + row);
        std::copy(source, source + rowLength, target);
        for (int g = 1; g <= kAtlasGutter; ++g) {
            std::copy(source, source + channels, target - size_t(g) * channels);
            std::copy(source + rowLength - channels, source + rowLength, target + rowLength + size_t(g - 1) * channels);
        }
    }
}

}  // namespace

MasonryAtlasLayout layOutMasonryAtlas(const std::vector<AtlasWall> &walls, double texelSize, size_t maxTexels) {
    if (!(texelSize > 0) || !std::isfinite(texelSize))
        throw std::invalid_argument(fmt::format("an atlas texel of {} m", texelSize));
    std::vector<Extent> extents;
    for (size_t i = 0; i < walls.size(); ++i) {
        extents.push_back(extentOf(walls[i], i));
        if (!(walls[i].texelScale >= 1) || !std::isfinite(walls[i].texelScale))
            throw std::invalid_argument(fmt::format("atlas wall {} has a texel scale of {}", i, walls[i].texelScale));
    }
    // The ladder texelSize · 2^(step / kAtlasTexelSteps), its last step clamped to the coarsest
    // texel. pack refuses a step as soon as its walls alone exceed the budget, before placing any.
    const int lastStep = texelSize < kCoarsestAtlasTexel
        ? int(std::ceil(kAtlasTexelSteps * std::log2(kCoarsestAtlasTexel / texelSize)))
        : 0;
    for (int step = 0; step <= lastStep; ++step) {
        double size = step == 0 ? texelSize
            : step == lastStep  ? kCoarsestAtlasTexel
                                : texelSize * std::exp2(double(step) / kAtlasTexelSteps);
        if (auto layout = pack(walls, extents, size, maxTexels)) return *layout;
    }
    throw std::length_error(fmt::format("the masonry of {} walls does not fit {} texels at {} m per texel",
                                        walls.size(), maxTexels, std::max(texelSize, kCoarsestAtlasTexel)));
}

MasonryAtlas bakeMasonryAtlas(const std::vector<AtlasWall> &walls, double texelSize, const MasonryLook &look,
                              size_t maxTexels) {
    MasonryAtlasLayout layout = layOutMasonryAtlas(walls, texelSize, maxTexels);
    int w = layout.width, h = layout.height;
    MasonryAtlas atlas{std::move(layout), Image(w, h, 4), Image(w, h, 3), Image(w, h, 1)};
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            float *n = atlas.normal.at(x, row);
            n[0] = 0.5f, n[1] = 0.5f, n[2] = 1.0f;
        }
    for (size_t i = 0; i < walls.size(); ++i) {
        const AtlasRegion &region = atlas.layout.regions[i];
        MasonryTextures wall = bakeMasonry(*walls[i].masonry, *walls[i].face, region.texelSize, look,
                                           size_t(region.width) * size_t(region.height));
        VEDUTA_CHECK(wall.origin == region.origin, "a baked wall's origin differs from its atlas region's");
        copyWithGutter(wall.diffuse, region, atlas.diffuse);
        copyWithGutter(wall.normal, region, atlas.normal);
        copyWithGutter(wall.specular, region, atlas.specular);
    }
    return atlas;
}

}  // namespace veduta
