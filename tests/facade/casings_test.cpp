#include "facade/casings.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace veduta {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

Polygon toCgal(const std::vector<Vec2d> &points) {
    Polygon p;
    for (Vec2d v : points) p.push_back(Kernel::Point_2(v.x, v.y));
    return p;
}

double area(const std::vector<PolygonWithHoles> &parts) {
    double sum = 0;
    for (const PolygonWithHoles &p : parts) {
        sum += CGAL::to_double(p.outer_boundary().area());
        for (const Polygon &h : p.holes()) sum += CGAL::to_double(h.area());
    }
    return sum;
}

double overlap(const std::vector<Vec2d> &a, const std::vector<Vec2d> &b) {
    std::vector<PolygonWithHoles> parts;
    CGAL::intersection(toCgal(a), toCgal(b), std::back_inserter(parts));
    return area(parts);
}

double outside(const std::vector<Vec2d> &piece, const std::vector<Vec2d> &region) {
    std::vector<PolygonWithHoles> parts;
    CGAL::difference(toCgal(piece), toCgal(region), std::back_inserter(parts));
    return area(parts);
}

double areaOf(const std::vector<Vec2d> &polygon) { return CGAL::to_double(toCgal(polygon).area()); }

constexpr double kSliverArea = 1e-12;  // square metres: the pieces' own least area

const CoarseOpening kWindow{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

RefinedOpening archedWindow() {
    std::array<EdgeRefinement, 4> e;
    e[kTop] = {0, 0, 0, 0.3, {{0, 0}, {0.1, 0.6}, {0.3, 0.9}, {0.5, 1}, {0.7, 0.9}, {0.9, 0.6}, {1, 0}}};
    return refineOpening(kWindow, e);
}

Casing casingOf(CasingStyle style) {
    Casing c;
    c.style = style;
    c.edges = {{{0.1, 0.03}, {0.1, 0.02}, {0.1, 0.04}, {0.1, 0.02}}};
    c.klinker = {0.12, 0.01, 0.01};
    return c;
}

std::set<PieceKind> kindsOf(const OpeningPieces &result) {
    std::set<PieceKind> kinds;
    for (const FacadePiece &p : result.pieces) kinds.insert(p.kind);
    return kinds;
}

TEST(Casings, NonDominantSideIsHeightLessTopSizeAndBottomThickness) {
    OpeningPieces result = buildOpeningPieces(archedWindow(), casingOf(CasingStyle::Einfach), {});
    size_t sides = 0;
    for (const FacadePiece &p : result.pieces) {
        auto [lo, hi] =
            std::minmax_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
        auto left = std::min_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.x < b.x; });
        if (p.kind == PieceKind::Casing && std::abs(left->x - 0.9) <= 1e-12) {
            EXPECT_NEAR(hi->y - lo->y, 1 - 0.3 - 0.1, 1e-12);
            EXPECT_NEAR(lo->y, 0.1, 1e-12);
            ++sides;
        }
    }
    EXPECT_EQ(sides, 1u);
}

TEST(Casings, NoPiecesOverlapAndTheyTileTheHoleInEveryStyle) {
    for (CasingStyle style :
         {CasingStyle::Einfach, CasingStyle::Gesims, CasingStyle::Doppelgesims, CasingStyle::Klinker}) {
        OpeningPieces result = buildOpeningPieces(archedWindow(), casingOf(style), {});
        const std::vector<FacadePiece> &pieces = result.pieces;
        double total = 0;
        for (size_t i = 0; i < pieces.size(); ++i) {
            EXPECT_GT(areaOf(pieces[i].polygon), 0) << "piece " << i;
            total += areaOf(pieces[i].polygon);
            EXPECT_NEAR(outside(pieces[i].polygon, result.hole), 0, 1e-12);
            for (size_t j = i + 1; j < pieces.size(); ++j) {
                EXPECT_NEAR(overlap(pieces[i].polygon, pieces[j].polygon), 0, 1e-12)
                    << "style " << int(style) << " pieces " << i << ", " << j;
            }
        }
        EXPECT_NEAR(total, areaOf(result.hole), 1e-9) << "style " << int(style);
    }
}

