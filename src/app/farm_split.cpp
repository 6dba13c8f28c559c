#include "app/farm_split.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

// `count` tiles in `rows` rows; the first count % rows rows hold one tile more, and each row's
// height follows its share of the tiles, so that all tiles have about the same area.
std::vector<PixelWindow> tilesInRows(int width, int height, int count, int rows) {
    std::vector<PixelWindow> tiles;
    int64_t tilesAbove = 0;
    for (int row = 0; row < rows; ++row) {
        int columns = count / rows + (row < count % rows ? 1 : 0);
        int y0 = int(tilesAbove * height / count);
        tilesAbove += columns;
        int y1 = int(tilesAbove * height / count);
        for (int column = 0; column < columns; ++column) {
            tiles.push_back(
                {int(int64_t(column) * width / columns), y0, int(int64_t(column + 1) * width / columns), y1});
        }
    }
    return tiles;
}

bool allHavePixels(const std::vector<PixelWindow> &tiles) {
    return std::none_of(tiles.begin(), tiles.end(), [](const PixelWindow &t) { return t.empty(); });
}

}  // namespace

std::vector<PixelWindow> splitIntoTiles(int width, int height, int count) {
    if (count < 1 || width < 1 || height < 1 || int64_t(count) > int64_t(width) * height) {
        throw std::invalid_argument(fmt::format("{} tiles do not fit a {}x{} image: give 1 to {}", count, width, height,
                                                int64_t(std::max(width, 0)) * std::max(height, 0)));
    }
    // Square tiles of the image's area / count have sides √(w·h/count): the image's height holds
    // √(count·h/w) of them. Rows nearest that come first; a row count whose rows or columns would
    // be thinner than a pixel is passed over (only in images of a few pixels per tile).
    const double ideal = std::sqrt(double(count) * height / width);
    std::vector<int> rowCounts;
    for (int rows = 1; rows <= std::min(count, height); ++rows) rowCounts.push_back(rows);
    std::stable_sort(rowCounts.begin(), rowCounts.end(),
                     [ideal](int a, int b) { return std::abs(std::log(a / ideal)) < std::abs(std::log(b / ideal)); });
    for (int rows : rowCounts) {
        std::vector<PixelWindow> tiles = tilesInRows(width, height, count, rows);
        if (allHavePixels(tiles)) return tiles;
    }
    throw std::logic_error(fmt::format("no split of {}x{} into {} tiles", width, height, count));
}

std::vector<SampleRange> splitSamples(uint32_t spp, uint32_t count) {
    if (count < 1 || count > spp) {
        throw std::invalid_argument(
            fmt::format("{} sample ranges do not fit {} samples per pixel: give 1 to {}", count, spp, spp));
    }
    std::vector<SampleRange> ranges;
    for (uint32_t i = 0; i < count; ++i) {
        auto start = uint32_t(uint64_t(i) * spp / count), end = uint32_t(uint64_t(i + 1) * spp / count);
        ranges.push_back({start, end - start});
    }
    return ranges;
}

}  // namespace veduta
