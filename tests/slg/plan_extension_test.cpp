// The floor-plan extension (digest-003 §3.1): doors, then windows, then the stairwell, by
// splitting walls and relabelling the pieces; the splits of §8.2 exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "slg/plan_extension.h"
#include "slg/thesis_levels.h"

namespace veduta {
namespace {

using enum EdgeLocation;

struct Piece {
    double length = 0;
    EdgeLocation location = Street;
};

SlgPath outlinePath(size_t corners) {
    SlgPath path;
    for (SlgNodeId n = 0; n < corners; ++n) {
        path.nodes.push_back(n);
        path.edges.push_back(n);
    }
    return path;
}

// The pieces of a path from node `from` on to node `to`, in the path's direction.
std::vector<Piece> piecesBetween(const SlgGraph &graph, const SlgPath &path, SlgNodeId from, SlgNodeId to) {
    auto start = std::ranges::find(path.nodes, from);
    EXPECT_NE(start, path.nodes.end());
    std::vector<Piece> pieces;
    for (size_t i = size_t(start - path.nodes.begin()); path.nodes[i % path.nodes.size()] != to || pieces.empty();
         ++i) {
        SlgEdgeId e = path.edges[i % path.nodes.size()];
        pieces.push_back({length(graph.along(e, path.nodes[i % path.nodes.size()])), graph.edge(e).location});
    }
    return pieces;
}

void expectPieces(const std::vector<Piece> &actual, const std::vector<Piece> &expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(actual[i].length, expected[i].length, 1e-12) << "piece " << i;
        EXPECT_EQ(actual[i].location, expected[i].location) << "piece " << i;
    }
}

WindowRule windows(double width, WindowArrangement arrangement, double spacing, double wallDistance,
                   std::optional<int> count = std::nullopt) {
    WindowRule rule;
    rule.width = width;
    rule.arrangement = arrangement;
    rule.spacing = spacing;
    rule.wallDistance = wallDistance;
    rule.count = count;
    return rule;
}

constexpr WindowArrangement kSeparated = WindowArrangement::Separated, kContiguous = WindowArrangement::Contiguous;

void expectAt(const SlgGraph &graph, SlgNodeId n, Vec2d p) {
    EXPECT_DOUBLE_EQ(graph.position(n).x, p.x) << "node " << n;
    EXPECT_DOUBLE_EQ(graph.position(n).y, p.y) << "node " << n;
}

// Each edge of a closed path joins its node and the next one.
void expectClosed(const SlgGraph &graph, const SlgPath &path) {
    ASSERT_EQ(path.nodes.size(), path.edges.size());
    for (size_t i = 0; i < path.edges.size(); ++i) {
        const SlgEdge &e = graph.edge(path.edges[i]);
        EXPECT_FALSE(e.removed);
        EXPECT_TRUE(e.touches(path.nodes[i]) && e.touches(path.nodes[(i + 1) % path.nodes.size()])) << i;
    }
}

// A rectangle w × h from the origin with the given locations, bottom edge first.
SlgGraph rectangle(double w, double h, std::vector<EdgeLocation> locations) {
    return outlineGraph({{0, 0}, {w, 0}, {w, h}, {0, h}}, locations);
}

TEST(PlanExtension, ACentredWindowOnFourMetresIsSplitAsTheThesisDoes) {
    // L1692: the 4 m edge becomes 1.5 + 2.5 m, then the 2.5 m piece 1 + 1.5 m.
    SlgGraph graph = rectangle(4, 3, {Street, NeighbourArea, NeighbourArea, NeighbourArea});
    SlgPath face = outlinePath(4);
    WindowRule one = windows(1, kSeparated, 1, 0, 1);
    WindowPlacement placed = insertWindows(graph, face, one);
    EXPECT_EQ(placed.windows, 1);
    expectPieces(piecesBetween(graph, face, 0, 1), {{1.5, Street}, {1, WindowToStreet}, {1.5, Street}});
    ASSERT_EQ(graph.nodes().size(), 6u);
    expectAt(graph, 4, {1.5, 0});      // the first split
    expectAt(graph, 5, {2.5, 0});      // then the second, in the 2.5 m rest
    EXPECT_EQ(graph.edge(0).end, 4u);  // the wall keeps its start
}

TEST(PlanExtension, TwoSeparatedWindowsOnFiveMetresLeaveOneMetreEverywhere) {
    // L1995: two 1 m windows 1 m apart and 1 m from the room's ends.
    SlgGraph graph = rectangle(5, 3, {Gap, NeighbourArea, NeighbourArea, NeighbourArea});
    SlgPath face = outlinePath(4);
    WindowRule separated = windows(1, kSeparated, 1, 1);
    EXPECT_EQ(insertWindows(graph, face, separated).windows, 2);
    expectPieces(piecesBetween(graph, face, 0, 1), {{1, Gap}, {1, WindowToGap}, {1, Gap}, {1, WindowToGap}, {1, Gap}});
    expectClosed(graph, face);
}

TEST(PlanExtension, ThreeContiguousShopWindowsOnEightMetres) {
    // L1999: three 2 m shop windows side by side with 1 m to the neighbouring walls.
    SlgGraph graph = rectangle(8, 5, {Street, NeighbourArea, Gap, NeighbourArea});
    SlgPath face = outlinePath(4);
    WindowRule shop = windows(2, kContiguous, 1, 1);
    WindowPlacement placed = insertWindows(graph, face, shop);
    expectPieces(piecesBetween(graph, face, 0, 1),
                 {{1, Street}, {2, WindowToStreet}, {2, WindowToStreet}, {2, WindowToStreet}, {1, Street}});
    // The 8 m gap at the back takes three as well; the spacing is not used when contiguous.
    expectPieces(piecesBetween(graph, face, 2, 3),
                 {{1, Gap}, {2, WindowToGap}, {2, WindowToGap}, {2, WindowToGap}, {1, Gap}});
    EXPECT_EQ(placed.windows, 6);
    EXPECT_EQ(placed.walls, 2);
}

TEST(PlanExtension, AsManyWindowsAsFitUnlessFewerAreAsked) {
    WindowRule separated = windows(1, kSeparated, 1, 1);
    EXPECT_EQ(windowsThatFit(separated, 5), 2);
    EXPECT_EQ(windowsThatFit(separated, 4.9), 1);
    EXPECT_EQ(windowsThatFit(separated, 7), 3);
    EXPECT_EQ(windowsThatFit(separated, 2.9), 0);
    EXPECT_EQ(windowsThatFit(separated, 0.5), 0);
    separated.count = 2;
    EXPECT_EQ(windowsThatFit(separated, 11), 2);
    WindowRule contiguous = windows(2, kContiguous, 5, 1);
    EXPECT_EQ(windowsThatFit(contiguous, 8), 3);
    EXPECT_EQ(windowsThatFit(contiguous, 7.9), 2);
    WindowRule single = windows(1, WindowArrangement::Single, 1, 1);
    EXPECT_EQ(windowsThatFit(single, 7), 1) << "einfach getrennt: one window a wall";
    EXPECT_EQ(windowsThatFit(single, 2.9), 0);
}

TEST(PlanExtension, FewerWindowsThanFitAreCentredAsAGroup) {
    // Three would fit on 9 m; two with their 2 m spacing make a 4 m group, 2.5 m from either end.
    SlgGraph graph = rectangle(9, 3, {Street, NeighbourArea, NeighbourArea, NeighbourArea});
    SlgPath face = outlinePath(4);
    insertWindows(graph, face, windows(1, kSeparated, 2, 0.5, 2));
    expectPieces(piecesBetween(graph, face, 0, 1),
                 {{2.5, Street}, {1, WindowToStreet}, {2, Street}, {1, WindowToStreet}, {2.5, Street}});
}

TEST(PlanExtension, WindowsOnlyOnOuterStreetAndGapWalls) {
    // An outline with a neighbour's wall, two short walls and an inner wall that is still a gap.
    SlgGraph graph =
        outlineGraph({{0, 0}, {5, 0}, {5, 3}, {0, 3}, {0, 1.5}}, {Street, Gap, NeighbourArea, Gap, Street});
    graph.addEdge(0, 2, Gap, false);
    WindowRule rule = windows(1, kSeparated, 1, 0.5);
    WindowPlacement placed = insertWindows(graph, rule);
    EXPECT_EQ(placed.walls, 4);
    EXPECT_EQ(placed.wallsTooShort, 2);  // the two 1.5 m pieces of the left side
    EXPECT_EQ(placed.windows, 3);
    SlgPath face = outlinePath(5);
    followSplits(graph, face);
    expectPieces(piecesBetween(graph, face, 0, 1),
                 {{1, Street}, {1, WindowToStreet}, {1, Street}, {1, WindowToStreet}, {1, Street}});
    expectPieces(piecesBetween(graph, face, 1, 2), {{1, Gap}, {1, WindowToGap}, {1, Gap}});
    expectPieces(piecesBetween(graph, face, 2, 0), {{5, NeighbourArea}, {1.5, Gap}, {1.5, Street}});
    EXPECT_EQ(graph.edge(5).location, Gap);  // the inner wall, whole
    EXPECT_EQ(graph.edge(5).end, 2u);
}

TEST(PlanExtension, AHouseDoorIsCentredInTheLongestWallAndTheRestStaysWall) {
    // The street walls are the right (4 m) and the top (6 m) one; the top is the longer.
    SlgGraph graph = rectangle(6, 4, {Gap, Street, Street, NeighbourArea});
    SlgPath corridor = outlinePath(4);
    DoorPlacement door = insertDoor(graph, corridor, houseDoor(1.2, 0.5, Street));
    ASSERT_EQ(door.outcome, DoorOutcome::Placed);
    EXPECT_EQ(graph.edge(door.door).location, MainEntrance);
    expectPieces(piecesBetween(graph, corridor, 2, 3), {{2.4, Street}, {1.2, MainEntrance}, {2.4, Street}});
    expectPieces(piecesBetween(graph, corridor, 1, 2), {{4, Street}});
    expectClosed(graph, corridor);
}

TEST(PlanExtension, OfEqualWallsTheFirstTakesTheDoor) {
    SlgGraph graph = rectangle(6, 4, {Street, Gap, Street, Gap});
    DoorPlacement door = insertDoor(graph, shopDoor(1, 0, DoorAlignment::Centre));
    ASSERT_EQ(door.outcome, DoorOutcome::Placed);
    EXPECT_EQ(graph.edge(door.door).location, Entrance);
    expectAt(graph, graph.edge(door.door).start, {2.5, 0});
    EXPECT_EQ(graph.edgeBetween(2, 3), 2u);  // the top wall is whole
}

TEST(PlanExtension, ShopDoorsAlignLeftOrRightSeenFromTheStreet) {
    // Seen from the street below, the bottom wall's left end is the origin; from above, the top
    // wall's left end is (6, 4).
    for (DoorAlignment alignment : {DoorAlignment::Left, DoorAlignment::Right}) {
        SlgGraph graph = rectangle(6, 4, {Street, NeighbourArea, Gap, NeighbourArea});
        SlgPath shop = outlinePath(4);
        insertDoor(graph, shop, shopDoor(1.5, 0.5, alignment));
        std::vector<Piece> left = {{0.5, Street}, {1.5, Entrance}, {4, Street}};
        std::vector<Piece> right = {{4, Street}, {1.5, Entrance}, {0.5, Street}};
        expectPieces(piecesBetween(graph, shop, 0, 1), alignment == DoorAlignment::Left ? left : right);
    }
    SlgGraph graph = rectangle(6, 4, {Gap, NeighbourArea, Street, NeighbourArea});
    SlgPath shop = outlinePath(4);
    insertDoor(graph, shop, shopDoor(1, 0, DoorAlignment::Left));
    expectPieces(piecesBetween(graph, shop, 2, 3), {{1, Entrance}, {5, Street}});
    expectAt(graph, graph.edge(2).end, {5, 4});  // one split: no margin to cut
}

// A room (0..4) and an apartment corridor (4..8), 3 m deep, that share the wall x = 4, stored
// upwards: the room's counter-clockwise path walks it upwards, the corridor's downwards.
struct RoomAndCorridor {
    SlgGraph graph;
    SlgNodeId bottom = kNoSlgId, top = kNoSlgId;  // of the shared wall
    SlgPath room, corridor;
};

RoomAndCorridor roomAndCorridor() {
    RoomAndCorridor plan;
    SlgGraph &graph = plan.graph;
    SlgNodeId a = graph.addNode({0, 0}, SlgNodeType::Corner), b = graph.addNode({4, 0}, SlgNodeType::Corner),
              c = graph.addNode({4, 3}, SlgNodeType::Corner), d = graph.addNode({0, 3}, SlgNodeType::Corner),
              e = graph.addNode({8, 0}, SlgNodeType::Corner), f = graph.addNode({8, 3}, SlgNodeType::Corner);
    SlgEdgeId wall = graph.addEdge(b, c, ApartmentCorridor, false);
    plan.room = {{a, b, c, d},
                 {graph.addEdge(a, b, Street, true), wall, graph.addEdge(c, d, NeighbourRoom, false),
                  graph.addEdge(d, a, NeighbourArea, true)}};
    plan.corridor = {{b, e, f, c},
                     {graph.addEdge(b, e, Street, true), graph.addEdge(e, f, NeighbourArea, true),
                      graph.addEdge(f, c, HouseCorridor, true), wall}};
    plan.bottom = b;
    plan.top = c;
    return plan;
}

TEST(PlanExtension, ADoorInAWallTheFaceWalksBackwardsAlignsToItsLeftAndTheNeighbourFollows) {
    RoomAndCorridor plan = roomAndCorridor();
    // Seen from the room, outside the corridor, the wall's left end is its top.
    DoorRule door{ApartmentCorridor, InnerEntrance, 1, 0.5, DoorAlignment::Left};
    ASSERT_EQ(insertDoor(plan.graph, plan.corridor, door).outcome, DoorOutcome::Placed);
    expectPieces(piecesBetween(plan.graph, plan.corridor, plan.top, plan.bottom),
                 {{0.5, ApartmentCorridor}, {1, InnerEntrance}, {1.5, ApartmentCorridor}});
    followSplits(plan.graph, plan.room);
    expectClosed(plan.graph, plan.room);
    expectPieces(piecesBetween(plan.graph, plan.room, plan.bottom, plan.top),
                 {{1.5, ApartmentCorridor}, {1, InnerEntrance}, {0.5, ApartmentCorridor}});
    EXPECT_DOUBLE_EQ(signedArea(plan.graph.polygon(plan.room)), 12);
    EXPECT_DOUBLE_EQ(signedArea(plan.graph.polygon(plan.corridor)), 12);
}

TEST(PlanExtension, AFaceFindsThePiecesOfAWallSplitFromTheOtherSide) {
    RoomAndCorridor plan = roomAndCorridor();
    DoorRule first{ApartmentCorridor, InnerEntrance, 1, 0.5, DoorAlignment::Left};
    ASSERT_EQ(insertDoor(plan.graph, plan.room, first).outcome, DoorOutcome::Placed);
    // The corridor's path still holds the wall whole; its longest piece left is the upper 1.5 m.
    DoorRule second{ApartmentCorridor, InnerEntrance, 0.5, 0, DoorAlignment::Centre};
    ASSERT_EQ(insertDoor(plan.graph, plan.corridor, second).outcome, DoorOutcome::Placed);
    expectClosed(plan.graph, plan.corridor);
    expectPieces(piecesBetween(plan.graph, plan.corridor, plan.top, plan.bottom),
                 {{0.5, ApartmentCorridor},
                  {0.5, InnerEntrance},
                  {0.5, ApartmentCorridor},
                  {1, InnerEntrance},
                  {0.5, ApartmentCorridor}});
}

TEST(PlanExtension, AWallTooShortForTheDoorIsReportedAndLeftAlone) {
    SlgGraph graph = rectangle(2, 1.5, {Street, NeighbourArea, Gap, NeighbourArea});
    EXPECT_EQ(insertDoor(graph, houseDoor(1, 0.6, Street)).outcome, DoorOutcome::WallTooShort);
    EXPECT_EQ(insertDoor(graph, apartmentDoor(1, 0)).outcome, DoorOutcome::NoWall);
    EXPECT_EQ(graph.edges().size(), 4u);
    EXPECT_EQ(graph.nodes().size(), 4u);
    DoorPlacement exact = insertDoor(graph, houseDoor(1, 0.5, Street));  // 2 m = 0.5 + 1 + 0.5
    ASSERT_EQ(exact.outcome, DoorOutcome::Placed);
    expectAt(graph, graph.edge(exact.door).start, {0.5, 0});
}

TEST(PlanExtension, DoorsGoFirstAndWindowsFillTheRestOfTheWall) {
    SlgGraph graph = rectangle(5, 3, {Street, NeighbourArea, NeighbourArea, NeighbourArea});
    SlgPath face = outlinePath(4);
    ASSERT_EQ(insertDoor(graph, face, houseDoor(1, 0.5, Street)).outcome, DoorOutcome::Placed);
    WindowPlacement placed = insertWindows(graph, face, windows(1, kSeparated, 1, 0.5));
    EXPECT_EQ(placed.walls, 2);  // the two 2 m street pieces beside the door
    EXPECT_EQ(placed.windows, 2);
    expectPieces(piecesBetween(graph, face, 0, 1),
                 {{0.5, Street},
                  {1, WindowToStreet},
                  {0.5, Street},
                  {1, MainEntrance},
                  {0.5, Street},
                  {1, WindowToStreet},
                  {0.5, Street}});
}

// An apartment 9 × 3 m in a row of rooms: the street below, the house corridor above, the
// neighbouring apartments left and right. Rooms, by their dividing walls:
//   [0, 2]     6.0 m², sides 2 and 3 (ratio 0.67)
//   [2, 4.5]   7.5 m², 2.5 and 3 (0.83)
//   [4.5, 6.8] 6.9 m², 2.3 and 3 (0.77)
//   [6.8, 9]   6.6 m², 2.2 and 3 (0.73)
Subdivision rowOfRooms() {
    const std::vector<double> walls = {0, 2, 4.5, 6.8, 9};
    Subdivision plan;
    SlgGraph &graph = plan.graph;
    std::vector<SlgNodeId> bottom, top;
    for (double x : walls) bottom.push_back(graph.addNode({x, 0}, SlgNodeType::Landmark));
    for (double x : walls) top.push_back(graph.addNode({x, 3}, SlgNodeType::Landmark));
    std::vector<SlgEdgeId> sides;
    for (size_t i = 0; i < walls.size(); ++i) {
        bool outer = i == 0 || i + 1 == walls.size();
        sides.push_back(graph.addEdge(bottom[i], top[i], outer ? NeighbourApartment : NeighbourRoom, outer));
    }
    for (size_t i = 0; i + 1 < walls.size(); ++i) {
        SlgEdgeId street = graph.addEdge(bottom[i], bottom[i + 1], Street, true);
        SlgEdgeId corridor = graph.addEdge(top[i], top[i + 1], HouseCorridor, true);
        PlanFace room;
        room.path = {{bottom[i], bottom[i + 1], top[i + 1], top[i]}, {street, sides[i + 1], corridor, sides[i]}};
        room.left = bottom[i];
        room.right = bottom[i + 1];
        plan.faces.push_back(room);
    }
    return plan;
}

TEST(PlanExtension, TheStairwellIsTheSmallestNearlySquareRoom) {
    Subdivision plan = rowOfRooms();
    std::optional<size_t> stairwell = insertStairwell(plan, 2, {});
    ASSERT_EQ(stairwell, 2u);  // [4.5, 6.8]: [6.8, 9] is smaller but too long for its width
    const SlgPath &room = plan.faces[2].path;
    expectClosed(plan.graph, room);
    // The stair door is Table 15's inner door, 1.5 m; centred in the 2.3 m wall to the house corridor.
    expectPieces(piecesBetween(plan.graph, room, room.nodes[2], room.nodes[5]),
                 {{0.4, HouseCorridor}, {1.5, InnerStairEntrance}, {0.4, HouseCorridor}});
    for (int i : {0, 1, 3}) expectClosed(plan.graph, plan.faces[size_t(i)].path);
}

TEST(PlanExtension, TheStairwellRuleDecidesWhichRoomsMayBeIt) {
    StairwellRule looser;
    looser.sideRatio = 0.7;
    Subdivision plan = rowOfRooms();
    EXPECT_EQ(insertStairwell(plan, 3, looser), 3u);
    StairwellRule larger;
    larger.minimumArea = 7;
    plan = rowOfRooms();
    EXPECT_EQ(insertStairwell(plan, 2, larger), 1u);
    StairwellRule wideDoor;
    wideDoor.door = stairDoor(2.4, 0);  // only the 2.5 m room's corridor wall takes it
    plan = rowOfRooms();
    EXPECT_EQ(insertStairwell(plan, 2, wideDoor), 1u);
    StairwellRule square;
    square.sideRatio = 0.9;
    plan = rowOfRooms();
    EXPECT_EQ(insertStairwell(plan, 2, square), std::nullopt);
    size_t edges = plan.graph.edges().size();
    EXPECT_EQ(insertStairwell(plan, 1, {}), std::nullopt);  // one storey: no stairs
    EXPECT_EQ(plan.graph.edges().size(), edges);
}

TEST(PlanExtension, DoorsInASubdividedApartmentKeepEveryFaceClosed) {
    Polygon2d outline = {{0, 0}, {12, 0}, {12, 8}, {0, 8}};
    Subdivision plan = subdivide(outline, {Street, NeighbourArea, HouseCorridor, NeighbourArea}, apartmentLevel(),
                                 PlanRandom(7, 1, RandomStream::SlgPlan));
    ASSERT_GE(plan.faces.size(), 3u);
    // Every face gets a door in its longest inner wall (still a gap: no rule has relabelled it),
    // some of them next to a wall another face's door has already split.
    int doors = 0;
    for (PlanFace &face : plan.faces) {
        DoorRule door{Gap, InnerEntrance, 0.8, 0.1, DoorAlignment::Centre};
        doors += insertDoor(plan.graph, face.path, door).outcome == DoorOutcome::Placed ? 1 : 0;
    }
    EXPECT_EQ(doors, int(plan.faces.size()));
    double area = 0;
    for (PlanFace &face : plan.faces) {
        followSplits(plan.graph, face.path);
        expectClosed(plan.graph, face.path);
        area += signedArea(plan.graph.polygon(face.path));
    }
    EXPECT_NEAR(area, 96, 1e-9);
    int doorPieces = int(std::ranges::count_if(
        plan.graph.edges(), [](const SlgEdge &e) { return !e.removed && e.location == InnerEntrance; }));
    EXPECT_EQ(doorPieces, doors);
}

}  // namespace
}  // namespace veduta