TEST(Casings, PaneLiesInsideTheOpening) {
    RefinedOpening opening = archedWindow();
    OpeningPieces result = buildOpeningPieces(opening, casingOf(CasingStyle::Einfach), {});
    size_t panes = 0;
    for (const FacadePiece &p : result.pieces) {
        if (p.kind != PieceKind::Pane) continue;
        EXPECT_NEAR(outside(p.polygon, opening.outline()), 0, 1e-12);
        ++panes;
    }
    EXPECT_EQ(panes, 4u);  // two bars cross the glass
}

TEST(Casings, EachStyleYieldsItsPieceKinds) {
    using K = PieceKind;
    RefinedOpening opening = archedWindow();
    EXPECT_EQ(kindsOf(buildOpeningPieces(opening, casingOf(CasingStyle::Einfach), {})),
              (std::set<K>{K::Casing, K::Frame, K::Bar, K::Pane}));
    EXPECT_EQ(kindsOf(buildOpeningPieces(opening, casingOf(CasingStyle::Gesims), {})),
              (std::set<K>{K::Cornice, K::Frame, K::Bar, K::Pane}));
    EXPECT_EQ(kindsOf(buildOpeningPieces(opening, casingOf(CasingStyle::Doppelgesims), {})),
              (std::set<K>{K::Cornice, K::GableCornice, K::Infill, K::Frame, K::Bar, K::Pane}));
    EXPECT_EQ(kindsOf(buildOpeningPieces(opening, casingOf(CasingStyle::Klinker), {})),
              (std::set<K>{K::KlinkerBrick, K::KlinkerMortar, K::Frame, K::Bar, K::Pane}));
}

TEST(Casings, KlinkerBricksAreEqualAndStandOutOfTheMortar) {
    std::array<EdgeRefinement, 4> straight;
    RefinedOpening opening = refineOpening(kWindow, straight);
    Casing klinker = casingOf(CasingStyle::Klinker);
    OpeningPieces result = buildOpeningPieces(opening, klinker, {});
    // The bottom strip is 1 m: round(0.99 / 0.13) = 8 bricks of (1 − 9 · 0.01) / 8 m.
    size_t bottomBricks = 0;
    for (const FacadePiece &p : result.pieces) {
        if (p.kind != PieceKind::KlinkerBrick) continue;
        auto top = std::max_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
        if (top->y > 0.1 + 1e-12) continue;
        auto [lo, hi] =
            std::minmax_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.x < b.x; });
        EXPECT_NEAR(hi->x - lo->x, 0.91 / 8, 1e-12);
        EXPECT_NEAR(p.front, 0.03 + 0.01, 1e-12);
        ++bottomBricks;
    }
    EXPECT_EQ(bottomBricks, 8u);
}

