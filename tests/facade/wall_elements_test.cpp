#include "facade/wall_elements.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace veduta {
namespace {

// An L footprint, counter-clockwise, with its one concave vertex at (4, 4).
const std::vector<Vec2d> kL{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 8}, {0, 8}};
const WallSubdivision kRhythm{0.5, 0.4, 4};

size_t countKind(const StoreyFacade &facade, size_t wall, ElementKind kind) {
    size_t n = 0;
    for (const FacadeElement &e : facade.elements) n += e.baseWall == wall && e.kind == kind;
    return n;
}

TEST(WallElements, AnLFootprintHasFiveCornersAndNoneAtItsConcaveVertex) {
    StoreyFacade facade = subdivideStorey({kL}, true, kRhythm);
    EXPECT_EQ(facade.baseWalls.size(), 6u);
    ASSERT_EQ(facade.corners.size(), 5u);
    for (const HouseCorner &c : facade.corners) EXPECT_FALSE(c.point == (Vec2d{4, 4}));
}

TEST(WallElements, EveryBaseWallHasOneZweFewerThanWalls) {
    StoreyFacade facade = subdivideStorey({kL}, true, kRhythm);
    size_t zweTotal = 0;
    for (size_t w = 0; w < facade.baseWalls.size(); ++w) {
        size_t walls = countKind(facade, w, ElementKind::Wall), zwe = countKind(facade, w, ElementKind::InterWall);
        EXPECT_GE(walls, 1u);
        EXPECT_EQ(zwe + 1, walls) << "base wall " << w;
        zweTotal += zwe;
    }
    EXPECT_GT(zweTotal, 0u);
}

TEST(WallElements, ElementsTileEachBaseWallWithCornerFacesAtConvexEnds) {
    StoreyFacade facade = subdivideStorey({kL}, true, kRhythm);
    for (size_t w = 0; w < facade.baseWalls.size(); ++w) {
        double at = 0;
        for (const FacadeElement &e : facade.elements) {
            if (e.baseWall != w) continue;
            EXPECT_NEAR(e.from, at, 1e-12);
            EXPECT_GT(e.to, e.from);
            if (e.kind == ElementKind::CornerFace) {
                EXPECT_NEAR(e.to - e.from, 0.5, 1e-12);
            }
            at = e.to;
        }
        EXPECT_NEAR(at, facade.baseWalls[w].length(), 1e-12);
    }
    // Base wall 2 runs (10,4)→(4,4): a corner at its start, none at the concave end.
    EXPECT_EQ(countKind(facade, 2, ElementKind::CornerFace), 1u);
    EXPECT_EQ(countKind(facade, 0, ElementKind::CornerFace), 2u);
    size_t faces = 0;
    for (size_t w = 0; w < facade.baseWalls.size(); ++w) faces += countKind(facade, w, ElementKind::CornerFace);
    EXPECT_EQ(faces, 2 * facade.corners.size());
}

TEST(WallElements, CountRuleSharesTheFreeLengthAmongEqualWalls) {
    std::vector<double> widths = wallAndInterWallWidths(10, {0, 0.5, 4});
    // round((10 + 0.5) / (2 + 0.5)) = 4 walls, 3 ZWE of 0.5 m; the walls share 8.5 m.
    ASSERT_EQ(widths.size(), 7u);
    for (size_t i = 0; i < widths.size(); ++i) EXPECT_NEAR(widths[i], i % 2 ? 0.5 : 2.125, 1e-12);
    EXPECT_EQ(wallAndInterWallWidths(10, {0, 0, 4}), std::vector<double>{10});
    EXPECT_EQ(wallAndInterWallWidths(0.3, {0, 0.5, 4}), std::vector<double>{0.3});
}

TEST(WallElements, SplitFeaturesGiveTheSameCornersAsOneClosedFeature) {
    StoreyFacade split = subdivideStorey({{kL[0], kL[1], kL[2], kL[3]}, {kL[3], kL[4], kL[5], kL[0]}}, true, kRhythm);
    EXPECT_EQ(split.baseWalls.size(), 6u);
    EXPECT_EQ(split.corners.size(), 5u);
    EXPECT_EQ(split.baseWalls[3].feature, 1u);
}

TEST(WallElements, AnOpenOutlineHasNoCornersAtItsEnds) {
    StoreyFacade open = subdivideStorey({{{0, 0}, {10, 0}, {10, 4}}}, false, kRhythm);
    ASSERT_EQ(open.corners.size(), 1u);
    EXPECT_EQ(open.corners[0].point, (Vec2d{10, 0}));
}

TEST(WallElements, BadOutlinesAreRefused) {
    EXPECT_THROW(subdivideStorey({{{0, 0}}}, true, kRhythm), std::invalid_argument);
    EXPECT_THROW(subdivideStorey({{{0, 0}, {1, 0}}, {{2, 0}, {3, 0}}}, false, kRhythm), std::invalid_argument);
    EXPECT_THROW(subdivideStorey({{{0, 0}, {0, 0}, {1, 0}}}, false, kRhythm), std::invalid_argument);
    EXPECT_THROW(subdivideStorey({kL}, true, {-1, 0, 0}), std::invalid_argument);
}

