// The CityGML reader (docs/citygml.md) on any file, with its result checked: every point
// finite, every triangle index within its polygon's points, and a textured polygon's texture
// coordinates finite and one per point.
#include <cmath>
#include <cstdlib>

#include "city/citygml_file.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, ".gml");
    fuzz::expectInputError([&] {
        CityGmlModel model = readCityGml(file);
        for (const CityGmlBuilding &building : model.buildings)
            for (const CityGmlPolygon &polygon : building.polygons) {
                size_t points = 0;
                for (const auto &ring : polygon.rings)
                    for (const CrsCoordinate &p : ring) {
                        ++points;
                        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
                    }
                if (polygon.triangles.empty() || polygon.triangles.size() % 3 != 0) std::abort();
                for (uint32_t index : polygon.triangles)
                    if (index >= points) std::abort();
                if (polygon.texture.empty() != polygon.uvs.empty()) std::abort();
                if (!polygon.uvs.empty() && polygon.uvs.size() != points) std::abort();
                for (const Vec2f &uv : polygon.uvs)
                    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) std::abort();
            }
    });
    return 0;
}
