// SceneDescription: what a scene file says, checked for form but not yet turned into
// geometry. docs/scene-format.md documents the XML it comes from.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "description/settings_map.h"
#include "geodesy/crs.h"
#include "geodesy/georeference.h"
#include "scene/camera.h"
#include "scene/environment.h"
#include "scene/fog.h"
#include "scene/material.h"
#include "scene/render_settings.h"
#include "scene/shapes.h"
#include "scene/sun.h"
#include "scene/sun_position.h"

namespace veduta {

// A reference by name, with the place it was written for messages.
struct NameRef {
    std::string name;  // empty: none given
    FileLoc loc;
};

// A <box>, <sphere>, ... or <mesh> element: one piece of geometry with its placement.
struct GeometryDesc {
    FileLoc loc;
    std::optional<ShapeSpec> shape;  // set for primitive shapes
    std::filesystem::path meshFile;  // set for <mesh>, already resolved against the scene's folder
    FileLoc meshFileLoc;
    // crs="EPSG:…" of a <mesh>: its x and y are eastings and northings of that CRS, placed
    // through the scene's georeference (io/georeferenced_mesh.h); 0: local metres.
    int meshEpsg = 0;
    FileLoc meshCrsLoc;
    Transform transform;
    NameRef material;
    uint32_t objectId = 0;    // 0 inside prototypes: their instances carry the id
    uint32_t buildingId = 0;  // the building it is part of; 0: none (and inside prototypes)
};

struct PrototypeDesc {
    FileLoc loc;
    std::string name;
    std::vector<GeometryDesc> parts;
};

struct InstanceDesc {
    FileLoc loc;
    NameRef prototype;
    Transform transform;
    NameRef material;  // overrides the prototype's materials when given
    uint32_t objectId = 0;
    uint32_t buildingId = 0;  // the building it is part of; 0: none
};

// An image file a material or the environment reads, with the place it was named.
struct ImageRef {
    std::filesystem::path file;  // already resolved against the naming file's folder; empty: none
    std::string colorSpace;      // OpenColorIO name; "" = the file's own
    FileLoc loc;

