#include "facade/ornament_growth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/check.h"

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The 1.2 m × 0.4 m panel under a sill at 1 cm cells, the vine rising from a baseline 1.5 cm up.
OrnamentRaster sillPanel() { return OrnamentRaster::fromRegion(rectangle(0, 0, 1.2, 0.4), {}, 0.01); }

std::vector<OrnamentElement> sillRoots(const OrnamentRaster &raster) {
    return {OrnamentElement::rootAlong(raster, {0.03, 0.015}, {1.17, 0.015})};
}

// An L: 0.6 m legs 0.25 m wide, at 1 cm; a root boss in its corner.
OrnamentRaster lShape() {
    return OrnamentRaster::fromRegion({{0, 0}, {0.6, 0}, {0.6, 0.25}, {0.25, 0.25}, {0.25, 0.6}, {0, 0.6}}, {}, 0.01);
}

// A 0.8 m × 0.5 m panel with a clockwise 0.2 m × 0.16 m hole, rooted at a point.
OrnamentRaster panelWithHole() {
    return OrnamentRaster::fromRegion(rectangle(0, 0, 0.8, 0.5), {{{0.3, 0.2}, {0.3, 0.36}, {0.5, 0.36}, {0.5, 0.2}}},
                                      0.01);
}

// Squared distances by brute force: to every non-free cell and to the frame around the raster.
std::vector<int32_t> bruteForceDistances(const OrnamentRaster &raster) {
    int w = raster.width(), h = raster.height();
    std::vector<int32_t> result(size_t(w * h), 0);
    for (int cell = 0; cell < w * h; ++cell) {
        if (raster.state(cell) != OrnamentCell::Free) continue;
        int x = cell % w, y = cell / w;
        int best = std::min({(x + 1) * (x + 1), (w - x) * (w - x), (y + 1) * (y + 1), (h - y) * (h - y)});
        for (int other = 0; other < w * h; ++other) {
            if (raster.state(other) == OrnamentCell::Free) continue;
            int dx = other % w - x, dy = other / w - y;
            best = std::min(best, dx * dx + dy * dy);
        }
        result[size_t(cell)] = best;
    }
    return result;
}

// The reduced medial axis from the definition, in the list order.
std::vector<MedialAxisEntry> bruteForceMedialAxis(const OrnamentRaster &raster, const std::vector<int32_t> &d) {
    int w = raster.width(), h = raster.height();
    std::vector<MedialAxisEntry> entries;
    for (int cell = 0; cell < w * h; ++cell) {
        if (raster.state(cell) != OrnamentCell::Free) continue;
        bool maximum = true;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                int x = cell % w + dx, y = cell / w + dy;
                if (x >= 0 && y >= 0 && x < w && y < h && d[size_t(y * w + x)] > d[size_t(cell)]) maximum = false;
            }
        }
        if (maximum) entries.push_back({cell, d[size_t(cell)]});
    }
    std::sort(entries.begin(), entries.end(), MedialAxisOrder());
    return entries;
}

TEST(OrnamentRaster, DistanceTransformMatchesBruteForceWithTheFrameAsObstacle) {
    int w = 23, h = 17;
    std::vector<OrnamentCell> cells(size_t(w * h), OrnamentCell::Free);
    for (int cell = 0; cell < w * h; ++cell) {
        int x = cell % w, y = cell / w;
        if ((x * 7 + y * 13) % 29 == 0 || (x >= 14 && x < 18 && y >= 3 && y < 9))
            cells[size_t(cell)] = OrnamentCell::Forbidden;
    }
    OrnamentRaster raster(w, h, 0.1, {0, 0}, cells);
    EXPECT_EQ(squaredDistanceTransform(raster), bruteForceDistances(raster));
    EXPECT_EQ(raster.squaredDistances(), bruteForceDistances(raster));
    EXPECT_EQ(raster.medialAxis(), bruteForceMedialAxis(raster, raster.squaredDistances()));

    // All free: the distance to the frame. Cell (4, 2) of 9 × 5 is 3 from the top and bottom.
    OrnamentRaster open(9, 5, 0.1, {0, 0}, std::vector<OrnamentCell>(45, OrnamentCell::Free));
    EXPECT_EQ(open.squaredDistances()[2 * 9 + 4], 9);
    EXPECT_EQ(open.squaredDistances()[0], 1);
    ASSERT_FALSE(open.medialAxis().empty());
    EXPECT_EQ(open.medialAxis().front(), (MedialAxisEntry{2 * 9 + 2, 9}));  // the ridge's first cell
}

