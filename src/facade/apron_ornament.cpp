#include "facade/apron_ornament.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "facade/ornament_growth.h"

namespace veduta {

namespace {

// The rim's height at `d` metres in from the panel's edge: flat on its outer half, falling to the
// field over its inner half (smoothstep), nothing beyond.
double rimAt(double d) {
    double t = std::clamp((kApronRimWidth - d) / (0.5 * kApronRimWidth), 0.0, 1.0);
    return kApronRimHeight * t * t * (3 - 2 * t);
}

}  // namespace

Image apronRelief(double width, double height) {
    if (!(width >= 3 * kApronRimWidth && height >= 3 * kApronRimWidth && width <= 10 && height <= 10))
        throw std::invalid_argument(fmt::format("an apron of {} × {} m", width, height));
    const int columns = std::max(1, int(std::lround(width / kApronCell)));
    const int rows = std::max(1, int(std::lround(height / kApronCell)));
    const int rim = int(std::lround(kApronRimWidth / kApronCell));
    const int half = columns / 2;  // the left half's columns; an odd panel's middle column copies its neighbour
    // The left half inside the rim, all free, its right side on the axis.
    OrnamentRaster raster(half - rim, rows - 2 * rim, kApronCell, {rim * kApronCell, rim * kApronCell},
                          std::vector<OrnamentCell>(size_t(half - rim) * size_t(rows - 2 * rim), OrnamentCell::Free));
    // The root: a stem up the axis, just inside the half, so that with its mirror image it is one.
    const double axis = (half - 0.6) * kApronCell;
    std::vector<OrnamentElement> roots{
        OrnamentElement::rootAlong(raster, {axis, (rim + 1.5) * kApronCell}, {axis, (rows - rim - 1.5) * kApronCell})};
    const Image grown = ornamentHeightMap(growOrnament(std::move(raster), std::move(roots)), kApronCell);

    Image relief(columns, rows, 1);
    for (int row = 0; row < rows; ++row)
        for (int x = 0; x < columns; ++x) {
            int mirrored = x < half ? x : std::min(columns - 1 - x, half - 1);
            double ornament = 0;
            if (mirrored >= rim && row >= rim && row < rows - rim) ornament = *grown.at(mirrored - rim, row - rim);
            double d = std::min({x + 0.5, columns - x - 0.5, row + 0.5, rows - row - 0.5}) * kApronCell;
            *relief.at(x, row) = float(std::max(ornament, rimAt(d)));
        }
    return relief;
}

}  // namespace veduta
