// Sweeping a cornice profile along a horizontal run of the outline (digest-001 §2.6, L1193–1201,
// L1650): one profile, laid at every vertex of the run in the mitre (bisector) plane and stretched
// there by 1/cos(half the turn), so that every profile point draws a line parallel to the run at
// its own distance from the wall (Fig. 5.25a). Each command of the profile sweeps a band; on each
// edge of the run a band is one piece, or, where it carries textures, a frieze (frieze.h): end
// pieces that take the mitre's distortion and the start/end textures, and straight mid tiles
// between (the texture fix of L1193–1201).
//
// Coordinates: world Z up, metres. The profile's x runs out of the wall (the run's outward side),
// its y up from `baseHeight`. Faces look out of the cornice's material (to the right of the
// profile's direction of travel, its turtle's normal). Normals are flat on a line's band and
// smooth across an arc's. u runs along the run so that it grows to the right seen from outside
// (a run whose outside is on its left is walked backwards); untextured pieces get u = metres along
// the run (measured on the wall line, so it jumps at corners by the mitre's offset) and v = metres
// along the profile; textured pieces get their pool rectangle, v's bottom at the band's start.
#pragma once

#include <vector>

#include "core/vecmath.h"
#include "facade/profile.h"
#include "scene/mesh.h"

namespace veduta {

enum class OutwardSide { Left, Right };

// A horizontal run of the outline in plan (x east, y north, metres).
struct SweepPath {
    std::vector<Vec2d> points;                 // at least 2 (3 when closed), no two neighbours equal
    double baseHeight = 0;                     // the z of the profile's y = 0
    bool closed = false;                       // a ring: the last point joins the first
    OutwardSide outward = OutwardSide::Right;  // seen walking from the first point on
};

// The sharpest turn the run may make at a vertex, in degrees: the mitre's stretch 1/cos(turn/2)
// grows without bound toward 180°.
inline constexpr double kSweepTurnLimit = 170;

struct SweepOptions {
    bool closeEnds = false;  // cap an open run's ends with the profile's cross section, closed to the wall
    double imageAspect = 1;  // width / height in pixels of the texture images
};

struct SweptCornice {
    Mesh mesh;                          // triangleMaterials are all kNoMaterial
    std::vector<int> triangleTextures;  // per triangle: the pool index it shows, -1 = untextured
};

// One edge of the run, walked with the outside on its right (a run whose outside is on its left
// backwards). A profile point `o` metres out starts `o * startSlope` and ends
// `length + o * endSlope` metres along the edge: the mitres. At a concave corner (the offset line
// is shorter than the wall) startSlope is positive and endSlope negative; at a convex one
// startSlope is negative and endSlope positive; both are 0 at an open end.
struct RunEdge {
    Vec2d start, direction, normal;  // normal: out of the wall
    double length = 0;
    double runStart = 0;  // metres along the run to `start`
    double startSlope = 0, endSlope = 0;
};

// The edges of `path` with their mitres. The run must turn by at most kSweepTurnLimit at each
// vertex (an internal error otherwise).
std::vector<RunEdge> runEdges(const SweepPath &path);

// Where a profile point `offset` metres out of the wall lies at every vertex of `path` (plan).
std::vector<Vec2d> offsetLine(const SweepPath &path, double offset);

// Sweeps the profile traced into `outline` (already scaled to metres: scaledOutline) along
// `path`, with the textures of `cornice`. The run must turn by at most kSweepTurnLimit at each
// vertex (an internal error otherwise).
SweptCornice sweepCornice(const CorniceDescription &cornice, const ProfileOutline &outline, const SweepPath &path,
                          const SweepOptions &options);

}  // namespace veduta