TEST(OrnamentRaster, RasterisesARegionByCellCentres) {
    OrnamentRaster hole =
        OrnamentRaster::fromRegion(rectangle(0, 0, 1, 0.5), {{{0.2, 0.1}, {0.2, 0.3}, {0.4, 0.3}, {0.4, 0.1}}}, 0.1);
    ASSERT_EQ(hole.width(), 10);
    ASSERT_EQ(hole.height(), 5);
    auto countFree = [](const OrnamentRaster &raster) {
        int n = 0;
        for (int cell = 0; cell < raster.cellCount(); ++cell) n += raster.state(cell) == OrnamentCell::Free;
        return n;
    };
    EXPECT_EQ(countFree(hole), 50 - 4);
    EXPECT_EQ(hole.state(hole.cellAt({0.25, 0.15})), OrnamentCell::Forbidden);
    EXPECT_EQ(hole.state(hole.cellAt({0.45, 0.15})), OrnamentCell::Free);

    OrnamentRaster l =
        OrnamentRaster::fromRegion({{0, 0}, {0.6, 0}, {0.6, 0.2}, {0.2, 0.2}, {0.2, 0.6}, {0, 0.6}}, {}, 0.1);
    ASSERT_EQ(l.width(), 6);
    ASSERT_EQ(l.height(), 6);
    EXPECT_EQ(countFree(l), 6 * 2 + 2 * 4);
    EXPECT_EQ(l.state(l.cellAt({0.35, 0.35})), OrnamentCell::Forbidden);
    EXPECT_EQ(sillPanel().width(), 120);
    EXPECT_EQ(sillPanel().height(), 40);
}

TEST(OrnamentRaster, RejectsBadRegionsAndCells) {
    EXPECT_THROW(OrnamentRaster::fromRegion(rectangle(0, 0, 1, 1), {}, 0), InternalError);
    std::vector<Vec2d> clockwise = rectangle(0, 0, 1, 1);
    std::reverse(clockwise.begin(), clockwise.end());
    EXPECT_THROW(OrnamentRaster::fromRegion(clockwise, {}, 0.1), InternalError);
    EXPECT_THROW(OrnamentRaster::fromRegion(rectangle(0, 0, 100, 100), {}, 0.01), InternalError);  // 10⁸ cells
    EXPECT_THROW(OrnamentRaster(2, 2, 0.1, {0, 0}, std::vector<OrnamentCell>(3)), InternalError);
    OrnamentRaster raster(4, 4, 0.1, {0, 0}, std::vector<OrnamentCell>(16, OrnamentCell::Free));
    raster.occupy({5}, 0);
    EXPECT_THROW(raster.occupy({5}, 1), InternalError);
    // A root must lie on free cells.
    EXPECT_THROW(OrnamentElement::rootAlong(sillPanel(), {0.0, 0.0}, {1.0, 0.0}), InternalError);
}

TEST(OrnamentRaster, IncrementalDistancesEqualAFullRecomputeAfterScatteredCells) {
    int w = 61, h = 37;
    OrnamentRaster raster(w, h, 0.01, {0, 0}, std::vector<OrnamentCell>(size_t(w * h), OrnamentCell::Free));
    // Single cells and small clusters scattered over the raster, one placement at a time.
    for (int i = 0; i < 60; ++i) {
        int cell = (i * 7919 + 13) % (w * h);
        std::vector<int> cells;
        for (int c : {cell, cell + 1, cell + w}) {
            if (c < w * h && raster.state(c) == OrnamentCell::Free) cells.push_back(c);
        }
        raster.occupy(cells, i);
        ASSERT_EQ(raster.squaredDistances(), squaredDistanceTransform(raster)) << "after placement " << i;
        ASSERT_EQ(raster.medialAxis(), bruteForceMedialAxis(raster, squaredDistanceTransform(raster)));
    }
    EXPECT_EQ(raster.squaredDistances(), bruteForceDistances(raster));
}

struct Region {
    const char *name;
    OrnamentRaster raster;
    std::vector<OrnamentElement> roots;
};

std::vector<Region> testRegions() {
    OrnamentRaster panel = sillPanel(), l = lShape(), hole = panelWithHole();
    std::vector<OrnamentElement> panelRoots = sillRoots(panel);
    std::vector<OrnamentElement> lRoots{OrnamentElement::rootAt(l, {0.05, 0.05})};
    std::vector<OrnamentElement> holeRoots{OrnamentElement::rootAt(hole, {0.1, 0.25})};
    return {{"panel", std::move(panel), std::move(panelRoots)},
            {"L", std::move(l), std::move(lRoots)},
            {"hole", std::move(hole), std::move(holeRoots)}};
}

