// One masonry texture atlas per building (digest-001 §2.5, §8 row 20): the masonry of all of a
// building's wall faces, each baked by bakeMasonry (facade/masonry_texture.h), packed into one
// diffuse, one normal and one specular image, with an affine map per wall from its wall metres to
// the atlas's (u, v). The thesis writes one RenderMan file per wall (L1018); our renderer reads
// textures from files, and a file per wall would make hundreds per street, so a building's walls
// share three. The wall meshes stay coarse (L1013); only their texture coordinates come from here.
//
// Choices where the thesis (which does not bake at all, digest §5) and the task leave it open:
// * Packing: shelves, tallest region first, ties by the walls' order; the atlas is as wide as the
//   widest region or the square root of all regions' area, whichever is more, trimmed to its widest
//   shelf. Sizes need not be powers of two (the texture cache mip-maps any size).
// * A gutter of kAtlasGutter texels around every wall, holding copies of the wall's edge texels
//   (each gutter texel repeats the nearest texel of the wall). A bilinear lookup reads texels up to
//   one beyond the point; a texel of the first mip level averages two of the base level and its
//   lookup reaches three base texels beyond the point. Four keep both within the wall's own texels
//   and their copies. A deeper level k (used where a wall texel is a quarter of a pixel or less)
//   reaches about 1.5 of its texels beyond the point and may then blend in the neighbour's edge, but
//   only within the wall's outermost pixel or two, where it meets its corner or cornice (L1013).
// * Texel per wall: each wall asks for its texel as a multiple (texelScale, at least 1) of the
//   atlas's texel size s, so that a wall far from the camera, or facing away from it, takes fewer
//   texels than the nearest one; a wall's texel is s · texelScale but never coarser than
//   kCoarsestAtlasTexel unless s itself is.
// * Budget (the resolution "chosen for the viewer", L1018): the atlas (width × height texels) never
//   exceeds `maxTexels`. Where the asked texel size s does not fit, the size grows for all walls
//   alike, along the ladder s · 2^(k/kAtlasTexelSteps), k = 1, 2, …, to the first step at which the
//   packing fits, its last step being kCoarsestAtlasTexel; if even that does not fit,
//   std::length_error (an asked size coarser than that is only tried itself). The layout is found
//   from the walls' sizes before any image is made, and walls are baked one at a time, so memory is
//   the atlas plus one wall's images.
// * A wall whose masonry has no stones (plastered, or too small for a single brick) is baked as
//   mortar only, not skipped: every wall of the building then has its region and its map, one
//   material serves them all, and the opening cut-outs (alpha 0) stay exact on it too.
// * The images' unused texels (at the shelves' ends) are transparent black with a flat normal, the
//   neutral values should a deep mip level reach them.
#pragma once

#include <cstddef>
#include <vector>

#include "core/image.h"
#include "core/vecmath.h"
#include "facade/masonry.h"
#include "facade/masonry_texture.h"

namespace veduta {

// Texels around each wall's region that repeat its edge (see above).
inline constexpr int kAtlasGutter = 4;
// The coarsest texel the budget may force, metres: one per 10 cm still shows a brick's courses.
inline constexpr double kCoarsestAtlasTexel = 0.1;
// Ladder steps per doubling of the texel size (each step about 1.1 %, 2.2 % fewer texels).
inline constexpr int kAtlasTexelSteps = 64;

// One wall face and its masonry, both outliving the call, and its texel as a multiple of the
// atlas's (see Texel per wall above).
struct AtlasWall {
    const Masonry *masonry = nullptr;
    const WallFace *face = nullptr;
    double texelScale = 1;
};

// The affine map from a wall's metres to atlas (u, v): u = scale.x · x + offset.x and
// v = scale.y · y + offset.y, v growing upwards from the atlas's bottom row as Textures::lookup
// reads it.
struct AtlasUvMap {
    Vec2d scale, offset;

    Vec2f operator()(Vec2d wallPoint) const {
        return {float(scale.x * wallPoint.x + offset.x), float(scale.y * wallPoint.y + offset.y)};
    }
};

// Where one wall lies in the atlas: its baked images (as bakeMasonry makes them, over the face's
// bounding rectangle) occupy columns [x, x + width) and rows [y, y + height), rows counted from the
// top as in Image; the gutter lies around that, kAtlasGutter wide.
struct AtlasRegion {
    int x = 0, y = 0, width = 0, height = 0;
    double texelSize = 0;  // metres, this wall's
    Vec2d origin;          // the wall point at the region's bottom left corner (the face's lowest x and y)
    AtlasUvMap uv;
};

struct MasonryAtlasLayout {
    double texelSize = 0;  // metres, of a wall of texelScale 1: the asked one or coarser (see Budget above)
    int width = 0, height = 0;
    std::vector<AtlasRegion> regions;  // one per wall, in the walls' order
};

struct MasonryAtlas {
    MasonryAtlasLayout layout;
    Image diffuse;   // RGBA, linear; alpha 0 in openings (bakeMasonry's)
    Image normal;    // RGB, tangent space, stored as n · 0.5 + 0.5
    Image specular;  // one channel

    // The atlas (u, v) of a point of wall `wall`, in its own metres.
    Vec2f uvOf(size_t wall, Vec2d wallPoint) const { return layout.regions.at(wall).uv(wallPoint); }
};

// Where each wall goes at `texelSize` metres per texel, or the coarsest size that fits
// `maxTexels` (see Budget above). No walls give an empty layout. Throws std::invalid_argument for
// a texel size that is not positive and finite, a texel scale not finite or below 1, a missing
// face or masonry, or a face with fewer
// than three corners or a corner not finite; std::length_error when even kCoarsestAtlasTexel
// does not fit.
MasonryAtlasLayout layOutMasonryAtlas(const std::vector<AtlasWall> &walls, double texelSize, size_t maxTexels);

// The atlas of `walls`, laid out by layOutMasonryAtlas and baked with `look`.
MasonryAtlas bakeMasonryAtlas(const std::vector<AtlasWall> &walls, double texelSize, const MasonryLook &look,
                              size_t maxTexels);

}  // namespace veduta
