// `veduta generate`: a town grown from a street L-system (issue 20, seed 002), written as a
// CityData file that a <city> builds, with GIS layers of its streets, blocks and lots and a DOT
// view of the street graph. docs/generate.md.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/shipped_files.h"
#include "city/building_rules.h"
#include "city/city_data_writer.h"
#include "city/city_layers.h"
#include "city/generate_city.h"
#include "city/ground_environment.h"
#include "city/grown_city.h"
#include "city/lot_subdivision.h"
#include "city/osm_import.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "geo/generate_landscape.h"
#include "geodesy/crs.h"
#include "io/output_files.h"
#include "streets/street_graph_dot.h"
#include "streets/street_rule_file.h"
#include "streets/tensor_field.h"

namespace veduta {

namespace {

namespace fs = std::filesystem;

struct GenerateArgs {
    std::string pattern = "grid";
    std::vector<double> centre = {0, 0};
    float radius = 500;
    uint32_t seed = 0;
    std::string crs;
    std::string rules;
    std::string lots;
    StreetHierarchy hierarchy;
    std::string dgm;
    float maxGrade = GroundLimits().maxGrade;
    std::vector<std::string> atkis;
    std::string osm;
    std::string output, geojson, gpkg, dot;
    bool quiet = false;
};

// A street rule file: the file named, or one of the patterns in rules/streets/.
fs::path patternFile(const std::string &pattern) {
    if (fs::is_regular_file(pattern)) return pattern;
    for (const char *shipped : {"grid", "organic", "radial"})
        if (pattern == shipped) return shippedFile(fs::path("rules/streets") / (pattern + ".txt"), "--pattern");
    throw InputError(
        FileLoc{"--pattern"},
        fmt::format("'{}' is no pattern: give grid, organic, radial, tensor or a street rule file", pattern));
}

// How the file was made, for its comment (which XML does not let hold "--").
std::string provenance(const GenerateArgs &args) {
    return fmt::format("grown by veduta generate: pattern {}, centre {} {}{}, radius {} m, seed {}", args.pattern,
                       args.centre[0], args.centre[1], args.crs.empty() ? "" : " of " + args.crs, args.radius,
                       args.seed);
}

size_t lotCount(const CityData &city) {
    size_t lots = 0;
    for (const CityBlock &block : city.blocks) lots += block.lots.size();
    return lots;
}

void writeOutputs(const GenerateArgs &args, const CityData &city, const CityGrowthReport &report, int epsg) {
    std::vector<fs::path> files = {args.output, args.dot, args.gpkg};
    if (!args.geojson.empty())
        for (const fs::path &file : cityLayerFiles(args.geojson)) files.push_back(file);
    for (const fs::path &file : files)
        if (!file.empty()) prepareOutputFile(file);
    OutputSet outputs(files);
    // The growth ran at the rules' origin; the files place it at the centre given.
    MapOffset offset{args.centre[0], args.centre[1]};
    writeCityData(city, {offset, provenance(args)}, args.output);
    if (!args.gpkg.empty()) writeCityLayers(city, {offset, epsg}, args.gpkg);
    if (!args.geojson.empty()) writeCityLayers(city, {offset, epsg}, args.geojson);
    if (!args.dot.empty()) {
        std::string dot = toDot(report.graph, CityGrowth().constraints.heightTolerance);
        writeBytesAtomically(args.dot, dot.data(), dot.size());
    }
    outputs.commit();
}

// The DGM and ATKIS layers the town grows on, read as a <landscape> reads them, with the centre
// as the frame's origin.
std::optional<LandscapeData> groundOf(const GenerateArgs &args, int epsg, std::vector<std::string> &warnings) {
    if (args.dgm.empty()) return std::nullopt;
    if (epsg == 0)
        throw InputError(FileLoc{"--dgm"}, "a town on a DGM needs --crs, the CRS of the DGM and of --centre");
    LandscapeDesc land;
    land.dgm.push_back({args.dgm, FileLoc{args.dgm}, 0});
    for (const std::string &layer : args.atkis) land.layers.push_back({layer, FileLoc{layer}, 0});
    return readLandscape(land, Georeference{epsg, args.centre[0], args.centre[1]}, warnings);
}

void runGenerate(const GenerateArgs &args) {
    auto start = std::chrono::steady_clock::now();
    int epsg = epsgOption(args.crs, "--crs");
    // The town is laid out in metres and placed by adding the centre: a projected CRS's.
    if (epsg != 0 && !crsByEpsg(epsg).projected)
        throw InputError(FileLoc{"--crs"},
                         fmt::format("EPSG:{} is not a projected CRS; give one in metres, such as "
                                     "EPSG:25832 (UTM 32N) or EPSG:31467 (Gauss-Krüger 3)",
                                     epsg));
    fs::path rules = args.rules.empty() ? shippedBuildingRules("--rules") : fs::path(args.rules);
    if (!fs::is_regular_file(rules))
        throw InputError(FileLoc{"--rules"}, fmt::format("cannot read the rule file {}", rules.string()));
    // "tensor" before any file of that name: the pattern names are the option's own words.
    bool tensor = args.pattern == "tensor";
    std::optional<StreetRuleSet> streetRules;
    if (!tensor) streetRules = readStreetRuleFile(patternFile(args.pattern));
    BuildingRules buildingRules(rules);

    CityGrowth growth;
    growth.radius = args.radius;
    growth.seed = args.seed;
    growth.hierarchy = args.hierarchy;
    std::vector<std::string> warnings;
    std::optional<LandscapeData> land = groundOf(args, epsg, warnings);
    std::optional<GroundEnvironment> ground;
    if (land) {
        LocalFrame frame{{args.centre[0], args.centre[1]}};
        ground.emplace(&land->grid, frame, streetObstacles(land->objects, frame), Vec2d{0, 0},
                       GroundLimits{args.maxGrade});
        growth.environment = &*ground;
        growth.roads = existingRoads(land->objects, frame, {0, 0}, args.radius);
    }
    if (!args.osm.empty()) {
        if (!fs::is_regular_file(args.osm))
            throw InputError(FileLoc{"--osm"}, fmt::format("cannot read the road file {}", args.osm));
        OsmImportOptions options;
        options.georeference = Georeference{epsg, args.centre[0], args.centre[1]};
        CityData osm = importOsm(args.osm, options);
        warnings.insert(warnings.end(), osm.warnings.begin(), osm.warnings.end());
        for (std::vector<Vec2f> &road : roadsInWindow(streetLines(osm), {0, 0}, args.radius))
            growth.roads.push_back(std::move(road));
    }
    CityGrowthReport report;
    CityData city = tensor ? traceCity(townField(args.seed, args.radius), {}, growth, warnings, &report)
                           : growCity(*streetRules, growth, warnings, &report);
    city.ruleFiles = {fs::absolute(rules)};
    if (!args.lots.empty()) {
        city.settings["LotSubdivision"] = settingValue(args.lots, FileLoc{"--lots"});
        lotSettingsFrom(SettingsStack({&city.settings}));  // an unknown name is an error even without blocks
    }
    cutLots(city, buildingRules.rules.settings, args.seed, warnings);
    for (const std::string &w : warnings) std::fprintf(stderr, "veduta: warning: %s\n", w.c_str());
    writeOutputs(args, city, report, epsg);
    if (args.quiet) return;
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (tensor) std::printf("streamlines: %zu\n", report.streamlines);
    else std::printf("expansions: %zu\n", report.growth.expansions);
    std::printf("streets: %zu\nmajor_streets: %zu\nblocks: %zu\nlots: %zu\nseconds: %.3f\n", city.streets.size(),
                report.majorStreets, city.blocks.size(), lotCount(city), seconds);
}

}  // namespace

void addGenerateCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<GenerateArgs>();
    CLI::App *cmd = app.add_subcommand(
        "generate",
        "Grow a town from a street L-system (grid, organic, radial or a rule file) or a tensor field and write it as "
        "CityData, with GeoJSON/GeoPackage layers and a DOT graph");
    cmd->add_option("--pattern", args->pattern,
                    "grid, organic, radial (rules/streets/), a street rule file, or tensor (streets traced through a "
                    "seeded tensor field)")
        ->capture_default_str();
    cmd->add_option("--centre", args->centre, "Where the town lies: E N, map coordinates of --crs (else local metres)")
        ->expected(2)
        ->capture_default_str();
    cmd->add_option("--radius", args->radius, "Radius of the window the streets grow in, metres")
        ->check(CLI::Range(1.0f, 50000.0f))
        ->capture_default_str();
    cmd->add_option("--seed", args->seed, "Seed of every random choice")->capture_default_str();
    cmd->add_option("--crs", args->crs, "EPSG:<code> of the centre and the files' coordinates (a projected CRS)");
    cmd->add_option("--dgm", args->dgm, "DGM to grow on (needs --crs): streets keep off slopes over 12 % and its edge");
    cmd->add_option("--max-grade", args->maxGrade, "Steepest a street may climb on the DGM, rise over run")
        ->check(CLI::Range(0.001f, 1.0f))
        ->needs("--dgm")
        ->capture_default_str();
    cmd->add_option("--atkis", args->atkis,
                    "ATKIS layer(s) whose water and forest the streets keep off and whose roads they grow onto (with "
                    "--dgm)")
        ->needs("--dgm");
    cmd->add_option("--osm", args->osm, "OpenStreetMap file whose highways the streets grow onto (with --crs)")
        ->needs("--crs");
    cmd->add_option("--rules", args->rules, "Building rule file the CityData names (default: the Gründerzeit rules)");
    cmd->add_option("--lots", args->lots,
                    "LotSubdivision of every block: perimeter, recursive, obb, skeleton, schrader");
    cmd->add_option("--major-width", args->hierarchy.majorWidth, "Width of main streets, metres")
        ->check(CLI::Range(1.0f, 100.0f))
        ->capture_default_str();
    cmd->add_option("--minor-width", args->hierarchy.minorWidth, "Width of the other streets, metres")
        ->check(CLI::Range(1.0f, 100.0f))
        ->capture_default_str();
    cmd->add_option("--major-share", args->hierarchy.majorShare, "Share of the street length that is main streets")
        ->check(CLI::Range(0.0f, 1.0f))
        ->capture_default_str();
    cmd->add_option("-o,--output", args->output, "CityData file to write (a <city file> loads it)")
        ->required()
        ->check(fileWithExtension(".xml"));
    cmd->add_option("--geojson", args->geojson, "Folder for streets.geojson, blocks.geojson and lots.geojson");
    cmd->add_option("--gpkg", args->gpkg, "GeoPackage with the layers streets, blocks and lots")
        ->check(fileWithExtension(".gpkg"));
    cmd->add_option("--dot", args->dot, "GraphViz file of the street graph (neato -n2 draws it to scale)");
    cmd->add_flag("-q,--quiet", args->quiet, "No summary");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runGenerate(*args); }); });
}

}  // namespace veduta
