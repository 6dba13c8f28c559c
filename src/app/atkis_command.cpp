// `veduta atkis info FILE`: what an ATKIS (or ALK) file holds, read as the scene loader reads
// it: EDBS natively, anything else through GDAL/OGR. key: value lines on stdout.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "geo/edbs.h"
#include "geo/vector_file.h"

namespace veduta {

namespace {

// The extent of points seen, as min/max easting and northing.
struct Extent {
    double minE = std::numeric_limits<double>::max(), minN = minE;
    double maxE = std::numeric_limits<double>::lowest(), maxN = maxE;

    void add(const MapPoint &p) {
        minE = std::min(minE, p.easting), maxE = std::max(maxE, p.easting);
        minN = std::min(minN, p.northing), maxN = std::max(maxN, p.northing);
    }
    bool empty() const { return minE > maxE; }
};

bool isEdbs(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    char start[4] = {};
    in.read(start, 4);
    return in.gcount() == 4 && std::string_view(start, 4) == "EDBS";
}

char geometryLetter(AtkisGeometry g) { return g == AtkisGeometry::Point ? 'P' : g == AtkisGeometry::Line ? 'L' : 'F'; }

void printObjects(const AtkisData &data) {
    std::map<std::tuple<int, std::string, char>, int> counts;
    for (const AtkisObject &o : data.objects) ++counts[{o.type, o.typeName, geometryLetter(o.geometry)}];
    std::printf("objects: %zu\n", data.objects.size());
    for (const auto &[key, count] : counts) {
        const auto &[type, typeName, geometry] = key;
        std::string name = typeName.empty() ? std::string(atkisTypeName(type)) : typeName;
        std::string code = type == 0 ? std::string("----") : fmt::format("{:04d}", type);
        std::printf("objects %s %s %c: %d\n", code.c_str(), name.empty() ? "(unknown)" : name.c_str(), geometry, count);
    }
}

void printExtent(const Extent &extent) {
    if (extent.empty()) std::printf("extent: none\n");
    else std::printf("extent: %.3f %.3f %.3f %.3f\n", extent.minE, extent.minN, extent.maxE, extent.maxN);
}

// EDBS states no CRS; the Gauss-Krüger zone shows in the eastings' leading digit.
void printEdbsCrs(const Extent &extent) {
    int zone = int(extent.minE / 1e6);
    if (!extent.empty() && zone == int(extent.maxE / 1e6) && zone >= 2 && zone <= 5)
        std::printf("crs: not stated (Gauss-Krüger zone %d by the eastings; the datum is not stated)\n", zone);
    else std::printf("crs: not stated\n");
}

void printWarnings(const std::vector<std::string> &warnings) {
    for (const std::string &w : warnings) std::fprintf(stderr, "veduta: warning: %s\n", w.c_str());
}

void edbsInfo(const std::string &path) {
    EdbsFile file = readEdbs(path);
    EdbsConversion conversion = toAtkis(file, IncompleteObjects::Skip);
    std::printf("format: EDBS (%s coordinates)\n", file.coordinates() == EdbsCoordinates::Alk ? "ALK" : "ATKIS");
    std::printf("records: %d\n", file.records);
    for (const auto &[kind, count] : file.recordCounts) std::printf("records %s: %d\n", kind.c_str(), count);
    std::printf("end_record: %s\n", file.hasEnd ? "yes" : "no");
    std::set<std::pair<double, double>> points;
    Extent extent;
    for (const EdbsLine &line : file.lines) {
        for (const MapPoint *p : {&line.start, &line.end}) points.insert({p->easting, p->northing}), extent.add(*p);
        for (const MapPoint &p : line.between) points.insert({p.easting, p.northing}), extent.add(p);
    }
    for (const EdbsObject &o : file.objects) extent.add(o.reference);
    std::printf("vector_elements: %zu\n", file.lines.size());
    std::printf("points: %zu\n", points.size());
    std::printf("attribute_records: %zu\n", file.attributes.size());
    printObjects(conversion.atkis);
    std::printf("incomplete_objects: %zu\n", conversion.skipped.size());
    if (!conversion.skipped.empty())
        std::printf(
            "note: %zu area or line objects do not close and are left out; BSPE output cut to a search "
            "rectangle (or a file cut short) leaves such objects; the scene loader rejects them "
            "(docs/atkis.md); the first: %s\n",
            conversion.skipped.size(), conversion.skipped.front().c_str());
    printEdbsCrs(extent);
    printExtent(extent);
    if (file.area)
        std::printf("order_area: %.3f %.3f %.3f %.3f\n", file.area->first.easting, file.area->first.northing,
                    file.area->second.easting, file.area->second.northing);
    printWarnings(conversion.warnings);
}

void vectorInfo(const std::string &path) {
    std::vector<std::string> warnings;
    AtkisData data = readVectorFile(path, warnings);
    size_t lines = 0, points = 0;
    Extent extent;
    for (const AtkisObject &o : data.objects) {
        for (const auto *set : {&o.areas, &o.lines})
            for (const MapLine &line : *set) {
                ++lines;
                points += line.size();
                for (const MapPoint &p : line) extent.add(p);
            }
        points += o.points.size();
        for (const MapPoint &p : o.points) extent.add(p);
    }
    std::printf("format: GDAL vector\n");
    std::printf("lines: %zu\n", lines);
    std::printf("points: %zu\n", points);
    printObjects(data);
    if (data.epsg != 0) std::printf("crs: EPSG:%d\n", data.epsg);
    else std::printf("crs: not stated\n");
    printExtent(extent);
    printWarnings(warnings);
}

}  // namespace

void addAtkisCommand(CLI::App &app, int &exitCode) {
    CLI::App *atkis = app.add_subcommand("atkis", "Read ATKIS data (EDBS, NAS, Shapefile, GeoPackage, …)");
    atkis->require_subcommand(1);
    auto path = std::make_shared<std::string>();
    CLI::App *info =
        atkis->add_subcommand("info", "Print what an ATKIS file holds: objects by type, lines, points, CRS, extent");
    info->add_option("file", *path, "EDBS file, or any vector file GDAL reads")->required();
    info->callback(
        [path, &exitCode] { exitCode = runGuarded([&] { isEdbs(*path) ? edbsInfo(*path) : vectorInfo(*path); }); });
}

}  // namespace veduta
