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
#include "city/street_geometry.h"
#include "geo/generate_landscape.h"
#include "geodesy/georeference.h"
#include "scene/render_scene.h"
#include "description/scene_description.h"

namespace veduta {

// The city's file, CityData XML or OpenStreetMap (.osm), with the <city>'s rule file where the
// data names none. With the scene's georeference the file's coordinates are map coordinates
// (CityData: of the <city>'s crs, by default the scene's; OpenStreetMap: WGS 84) placed through
// geo/map_projection.h; without one, local metres (OpenStreetMap: on the tangent plane at the
// data's centre). The scene reads its cities first: their streets are cut into a landscape
// before the city is built on it. Throws InputError.
CityData readCity(const CityDesc &city, const std::optional<Georeference> &georeference);

// Builds the streets and every lot of the city read by readCity; its buildings take the ids
// from `firstBuildingId` on, in the order of the file's blocks and lots. Returns how many ids
// it took. With a `landscape`, the streets lie on its terrain (streetsOnTerrain) and every
// building stands on its ground with a plinth, as a <buildings> building without base does:
// the terrain decides, the points' heights u are ignored (a warning says so where one is not
// 0). Warnings (a clockwise block, probabilities renormalised …) are appended once each as
// "file:line:col: message"; errors throw InputError.
uint32_t generateCity(const CityDesc &city, const CityData &data, const LandscapeGround *landscape,
                      uint32_t firstBuildingId, RenderSceneBuilder &builder, std::vector<std::string> &warnings);
// The same for a city made in memory (as the benchmark does); errors about the city as a
// whole (no rule file) have no place in a file.
uint32_t generateCity(const CityData &data, uint32_t seed, ObjectId objectId, uint32_t firstBuildingId,
                      RenderSceneBuilder &builder, std::vector<std::string> &warnings,
                      const LandscapeGround *landscape = nullptr);

// The parts, in the order generateCity runs them.
// The city's streets as a network of its points (metres, x east, y north).
StreetNetwork streetNetworkOf(const CityData &data);
// The lots of a block: its own, or those its LotSubdivision setting cuts from what the streets
// and sidewalks leave of it (subdivideBlock: by default perimeter lots, seed 000's
// Blockrandbebauung, and Müller's recursive subdivision where no ring of houses fits).
std::vector<Footprint> lotsOf(const CityBlock &block, const StreetNetwork &streets, const SettingsStack &blockSettings,
                              uint32_t seed, uint32_t blockIndex);

}  // namespace veduta
