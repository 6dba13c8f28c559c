// The city generator for a scene's <city>: a CityData file (docs/citydata.md) whose blocks
// without lots are cut into perimeter lots (docs/lots.md) and whose lots are built with the
// grammar of its rule files (docs/buildings.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "city/city_data.h"
#include "city/footprint.h"
#include "city/futuristic_city.h"
#include "city/masonry_maps.h"
#include "city/modular_buildings.h"
#include "city/street_geometry.h"
#include "city/street_index.h"
#include "description/scene_description.h"
#include "geo/generate_landscape.h"
#include "geodesy/georeference.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

// The city's file, CityData XML or OpenStreetMap (.osm), with the <city>'s rule file where the
// data names none. With the scene's georeference the file's coordinates are map coordinates
// (CityData: of the <city>'s crs, by default the scene's; OpenStreetMap: WGS 84) placed through
// geodesy/map_projection.h; without one, local metres (OpenStreetMap: on the tangent plane at the
// data's centre). The scene reads its cities first: their streets are cut into a landscape
// before the city is built on it. A <generate> (city.growth) grows the city from its street
// rules with `seed` (the city's resolved seed) instead, at its centre, with the growth's
// warnings at the element; on the scene's `landscape` (read, not yet built) its streets keep
// off slopes too steep, water, forest and the land beyond the DGM (ground_environment.h); with
// levels > 1 the same rules grow its upper levels too (futuristic_city.h).
// Throws InputError.
struct SceneCity {
    CityData data;  // the ground level
    std::vector<UpperLevel> upperLevels;
    StreetLevels levels;
};
SceneCity readCity(const CityDesc &city, const std::optional<Georeference> &georeference, uint32_t seed,
                   const LandscapeData *landscape = nullptr);

// Builds the streets and every lot of the city read by readCity with `seed`, the city's
// resolved seed (buildRenderScene). Each building's id is cityBuildingId of the city's object
// id and its lot's identity (lotsOf), so adding a lot or a block leaves the other buildings as
// they were. A futuristic city's upper levels follow (buildUpperLevels), over the ground's
// junctions. Returns how many buildings it built. With a `landscape`, the streets lie on its
// terrain (streetsOnTerrain) and every building stands on its ground with a plinth, as a
// <buildings> building without base does: the terrain decides, the points' heights u are
// ignored (a warning says so where one is not 0). Warnings (a clockwise block, probabilities
// renormalised, two buildings of one id …) are appended once each as "file:line:col: message";
// errors throw InputError.
//
// Seen from `detail.camera`, a building the coarse rule picks (too few pixels high, or beyond
// coarse_beyond) is one plain quad a wall and its roof; while the builder's geometry budget
// lasts the others keep their facades, past it the farthest lose them first, with
// a warning. Distant buildings share one mesh. Without a camera every building keeps its
// facades while the budget lasts.
// The rule files' <Masonry> walls are baked for the camera into maps registered through
// `masonryMaps`; without either, they keep their model's texture (a warning says so).
//
// A city with a modular look (ModularLookDesc) builds each lot as one of `modular`'s buildings
// instead (footprintBuilding): edge 0 its longest street edge, its storeys nearest the data's own
// BuildingHeight (the lot's, block's or city's, not the rule file's), else as the structure has
// them; one the coarse rule picks is a block of its modules. Its rule files, if any, then only say
// how blocks are cut into lots.
struct BuildingDetail {
    std::optional<Camera> camera;
    CoarseRule coarse;
    MasonryOutput masonryMaps = {};
    const ModularLookDesc *look = nullptr;
    ModularBuildings *modular = nullptr;
};
uint32_t generateCity(const CityDesc &city, const SceneCity &read, uint32_t seed, const LandscapeGround *landscape,
                      RenderSceneBuilder &builder, std::vector<std::string> &warnings, const Camera &camera,
                      const MasonryOutput &masonryMaps = {}, ModularBuildings *modular = nullptr);
// The same for a city made in memory (as the benchmark does); errors about the city as a
// whole (no rule file) have no place in a file.
uint32_t generateCity(const CityData &data, uint32_t seed, ObjectId objectId, RenderSceneBuilder &builder,
                      std::vector<std::string> &warnings, const LandscapeGround *landscape = nullptr,
                      const BuildingDetail &detail = {});

// The parts, in the order generateCity runs them.
// The city's streets as a network of its points (metres, x east, y north).
StreetNetwork streetNetworkOf(const CityData &data);
// A lot with its identity: its own (CityLot::sourceId), or for a lot cut from a block the
// block's identity and the lot's place among the lots cut from it.
struct IdentifiedLot {
    Footprint footprint;
    uint32_t identity = 0;
};

// The lots of a block: its own, or those its LotSubdivision setting cuts from what the streets
// and sidewalks leave of it (subdivideBlock: by default perimeter lots, Bilke's
// Blockrandbebauung, and Müller's recursive subdivision where no ring of houses fits). The
// draws of each piece the streets leave come from the seed, the block's identity and the
// piece's place among them, never from the block's place in the file.
// A piece that rounding to float left no simple polygon (a sliver a few float steps wide) gets
// no lots; `slivers`, when given, counts such pieces. The streets near the block are asked of
// `near` (the index of `streets`) where it is given, as cutting every block of a city does.
std::vector<IdentifiedLot> lotsOf(const CityBlock &block, const StreetNetwork &streets,
                                  const SettingsStack &blockSettings, uint32_t seed, size_t *slivers = nullptr,
                                  const StreetIndex *near = nullptr);

// Gives each block without lots of its own the lots lotsOf cuts from it with the block's
// settings over `ruleFileSettings`: what `veduta generate` writes, so that its files hold the
// lots the buildings will stand on. Each lot keeps its identity in sourceId.
// Pieces left without lots (see lotsOf) are counted in one warning.
void cutLots(CityData &data, const SettingsMap &ruleFileSettings, uint32_t seed, std::vector<std::string> &warnings);

// A city building's id, 1 to 2^24 − 1 so that the IndexBuilding pass (floats) holds it exactly:
// a hash of the city's object id and its lot's identity. Two lots of a city may hash to one id
// (for n buildings a chance of about n² / 2^25; generateCity warns): they then share their
// random choices and their IndexBuilding id, nothing else.
uint32_t cityBuildingId(ObjectId city, uint32_t lotIdentity);

}  // namespace veduta
