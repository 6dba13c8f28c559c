// What a CityGML building measures, as the procedural twin and `veduta compare` need it
// (issue 18): its ground, eaves and ridge heights, its volume when its surfaces close, its
// footprint, and its roof type from the AdV or CityGML code list.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "city/citygml_file.h"
#include "city/roof_shapes.h"

namespace veduta {

struct BuildingMeasures {
    double ground = 0;  // the lowest point of its ground surfaces (of every surface if it has none)
    double eaves = 0;   // the lowest point of its roof surfaces (the top of its walls if it has none)
    double ridge = 0;   // its highest point
    // By the divergence theorem, when the building's triangles close (their vector area is
    // below 10⁻⁶ of their area); unset for an open model, whose volume has no meaning.
    std::optional<double> volume;
    // The outlines of its ground surfaces in map coordinates, each counter-clockwise seen from
    // above; a LoD1 solid's bottom face counts as its ground.
    std::vector<std::vector<CrsCoordinate>> footprint;
    // From the roofType code, else from the slopes of its roof surfaces (roofTypeFromSlopes);
    // unset when neither gives a roof veduta builds.
    std::optional<RoofType> roofType;
};

BuildingMeasures measureBuilding(const CityGmlBuilding &building);

// Sums over a building's triangles, taken about `o` so that map magnitudes cost no precision.
struct SurfaceSums {
    double volume = 0;              // by the divergence theorem: positive when the faces face out
    double area = 0;                // of all triangles
    double vx = 0, vy = 0, vz = 0;  // the vector area: zero for a closed surface
};
SurfaceSums sumSurfaces(const CityGmlBuilding &building, const CrsCoordinate &o);

// The area of a ring's projection onto the ground, positive when it runs counter-clockwise
// seen from above; about its first point, in double.
double groundArea(const std::vector<CrsCoordinate> &ring);

// The roof type of a roofType code: the AdV list of the German LoD2 buildings (1000 flat, 2100
// shed, 3100 gable, 3200 hip, 3300 half-hip, 3400 mansard, 3500 pyramid …) and CityGML's
// (SIG 3D) list (1000 flat, 1010 shed, 1030 gable, 1040 hip, 1050 half-hip, 1060 mansard,
// 1070 pyramid …). Unset for a code of a roof veduta does not build (domes, arches, mixed) or
// one it does not know.
std::optional<RoofType> roofTypeOfCode(std::string_view code);

// The roof type the roof surfaces' slopes show: flat when under a tenth of the roof area slopes
// by 5° or more; else the sloped faces grouped into sides by the direction they face (within
// 20°, a side under 5 % of the sloped area left out as a dormer): one side a shed, two opposite
// ones a gable, three or more a hip — a mansard where a side's faces differ in pitch by more
// than 15°. A half-hip reads as a hip; unset for two sides that are not opposite.
std::optional<RoofType> roofTypeFromSlopes(const CityGmlBuilding &building);

}  // namespace veduta
