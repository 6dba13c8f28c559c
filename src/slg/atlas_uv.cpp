#include "slg/atlas_uv.h"

#include "core/check.h"

namespace veduta {

namespace {

QuadUv spanning(double left, double right, const AtlasRect &motif) {
    double top = motif.topLeft.v, bottom = motif.bottomRight.v;
    return {Uv{left, bottom}, Uv{right, bottom}, Uv{right, top}, Uv{left, top}};
}

}  // namespace

AtlasRect gridMotif(int column, int row, int columns, int rows) {
    VEDUTA_CHECK(column >= 0 && column < columns && row >= 0 && row < rows, "a grid motif lies in its grid");
    double width = 1.0 / columns, height = 1.0 / rows;
    return {{column * width, row * height}, {(column + 1) * width, (row + 1) * height}};
}

QuadUv simpleMapping(const AtlasRect &motif) { return spanning(motif.topLeft.u, motif.bottomRight.u, motif); }

QuadUv tiledMapping(const AtlasRect &motif, double textureLength, double from, double to) {
    VEDUTA_CHECK(motif.topLeft.u == 0 && motif.bottomRight.u == 1, "a tiled motif spans the atlas's width");
    VEDUTA_CHECK(textureLength > 0, "a tiled motif has a real length");
    return spanning(from / textureLength, to / textureLength, motif);
}

}  // namespace veduta