TEST(Casings, HoleIsTheOuterOutlineOfCasingAndOpening) {
    RefinedOpening opening = archedWindow();
    OpeningPieces result = buildOpeningPieces(opening, casingOf(CasingStyle::Einfach), {});
    EXPECT_NEAR(outside(opening.outline(), result.hole), 0, 1e-12);
    // The arch's casing stands 0.1 above the arch's ends, as high as the band reaches.
    auto top = std::max_element(result.hole.begin(), result.hole.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
    EXPECT_NEAR(top->y, 1, 1e-12);
}

TEST(Casings, DoorIsOnePolygonWithoutBarsOrThresholdFrame) {
    std::array<EdgeRefinement, 4> e;
    RefinedOpening door = refineOpening(kWindow, e, Dominance::BottomAndTop, OpeningKind::Door);
    Casing casing = casingOf(CasingStyle::Einfach);
    casing.edges[kBottom] = {};
    OpeningPieces result = buildOpeningPieces(door, casing, {});
    size_t doors = 0, frames = 0;
    for (const FacadePiece &p : result.pieces) {
        EXPECT_NE(p.kind, PieceKind::Bar);
        EXPECT_NE(p.kind, PieceKind::Pane);
        doors += p.kind == PieceKind::Door;
        frames += p.kind == PieceKind::Frame;
        if (p.kind == PieceKind::Door) {
            auto low = std::min_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
            EXPECT_EQ(low->y, 0);
        }
    }
    EXPECT_EQ(doors, 1u);
    EXPECT_EQ(frames, 3u);
}

TEST(Casings, OversizedCasingsAreRefused) {
    Casing thick = casingOf(CasingStyle::Einfach);
    thick.edges[kBottom].thickness = 0.8;
    EXPECT_THROW(buildOpeningPieces(archedWindow(), thick, {}), std::invalid_argument);
    Casing tooThickForBand = casingOf(CasingStyle::Doppelgesims);
    tooThickForBand.edges[kTop].thickness = 0.2;
    EXPECT_THROW(buildOpeningPieces(archedWindow(), tooThickForBand, {}), std::invalid_argument);
    EXPECT_THROW(buildOpeningPieces(archedWindow(), casingOf(CasingStyle::Einfach), {0.6, 0, -0.1}),
                 std::invalid_argument);
}

TEST(Casings, ExtrudedPiecesFaceOutOfTheWall) {
    std::array<EdgeRefinement, 4> straight;
    OpeningPieces result = buildOpeningPieces(refineOpening(kWindow, straight), casingOf(CasingStyle::Einfach), {});
    // A south wall: along +x, up +z, so outward is −y.
    WallFrame3d frame{{10, 5, 0}, {1, 0, 0}, {0, 0, 1}};
    PieceMaterials materials;
    materials.casing = 1;
    materials.frame = 2;
    materials.pane = 3;
    Mesh mesh = extrudePieces(result.pieces, frame, materials);
    ASSERT_EQ(mesh.indices.size(), 3 * mesh.triangleMaterials.size());
    double paneArea = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3f a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
              c = mesh.positions[mesh.indices[3 * t + 2]];
        Vec3f n = cross(b - a, c - a);
        EXPECT_NE(mesh.triangleMaterials[t], kNoMaterial);
        if (mesh.triangleMaterials[t] == 3) {
            EXPECT_LT(n.y, 0);
            EXPECT_NEAR(a.y, 5 + 0.1, 1e-6);  // the pane lies 0.1 m behind the wall plane
            paneArea += length(n) / 2;
        }
    }
    double expected = 0;
    for (const FacadePiece &p : result.pieces) expected += p.kind == PieceKind::Pane ? areaOf(p.polygon) : 0;
    EXPECT_NEAR(paneArea, expected, 1e-5);
}

TEST(Casings, KlinkerBricksMustBePositiveFiniteAndSpacedNotNegatively) {
    RefinedOpening opening = refineOpening(kWindow, {});
    const double nan = std::nan(""), inf = HUGE_VAL;
    for (KlinkerBricks bad : std::vector<KlinkerBricks>{{0, 0.01, 0.01},
                                                        {-0.1, 0.01, 0.2},
                                                        {nan, 0.01, 0.01},
                                                        {inf, 0.01, 0.01},
                                                        {0.12, 0.01, -0.01},
                                                        {0.12, 0.01, nan},
                                                        {0.12, 0.01, inf},
                                                        {0.12, nan, 0.01}}) {
        Casing klinker = casingOf(CasingStyle::Klinker);
        klinker.klinker = bad;
        EXPECT_THROW(buildOpeningPieces(opening, klinker, {}), std::invalid_argument)
            << bad.brickWidth << " " << bad.brickOverhang << " " << bad.spacing;
        klinker.style = CasingStyle::Einfach;  // other styles do not use them
        EXPECT_NO_THROW(buildOpeningPieces(opening, klinker, {}));
    }
}

TEST(Casings, KlinkerRefusesMoreBricksAlongAStripThanItsLimit) {
    Casing klinker = casingOf(CasingStyle::Klinker);
    klinker.klinker = {0.0009, 0.01, 0};  // 1111 bricks along the 1 m bottom strip
    EXPECT_THROW(buildOpeningPieces(refineOpening(kWindow, {}), klinker, {}), std::invalid_argument);
    klinker.klinker = {1e-12, 0.01, 0};
    EXPECT_THROW(buildOpeningPieces(refineOpening(kWindow, {}), klinker, {}), std::invalid_argument);
}

