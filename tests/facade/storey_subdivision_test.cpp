#include "facade/storey_subdivision.h"

#include <gtest/gtest.h>

#include <string>

#include "core/polygon_area.h"
#include "facade/plan_features.h"

namespace veduta {
namespace {

// Fig. 4.17 mirrored into counter-clockwise order (floor_plan.h): the pentagon p1..p5 of Fig. 4.1
// with q1 on e4, q2 on e1, q3 on e5, q4 on e3; the segments q2-q1 and q3-q4 cross in q5.
const std::vector<Vec2d> kPentagon = {{0, 0}, {1, 3}, {-2, 5}, {-5, 3}, {-4, 0}};
const Vec2d p1{0, 0}, p2{1, 3}, p3{-2, 5}, p4{-5, 3}, p5{-4, 0};
const Vec2d q1{-4.5, 1.5}, q2{0.5, 1.5}, q3{-2, 0}, q4{-3.5, 4}, q5{-2.5625, 1.5};

StoreySubdivision figure417() {
    return subdivideModule(kPentagon, {{3, 0.5}, {0, 0.5}, {4, 0.5}, {2, 0.5}}, {{1, 0}, {2, 3}}, {});
}

// Whether some cell has exactly these vertices (in any order), each within 1e-9.
bool hasCell(const std::vector<std::vector<Vec2d>> &cells, const std::vector<Vec2d> &expected) {
    for (const std::vector<Vec2d> &cell : cells) {
        if (cell.size() != expected.size()) continue;
        bool all = true;
        for (Vec2d e : expected) {
            bool found = false;
            for (Vec2d v : cell) found = found || length(v - e) < 1e-9;
            all = all && found;
        }
        if (all) return true;
    }
    return false;
}

void expectPolyline(const std::vector<Vec2d> &actual, const std::vector<Vec2d> &expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(actual[i].x, expected[i].x, 1e-9) << i;
        EXPECT_NEAR(actual[i].y, expected[i].y, 1e-9) << i;
    }
}

TEST(StoreySubdivision, PentagonSplitsIntoTheFourCellsOfFigure417) {
    StoreySubdivision s = figure417();
    ASSERT_EQ(s.cells.size(), 4u);
    EXPECT_TRUE(hasCell(s.cells, {p1, q3, q5, q2}));
    EXPECT_TRUE(hasCell(s.cells, {q3, p5, q1, q5}));
    EXPECT_TRUE(hasCell(s.cells, {q5, q1, p4, q4}));
    EXPECT_TRUE(hasCell(s.cells, {q2, q5, q4, p3, p2}));
    double total = 0;
    for (const auto &cell : s.cells) {
        EXPECT_GT(signedArea(cell), 0);
        total += signedArea(cell);
    }
    EXPECT_NEAR(total, signedArea(kPentagon), 1e-9);
}

TEST(StoreySubdivision, PentagonHasNineCandidateModules) {
    // L886: at most nine; 4 cells, 4 pairs across a segment, the whole; the triples are L-shaped.
    StoreySubdivision s = figure417();
    EXPECT_EQ(s.candidates.size(), 9u);
    int singles = 0, pairs = 0, whole = 0;
    for (const auto &c : s.candidates) {
        singles += c.size() == 1;
        pairs += c.size() == 2;
        whole += c.size() == 4;
    }
    EXPECT_EQ(singles, 4);
    EXPECT_EQ(pairs, 4);
    EXPECT_EQ(whole, 1);
    std::vector<Vec2d> all = candidateOutline(s, s.candidates.back());
    EXPECT_NEAR(signedArea(all), signedArea(kPentagon), 1e-9);
    EXPECT_EQ(all.size(), 5u);
}

TEST(StoreySubdivision, BadSubdivisionsAreRejected) {
    FileLoc loc{"house.txt", 4, 2};
    auto errorOf = [&](const std::vector<SubdivisionPoint> &points, const std::vector<std::pair<int, int>> &segments) {
        try {
            subdivideModule(kPentagon, points, segments, loc);
        } catch (const InputError &e) {
            return std::string(e.what());
        }
        return std::string();
    };
    try {
        subdivideModule({{0, 0}, {0, 1}, {1, 0}}, {}, {}, loc);
        ADD_FAILURE() << "a clockwise module was subdivided";
    } catch (const InputError &e) {
        EXPECT_EQ(std::string(e.what()),
                  "house.txt:4:2: the subdivided module is not a convex counter-clockwise polygon");
    }
    EXPECT_EQ(errorOf({{5, 0.5}}, {}), "house.txt:4:2: subdivision point 0: the module has no edge 5");
    EXPECT_EQ(errorOf({{0, 1.0}}, {}), "house.txt:4:2: subdivision point 0: t = 1 is outside [0, 1)");
    EXPECT_EQ(errorOf({{0, 0.2}, {0, 0.6}}, {{0, 1}}),
              "house.txt:4:2: subdivision segment 0: it runs along the module's edge");
    // A fan of segments from one vertex through many edge points makes more cells than allowed.
    std::vector<SubdivisionPoint> fan = {{0, 0}};
    std::vector<std::pair<int, int>> spokes;
    for (int i = 1; i <= 20; ++i) {
        fan.push_back({2, i / 21.0});
        spokes.push_back({0, i});
    }
    EXPECT_EQ(errorOf(fan, spokes), "house.txt:4:2: the subdivision makes more than 16 cells");
}

TEST(StoreySubdivision, RepeatedStoreyHasIdenticalFeatures) {
    FloorPlanModule square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "", 0.3, 3, "", {}};
    FloorPlan storey({{kPentagon, "", 0.4, 3, "", {}}, square}, {{false, 0, 4, 1, 1, 0.25, 0.75, {}}}, {});
    FloorPlan repeated = repeatStorey(storey);
    std::vector<Feature> a = planFeatures(storey), b = planFeatures(repeated);
    ASSERT_EQ(a.size(), b.size());
    for (size_t f = 0; f < a.size(); ++f) {
        EXPECT_EQ(a[f].module, b[f].module);
        ASSERT_EQ(a[f].edges.size(), b[f].edges.size());
        for (size_t e = 0; e < a[f].edges.size(); ++e) {
            EXPECT_EQ(a[f].edges[e].element, b[f].edges[e].element);
            EXPECT_EQ(a[f].edges[e].t0, b[f].edges[e].t0);
            EXPECT_EQ(a[f].edges[e].t1, b[f].edges[e].t1);
            EXPECT_EQ(a[f].edges[e].from, b[f].edges[e].from);
            EXPECT_EQ(a[f].edges[e].to, b[f].edges[e].to);
        }
    }
}

