// The hip roof as planar faces over shared corners (issue 7, anchors-procedural §7): CGAL's
// straight skeleton of a footprint, its points raised by offset time × tan(pitch). Gable and
// half-hip ends (roof_gables.h) reshape these faces before they become a mesh; every face
// keeps its plane, so that an edit can be checked against it.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "city/roof_shapes.h"

namespace veduta {

using RoofKernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// A footprint edge: every ring's edges, the outline's first, numbered on through the holes.
struct RoofEdge {
    Vec2f start, end;
    size_t previous, next;  // the edges before and after it on its ring
    float perimeterBefore;  // metres along its ring from the ring's first point
};

struct RoofFace {
    // Indices into SkeletonRoof::corners, counter-clockwise seen from above (a wall: from
    // outside), starting with the face's edge where it has one along the eaves.
    std::vector<uint32_t> corners;
    RoofKernel::Plane_3 plane;  // its normal points out and up
    size_t edge;                // the footprint edge it rises from
    RoofSurface surface;
};

struct SkeletonRoof {
    std::vector<RoofEdge> edges;
    std::vector<RoofKernel::Point_3> corners;
    // faces[e] belongs to edges[e]; faces added later (a half-hip's small hip) follow.
    std::vector<RoofFace> faces;
    size_t skeletonCorners = 0;  // corners[0 … skeletonCorners) are the skeleton's, the rest added by edits
    float base = 0, eavesZ = 0, slope = 0;
};

// The hip roof over `footprint` with its eaves at height eavesZ, or nullopt when CGAL cannot
// build the footprint's straight skeleton.
std::optional<SkeletonRoof> skeletonRoof(const RoofFootprint &footprint, float eavesZ, float slope);

// The plane that rises from `edge` at the roof's slope, starting `raise` metres above the eaves.
RoofKernel::Plane_3 slopePlane(const SkeletonRoof &roof, size_t edge, double raise);

// Whether the face's outline, seen from above in floats as the mesh will have it, is simple.
bool isSimpleFromAbove(const SkeletonRoof &roof, const RoofFace &face);

// The roof's faces as a mesh (roofs.h's conventions), or why a face does not triangulate.
std::variant<Mesh, std::string> roofMesh(const SkeletonRoof &roof);

}  // namespace veduta
