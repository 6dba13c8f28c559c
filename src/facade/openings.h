// Window and door openings in a wall: the coarse opening (Def 5.12, L1287) and its refinement
// edge by edge (Def 5.13, L1291–1322; digest-001 §2.8). Coordinates are the wall's own plane
// (along, up) in metres; outlines are counter-clockwise there.
//
// Edges run counter-clockwise from the bottom (Def 5.12): bottom (f_bl, f_br), right (f_br, f_tr),
// top (f_tr, f_tl), left (f_tl, f_bl). Each edge (f_l, f_r) becomes (l, r) by
//   l = f_l + dist_l (f_r − f_l) + (dist_b + size) in,   r = f_r + dist_r (f_l − f_r) + (dist_b + size) in,
// where `in` is the edge's inward vector across the whole opening (f_tl − f_tr for the right edge,
// f_bl − f_tl for the top, as in L1322). Choices where the thesis is open:
// * The left edge's inward vector is f_tr − f_tl; L1322 prints f_tl − f_tr, which would push the
//   edge out of the opening (digest §10). So both side edges move along the top edge, as the
//   right edge does in L1322; on a non-parallelogram opening this is not f_br − f_bl. For the
//   bottom it is f_tr − f_br.
// * dist_l trims the edge's l end, its start in counter-clockwise order, for all four edges alike
//   (the thesis wants no difference between edges, L1291). Fig. 5.36 labels the top edge's
//   distances by the side of the picture, which swaps them there.
// * A non-dominant edge ends on its dominant neighbours' refined lines: its ends move inward
//   by the neighbour's dist_b + size too (L1322: rr has size_top). Its own dist_l, dist_r still
//   trim it, as fractions of the whole coarse edge, like every edge's.
// * The `size` band F_Kantenzug lies between (l, r) and the same line moved out by size; a
//   profile polyline in [0,1]² is mapped into it, x from l to r and y outward, so (0,0) is l and
//   (1,0) is r; the outline goes l → profile → r. No profile: the straight edge. Only dominant
//   edges may have a band: a non-dominant one is crossed by its full-width neighbours, and with
//   the L1322 formulas the outline would fold back along their refined lines.
// * Absolute placement (Breite, Hoehe, dist_links, dist_rechts, L1520) over-determines the width:
//   the free width is shared in the ratio dist_links : dist_rechts (equal: centred; when they add
//   up to the free width they are plain distances); the sill height is given in metres.
// * Doors ignore the bottom edge's refinement (L1520).
#pragma once

#include <array>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

// The point a + t (b − a), for the opening's corners and edges and the casings on them.
inline Vec2d lerp(Vec2d a, Vec2d b, double t) { return a + (b - a) * t; }

// A wall quad in its plane; the coarse opening is placed bilinearly in it, which for the usual
// rectangular wall is Def 5.12's f_bl = w_bl + v_s (w_br − w_bl) + h_s (w_tl − w_bl).
struct WallQuad {
    Vec2d bl, br, tr, tl;
    static WallQuad rectangle(Vec2d min, Vec2d max) { return {min, {max.x, min.y}, max, {min.x, max.y}}; }
};

// The coarse opening (f_bl, f_br, f_tr, f_tl), counter-clockwise.
struct CoarseOpening {
    Vec2d bl, br, tr, tl;
    Vec2d corner(int i) const { return std::array<Vec2d, 4>{bl, br, tr, tl}[size_t(i & 3)]; }
};

// Throws std::invalid_argument unless 0 ≤ vStart < vEnd ≤ 1 and 0 ≤ hStart < hEnd ≤ 1 and the wall's
// corners are finite.
CoarseOpening coarseOpening(const WallQuad &wall, double vStart, double vEnd, double hStart, double hEnd);

// Absolute placement in metres on a rectangular wall (see the header comment).
struct AbsolutePlacement {
    double width = 0, height = 0;
    double distLeft = 1, distRight = 1;
    double sillHeight = 0;
};
// Throws std::invalid_argument when the opening does not fit the wall or a value is negative or
// not finite.
CoarseOpening placeOpening(const WallQuad &wall, const AbsolutePlacement &placement);

enum class OpeningKind { Window, Door };
enum class Dominance { BottomAndTop, LeftAndRight };
inline constexpr int kBottom = 0, kRight = 1, kTop = 2, kLeft = 3;

// Def 5.13 for one edge; every value in [0,1]. `profile`: points in [0,1]², empty for a straight
// edge (the profile language that draws arches and gables is another file's).
struct EdgeRefinement {
    double distL = 0, distR = 0, distB = 0, size = 0;
    std::vector<Vec2d> profile;
};

struct RefinedEdge {
    Vec2d l, r;
    Vec2d outward;  // from (l, r) to the far side of F_Kantenzug: size · (−in)
    double distB = 0, size = 0;
    bool dominant = false;
    std::vector<Vec2d> profile;
    // The profile mapped with `depth` as the fraction of F_Kantenzug that y = 1 reaches, offset
    // outward by `lift` of it: l + x (r − l) + (lift + y · depth) · outward.
    std::vector<Vec2d> polyline(double depth = 1, double lift = 0) const;
};

struct RefinedOpening {
    CoarseOpening coarse;
    OpeningKind kind = OpeningKind::Window;
    std::array<RefinedEdge, 4> edges;  // kBottom, kRight, kTop, kLeft
    std::array<Vec2d, 4> inward;       // per edge: across the whole coarse opening
    // The opening's outline, counter-clockwise, with repeated points dropped.
    std::vector<Vec2d> outline() const;
};

// Throws std::invalid_argument for a coarse opening that is not a convex counter-clockwise quad
// with finite corners, values outside [0,1], profile points outside [0,1]², a band (size > 0) on a
// non-dominant edge, an edge trimmed to nothing (dist_l + dist_r ≥ 1) or opposite edges that meet
// (their dist_b + size add up to 1 or more).
RefinedOpening refineOpening(const CoarseOpening &coarse, const std::array<EdgeRefinement, 4> &edges,
                             Dominance dominance = Dominance::BottomAndTop, OpeningKind kind = OpeningKind::Window);

}  // namespace veduta
