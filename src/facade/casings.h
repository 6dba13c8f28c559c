// What fills a refined opening: the casing (Fenster-/Türstock, Def 5.14, L1343–1357) in one of the
// four styles Einfach, Gesims, Doppelgesims and Klinker (L1389–1392), the frame with its two bars
// and the pane, or the door (Def 5.15, L1395–1398); digest-001 §2.8. The result is flat pieces in
// the wall's (along, up) plane, each with the depth range it stands out of the wall, plus the
// hole the wall must cut; `extrudePieces` turns them into a mesh.
//
// Choices where the thesis is open:
// * A casing's thickness bf ∈ [0,1] is a fraction of the opening across its edge, the unit of
//   dist_b and size (so §8 row 9's side = height − size(top) − bf(bottom) holds in those units).
//   On a straight edge the casing runs inward from the refined edge. On an edge with a `size`
//   band it stays in F_Kantenzug: the profile is scaled into the band less bf and the casing is
//   the strip bf thick above it, so the casing's inner side is the refined polyline and the pane
//   follows it ("Pane = the casing's inner polyline").
// * Non-dominant edges shrink by the thickness of their dominant neighbours' casings when those
//   lie inside the opening; a `size` edge's casing lies outside its (l, r) line and takes nothing.
//   A `size` band is only allowed on a dominant edge: on a non-dominant one the full-width
//   neighbours would cross it, and the opening outline folds back on itself.
// * Gesims: for now a plain block of the casing's shape (the profiled sweep is another file's).
//   Doppelgesims on a `size` edge: a straight cornice bf thick on (l, r), the gable or arch
//   cornice bf thick above it following the polyline, and the wall infill (tympanum) between;
//   on a straight edge it is a Gesims.
// * Klinker: along each casing strip, equal bricks and mortar joints of width `spacing` at both
//   ends and between; the brick count is round((L − s) / (w + s)) (at least 1), the bricks take
//   what the joints leave. Bricks stand `brickOverhang` in front of the mortar. Spacing 0 gives
//   bricks that touch, with no joints.
// * Frame: bf ∈ [0,1] of the coarse opening's width, inset along the clear opening with mitred
//   corners; doors have none along their threshold. The two bars (L1398) are a mullion at the
//   middle and a transom at two thirds of the height, as German Kreuzstock windows have. The
//   glass is what frame and bars leave, so no piece overlaps another.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/vecmath.h"
#include "facade/openings.h"
#include "scene/mesh.h"

namespace veduta {

enum class CasingStyle { Einfach, Gesims, Doppelgesims, Klinker };

// Def 5.14 per edge: thickness bf ∈ [0,1] and overhang o in metres in front of the wall.
struct EdgeCasing {
    double thickness = 0;
    double overhang = 0;
};

// The Klinker concept {Breite, Vorsprung, Abstand}, in metres.
struct KlinkerBricks {
    double brickWidth = 0.25;
    double brickOverhang = 0.02;
    double spacing = 0.01;
};

struct Casing {
    CasingStyle style = CasingStyle::Einfach;
    std::array<EdgeCasing, 4> edges;  // kBottom, kRight, kTop, kLeft
    KlinkerBricks klinker;
};

// Def 5.15: thickness bf ∈ [0,1] of the coarse opening's width; the frame stands from `paneDepth`
// to `overhang` (metres in front of the wall plane, negative = behind it); pane and door lie at
// `paneDepth`.
struct WindowFrame {
    double thickness = 0.06;
    double overhang = -0.05;
    double paneDepth = -0.1;
};

enum class PieceKind { Casing, Cornice, GableCornice, Infill, KlinkerBrick, KlinkerMortar, Frame, Bar, Pane, Door };

// A flat piece, counter-clockwise in the wall's (along, up) plane, standing out of the wall from
// `back` to `front` metres.
struct FacadePiece {
    std::vector<Vec2d> polygon;
    double back = 0, front = 0;
    PieceKind kind = PieceKind::Casing;
};

struct OpeningPieces {
    std::vector<FacadePiece> pieces;
    std::vector<Vec2d> hole;  // counter-clockwise: the outer outline of the casing and the opening
};

// Throws std::invalid_argument for thicknesses outside [0,1], overhangs or depths that are not
// finite, Klinker bricks that are not positive and finite or spaced negatively (or more than 1000
// of them along one strip), a casing thicker than the opening leaves room for, a `size` band on a
// non-dominant edge or thinner than its casing (twice for Doppelgesims), an opening outline or
// casing piece that crosses itself (a profile can turn back), casing pieces that leave a gap, or a
// frame too thick for the clear opening.
OpeningPieces buildOpeningPieces(const RefinedOpening &opening, const Casing &casing, const WindowFrame &frame);

// The wall's frame in the scene: a point (along, up) of the wall plane lies at
// origin + along · x + up · y; unit vectors, at right angles; `along` points right seen from
// outside, so the outward normal is along × up.
struct WallFrame3d {
    Vec3f origin, along, up;
};

struct PieceMaterials {
    MaterialId casing = kNoMaterial, cornice = kNoMaterial, wall = kNoMaterial, brick = kNoMaterial,
               mortar = kNoMaterial, frame = kNoMaterial, pane = kNoMaterial, door = kNoMaterial;
};

// Each piece as a front face at `front` and, where it has depth, side faces down to `back`
// (the back face lies on the wall or behind it and is never seen). Flat shading; outward faces
// wind counter-clockwise. Throws std::invalid_argument for a piece that is not a finite simple
// counter-clockwise polygon with finite depths, or a frame that is not finite.
Mesh extrudePieces(const std::vector<FacadePiece> &pieces, const WallFrame3d &frame, const PieceMaterials &materials);

// How deep the reveal runs behind the wall: a room's worth of dark, so that a pane shows a dim
// inside and not the sky through the far side of the house (the walls are sheets).
inline constexpr double kRevealDepth = 0.6;

// The opening's reveal: the hole's sides run `depth` metres back into the wall, facing into the
// opening, and a back face closes them; all in `material`. Throws std::invalid_argument as
// extrudePieces does for a hole that is not a finite simple counter-clockwise polygon.
Mesh revealMesh(const std::vector<Vec2d> &hole, const WallFrame3d &frame, double depth, MaterialId material);

}  // namespace veduta
