#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "city/start_shapes.h"

namespace veduta {
namespace {

// T7's building: 20 m along the street (edge 0, facing south), 12 m deep.
Footprint rectangle(std::vector<bool> streetEdges) { return {{{0, 0}, {20, 0}, {20, 12}, {0, 12}}, streetEdges, 0}; }

std::vector<std::string> symbols(const std::vector<StartShape> &shapes) {
    std::vector<std::string> names;
    for (const StartShape &s : shapes) names.push_back(s.symbol);
    return names;
}

void expectNear(Vec3f actual, Vec3f expected, const std::string &what) {
    EXPECT_NEAR(actual.x, expected.x, 1e-4f) << what;
    EXPECT_NEAR(actual.y, expected.y, 1e-4f) << what;
    EXPECT_NEAR(actual.z, expected.z, 1e-4f) << what;
}

TEST(StartShapes, RectangleOnALongStreetEdge) {
    std::vector<StartShape> shapes = makeStartShapes(rectangle({true, false, false, false}), 15);
    EXPECT_EQ(symbols(shapes), (std::vector<std::string>{"FrontFacade", "SideFacade", "BackFacade", "SideFacade"}));
    const float widths[] = {20, 12, 20, 12};
    for (uint32_t e = 0; e < 4; ++e) {
        EXPECT_EQ(shapes[e].edge, e);
        EXPECT_FLOAT_EQ(shapes[e].width, widths[e]);
        EXPECT_FLOAT_EQ(shapes[e].height, 15);
    }
}

TEST(StartShapes, EdgesNarrowerThanThreeMetresAreSmallFacades) {
    Footprint narrow{{{0, 0}, {20, 0}, {20, 2.5f}, {0, 2.5f}}, {true, false, false, false}, 0};
    EXPECT_EQ(symbols(makeStartShapes(narrow, 15)),
              (std::vector<std::string>{"FrontFacade", "SmallFacade", "BackFacade", "SmallFacade"}));
    // A 2.5 m street edge is still a street facade, and a 3 m edge is not small.
    narrow.streetEdges = {true, true, false, false};
    EXPECT_EQ(symbols(makeStartShapes(narrow, 15)),
              (std::vector<std::string>{"FrontFacade", "Facade", "BackFacade", "SmallFacade"}));
    Footprint three{{{0, 0}, {20, 0}, {20, 3}, {0, 3}}, {true, false, false, false}, 0};
    EXPECT_EQ(symbols(makeStartShapes(three, 15))[1], "SideFacade");
}

TEST(StartShapes, TheLongestStreetEdgeIsTheFront) {
    // A corner house: streets east (12 m) and north (20 m).
    EXPECT_EQ(symbols(makeStartShapes(rectangle({false, true, true, false}), 15)),
              (std::vector<std::string>{"BackFacade", "Facade", "FrontFacade", "SideFacade"}));
}

TEST(StartShapes, WithoutStreetsTheLongestEdgeIsTheFront) {
    // Edges 0 and 2 are equally long: the first wins.
    EXPECT_EQ(symbols(makeStartShapes(rectangle({false, false, false, false}), 15)),
              (std::vector<std::string>{"FrontFacade", "SideFacade", "BackFacade", "SideFacade"}));
}

TEST(StartShapes, TheBackFacesAwayFromTheFront) {
    // A corner cut off: the diagonal edge 2 faces 45° from straight away from the front
    // (cosine −0.707), a back by default and a side with a stricter threshold; the north edge
    // faces straight away (cosine −1), the east and west edges across (cosine 0).
    Footprint f{{{0, 0}, {20, 0}, {20, 12}, {8, 24}, {0, 24}}, {true, false, false, false, false}, 0};
    EXPECT_EQ(symbols(makeStartShapes(f, 15)),
              (std::vector<std::string>{"FrontFacade", "SideFacade", "BackFacade", "BackFacade", "SideFacade"}));
    EXPECT_EQ(symbols(makeStartShapes(f, 15, {3, -0.8f})),
              (std::vector<std::string>{"FrontFacade", "SideFacade", "SideFacade", "BackFacade", "SideFacade"}));
}

TEST(StartShapes, FacadeFrameStandsOnTheEdgeFacingOut) {
    Footprint f = rectangle({true, false, false, false});
    f.base = 3;
    const Vec3f outward[] = {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    for (const StartShape &s : makeStartShapes(f, 15)) {
        std::string edge = "edge " + std::to_string(s.edge);
        Vec3f left = lift(f.edgeStart(s.edge), 3), right = lift(f.edgeEnd(s.edge), 3);
        expectNear(s.facadeToWorld.applyPoint({0, 0, 0}), left, edge + ": left end");
        expectNear(s.facadeToWorld.applyPoint({s.width, 0, 0}), right, edge + ": right end");
        expectNear(s.facadeToWorld.applyPoint({0, 0, 1}), left + outward[s.edge], edge + ": one metre out");
        expectNear(s.facadeToWorld.applyPoint({0, s.height, 0}), left + Vec3f{0, 0, 15}, edge + ": up");
        EXPECT_NEAR(s.facadeToWorld.determinant(), 1, 1e-6f) << edge;
    }
}

// Seen from outside, standing in front of the wall and facing it, x runs to the right.
TEST(StartShapes, FacadeXRunsRightSeenFromOutside) {
    float angle = radians(30);
    Footprint f{{}, {true, false, false}, 0};
    for (int k = 0; k < 3; ++k) {
        float phi = angle + float(k) * 2 * kPi / 3;
        f.points.push_back({10 * std::cos(phi), 10 * std::sin(phi)});
    }
    for (const StartShape &s : makeStartShapes(f, 10)) {
        Vec3f right = s.facadeToWorld.applyVector({1, 0, 0}), out = s.facadeToWorld.applyVector({0, 0, 1});
        Vec3f facing = -out;  // the viewer looks at the wall
        Vec3f viewersRight = cross(facing, Vec3f{0, 0, 1});
        expectNear(right, viewersRight, "edge " + std::to_string(s.edge));
        Vec3f middle = s.facadeToWorld.applyPoint({s.width / 2, 0, 0});
        EXPECT_GT(dot(out, middle), 0) << "the triangle is centred on the origin, so out points away from it";
    }
}

}  // namespace
}  // namespace veduta
