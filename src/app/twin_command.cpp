// `veduta twin`: the procedural twin of a CityGML district, written as a scene file whose
// <buildings> derive, from each modelled building's footprint, heights, roof type and
// storeys, a building of the chosen facade rules (docs/compare.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "app/shipped_files.h"
#include "city/citygml_buildings.h"
#include "city/citygml_file.h"
#include "city/citygml_twin.h"
#include "compare/height_map.h"
#include "compare/views.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/xml_escape.h"
#include "geodesy/map_projection.h"
#include "io/output_files.h"

namespace veduta {

namespace {

namespace fs = std::filesystem;

struct TwinArgs {
    std::string input;
    std::string output;
    std::string rules;
    std::string crs;
    std::vector<double> origin;
    unsigned lod = 0;
};

// The file's envelope centre (else its buildings' middle), to the metre.
MapPoint originOf(const CityGmlModel &model) {
    if (model.envelopeLow && model.envelopeHigh)
        return {std::round((model.envelopeLow->x + model.envelopeHigh->x) / 2),
                std::round((model.envelopeLow->y + model.envelopeHigh->y) / 2)};
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const CityGmlBuilding &b : model.buildings)
        for (const CityGmlPolygon &p : b.polygons)
            for (const CrsCoordinate &c : p.rings.front())
                x0 = std::min(x0, c.x), y0 = std::min(y0, c.y), x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
    return {std::round((x0 + x1) / 2), std::round((y0 + y1) / 2)};
}

// A path as the scene file should name it: relative to the scene's folder where it can be.
std::string pathFrom(const fs::path &sceneFolder, const fs::path &file) {
    std::error_code error;
    fs::path relative = fs::relative(fs::absolute(file), fs::absolute(sceneFolder), error);
    // Two folders up at most: further, the two are only related by where they happen to be.
    int up = int(std::count(relative.begin(), relative.end(), fs::path("..")));
    return escapeXml((error || relative.empty() || up > 2 ? fs::absolute(file) : relative).generic_string());
}

std::string buildingElement(const TwinBuilding &twin) {
    std::string footprint;
    for (const Vec2f &p : twin.footprint)
        footprint += fmt::format("{}{:.3f} {:.3f}", footprint.empty() ? "" : "  ", p.x, p.y);
    std::string settings = fmt::format("<BuildingHeight>{:.3f}</BuildingHeight><FloorHeight>{:.3f}</FloorHeight>",
                                       twin.wallHeight, twin.floorHeight);
    // Under 10 cm of roof is a flat one: the modelled roof only leans to drain.
    bool flat = twin.roofHeight < 0.1 || twin.roof == RoofType::Flat;
    settings += fmt::format("<RoofHeight>{:.3f}</RoofHeight>", flat ? 0.0 : twin.roofHeight);
    if (twin.roof && !flat) settings += fmt::format("<RoofType>{}</RoofType>", roofTypeName(*twin.roof));
    return fmt::format(
        "    <!-- {}: {} storey(s) -->\n    <building id=\"{}\" base=\"{:.3f}\" footprint=\"{}\">\n"
        "      <BuildingSettings>{}</BuildingSettings>\n    </building>\n",
        escapeXml(twin.gmlId), twin.storeys, twin.id, twin.base, footprint, settings);
}

void runTwin(const TwinArgs &args) {
    fs::path output = args.output;
    prepareOutputFile(output);
    fs::path rules = args.rules.empty() ? shippedBuildingRules("--rules") : fs::path(args.rules);
    if (!fs::is_regular_file(rules))
        throw InputError(FileLoc{"--rules"}, fmt::format("cannot read the rule file {}", rules.string()));
    CityGmlOptions read;
    if (args.lod) read.minLod = read.maxLod = args.lod;
    CityGmlModel model = readCityGml(args.input, read);
    printWarnings(model.warnings);
    CityGmlDesc desc;
    desc.file = args.input, desc.fileLoc = desc.loc = desc.crsLoc = FileLoc{args.input};
    desc.epsg = epsgOption(args.crs, "--crs");
    int epsg = cityGmlEpsg(desc, model);
    Georeference georeference{epsg, 0, 0};
    MapPoint origin = args.origin.empty() ? originOf(model) : MapPoint{args.origin[0], args.origin[1]};
    georeference.originEasting = origin.easting, georeference.originNorthing = origin.northing;
    MapProjection projection(crsByEpsg(epsg), georeference);

    std::vector<std::string> warnings;
    std::vector<TwinBuilding> twins;
    std::set<uint32_t> ids;
    for (const CityGmlBuilding &building : model.buildings)
        if (std::optional<TwinBuilding> twin = deriveTwin(building, projection, warnings)) {
            if (!ids.insert(twin->id).second) {
                warnings.push_back(
                    fmt::format("building {}: its building id {} is another's too (a hash collision); "
                                "its twin is left out",
                                building.id, twin->id));
                continue;
            }
            twins.push_back(std::move(*twin));
        }
    printWarnings(warnings);
    if (twins.empty())
        throw InputError(FileLoc{args.input},
                         fmt::format("no building of the file has a twin ({} read)", model.buildings.size()));

    // An overview camera over the twins' footprints.
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, low = 1e300, high = -1e300;
    for (const TwinBuilding &t : twins) {
        for (const Vec2f &p : t.footprint)
            x0 = std::min(x0, double(p.x)), y0 = std::min(y0, double(p.y)), x1 = std::max(x1, double(p.x)),
            y1 = std::max(y1, double(p.y));
        low = std::min(low, t.base), high = std::max(high, t.base + t.wallHeight + t.roofHeight);
    }
    GroundGrid extent{x0, y0, 1, int(std::ceil(x1 - x0)), int(std::ceil(y1 - y0))};
    Camera camera = overviewCamera(extent, float(low), float(high), 960, 540);

    fs::path folder = output.parent_path();
    std::string text = fmt::format(
        R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- The procedural twin of {input}: {count} of its {read} buildings, made by `veduta twin`
     (docs/compare.md). Each <building> has the modelled one's footprint, base, wall and roof
     heights, roof type and storeys, and its building id, so that `veduta compare` pairs them. -->
<scene version="1">
  <georeference crs="EPSG:{epsg}" origin="{e:.3f} {n:.3f}"/>
  <camera position="{px:.2f} {py:.2f} {pz:.2f}" look_at="{lx:.2f} {ly:.2f} {lz:.2f}" up="0 0 1" fov="{fov}" resolution="960 540"/>
  <sun azimuth="215" elevation="38" irradiance="3.2 3.05 2.8" angular_diameter="0.53"/>
  <environment radiance="0.38 0.5 0.78"/>
  <render spp="64" max_depth="6"/>
  <materials file="{materials}"/>
  <!-- Level ground 200 m round the buildings, 5 cm under the lowest: `veduta compare` puts
       the modelled buildings on it too. -->
  <material name="twin/ground" diffuse="0.3 0.3 0.28"/>
  <plane size="{gw:.0f} {gh:.0f}" translate="{gx:.2f} {gy:.2f} {gz:.2f}" material="twin/ground"/>
  <buildings rules="{rules}">
    <!-- The heights are the modelled ones, not drawn; a flat roof has no parapet of its own. -->
    <BuildingSettings><BuildingHeightVar>0</BuildingHeightVar><FloorHeightVar>0</FloorHeightVar><RoofHeightVar>0</RoofHeightVar><ParapetHeight>0</ParapetHeight></BuildingSettings>
)",
        fmt::arg("input", escapeXml(fs::path(args.input).filename().string())), fmt::arg("count", twins.size()),
        fmt::arg("read", model.buildings.size()), fmt::arg("epsg", epsg), fmt::arg("e", origin.easting),
        fmt::arg("n", origin.northing), fmt::arg("px", camera.position.x), fmt::arg("py", camera.position.y),
        fmt::arg("pz", camera.position.z), fmt::arg("lx", camera.lookAt.x), fmt::arg("ly", camera.lookAt.y),
        fmt::arg("lz", camera.lookAt.z), fmt::arg("fov", camera.verticalFovDegrees),
        fmt::arg("materials", pathFrom(folder, rules.parent_path() / "materials.xml")),
        fmt::arg("rules", pathFrom(folder, rules)), fmt::arg("gw", x1 - x0 + 400), fmt::arg("gh", y1 - y0 + 400),
        fmt::arg("gx", (x0 + x1) / 2), fmt::arg("gy", (y0 + y1) / 2), fmt::arg("gz", low - 0.05));
    for (const TwinBuilding &twin : twins) text += buildingElement(twin);
    text += "  </buildings>\n</scene>\n";
    writeBytesAtomically(output, text.data(), text.size());
    std::fprintf(stderr, "%s: the twins of %zu of %zu buildings\n", output.c_str(), twins.size(),
                 model.buildings.size());
}

}  // namespace

void addTwinCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<TwinArgs>();
    CLI::App *cmd =
        app.add_subcommand("twin", "Write a scene of procedural buildings made after the buildings of a CityGML file");
    cmd->add_option("CITYGML", args->input, "CityGML 1.0 or 2.0 file of LoD1/LoD2 buildings")->required();
    cmd->add_option("-o,--output", args->output, "Scene file to write")->required()->check(fileWithExtension(".xml"));
    cmd->add_option("--rules", args->rules,
                    "Facade rule file (docs/rules.md); its folder's materials.xml is used too [the Gründerzeit rules]");
    cmd->add_option("--crs", args->crs, "CRS of the file's coordinates when it names none (EPSG:<code>)");
    cmd->add_option("--origin", args->origin, "Scene origin, easting and northing in the file's CRS [its centre]")
        ->expected(2)
        ->type_name("E N");
    cmd->add_option("--lod", args->lod, "Read this LoD only [each building's highest of 1 and 2]")
        ->check(CLI::Range(1u, 2u));
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runTwin(*args); }); });
}

}  // namespace veduta