    bool given() const { return !file.empty(); }
};

// A material with its maps named but not yet loaded; material_file.h reads it.
struct MaterialDesc {
    FileLoc loc;
    Material material;
    ImageRef diffuseMap, specularMap, normalMap, reflectionMap, opacityMap;
};

// Light from outside the scene: a constant radiance, a cubemap from image files, or a clear
// sky computed for the sun's position.
struct EnvironmentDesc {
    FileLoc loc;
    Vec3f radiance{0.0f};
    ImageRef cubemap;  // six faces ({face} or {axis} in the name), a cross, or a lat-long image
    int faceSize = 0;  // for lat-long images and the sky; 0 = chosen from the image
    bool sky = false;
    float turbidity = 3;
    float groundAlbedo = 0.2f;
    float rotationDegrees = 0;
    float intensity = 1;
};

// The sun's place in the sky from a date and time, as an alternative to a direction.
struct SunTimeDesc {
    FileLoc loc;
    CivilTime time;
    std::optional<GeographicPoint> place;  // unset: the georeference's origin
};

// One procedural building: a footprint whose walls its group's rules derive.
struct BuildingDesc {
    FileLoc loc;
    uint32_t buildingId = 0;  // its identity: its random choices and the IndexBuilding pass
    uint32_t objectId = 0;
    std::vector<Vec2f> footprint;  // x y pairs, metres, either orientation
    FileLoc footprintLoc;
    std::vector<uint32_t> streetEdges;  // edge i runs from point i to point i+1
    FileLoc streetLoc;
    // The height it stands on; unset: the terrain's lowest point under it when the scene has
    // a <landscape> (docs/terrain.md), else 0.
    std::optional<float> base;
    SettingsMap settings;
};

// A lone facade: a start symbol on a width × height rectangle, for studies of a rule set. It
// stands on the x axis facing −y (south) before its transform.
struct FacadeDesc {
    FileLoc loc;
    uint32_t buildingId = 0;  // numbered with the buildings
    uint32_t objectId = 0;
    std::string start;
    float width = 0, height = 0;
    Transform transform;
    SettingsMap settings;
};

// A <buildings> element: buildings derived with one rule file (docs/buildings.md).
struct BuildingGroupDesc {
    FileLoc loc;
    std::filesystem::path rules;  // resolved against the scene's folder
    FileLoc rulesLoc;
    std::optional<uint32_t> seed;  // with each building's id, every random choice; unset: the scene's
    SettingsMap settings;
    std::vector<BuildingDesc> buildings;
    std::vector<FacadeDesc> facades;
};

// A <city> element: a CityData file (Bilke's Listing 2.1, docs/citydata.md) whose blocks are
// cut into lots where they have none and whose lots are built with the rule files it names.
// A <generate>: a town that a street L-system grows (docs/generate.md), built as a <city> is.
struct CityGrowthDesc {
    std::filesystem::path streets;  // the street rule file, resolved against the scene's folder
    FileLoc streetsLoc;
    bool tensor = false;  // pattern="tensor": the streets are traced through a seeded tensor field instead
    // Where the town lies: map coordinates of the scene's CRS, or local metres without a
    // <georeference>.
    double centreE = 0, centreN = 0;
    FileLoc centreLoc;
    float radius = 500;
    float majorWidth = 12, minorWidth = 7, majorShare = 0.25f;  // the street hierarchy's
    float maxGrade = 0.12f;  // the steepest a street may climb on a <landscape>'s DGM, rise over run
    std::string lots;        // the LotSubdivision of its blocks; empty: the rule file's, or perimeter lots
    FileLoc lotsLoc;
    // An OpenStreetMap file whose highways the town grows onto (docs/generate.md); empty: none.
    std::filesystem::path roads;
    FileLoc roadsLoc;
    // A futuristic city's street levels (docs/futuristic.md), the ground's included: 1 is an
    // ordinary town. The upper ones lie `levelSpacing` apart, joined by lifts between junctions
    // at most `liftReach` apart in plan; their streets are `streetThickness` thick.
    unsigned levels = 1;
    float levelSpacing = 40, liftReach = 15, streetThickness = 1;
};

// When a generator draws a building coarse (a box with its roof) rather than in full: when it
// spans fewer than `belowPixels` pixels of the image's height (Camera::pixelsSpanned), or lies
// farther from the camera than `beyond` metres where that is given (seed 000's switch at 300 m).
// Either makes it coarse. `coarse_below_px` and `coarse_beyond` on <city>, <generate> and
// <citygml>.
struct CoarseRule {
    std::optional<float> beyond;
    float belowPixels = 8;  // a building this small shows no window as large as a pixel
    bool isCoarse(const Camera &camera, Vec3f low, Vec3f high) const {
        if (camera.pixelsSpanned(low, high) < belowPixels) return true;
        return beyond && length((low + high) * 0.5f - camera.position) > *beyond;
    }
};

// structure="…" style="…" on a <city>, <citygml> or <landscape>: its buildings' footprints stand as
// Finkenzeller's modular buildings (docs/facades.md, "Footprints from data"): each split into
// modules that take the structure's one module's storeys, refitted to the storeys or height the
// data gives, in the style.
struct ModularLookDesc {
    std::filesystem::path structure, style;  // resolved against the scene's folder
    FileLoc structureLoc, styleLoc;
};

struct CityDesc {
    FileLoc loc;
    std::filesystem::path file;  // resolved against the scene's folder; .osm: OpenStreetMap (docs/osm.md)
    FileLoc fileLoc;
    std::optional<CityGrowthDesc> growth;  // a <generate>: no file, the rules grow the city
    // The rule file for a city that names none (an OpenStreetMap file never does); empty: none.
    std::filesystem::path rules;
    FileLoc rulesLoc;
    // The CRS of a CityData file's points; 0: the scene's georeference CRS, or local metres in
    // a scene without one.
    int epsg = 0;
    FileLoc crsLoc;
    std::optional<uint32_t> seed;  // with each lot's identity, every random choice; unset: the scene's
    CoarseRule coarse;
    std::optional<ModularLookDesc> modular;  // its lots' buildings; the rule files then only cut lots
    bool streetTrees = true;                 // trees along the streets wide enough (city/street_trees.h)
    uint32_t objectId = 0;
};

// A <citygml> element: the buildings of a CityGML file (docs/citygml.md), placed at their map
// coordinates through the scene's georeference.
struct CityGmlDesc {
    FileLoc loc;
    std::filesystem::path file;  // resolved against the scene's folder
    FileLoc fileLoc;
    // The CRS of the file's coordinates when the file names none (srsName); 0: none given.
    int epsg = 0;
    FileLoc crsLoc;
    // The LoDs read: each building at the highest of them it has.
    unsigned minLod = 1, maxLod = 2;
    // bbox="E0 N0 E1 N1": only the buildings whose bounding box's centre lies in this rectangle
    // of the scene's CRS are placed; unset: all.
    std::optional<std::array<double, 4>> bbox;
    FileLoc bboxLoc;
    CoarseRule coarse;
    std::optional<ModularLookDesc> modular;  // its buildings rebuilt on their footprints (citygml_twin.h)
    uint32_t objectId = 0;
};

// A <modular_building> element: a building of floor-plan modules in Finkenzeller's structure and
// style languages (docs/facades.md), placed by its transform.
struct ModularBuildingDesc {
    FileLoc loc;
    std::filesystem::path structure, style;  // resolved against the scene's folder
    FileLoc structureLoc, styleLoc;
    // footprint="x y …": the structure's one module is a prototype, the footprint is split into
    // modules that take its storeys (facade/building_structure.h, structureOnFootprint).
    std::vector<Vec2f> footprint;
    FileLoc footprintLoc;
    Transform transform;
    std::optional<uint32_t> seed;
    uint32_t objectId = 0;
    uint32_t buildingId = 0;  // its random choices (the masonry) and its id pass
    // A footprint from data (ModularLookDesc): the storeys the data counts, else the eaves height
    // it gives, refit the structure's (refitStoreys); a footprint that no partition splits into
    // modules is left out with a warning rather than an error.
    bool fromData = false;
    std::optional<size_t> storeys;
    std::optional<double> eaves;
    // The rule of the element that reads the footprint: a building it picks, seen from the camera,
    // is a block of its modules up to the eaves in its style's wall and roof materials.
    std::optional<CoarseRule> coarse;
};

// An <slg> element: a block or a district planned with Schrader's Spatial Landmark Graph from
// the urban-geography tables alone (docs/slg.md): its outline in the scene's metres, cut into
// lots (a district first into blocks between streets), each lot's building planned down to its
// rooms and built at the level of detail its distance from the camera asks for.
struct SlgDesc {
    FileLoc loc;
    // Atkis: the blocks are the <landscape>'s settlement areas, the buildings its footprints.
    enum class Level : uint8_t { Block, District, Atkis } level = SlgDesc::Level::Block;
    std::vector<Vec2f> outline;  // counter-clockwise in the scene's x/y, at height `base`
    FileLoc outlineLoc;
    float base = 0;
    std::filesystem::path tables;  // rules/slg/urban-geography.xml or one like it
    FileLoc tablesLoc;
    // A building shows its rooms behind the glass when it is nearer than `rooms` metres and spans
    // at least `roomsPixels` of the image's height (Camera::pixelsSpanned); its storeys, windows
    // and door when nearer than `storeys` metres and at least `storeysPixels` high; else one quad
    // a side. The distances are Table 12's; the pixels keep the levels where they show.
    float rooms = 50, storeys = 100;
    float roomsPixels = 100, storeysPixels = 8;
    std::optional<uint32_t> seed;  // with each building's identity, every random choice; unset: the scene's
    uint32_t objectId = 0;
};

// A data file a <landscape> reads, with the CRS of its coordinates.
struct DataFileDesc {
    std::filesystem::path file;  // resolved against the scene's folder
    FileLoc loc;
    int epsg = 0;  // 0: the scene's georeference CRS
};

// How many rings from the nearest height a <landscape nodata="fill"> fills by default: gaps of
// up to about 16 nodes across (bridges and buildings cut out of a DGM1, a missing tile row),
// not the margin of a tile whose data covers half its raster.
inline constexpr int kDefaultFillDistance = 8;

// A <landscape> element: terrain from DGM tiles, with ATKIS layers draped on it and trees in
// its forests (docs/terrain.md). Needs the scene's <georeference>, whose origin is the local
// frame's.
struct LandscapeDesc {
    FileLoc loc;
    std::vector<DataFileDesc> dgm;     // tiles of one grid, mosaicked
    std::vector<DataFileDesc> layers;  // ATKIS: EDBS, NAS, Shapefile, GeoPackage, GeoJSON …
    // nodata="fill": holes within this many nodes of a height are filled (a warning), farther
    // ones cut; nodata="cut": 0, every hole stays open.
    int fillDistance = kDefaultFillDistance;
    float simplify = 0;  // the largest height error of a simplified mesh; 0: full resolution
    bool trees = true;
    uint32_t treeBudget = 500000;            // more trees than this is an error
    std::optional<uint32_t> seed;            // with each object's identity, every random choice; unset: the scene's
    std::optional<ModularLookDesc> modular;  // its building footprints (ALK Folie 011) raised as buildings
    uint32_t objectId = 0;
};

// A camera placed in map coordinates (<camera crs="EPSG:…">): position and look_at are
// easting, northing and height in that CRS; buildRenderScene takes them into the render frame.
struct MapCameraDesc {
    int epsg = 0;
    CrsCoordinate position, lookAt;
    FileLoc loc;  // of the crs attribute
};

struct SceneDescription {
    std::string source;  // file name, or a name for built-in text
    Camera camera;
    std::optional<MapCameraDesc> mapCamera;
    Sun sun;
    std::optional<SunTimeDesc> sunTime;
    std::optional<Georeference> georeference;
    EnvironmentDesc environment;
    Fog fog;  // its inscatter is left to buildRenderScene, which takes it from the sky
    // <scene seed> (or --seed): the seed of every random choice whose generator has no seed of
    // its own; buildRenderScene resolves them all, in one place.
    uint32_t seed = 0;
    std::optional<uint32_t> renderSeed;  // <render seed>: the sampler's; unset: the scene's
    RenderSettings settings;             // its seed is the resolved one only in the RenderScene
    // <render masonry>: Finkenzeller's masonry shaded where it is looked up (procedural, the
    // default) or baked to images (docs/facades.md, "Baked or shaded procedurally").
    bool proceduralMasonry = true;
    std::vector<MaterialDesc> materials;
    std::vector<GeometryDesc> geometry;
    std::vector<PrototypeDesc> prototypes;
    std::vector<InstanceDesc> instances;
    std::vector<BuildingGroupDesc> buildingGroups;
    std::vector<CityDesc> cities;
    std::vector<CityGmlDesc> cityGml;
    std::vector<ModularBuildingDesc> modularBuildings;
    std::vector<SlgDesc> slg;
    std::optional<LandscapeDesc> landscape;
};

// Parse a scene file; throws InputError with file:line:column on any problem.
SceneDescription readSceneFile(const std::filesystem::path &file);
// Parse scene XML held in memory; relative mesh paths resolve against `baseDirectory`.
SceneDescription readSceneText(std::string text, const std::string &name, const std::filesystem::path &baseDirectory);

}  // namespace veduta
