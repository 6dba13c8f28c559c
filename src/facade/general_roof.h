// The roof of one floor-plan module (Finkenzeller 2008, §4.4.1; digest-001 §2.3): the general
// roof of Def 4.13 (hip, gable, shed and pyramid as special cases) and the flat roof with a
// parapet of Def 4.12, as planar faces and as a mesh, plus the height of the roof surface over a
// point, for a caller that drops windows under a roof line (L1608).
//
// Choices where the thesis is open:
// * Faces ([GAP], the thesis only draws them, Figs 4.23–4.27): the roof is the upper part of the
//   3D convex hull of the outline at eaves height and the ridge ends r_a, r_b, coplanar hull
//   triangles merged. That is the only reading in which every outline side slopes up to the ridge
//   with planar faces for any convex outline and any ridge, it closes on the outline by
//   construction, and it gives exactly the thesis's cases: a hip has no vertical face, a gable a
//   vertical triangle over each edge its ridge ends on, a pyramid none.
// * The ridge formula (L944) lacks q_ei (OCR, digest §10); we use r = q_ei + a (q_ej − q_ei) + up·h.
// * Interfaces: every vertical face is tagged Interface, whether a neighbour docks there or it is
//   a gable wall on a free side; `edge` and ModuleRoof::connected tell them apart. A shed's quad
//   is its interface (L963), and its two side triangles are vertical too, as in any reading (the
//   ridge ends stand over outline corners); they are Interface faces as well.
// * Flat roof (Def 4.12, tuple says b, text w: the width): the deck is the outline inset by the
//   parapets; a parapet is a wall of width w inside the outline, mitred where two meet and cut
//   flush with the seam where it meets a connected edge (a vertical end cap there).
// * The outline is counter-clockwise (the thesis walks clockwise, L676); nothing here depends on
//   the direction beyond that. It must be strictly convex (Def 4.1).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/vecmath.h"
#include "scene/mesh.h"

namespace veduta {

enum class RoofFaceKind {
    Slope,      // the roof covering, a flat roof's deck included
    Interface,  // a vertical face standing on the outline (Schnittstelle, L940)
    Parapet,    // the faces of a flat roof's parapet (Attika)
};

inline constexpr size_t kNoOutlineEdge = ~size_t{0};

struct ModuleRoofFace {
    std::vector<Vec3d> corners;  // counter-clockwise seen from outside; planar
    RoofFaceKind kind = RoofFaceKind::Slope;
    size_t edge = kNoOutlineEdge;  // the outline edge it rises from or stands on, where it has one
};

struct RoofRidge {
    Vec3d a, b;  // r_a and r_b; equal for a pyramid
};

struct ModuleRoof {
    std::vector<Vec2d> outline;   // counter-clockwise, metres; edge i runs from point i to point i + 1
    std::vector<bool> connected;  // per outline edge: a seam to a neighbouring module
    double eavesZ = 0;
    std::optional<RoofRidge> ridge;  // none on a flat roof
    std::vector<ModuleRoofFace> faces;
};

// Def 4.13's (e_i, e_j, c, d, a, b, h): the ridge runs over the chord from e_i[c] to e_j[d],
// from its fraction a to its fraction b, h above the eaves.
struct GeneralRoofParameters {
    size_t edgeI = 0, edgeJ = 0;
    double c = 0.5, d = 0.5, a = 0, b = 1, height = 1;
};

// Def 4.12's (h, w).
struct ParapetParameters {
    double height = 1, width = 0.3;
};

// The general roof over `outline` (strictly convex, counter-clockwise, metres) with its eaves at
// eavesZ. Throws std::invalid_argument, saying what is wrong, for a bad outline, a `connected`
// of the wrong size, an edge that is not the outline's, a fraction outside [0, 1], a > b or a
// height that is not positive.
ModuleRoof generalRoof(const std::vector<Vec2d> &outline, double eavesZ, const std::vector<bool> &connected,
                       const GeneralRoofParameters &parameters);

// The flat roof over `outline` with a parapet on every edge that is not connected; on a module too
// thin for the parapet's width, a narrower one that leaves a deck (0.9 of the width at which the
// deck would lose an edge). Throws std::invalid_argument as generalRoof does, and for a parapet
// without height or width.
ModuleRoof flatRoof(const std::vector<Vec2d> &outline, double eavesZ, const std::vector<bool> &connected,
                    const ParapetParameters &parapet);

// Lengths below this count as zero on the roof (1e-9 of its outline's extent, at least 1e-9 m):
// ridge ends and merged planes are rounded doubles.
double roofTolerance(const ModuleRoof &roof);

// A non-vertical face's plane as z = z0 + gx·x + gy·y.
struct RoofPlane {
    double z0 = 0, gx = 0, gy = 0;
    double heightAt(Vec2d p) const { return z0 + gx * p.x + gy * p.y; }
};

// The outward unit normal of a planar face (Newell's method, so any corner order works).
Vec3d faceNormal(const ModuleRoofFace &face);
// The plane of a face that is not vertical.
RoofPlane facePlane(const ModuleRoofFace &face);
// The planes of the roof's Slope faces. The roof surface is their minimum wherever the roof
// stands: it is concave (a convex hull's top), also after a merge, which only extends slopes.
std::vector<RoofPlane> slopePlanes(const ModuleRoof &roof);

// The height of the roof's top surface over `p` (on the covering, a parapet's top counting as
// the deck's height beneath it), or nullopt where the roof does not cover p.
std::optional<double> roofHeightAt(const ModuleRoof &roof, Vec2d p);

struct RoofMaterials {
    MaterialId slope = kNoMaterial, interface = kNoMaterial, parapet = kNoMaterial;
};

// The roof as triangles with flat outward normals (corners split per face) and texture
// coordinates in metres in the face's plane: u runs horizontally, along the eaves on a slope and
// counter-clockwise round the outline on a wall; v rises from the eaves height along the face.
// Horizontal faces take u = x, v = y.
Mesh roofMesh(const ModuleRoof &roof, const RoofMaterials &materials);

}  // namespace veduta