TEST(OrnamentGrowth, IncrementalDistancesAndMedialAxisEqualAFullRecomputeAfterEveryPlacement) {
    for (Region &region : testRegions()) {
        OrnamentGrower grower(region.raster, region.roots);
        int steps = 0;
        while (grower.step()) {
            ++steps;
            const OrnamentRaster &raster = grower.ornament().raster;
            std::vector<int32_t> full = squaredDistanceTransform(raster);
            ASSERT_EQ(raster.squaredDistances(), full) << region.name << " after step " << steps;
            std::vector<MedialAxisEntry> axis = raster.medialAxis();
            ASSERT_EQ(axis, bruteForceMedialAxis(raster, full)) << region.name << " after step " << steps;
        }
        EXPECT_GT(steps, 20) << region.name;
        EXPECT_EQ(grower.ornament().raster.squaredDistances(), bruteForceDistances(grower.ornament().raster));
    }
}

TEST(OrnamentGrowth, MedialAxisIsSortedAndEachEntryIsALocalMaximum) {
    Ornament ornament = growOrnament(sillPanel(), sillRoots(sillPanel()));
    const OrnamentRaster &raster = ornament.raster;
    std::vector<MedialAxisEntry> axis = raster.medialAxis();
    ASSERT_FALSE(axis.empty());
    EXPECT_TRUE(std::is_sorted(axis.begin(), axis.end(), MedialAxisOrder()));
    for (const MedialAxisEntry &entry : axis) {
        EXPECT_EQ(raster.state(entry.cell), OrnamentCell::Free);
        EXPECT_EQ(entry.squaredRadius, raster.squaredDistances()[size_t(entry.cell)]);
        int x = entry.cell % raster.width(), y = entry.cell / raster.width();
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if (x + dx < 0 || y + dy < 0 || x + dx >= raster.width() || y + dy >= raster.height()) continue;
                EXPECT_LE(raster.squaredDistances()[size_t((y + dy) * raster.width() + x + dx)], entry.squaredRadius);
            }
        }
    }
}

TEST(OrnamentGrowth, StopsOnlyWhenNoRegionIsFreeOrNoElementGrows) {
    for (Region &region : testRegions()) {
        OrnamentSettings settings;
        Ornament ornament = growOrnament(region.raster, region.roots, settings);
        const OrnamentRaster &raster = ornament.raster;
        auto minSquared = int32_t(std::ceil(settings.minRadius * settings.minRadius));
        if (ornament.stop == OrnamentStop::NoFreeRegion) {
            for (int32_t d : raster.squaredDistances()) EXPECT_LT(d, minSquared) << region.name;
            continue;
        }
        ASSERT_EQ(ornament.stop, OrnamentStop::NoGrowth) << region.name;
        // No element at all, near or not, grows into any circle that is left.
        std::vector<MedialAxisEntry> left = raster.medialAxis(minSquared);
        EXPECT_FALSE(left.empty());
        for (const MedialAxisEntry &entry : left) {
            FreeCircle circle{raster.centre(entry.cell), std::sqrt(double(entry.squaredRadius)) * raster.cellSize()};
            for (size_t e = 0; e < ornament.elements.size(); ++e) {
                double gap = 1e9;
                for (int cell : ornament.elements[e].cells())
                    gap = std::min(gap, length(raster.centre(cell) - circle.centre));
                if (gap > circle.radius + settings.reach * raster.cellSize() + 1e-12) continue;
                EXPECT_FALSE(ornament.elements[e].grow(raster, circle, int(e)).success) << region.name;
            }
        }
    }
}

TEST(OrnamentGrowth, NoTwoElementsShareACellAndNoneLeavesTheRegion) {
    for (Region &region : testRegions()) {
        Ornament ornament = growOrnament(region.raster, region.roots);
        std::vector<int> claimed(size_t(region.raster.cellCount()), -1);
        for (size_t e = 0; e < ornament.elements.size(); ++e) {
            ASSERT_FALSE(ornament.elements[e].cells().empty());
            for (int cell : ornament.elements[e].cells()) {
                EXPECT_EQ(claimed[size_t(cell)], -1) << region.name << ": cell " << cell << " claimed twice";
                claimed[size_t(cell)] = int(e);
                EXPECT_EQ(region.raster.state(cell), OrnamentCell::Free) << region.name << ": on a forbidden cell";
                EXPECT_EQ(ornament.raster.owner(cell), int(e));
            }
        }
        for (int cell = 0; cell < region.raster.cellCount(); ++cell) {
            EXPECT_EQ(ornament.raster.state(cell) == OrnamentCell::Occupied, claimed[size_t(cell)] >= 0);
        }
    }
}

