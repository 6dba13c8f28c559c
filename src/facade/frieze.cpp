#include "facade/frieze.h"

#include <cmath>

#include <fmt/format.h>

#include "core/check.h"

namespace veduta {
namespace {

// The width that keeps the texture's aspect ratio at `stripHeight`; 0 without a texture.
double naturalWidth(int texture, double stripHeight, const std::vector<TextureRegion> &pool, double imageAspect) {
    if (texture < 0) return 0;
    const TextureRegion &region = pool[size_t(texture)];
    return stripHeight * imageAspect * (region.right - region.left) / (region.bottom - region.top);
}

}  // namespace

std::vector<FriezePiece> layFrieze(double length, double stripHeight, const std::array<int, 3> &textures,
                                   const std::vector<TextureRegion> &pool, double imageAspect) {
    VEDUTA_CHECK(length >= 0 && stripHeight > 0 && imageAspect > 0, "a frieze strip has a size");
    for (int texture : textures) VEDUTA_CHECK(texture < int(pool.size()), "frieze textures are in the pool");
    auto [startTexture, midTexture, endTexture] = textures;
    std::vector<FriezePiece> pieces;
    double start = naturalWidth(startTexture, stripHeight, pool, imageAspect);
    double end = naturalWidth(endTexture, stripHeight, pool, imageAspect);
    if (length == 0) {
        pieces.push_back({FriezePart::Mid, 0, 0, midTexture});
        return pieces;
    }
    if (start + end >= length) {
        double split = length * start / (start + end);
        if (start > 0) pieces.push_back({FriezePart::Start, 0, split, startTexture});
        if (end > 0) pieces.push_back({FriezePart::End, split, length, endTexture});
        return pieces;
    }
    if (start > 0) pieces.push_back({FriezePart::Start, 0, start, startTexture});
    double rest = length - start - end;
    double tile = naturalWidth(midTexture, stripHeight, pool, imageAspect);
    double tiles = tile > 0 ? std::max(1.0, std::round(rest / tile)) : 1;
    if (tiles > kFriezeTileLimit)
        throw InputError(pool[size_t(midTexture)].loc,
                         fmt::format("a frieze strip of {} m would need {} tiles of this texture (at most {})", length,
                                     tiles, kFriezeTileLimit));
    int count = int(tiles);
    double from = start;
    for (int i = 1; i <= count; ++i) {
        double to = i == count ? length - end : start + rest * i / count;
        pieces.push_back({FriezePart::Mid, from, to, midTexture});
        from = to;
    }
    if (end > 0) pieces.push_back({FriezePart::End, length - end, length, endTexture});
    return pieces;
}

}  // namespace veduta
