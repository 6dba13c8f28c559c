// The generator of a scene's <citygml>: the buildings of a CityGML file (city/citygml_file.h)
// as meshes in the scene's frame, one object per building (docs/citygml.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "city/citygml_file.h"
#include "description/scene_description.h"
#include "geodesy/georeference.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

// The materials of surfaces without an appearance in the file, by kind; a scene's material of
// the same name restyles them.
Material cityGmlMaterial(SurfaceKind kind);

// The building id (the IndexBuilding pass) of a CityGML building: a hash of its gml:id, from 1
// to 2²⁴ − 1, which the float pass holds exactly.
uint32_t cityGmlBuildingId(const std::string &gmlId);

// The CRS of the model's coordinates: the file's srsName, else the element's crs=. Throws
// InputError when neither names one, when srsName names a CRS veduta does not know, or when
// the two disagree.
int cityGmlEpsg(const CityGmlDesc &desc, const CityGmlModel &model);

// Reads the element's file and adds each building (within the element's bbox, when it has
// one: a warning says how many it keeps) as a world mesh with the element's object
// id and cityGmlBuildingId, its coordinates placed through the georeference in double
// (geodesy/map_projection.h). A building the element's coarse rule picks seen from `camera`
// (or, past the builder's geometry budget, the farthest first, with a warning) is
// a box instead: its footprint raised to its mean roof height, flat-topped, in one mesh with the
// other boxes (its record stays, its building id does not). Polygons take the file's ParameterizedTexture (its image
// through `addTexture`) or X3DMaterial colour when it gives one, else cityGmlMaterial of their kind; an image that
// cannot be read is said once, with how many polygons go without it. The reader's warnings, and one when the file holds
// no building to draw (saying how many objects it read and why), are appended. Returns how many buildings it added.
// Throws InputError (the scene needs a georeference).
uint32_t generateCityGml(const CityGmlDesc &desc, const std::optional<Georeference> &georeference, const Camera &camera,
                         RenderSceneBuilder &builder, const AddTexture &addTexture, std::vector<std::string> &warnings);

// The same element with a modular look (ModularLookDesc): each building the bbox keeps stands on
// its procedural twin's footprint (deriveTwin; a building without one is said and left out) at
// its ground, edge 0 the footprint's longest, with the storeys the file counts
// (storeysAboveGround), else those nearest its eaves, and the element's coarse rule. Throws
// InputError, as generateCityGml.
std::vector<ModularBuildingDesc> cityGmlModularBuildings(const CityGmlDesc &desc,
                                                         const std::optional<Georeference> &georeference,
                                                         std::vector<std::string> &warnings);

}  // namespace veduta