TEST(OrnamentGrowth, APanelUnderASillFillsWithAVine) {
    Ornament ornament = growOrnament(sillPanel(), sillRoots(sillPanel()));
    int counts[4] = {};
    for (const OrnamentElement &element : ornament.elements) ++counts[int(element.kind())];
    EXPECT_EQ(counts[int(OrnamentKind::Root)], 1);
    EXPECT_GE(counts[int(OrnamentKind::Stem)], 8);
    EXPECT_GE(counts[int(OrnamentKind::Leaf)], 10);
    EXPECT_GE(counts[int(OrnamentKind::Tendril)], 5);
    int occupied = 0;
    for (int cell = 0; cell < ornament.raster.cellCount(); ++cell) {
        occupied += ornament.raster.state(cell) == OrnamentCell::Occupied;
    }
    EXPECT_GT(occupied, ornament.raster.cellCount() * 2 / 5);  // the vine covers much of the panel
    // Every stem, leaf and tendril hangs on an earlier element.
    for (size_t e = 1; e < ornament.elements.size(); ++e) {
        EXPECT_GE(ornament.elements[e].parent(), 0);
        EXPECT_LT(ornament.elements[e].parent(), int(e));
    }
}

TEST(OrnamentGrowth, TheSameRegionGivesTheIdenticalOrnament) {
    for (int run = 0; run < 2; ++run) {
        Region a = std::move(testRegions()[size_t(run + 1)]);
        Region b = std::move(testRegions()[size_t(run + 1)]);
        Ornament first = growOrnament(a.raster, a.roots), second = growOrnament(b.raster, b.roots);
        EXPECT_EQ(first.elements, second.elements);
        EXPECT_EQ(first.stop, second.stop);
        EXPECT_EQ(ornamentHeightMap(first, 0.005).pixels, ornamentHeightMap(second, 0.005).pixels);
    }
}

TEST(OrnamentGrowth, StopsAtTheElementLimitOnAHugeRegion) {
    // 4 m × 4 m at 1 cm: 33 sill panels' worth of cells, far more than the limit of elements fills.
    OrnamentRaster huge = OrnamentRaster::fromRegion(rectangle(0, 0, 4, 4), {}, 0.01);
    std::vector<OrnamentElement> roots{OrnamentElement::rootAt(huge, {2, 2})};
    Ornament ornament = growOrnament(std::move(huge), std::move(roots));
    EXPECT_EQ(ornament.stop, OrnamentStop::ElementLimit);
    EXPECT_EQ(ornament.elements.size(), size_t(kOrnamentElementLimit));
}

TEST(OrnamentPrimitive, CountsTheThesisParametersAndReachesItsCells) {
    OrnamentRaster raster(12, 12, 1, {0, 0}, std::vector<OrnamentCell>(144, OrnamentCell::Free));
    OrnamentPrimitive bezier{PrimitiveType::Bezier, {{1, 1}, {2, 3}, {4, 3}, {5, 1}}, 0, 0, 0, 0};
    EXPECT_EQ(bezier.parameterCount(), 8);
    bezier.points.insert(bezier.points.end(), {{6, 0}, {7, 0}, {8, 1}});
    EXPECT_EQ(bezier.parameterCount(), 14);
    EXPECT_FALSE(bezier.filled());
    OrnamentPrimitive point{PrimitiveType::Point, {{3.5, 4.5}}, 0, 0, 0, 0};
    EXPECT_EQ(footprintCells(raster, point), std::vector<int>{4 * 12 + 3});  // exactly one cell
    OrnamentPrimitive line{PrimitiveType::Line, {{2.5, 6.5}, {6.5, 6.5}}, 0, 0, 0, 0};
    EXPECT_EQ(footprintCells(raster, line), (std::vector<int>{74, 75, 76, 77, 78}));  // one cell wide
    line.relief = 0.6;                                             // a tube reaching half into the rows on either side
    EXPECT_EQ(footprintCells(raster, line).size(), 3u * 7u - 4u);  // without the 4 corner cells
    OrnamentPrimitive circle{PrimitiveType::Circle, {{6, 6}}, 2.5, 0, 0, 0.1};
    std::vector<int> disc = footprintCells(raster, circle);
    for (int cell = 0; cell < 144; ++cell) {
        Vec2d low{double(cell % 12), double(cell / 12)};
        double dx = std::max({low.x - 6, 0.0, 6 - low.x - 1}), dy = std::max({low.y - 6, 0.0, 6 - low.y - 1});
        bool in = std::binary_search(disc.begin(), disc.end(), cell);
        if (std::hypot(dx, dy) < 2.4) {
            EXPECT_TRUE(in) << cell;  // the 48-gon reaches at least 2.49
        } else if (std::hypot(dx, dy) > 2.5) {
            EXPECT_FALSE(in) << cell;
        }
    }
    EXPECT_EQ(disc.size(), 32u);  // the 6 × 6 block with the 4 corners (at √2 · 2 = 2.83) left out
    OrnamentPrimitive arc{PrimitiveType::Arc, {{6, 6}}, 3, 0, kPi, 0};
    EXPECT_EQ(arc.parameterCount(), 5);
    EXPECT_NEAR(arc.path().back().x, 3, 1e-12);
}

