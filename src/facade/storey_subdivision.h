// Storeys after Finkenzeller (digest-001 §2.2, Defs 4.7-4.11, L862-930): a module is subdivided
// by points on its edges and segments between them into minimal convex cells; convex unions of
// cells are the candidate modules of the next storey. Repeating a storey skips the subdivision
// and reuses modules, connections and so features. The storey features compare a storey with
// the one above: free outer edges, inner edges, external connections and seams.
//
// Choices where the thesis is open:
// * Points are given per edge as (edge, t) with t in [0, 1); t = 0 is the vertex p_edge, so V
//   and V' of Def 4.7 are addressed alike.
// * A candidate is any set of cells whose union is convex (Def 4.7, "zulässige Kombinationen").
//   A union of cells is convex exactly when its area equals that of its convex hull, which is
//   how it is tested. For Fig. 4.17 this gives the thesis's nine.
// * The enumeration is exponential in the number of cells, so a module is limited to
//   kMaxSubdivisionCells cells; more is an input error, not a long wait.
// * A docked module of the upper storey is an external connection (Def 4.10) when part of it
//   (more than a 1e-9 share of its area) lies outside the lower storey's outline, otherwise an
//   internal one (L890-895).
#pragma once

#include <utility>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "facade/floor_plan.h"

namespace veduta {

inline constexpr int kMaxSubdivisionCells = 16;

// A point on the module's edge `edge` at parameter t (Def 4.7: V and V').
struct SubdivisionPoint {
    int edge = 0;
    double t = 0;
};

struct StoreySubdivision {
    // The minimal convex cells, counter-clockwise, with every subdivision point and segment
    // crossing (V'') on their boundary kept as a vertex.
    std::vector<std::vector<Vec2d>> cells;
    // The candidate modules of the next storey: each a sorted list of cells with a convex union,
    // single cells included.
    std::vector<std::vector<int>> candidates;
};

// Def 4.7 for one module (convex, counter-clockwise). segments join points by their indices.
// Throws InputError at `loc` for points off the module, degenerate segments or too many cells.
StoreySubdivision subdivideModule(const std::vector<Vec2d> &outline, const std::vector<SubdivisionPoint> &points,
                                  const std::vector<std::pair<int, int>> &segments, const FileLoc &loc);

// The outline of a candidate: the convex hull of its cells, counter-clockwise, without collinear
// vertices.
std::vector<Vec2d> candidateOutline(const StoreySubdivision &subdivision, const std::vector<int> &candidate);

// A storey repeated above itself (L886): the same modules and connections, so the same features.
FloorPlan repeatStorey(const FloorPlan &storey);

struct StoreyFeatures {
    std::vector<std::vector<Vec2d>> freeOuterEdges;  // Def 4.8: lower outline not under the upper storey
    std::vector<std::vector<Vec2d>> innerEdges;      // Def 4.9: rest of the free area's boundary
    std::vector<int> externalConnections;            // Def 4.10: upper KK connections outside the lower outline
    std::vector<int> internalConnections;            // the other upper KK connections
    std::vector<std::vector<Vec2d>> seams;           // Def 4.11: outer edges both storeys share
};

// The storey features between a storey and the one above it. Polylines run counter-clockwise
// round the free area (free outer and inner edges) or the upper storey (seams).
StoreyFeatures storeyFeatures(const FloorPlan &lower, const FloorPlan &upper);

}  // namespace veduta
