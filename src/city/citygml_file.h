// Reading CityGML building models (CityGML 1.0 and 2.0, the AdV LoD1/LoD2 profile every German
// state publishes) with libcitygml: each Building, its BuildingParts folded in, as planar
// polygons of map coordinates in double, each with its surface kind and triangulated (CGAL,
// holes kept). The polygons of a lod2Solid that its thematic surfaces (WallSurface, RoofSurface
// …) name through xlink:href are taken once, with the kind of their thematic surface; those
// no surface names (LoD1 solids) get a kind from their normal. Each polygon keeps the
// appearance of the first theme that gives it one: a ParameterizedTexture's image and
// coordinates, else an X3DMaterial's colour. Nothing is placed in a scene
// here: the coordinates are the file's, its CRS named by `epsg` (docs/citygml.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/vecmath.h"
#include "geodesy/crs.h"

namespace veduta {

enum class SurfaceKind : uint8_t { Wall, Roof, Ground, Closure, Other };

const char *surfaceKindName(SurfaceKind kind);

struct CityGmlPolygon {
    std::string id;  // gml:id, empty when the file gives none
    SurfaceKind kind = SurfaceKind::Other;
    // The outline (rings[0], counter-clockwise seen from the side the polygon faces) and its
    // holes, each without the closing repeat of its first point.
    std::vector<std::vector<CrsCoordinate>> rings;
    // Three per triangle, into the rings' points counted in order (ring 1 after ring 0),
    // counter-clockwise seen from the side the polygon faces.
    std::vector<uint32_t> triangles;
    std::optional<Vec3f> diffuse;  // the X3DMaterial's diffuse colour, when the file gives one
    // The ParameterizedTexture's image (the imageURI against the file's folder) and the
    // texture coordinates of the rings' points in their order, v up from the image's bottom
    // row; both empty when the polygon has none.
    std::filesystem::path texture;
    std::vector<Vec2f> uvs;
};

struct CityGmlBuilding {
    std::string id;      // gml:id of the Building
    unsigned lod = 0;    // the level of detail its polygons are of
    uint32_t parts = 0;  // BuildingParts folded into it
    std::vector<CityGmlPolygon> polygons;
    // Every attribute libcitygml reads, by its lower-case qualified name
    // ("bldg:measuredheight", "bldg:rooftype", generic ones by their own name).
    std::map<std::string, std::string> attributes;
    std::optional<double> measuredHeight;  // metres
    std::string roofType;                  // the AdV / CityGML code, e.g. "3100"; empty: none
    std::optional<int> storeysAboveGround;
    std::string function;  // bldg:function, e.g. "31001_2000"
};

struct CityGmlModel {
    std::string srsName;  // as the file writes it (the model's, else its envelope's); empty: none
    int epsg = 0;         // the supported CRS srsName names; 0 when it names none or is absent
    std::optional<CrsCoordinate> envelopeLow, envelopeHigh;
    std::vector<CityGmlBuilding> buildings;  // those with polygons at the chosen LoD
    uint32_t buildingsWithoutGeometry = 0;   // Buildings with no polygon at the chosen LoD
    uint32_t otherObjects = 0;               // top-level city objects that are no Building
    uint32_t skippedPolygons = 0;            // polygons left out (each has a warning)
    uint32_t untexturedPolygons = 0;         // textured polygons read without it (each has a warning)
    // Messages from libcitygml and from veduta, "file:line:col: message" where the place is known.
    std::vector<std::string> warnings;
};

struct CityGmlOptions {
    // The LoDs taken, lowest and highest; each building is read at the highest of them it has.
    unsigned minLod = 1, maxLod = 2;
};

// A polygon with more points than this (all rings) is refused: a real LoD2 surface has tens.
inline constexpr size_t kMaxCityGmlPolygonPoints = 100'000;

// The EPSG code of a CityGML srsName: "EPSG:25832", "urn:ogc:def:crs:EPSG::25832",
// "urn:ogc:def:crs:EPSG:6.12:25832", "http://www.opengis.net/def/crs/EPSG/0/25832", a compound
// "urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837" (its first part) and the AdV names
// ("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH"). 0 when it names none of these.
int gmlSrsEpsg(std::string_view srsName);

// Throws InputError naming the file (and the line and column where the XML parser stopped)
// when it is not a regular file, holds a document type declaration, is no well-formed XML,
// has a text of more than a million characters (which libcitygml would cut short) or a
// polygon of more than kMaxCityGmlPolygonPoints points.
CityGmlModel readCityGml(const std::filesystem::path &file, const CityGmlOptions &options = {});

}  // namespace veduta