TEST(Casings, KlinkerWithoutSpacingHasTouchingBricksAndNoMortar) {
    Casing klinker = casingOf(CasingStyle::Klinker);
    klinker.klinker.spacing = 0;
    OpeningPieces result = buildOpeningPieces(refineOpening(kWindow, {}), klinker, {});
    size_t bottomBricks = 0;
    double total = 0;
    for (const FacadePiece &p : result.pieces) {
        EXPECT_NE(p.kind, PieceKind::KlinkerMortar);
        EXPECT_GT(areaOf(p.polygon), kSliverArea);
        total += areaOf(p.polygon);
        auto top = std::max_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
        if (p.kind != PieceKind::KlinkerBrick || top->y > 0.1 + 1e-12) continue;
        auto [lo, hi] =
            std::minmax_element(p.polygon.begin(), p.polygon.end(), [](Vec2d a, Vec2d b) { return a.x < b.x; });
        EXPECT_NEAR(hi->x - lo->x, 1.0 / 8, 1e-12);  // round(1 / 0.12) = 8 bricks share the metre
        ++bottomBricks;
    }
    EXPECT_EQ(bottomBricks, 8u);
    EXPECT_NEAR(total, areaOf(result.hole), 1e-9);
}

TEST(Casings, OverhangsAndDepthsMustBeFinite) {
    RefinedOpening opening = refineOpening(kWindow, {});
    Casing casing = casingOf(CasingStyle::Einfach);
    casing.edges[kRight].overhang = std::nan("");
    EXPECT_THROW(buildOpeningPieces(opening, casing, {}), std::invalid_argument);
    casing = casingOf(CasingStyle::Einfach);
    EXPECT_THROW(buildOpeningPieces(opening, casing, {0.06, HUGE_VAL, -0.1}), std::invalid_argument);
    EXPECT_THROW(buildOpeningPieces(opening, casing, {0.06, -0.05, std::nan("")}), std::invalid_argument);
}

TEST(Casings, AProfileThatTurnsBackIsRefusedNotAFailedCheck) {
    // The arch's outline crosses itself.
    std::array<EdgeRefinement, 4> e;
    e[kTop] = {0, 0, 0, 0.3, {{0.8, 1}, {0.2, 1}}};
    EXPECT_THROW(buildOpeningPieces(refineOpening(kWindow, e), casingOf(CasingStyle::Einfach), {}),
                 std::invalid_argument);
    // A band's casing that closes a gap against the opening (found by random search).
    const CoarseOpening skewed{{0, 0},
                               {1.2181001869715322, 0},
                               {1.2181001869715322, 2.1236638096642957 + 0.35440864996217336},
                               {0, 2.1236638096642957}};
    e = {};
    e[kRight] = {0.16199516023646721,
                 0.22021569636439536,
                 0,
                 0.041319851061046659,
                 {{0.05248556457767091, 0.98710164631874642},
                  {0.42802530256450944, 0.66988800281374872},
                  {0.75314438850720922, 0},
                  {0.80454975605992796, 0.5671313560336656},
                  {1, 0.1801164617850394}}};
    e[kTop].distL = 0.22323141740535757;
    e[kLeft] = {0.0042511760265509695,
                0,
                0,
                0.34382070826885713,
                {{0.33457947067304872, 0.24469222582214167},
                 {0.59639786621472246, 0},
                 {0.75103731829570897, 0.9393312856473468}}};
    Casing casing;
    casing.edges[kRight] = {0.018981442416256589, 0.014614954832683416};
    EXPECT_THROW(buildOpeningPieces(refineOpening(skewed, e, Dominance::LeftAndRight, OpeningKind::Door), casing,
                                    {0.08, -0.05, -0.1}),
                 std::invalid_argument);
}

