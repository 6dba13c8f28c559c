// Schrader's texture coordinates (digest-003 §3.3, thesis L2174–2237): one atlas image per model,
// each motif (a wall, a door, a window, a roof) a rectangle of it, and two ways of laying a
// motif on a quad: stretched over it, or repeated along a run of walls at the motif's real size.
#pragma once

#include <array>

namespace veduta {

// A texture coordinate: (0, 0) is the image's top-left corner, (1, 1) its bottom-right (L2188).
struct Uv {
    double u = 0, v = 0;
    bool operator==(const Uv &) const = default;
};

// A motif's rectangle in the atlas.
struct AtlasRect {
    Uv topLeft, bottomRight;
};

// Motif (column, row), counted from 0 at the top left, of an atlas cut into equal columns and
// rows: the thesis's six numbers side by side are six columns of one row (L2196–2204), the
// block atlas's two stacked squares one column of two rows (L2744).
AtlasRect gridMotif(int column, int row, int columns, int rows);

// The coordinates of a quad's corners in Listing 4's order: bottom left, bottom right, top
// right, top left.
using QuadUv = std::array<Uv, 4>;

// Simple mapping (L2225): the whole motif stretched over the quad.
QuadUv simpleMapping(const AtlasRect &motif);

// Tiled mapping (eq 35): a wall shows wallLength / textureLength repeats of the motif, starting
// at u0, the u of the previous wall's right corners (0 for the first), so the texture runs on
// across a storey's walls without a seam. The wall is given by where it starts and ends along
// the run of walls, `from` and `to` metres from the first corner: u0 = from / textureLength,
// worked out alike for the wall that ends there, so the corners' u agree to the bit. Only a
// motif as wide as the atlas can repeat along u (the neighbouring motifs would show otherwise);
// its height is stretched.
QuadUv tiledMapping(const AtlasRect &motif, double textureLength, double from, double to);

}  // namespace veduta