TEST(OrnamentHeightMap, IsZeroOffTheElementsAndPositiveOnStemsAndLeaves) {
    for (Region &region : testRegions()) {
        Ornament ornament = growOrnament(region.raster, region.roots);
        const OrnamentRaster &raster = ornament.raster;
        double pixel = raster.cellSize() / 4;
        Image relief = ornamentHeightMap(ornament, pixel);
        ASSERT_EQ(relief.width, raster.width() * 4);
        ASSERT_EQ(relief.height, raster.height() * 4);
        ASSERT_EQ(relief.channels, 1);
        auto at = [&](Vec2d p) {
            int x = int(std::floor((p.x - raster.origin().x) / pixel));
            int y = relief.height - 1 - int(std::floor((p.y - raster.origin().y) / pixel));
            return *relief.at(x, y);
        };
        for (int y = 0; y < relief.height; ++y) {
            for (int x = 0; x < relief.width; ++x) {
                Vec2d centre = raster.origin() + Vec2d{(x + 0.5) * pixel, (relief.height - 1 - y + 0.5) * pixel};
                if (raster.state(raster.cellAt(centre)) != OrnamentCell::Occupied) {
                    ASSERT_EQ(*relief.at(x, y), 0.0f) << region.name << " at " << x << ", " << y;
                }
            }
        }
        int leaves = 0;
        for (const OrnamentElement &element : ornament.elements) {
            const OrnamentPrimitive &spine = element.primitives().front();
            if (element.kind() == OrnamentKind::Stem) {
                for (Vec2d p : spine.path()) EXPECT_GT(at(p), 0.0f) << region.name;
            }
            if (element.kind() == OrnamentKind::Leaf) {
                ++leaves;
                Vec2d middle = (spine.points[0] + spine.points[3]) * 0.5;  // base and tip
                EXPECT_GT(at(middle), 0.0f) << region.name;
            }
        }
        EXPECT_GT(leaves, 0) << region.name;
    }
}

TEST(OrnamentHeightMap, StemsAreHalfRoundTubes) {
    OrnamentRaster raster = OrnamentRaster::fromRegion(rectangle(0, 0, 0.2, 0.1), {}, 0.01);
    std::vector<OrnamentElement> roots{OrnamentElement::rootAlong(raster, {0.05, 0.055}, {0.15, 0.055})};
    Ornament ornament{raster, roots, OrnamentStop::Running};
    Image relief = ornamentHeightMap(ornament, 0.001);
    ASSERT_EQ(relief.width, 200);
    ASSERT_EQ(relief.height, 100);
    // Pixel column 100 (x = 0.1005); bottom index 55 is y = 0.0555, 0.5 mm off the 5 mm tube's axis.
    int row = relief.height - 1 - 55;
    EXPECT_NEAR(*relief.at(100, row), std::sqrt(0.005 * 0.005 - 0.0005 * 0.0005), 1e-8);
    EXPECT_NEAR(*relief.at(100, row + 2), std::sqrt(0.005 * 0.005 - 0.0015 * 0.0015), 1e-8);
    EXPECT_EQ(*relief.at(100, row - 5), 0.0f);  // y = 0.0605: beyond the radius
    EXPECT_EQ(*relief.at(100, row + 6), 0.0f);
    EXPECT_EQ(*relief.at(3, row), 0.0f);
}

}  // namespace
}  // namespace veduta
