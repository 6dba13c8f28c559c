// A city's street surfaces on a landscape's terrain (issue 16): the flat plan of streetGeometry
// (carriageways, junctions, sidewalks, kerbs) lifted onto the finished terrain the way ribbons
// are (docs/streets.md, "On terrain"): level across each street, following the ground along it,
// never below the surface, the junctions level platforms the streets meet without a step.
#pragma once

#include "city/street_geometry.h"
#include "geo/terrain_surface.h"
#include "scene/mesh.h"

namespace veduta {

// Metres a carriageway keeps above the terrain at least: above the ATKIS road ribbons' 0.07 m
// (geo/ribbons.h), so that where a city street and an ATKIS road line are the same street the
// city's surface is seen.
inline constexpr double kStreetLiftOnTerrain = 0.08;

// The street surfaces of `network` (local metres, its height ignored) on `terrain`: the mesh of
// streetGeometry, its triangles cut where the height changes slope, every vertex at the street
// height there (+ kerbHeight on sidewalks and kerb tops). A street's height depends only on the
// distance along it, so it is level across. Within a node's platform radius (where the street
// areas meeting at the node overlap, and where its round joint reaches) the height is the
// node's; between, the street is cut at its ends' platforms and where its centre line crosses
// the terrain's cell lines, and each piece is linear along. Heights start at the highest ground
// across each cut (over each platform) + kStreetLiftOnTerrain; then every piece is raised, its
// ends together, until it lies that far above the surface everywhere (TerrainSurface::maxAbove,
// exact). Nodes whose platforms reach each other along a street share one height. Parts off the
// terrain take the street's highest height on it. Faces are flat-shaded (normals per triangle).
Mesh streetsOnTerrain(const StreetNetwork &network, const TerrainSurface &terrain, const StreetStyle &style = {});

}  // namespace veduta
