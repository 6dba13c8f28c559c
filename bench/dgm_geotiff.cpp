// Writes bench_terrain's 34 × 20 km DGM at 10 m (generated_dgm.h: 3401 × 2001 nodes in
// EPSG:25832) as a float32 GeoTIFF, for bench/big_landscape.sh, and prints its extent and the
// height of its terrain surface (what a ray hits) at each point given, so that a camera can be
// placed above it.
//
//   build/release/bench/bench_dgm_geotiff FILE.tif [EASTING NORTHING]...
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>

#include "generated_dgm.h"
#include "geo/height_queries.h"

int main(int argc, char **argv) {
    using namespace veduta;
    if (argc < 2 || argc % 2 != 0) {
        std::fprintf(stderr, "usage: %s FILE.tif [EASTING NORTHING]...\n", argv[0]);
        return 2;
    }
    try {
        HeightGrid grid = generatedDgm34x20km();
        writeGeoTiff(grid, argv[1]);
        std::printf("nodes: %d %d\nspacing: %g\nsouth_west: %.3f %.3f\nnorth_east: %.3f %.3f\n", grid.columns,
                    grid.rows, grid.spacing, grid.west, grid.south, grid.east(), grid.north());
        for (int i = 2; i + 1 < argc; i += 2) {
            MapPoint point{std::strtod(argv[i], nullptr), std::strtod(argv[i + 1], nullptr)};
            std::optional<double> height = surfaceHeight(grid, point);
            if (!height) {
                std::fprintf(stderr, "%s %s lies outside the DGM\n", argv[i], argv[i + 1]);
                return 1;
            }
            std::printf("height: %.3f %.3f %.3f\n", point.easting, point.northing, *height);
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