TEST(StoreySubdivision, StoreyFeaturesOfFigure419) {
    // The upper storey is the cell fpm' = {q2, q5, q4, p3, p2} on the pentagon.
    StoreySubdivision s = figure417();
    int top = -1;
    for (size_t c = 0; c < s.candidates.size(); ++c)
        if (s.candidates[c].size() == 1 && hasCell({s.cells[s.candidates[c][0]]}, {q2, q5, q4, p3, p2}))
            top = static_cast<int>(c);
    ASSERT_GE(top, 0);
    FloorPlan lower({{kPentagon, "", 0.4, 3, "", {}}}, {}, {});
    FloorPlan upper({{candidateOutline(s, s.candidates[top]), "", 0.4, 3, "", {}}}, {}, {});
    StoreyFeatures f = storeyFeatures(lower, upper);
    // Def 4.8: q2, p1, p5, p4, q4 (counter-clockwise: from q4 to q2).
    ASSERT_EQ(f.freeOuterEdges.size(), 1u);
    expectPolyline(f.freeOuterEdges[0], {q4, p4, p5, p1, q2});
    // Def 4.9: q4, q5, q2.
    ASSERT_EQ(f.innerEdges.size(), 1u);
    expectPolyline(f.innerEdges[0], {q2, q5, q4});
    // Def 4.11: the upper outline's part on the lower one.
    ASSERT_EQ(f.seams.size(), 1u);
    expectPolyline(f.seams[0], {q2, p2, p3, q4});
    EXPECT_TRUE(f.externalConnections.empty());
}

TEST(StoreySubdivision, DockOutsideTheLowerStoreyIsAnExternalConnection) {
    // Def 4.10, Fig. 4.20: on the cell {p1, q3, q5, q2}, fpm' docks inside (the cell above it)
    // and fpm'' outside, on the edge (q3, p1) that lies on e5.
    StoreySubdivision s = figure417();
    std::vector<Vec2d> corner, above;
    for (const auto &c : s.candidates) {
        if (c.size() != 1) continue;
        if (hasCell({s.cells[c[0]]}, {p1, q3, q5, q2})) corner = candidateOutline(s, c);
        if (hasCell({s.cells[c[0]]}, {q2, q5, q4, p3, p2})) above = candidateOutline(s, c);
    }
    ASSERT_FALSE(corner.empty());
    ASSERT_FALSE(above.empty());
    auto edgeFrom = [](const std::vector<Vec2d> &ring, Vec2d from) {
        for (size_t i = 0; i < ring.size(); ++i)
            if (length(ring[i] - from) < 1e-12) return static_cast<int>(i);
        return -1;
    };
    FloorPlanModule square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "", 0.3, 3, "", {}};
    FloorPlan lower({{kPentagon, "", 0.4, 3, "", {}}}, {}, {});
    FloorPlan upper({{corner, "", 0.4, 3, "", {}}, {above, "", 0.4, 3, "", {}}, square},
                    {{false, 0, edgeFrom(corner, q2), 1, edgeFrom(above, q5), 0, 1, {}},
                     {false, 0, edgeFrom(corner, q3), 2, 0, 0.25, 0.75, {}}},
                    {});
    StoreyFeatures f = storeyFeatures(lower, upper);
    EXPECT_EQ(f.internalConnections, std::vector<int>{0});
    EXPECT_EQ(f.externalConnections, std::vector<int>{1});
}

}  // namespace
}  // namespace veduta
