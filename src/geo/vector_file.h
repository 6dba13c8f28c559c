// ATKIS objects from any vector source GDAL/OGR reads: NAS (the AAA exchange format), ATKIS
// Shapefile exports, GeoPackage, GeoJSON. The Objektart comes from an OBJART field (any case)
// or, for NAS's AAA classes, from the layer's name; docs/atkis.md lists the mapping.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "geo/atkis.h"

namespace veduta {

// Every feature with a geometry; polygons keep their outer ring only (a warning names the
// holes left out). Throws InputError when GDAL cannot read the file.
AtkisData readVectorFile(const std::filesystem::path &path, std::vector<std::string> &warnings);

// The Objektart of a NAS (AAA) class such as AX_Wald, or 0 when it has none here.
int nasClassType(std::string_view layerName);

// The EPSG code of an AdV CRS name as NAS files give them (urn:adv:crs:ETRS89_UTM32 → 25832),
// or 0 when it is not one known here.
int advCrsEpsg(std::string_view urn);

}  // namespace veduta
