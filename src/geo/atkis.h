// The ATKIS object model (Rilling 2006, §3.2–3.4): objects of an Objektart (a 4-digit code) with
// attributes (a 3-letter name and a value) and point, line or area geometry in a projected
// CRS. The EDBS parser (edbs.h) and the GDAL/OGR reader for NAS, Shapefile and GeoPackage
// (vector_file.h) both produce it; draping, vegetation and `veduta atkis` read it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geodesy/map_point.h"

namespace veduta {

enum class AtkisGeometry { Point, Line, Area };  // Objekttyp P, L, F

struct AtkisObject {
    std::string id;        // Objektnummer (7 characters in EDBS) or the feature's id
    int type = 0;          // Objektart, e.g. 3101 Straße; 0 when the source has none we know
    std::string typeName;  // the source's own class name (NAS: AX_Wald), or empty
    AtkisGeometry geometry = AtkisGeometry::Area;
    std::map<std::string, std::string> attributes;  // "BRF" → "0065"
    std::vector<MapRing> areas;    // Area: one closed outline per object part (ATKIS areas have no holes)
    std::vector<MapLine> lines;    // Line: one polyline per object part
    std::vector<MapPoint> points;  // Point: the reference point(s)
    std::string where;             // for messages: "file.edbs: record 123" or "file.gpkg: layer x, feature 7"
};

struct AtkisData {
    int epsg = 0;  // the CRS of every coordinate; 0 when the source does not say
    std::vector<AtkisObject> objects;
};

// What a renderer makes of an object: the class decides material, draping priority and
// vegetation. Derived from the Objektart (and for Wald/Gehölz its vegetation attribute); for
// ALK data, whose Objektarten mean other things, from the Folie (docs/atkis.md).
enum class LandClass {
    Other,
    Road,        // 3101 Straße and the other road codes
    Path,        // 3102 Weg
    Rail,        // 3201 Schienenbahn, 3203/3204 Bahnkörper/Bahnstrecke
    Settlement,  // 2101 Ortslage, 2111–2114 built-up areas, 2227 Grünanlage is Park
    Park,
    Farmland,    // 4101 Ackerland
    Grassland,   // 4102 Grünland, 4104–4106 heath, moor, swamp
    Forest,      // 4107 Wald, Forst
    Shrubs,      // 4108 Gehölz
    Water,       // standing water: 5112 Binnensee/Stausee/Teich; levelled when draped
    River,       // flowing water: 5101 Strom/Fluss/Bach; follows the terrain downstream
    TreeRow,     // 4202 Baumreihe (a line), 4201 Baum (a point)
    Hedge,       // 4203 Hecke
    CityStreet,  // not ATKIS: a <city>'s streets and sidewalks, cut into the terrain above every area
    Building,    // ALK Folie 011 Gebäude: a building's footprint, draped as the ground it covers
    Parcel,      // ALK Folie 001 Flurstücke: cadastral parcels, not land cover; not draped
};

enum class TreeKind { Broadleaf, Conifer, Mixed };

// An attribute's text as the source gave it ("0065"), by its upper-case name; nothing when absent.
std::optional<std::string_view> attribute(const AtkisObject &object, const std::string &name);
// An attribute written as a whole number, blanks round it allowed ("1303", " 0065 ");
// nothing when absent or not such a number.
std::optional<long> attributeNumber(const AtkisObject &object, const std::string &name);

// The Objektart's German name from the code table ("Straße"), or "" for an unknown code.
std::string_view atkisTypeName(int type);
LandClass landClass(const AtkisObject &object);
std::string_view landClassName(LandClass c);  // "road", "forest", … as scene files and materials name them
// Laub-, Nadel- or Mischholz from the vegetation attribute (VEG); Mixed when absent.
TreeKind treeKind(const AtkisObject &object);
// Tracks of a railway: GLS as a count (1, 2) or as a code in thousands (1000, 2000); NAS's
// anzahlDerStreckengleise likewise. One when absent or unreadable.
int trackCount(const AtkisObject &object);
// The width of a road, path or rail ribbon in metres: BRF (carriageway width in dm) when
// given and positive, else BRV, else a default per class (docs/terrain.md lists them).
double ribbonWidth(const AtkisObject &object);

}  // namespace veduta