TEST(WallElements, PartitionsScaleTheirCutsByTheHeight) {
    std::vector<Partition> p = partitionHeights(3, {0, 0.1, 0.9, 1});
    ASSERT_EQ(p.size(), 3u);
    EXPECT_NEAR(p[1].zFrom, 0.3, 1e-12);
    EXPECT_NEAR(p[1].zTo, 2.7, 1e-12);
    EXPECT_THROW(partitionHeights(3, {0, 0.5, 0.5, 1}), std::invalid_argument);
    EXPECT_THROW(partitionHeights(3, {0.1, 1}), std::invalid_argument);
}

TEST(WallElements, EqualPartitionsOnAllElementsFormRingBandsAtTheSameHeight) {
    StoreyFacade facade = subdivideStorey({kL}, true, kRhythm);
    std::vector<std::vector<Partition>> partitions(facade.elements.size(), partitionHeights(3, {0, 0.1, 0.9, 1}));
    std::vector<BandRun> bands = findBands(facade, partitions);
    ASSERT_EQ(bands.size(), 3u);
    for (const BandRun &b : bands) {
        EXPECT_TRUE(b.aroundTheOutline);
        EXPECT_EQ(b.count, facade.elements.size());
    }
    EXPECT_NEAR(bands[0].zTo, 0.3, 1e-12);
    EXPECT_NEAR(bands[2].zFrom, 2.7, 1e-12);
}

TEST(WallElements, AnElementWithOtherCutsBreaksTheBandIntoARunAroundIt) {
    StoreyFacade facade = subdivideStorey({kL}, true, kRhythm);
    size_t n = facade.elements.size();
    std::vector<std::vector<Partition>> partitions(n, partitionHeights(3, {0, 0.1, 1}));
    partitions[3] = partitionHeights(3, {0, 0.2, 1});
    std::vector<BandRun> bands = findBands(facade, partitions);
    // The plinth [0, 0.3] runs from element 4 round to element 2; element 3 has its own two.
    ASSERT_EQ(bands.size(), 4u);
    EXPECT_EQ(bands[0].first, 3u);
    EXPECT_EQ(bands[0].count, 1u);
    EXPECT_EQ(bands[2].first, 4u);
    EXPECT_EQ(bands[2].count, n - 1);
    EXPECT_FALSE(bands[2].aroundTheOutline);
    EXPECT_NEAR(bands[2].zTo, 0.3, 1e-12);
}

TEST(WallElements, AbsurdZweCountsAndNonFiniteValuesAreRefused) {
    const double nan = std::nan(""), inf = HUGE_VAL;
    // 1e-12 m ZWE would ask about 1e13 elements of a 10 m wall.
    EXPECT_THROW(wallAndInterWallWidths(10, {0, 1e-12, 4}), std::invalid_argument);
    EXPECT_THROW(subdivideStorey({kL}, true, {0.5, 1e-12, 4}), std::invalid_argument);
    EXPECT_THROW(wallAndInterWallWidths(10, {0, 0.009, 4}), std::invalid_argument);
    EXPECT_EQ(wallAndInterWallWidths(10, {0, 0.01, 4}).size(), 2 * 200u - 1);  // round(10.01 / 0.05)
    // The narrowest ZWE with a tiny ratio: the count limit refuses a long wall.
    EXPECT_THROW(wallAndInterWallWidths(1000, {0, 0.01, 1e-9}), std::invalid_argument);
    for (WallSubdivision bad : std::vector<WallSubdivision>{
             {nan, 0.4, 4}, {0.5, nan, 4}, {0.5, 0.4, nan}, {inf, 0.4, 4}, {0.5, inf, 4}, {0.5, 0.4, inf}}) {
        EXPECT_THROW(subdivideStorey({kL}, true, bad), std::invalid_argument);
        EXPECT_THROW(wallAndInterWallWidths(10, bad), std::invalid_argument);
    }
    EXPECT_THROW(wallAndInterWallWidths(nan, kRhythm), std::invalid_argument);
    EXPECT_THROW(wallAndInterWallWidths(inf, kRhythm), std::invalid_argument);
    EXPECT_THROW(wallAndInterWallWidths(-1, kRhythm), std::invalid_argument);
    EXPECT_THROW(subdivideStorey({{{0, 0}, {nan, 0}, {1, 1}}}, true, kRhythm), std::invalid_argument);
    EXPECT_THROW(subdivideStorey({{{-1e308, 0}, {1e308, 0}, {0, 1}}}, true, kRhythm), std::invalid_argument);
    EXPECT_THROW(partitionHeights(nan, {0, 1}), std::invalid_argument);
    EXPECT_THROW(partitionHeights(inf, {0, 1}), std::invalid_argument);
    EXPECT_THROW(partitionHeights(-3, {0, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace veduta