TEST(Casings, AKlinkerSliverTheFrameCannotFollowIsRefusedNotNaN) {
    // Found by random search: the clear opening keeps a corner that turns back on itself.
    const CoarseOpening skewed{{0, 0},
                               {1.3562335727900678, 0},
                               {1.3562335727900678, 2.9366595651445433 + 0.031137680519812746},
                               {0, 2.9366595651445433}};
    std::array<EdgeRefinement, 4> e;
    e[kBottom] = {0.15414520278074381, 0, 0, 0.36495678276965798, {}};
    e[kRight] = {0.31302424398820899, 0, 0.20793330731923251, 0, {}};
    e[kTop] = {0.31898924894536917, 0.31452508032507182, 0, 0, {}};
    e[kLeft] = {0.043901289170635197, 0.14477663276672156, 0, 0, {}};
    Casing klinker;
    klinker.style = CasingStyle::Klinker;
    klinker.edges = {{{0.033129274085302446, 0.011941801728510294},
                      {0.057246976582504661, 0.047954066579480058},
                      {0.2061674254537274, 0.033248265203539663},
                      {0.22297516964473149, 0.044893958674876999}}};
    klinker.klinker = {0.17122361257284099, 0.01, 0.018036081627112257};
    EXPECT_THROW(buildOpeningPieces(refineOpening(skewed, e, Dominance::BottomAndTop, OpeningKind::Door), klinker,
                                    {0.067609037563462593, -0.05, -0.1}),
                 std::invalid_argument);
}

TEST(Casings, ExtrudingRefusesPiecesThatAreNotFiniteSimplePolygons) {
    WallFrame3d frame{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    FacadePiece bowTie{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0, 0.1, PieceKind::Casing};
    EXPECT_THROW(extrudePieces({bowTie}, frame, {}), std::invalid_argument);
    FacadePiece nan{{{0, 0}, {1, 0}, {std::nan(""), 1}}, 0, 0.1, PieceKind::Casing};
    EXPECT_THROW(extrudePieces({nan}, frame, {}), std::invalid_argument);
    FacadePiece deep{{{0, 0}, {1, 0}, {1, 1}}, 0, HUGE_VAL, PieceKind::Casing};
    EXPECT_THROW(extrudePieces({deep}, frame, {}), std::invalid_argument);
    FacadePiece fine{{{0, 0}, {1, 0}, {1, 1}}, 0, 0.1, PieceKind::Casing};
    EXPECT_EQ(extrudePieces({fine}, frame, {}).triangleCount(), 7u);
    EXPECT_THROW(extrudePieces({fine}, {{0, 0, 0}, {std::nanf(""), 0, 0}, {0, 0, 1}}, {}), std::invalid_argument);
}

TEST(Casings, TheRevealFacesIntoTheOpeningAndItsBackFacesOut) {
    std::vector<Vec2d> hole{{1, 1}, {2, 1}, {2, 3}, {1, 3}};
    // A wall along y, so that its outside is -x: nothing here may assume the wall faces y.
    WallFrame3d frame{{5, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vec3f outward = cross(frame.along, frame.up);
    Vec3f centre = frame.origin + frame.along * 1.5f + frame.up * 2.0f;
    Mesh mesh = revealMesh(hole, frame, 0.6, 3);
    ASSERT_EQ(mesh.triangleCount(), 2 + 2 * hole.size());
    size_t back = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3f a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
              c = mesh.positions[mesh.indices[3 * t + 2]];
        Vec3f n = normalize(cross(b - a, c - a));
        EXPECT_EQ(mesh.triangleMaterials[t], 3u);
        if (std::abs(dot(n, outward) - 1) < 1e-6f) {
            for (Vec3f p : {a, b, c}) EXPECT_NEAR(dot(p - frame.origin, outward), -0.6f, 1e-6f);
            ++back;
            continue;
        }
        Vec3f middle = (a + b + c) * (1.0f / 3);
        Vec3f toCentre = centre - middle;
        toCentre = toCentre - outward * dot(toCentre, outward);
        EXPECT_GT(dot(n, toCentre), 0) << "side triangle " << t << " faces away from the opening";
    }
    EXPECT_EQ(back, 2u);
}

}  // namespace
}  // namespace veduta
