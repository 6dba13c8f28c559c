#include "city/lot_checks.h"
#include "city/lot_test_blocks.h"

#include <gtest/gtest.h>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <cmath>

namespace veduta {

namespace {

using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<ExactKernel>;

double totalArea(const std::vector<ExactPolygonWithHoles> &polygons) {
    double sum = 0;
    for (const ExactPolygonWithHoles &p : polygons) {
        sum += area(p.outer_boundary());
        for (const ExactPolygon &hole : p.holes()) sum += area(hole);  // holes run clockwise
    }
    return sum;
}

}  // namespace

ExactPolygon exact(const std::vector<Vec2f> &points) {
    ExactPolygon polygon;
    for (Vec2f p : points) polygon.push_back(ExactKernel::Point_2(p.x, p.y));
    return polygon;
}

double area(const ExactPolygon &polygon) { return CGAL::to_double(polygon.area()); }

double intersectionArea(const ExactPolygon &a, const ExactPolygon &b) {
    std::vector<ExactPolygonWithHoles> parts;
    CGAL::intersection(a, b, std::back_inserter(parts));
    return totalArea(parts);
}

double unionArea(const std::vector<ExactPolygon> &polygons) {
    std::vector<ExactPolygonWithHoles> joined;
    CGAL::join(polygons.begin(), polygons.end(), std::back_inserter(joined));
    return totalArea(joined);
}

bool onStreetEdge(Vec2f a, Vec2f b, const Block &block) {
    for (size_t e = 0; e < block.points.size(); ++e) {
        Vec2f s = block.points[e], t = block.points[(e + 1) % block.points.size()];
        if (block.streetEdges[e] && distanceToSegment(a, s, t) < kLengthTolerance &&
            distanceToSegment(b, s, t) < kLengthTolerance) {
            return true;
        }
    }
    return false;
}

bool nearBlockPoint(Vec2f p, const Block &block) {
    for (Vec2f q : block.points) {
        if (std::hypot(p.x - q.x, p.y - q.y) < kLengthTolerance) return true;
    }
    return false;
}

double frontage(const Footprint &lot) {
    double length = 0;
    for (size_t e = 0; e < lot.edgeCount(); ++e) {
        if (lot.streetEdges[e]) length += lot.edgeLength(e);
    }
    return length;
}

void expectLotInside(const Footprint &lot, const ExactPolygon &outline) {
    ASSERT_GE(lot.points.size(), 3u);
    ASSERT_EQ(lot.streetEdges.size(), lot.points.size());
    ASSERT_TRUE(isSimplePolygon(lot.points));
    ASSERT_TRUE(isCounterClockwise(lot.points));
    ExactPolygon polygon = exact(lot.points);
    EXPECT_NEAR(intersectionArea(polygon, outline), area(polygon), kAreaTolerance);
}

void expectValidLots(const Block &block, const std::vector<Footprint> &lots) {
    ExactPolygon outline = exact(block.points);
    std::vector<ExactPolygon> exactLots;
    double sum = 0;
    for (size_t i = 0; i < lots.size(); ++i) {
        const Footprint &lot = lots[i];
        SCOPED_TRACE(testing::Message() << "lot " << i);
        expectLotInside(lot, outline);
        if (testing::Test::HasFatalFailure()) return;
        ExactPolygon polygon = exact(lot.points);
        bool street = false;
        for (size_t e = 0; e < lot.edgeCount(); ++e) {
            if (!lot.streetEdges[e]) continue;
            street = true;
            EXPECT_TRUE(onStreetEdge(lot.edgeStart(e), lot.edgeEnd(e), block)) << "edge " << e;
        }
        EXPECT_TRUE(street);
        sum += area(polygon);
        exactLots.push_back(polygon);
    }
    // The union is smaller than the sum by at least any pair's overlap.
    if (!exactLots.empty()) {
        EXPECT_LT(sum - unionArea(exactLots), kAreaTolerance);
    }
}

bool sameLots(const std::vector<Footprint> &a, const std::vector<Footprint> &b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].points.size() != b[i].points.size() || a[i].streetEdges != b[i].streetEdges) return false;
        for (size_t k = 0; k < a[i].points.size(); ++k) {
            if (a[i].points[k].x != b[i].points[k].x || a[i].points[k].y != b[i].points[k].y) return false;
        }
    }
    return true;
}

std::string errorOf(const std::function<void()> &call) {
    try {
        call();
    } catch (const std::runtime_error &e) {
        return e.what();
    }
    return "";
}

void expectRandomBlocksGiveValidLots(const Subdivision &subdivide) {
    size_t withLots = 0;
    for (uint32_t index = 0; index < 300; ++index) {
        Block block = randomBlock(index);
        SCOPED_TRACE(testing::Message() << "block " << index);
        try {
            std::vector<Footprint> lots = subdivide(block, LotSettings{}, 3, index);
            expectValidLots(block, lots);
            withLots += !lots.empty();
        } catch (const LotError &e) {
            EXPECT_STRNE(e.what(), "");
        }
    }
    EXPECT_GT(withLots, 200u);
}

}  // namespace veduta
