// Where an exported file lies on the Earth: the scene's CRS and origin, in the file itself
// (glTF's asset extras) and in sidecars GIS tools read (OUT.prj, the CRS as ESRI WKT, and
// OUT.geo.json with origin, CRS and axes). A file point (x, y, z) in veduta's Z-up frame is
// easting E0 + x, northing N0 + y, height z; glTF's Y-up (x, y, z) is E0 + x, N0 − z, height y.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "geodesy/georeference.h"
#include "io/export_job.h"

namespace veduta {

enum class FileAxes { ZUp, YUp };

// The JSON object {"crs": "EPSG:25832", "origin": [E, N, 0], "up": "Y", "units": "m", …};
// without a georeference "crs" is null and "georeferenced" false.
std::string georeferenceJson(const std::optional<Georeference> &georeference, FileAxes axes);

// OUT.prj and OUT.geo.json beside `out`; none without a georeference. Throws
// std::runtime_error when the CRS has no WKT.
std::vector<ExportFile> georeferenceSidecars(const std::optional<Georeference> &georeference,
                                             const std::filesystem::path &out, FileAxes axes);

}  // namespace veduta
