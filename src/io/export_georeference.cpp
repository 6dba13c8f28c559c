#include "io/export_georeference.h"

#include <stdexcept>

#include <fmt/format.h>
#include <ogr_spatialref.h>

#include "io/export_json.h"

namespace veduta {

namespace {

const char *axesText(FileAxes axes) {
    switch (axes) {
    case FileAxes::ZUp: return "x east, y north, z up";
    case FileAxes::YUp: return "x east, y up, z south";
    }
    return "";
}

const char *upAxis(FileAxes axes) { return axes == FileAxes::YUp ? "Y" : "Z"; }

// The CRS as ESRI's WKT 1, what a .prj beside a file holds, from GDAL's copy of the EPSG
// registry.
std::string esriWkt(int epsg) {
    OGRSpatialReference srs;
    if (srs.importFromEPSG(epsg) != OGRERR_NONE) throw std::runtime_error(fmt::format("EPSG:{} has no WKT", epsg));
    const char *const options[] = {"FORMAT=WKT1_ESRI", nullptr};
    char *wkt = nullptr;
    OGRErr error = srs.exportToWkt(&wkt, options);
    std::string out = wkt ? wkt : "";
    CPLFree(wkt);
    if (error != OGRERR_NONE || out.empty()) throw std::runtime_error(fmt::format("EPSG:{} has no ESRI WKT", epsg));
    return out;
}

}  // namespace

std::string georeferenceJson(const std::optional<Georeference> &georeference, FileAxes axes) {
    std::string frame = fmt::format("\"up\": \"{}\", \"axes\": \"{}\", \"units\": \"m\"", upAxis(axes), axesText(axes));
    if (!georeference) return fmt::format("{{\"georeferenced\": false, \"crs\": null, {}}}", frame);
    return fmt::format(
        "{{\"georeferenced\": true, \"crs\": \"EPSG:{}\", \"crs_name\": {}, \"origin\": [{}, {}, 0], {}}}",
        georeference->epsg, jsonString(crsName(georeference->epsg)), jsonNumber(georeference->originEasting),
        jsonNumber(georeference->originNorthing), frame);
}

std::vector<ExportFile> georeferenceSidecars(const std::optional<Georeference> &georeference,
                                             const std::filesystem::path &out, FileAxes axes) {
    if (!georeference) return {};
    std::filesystem::path prj = out, json = out;
    prj.replace_extension(".prj");
    json.replace_extension(".geo.json");
    std::string text = fmt::format("{{\"file\": {}, \"veduta\": {}}}\n", jsonString(out.filename().string()),
                                   georeferenceJson(georeference, axes));
    return {{prj, esriWkt(georeference->epsg) + "\n", {}}, {json, text, {}}};
}

}  // namespace veduta
