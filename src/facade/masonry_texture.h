// Masonry baked to the images a wall's material reads (digest-001 §2.5 and §2.9 step 4: "coarse
// geometry, texture exact at the seams"): the stones and mortar of one wall face become a diffuse,
// a normal and a specular map over the face's bounding rectangle (the thesis's texture domain,
// L1054), so the wall's mesh stays a few triangles however many bricks it shows. The texel size is
// the caller's: matched to the size of the wall in the image, so that a far wall costs a few
// kilobytes and a near one is sharp.
#pragma once

#include "core/image.h"
#include "facade/masonry.h"

namespace veduta {

struct MasonryLook {
    float stoneSpecular = 0.04f;  // the specular map's value on stone (a dull sheen)
    float mortarSpecular = 0.0f;  // and on mortar
    double bevel = 0.004;         // metres over which a stone's edge falls to the mortar
};

struct MasonryTextures {
    // Texel (x, y) covers wall coordinates [origin.x + x·s, origin.x + (x+1)·s] ×
    // [top − (y+1)·s, top − y·s] with s = texelSize and top = origin.y + height·s: the images' top
    // row is the top of the wall, as image files store them.
    Vec2d origin;
    double texelSize = 0;
    Image diffuse;   // RGBA, linear; alpha 0 inside an opening, where the wall has a hole
    Image normal;    // RGB, tangent space (x along the wall, y up, z out), stored as n · 0.5 + 0.5
    Image specular;  // one channel
};

// The relief's height at a wall point: bilinear between its cells' centres, held at its edge cells,
// 0 outside it.
double reliefHeightAt(const MasonryRelief &relief, Vec2d p);

// The textures of `masonry` laid on `face` at `texelSize` metres per texel. A texel takes what
// lies under its centre: an opening, a stone, or else the mortar. Throws std::invalid_argument
// when the face would need more than `maxTexels` texels (the caller picks a coarser size).
MasonryTextures bakeMasonry(const Masonry &masonry, const WallFace &face, double texelSize,
                            const MasonryLook &look = {}, size_t maxTexels = size_t(1) << 26);

}  // namespace veduta
