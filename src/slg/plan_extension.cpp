#include "slg/plan_extension.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/check.h"

namespace veduta {

namespace {

// Lengths this close are equal: a wall exactly as long as its openings and margins takes them
// (5 m = 1 + 1 + 1 + 1 + 1 in any rounding), and no piece shorter than this is cut off.
constexpr double kSameLength = 1e-9;

// An edge with the end its openings are measured from.
struct Wall {
    SlgEdgeId edge = kNoSlgId;
    SlgNodeId left = kNoSlgId;
};

double wallLength(const SlgGraph &graph, const Wall &wall) { return length(graph.along(wall.edge, wall.left)); }

std::vector<Wall> graphWalls(const SlgGraph &graph) {
    std::vector<Wall> walls;
    for (SlgEdgeId e = 0; e < graph.edges().size(); ++e)
        if (!graph.edge(e).removed) walls.push_back({e, graph.edge(e).start});
    return walls;
}

std::vector<Wall> faceWalls(const SlgPath &face) {
    std::vector<Wall> walls;
    for (size_t i = 0; i < face.edges.size(); ++i) walls.push_back({face.edges[i], face.nodes[i]});
    return walls;
}

// The other of the two pieces that meet at a split node.
SlgEdgeId otherPieceAt(const SlgGraph &graph, SlgNodeId cut, SlgEdgeId piece) {
    const std::vector<SlgEdgeId> &edges = graph.node(cut).edges;
    return edges[0] == piece ? edges[1] : edges[0];
}

// Splits a wall `offset` from its left end and returns the part right of the cut.
Wall cutAt(SlgGraph &graph, const Wall &wall, double offset) {
    if (offset <= kSameLength) return wall;
    double total = wallLength(graph, wall);
    bool forward = graph.edge(wall.edge).start == wall.left;
    double t = forward ? offset / total : 1 - offset / total;
    SlgNodeId cut = graph.splitEdge(wall.edge, t, SlgNodeType::Inner);
    // A split keeps the edge's start: going forward the right part is the new piece, going
    // backward it is the edge itself.
    return {forward ? otherPieceAt(graph, cut, wall.edge) : wall.edge, cut};
}

struct Cut {
    SlgEdgeId piece = kNoSlgId;
    Wall rest;  // right of the piece; no edge when the piece reaches the wall's right end
};

// The replacement of L1692: [offset][piece of `width`][rest], by at most two splits.
Cut cutPiece(SlgGraph &graph, const Wall &wall, double offset, double width) {
    Wall fromPiece = cutAt(graph, wall, offset);
    if (wallLength(graph, fromPiece) - width <= kSameLength) return {fromPiece.edge, {}};
    Wall rest = cutAt(graph, fromPiece, width);
    // Whichever part of the split kept the edge's id, the other one is new.
    SlgEdgeId piece = rest.edge == fromPiece.edge ? otherPieceAt(graph, rest.left, rest.edge) : fromPiece.edge;
    return {piece, rest};
}

bool takesDoor(double wallLength, const DoorRule &rule) {
    return wallLength >= rule.width + 2 * rule.wallDistance - kSameLength;
}

double doorOffset(const DoorRule &rule, double length) {
    switch (rule.alignment) {
    case DoorAlignment::Left: return rule.wallDistance;
    case DoorAlignment::Right: return length - rule.wallDistance - rule.width;
    case DoorAlignment::Centre: break;
    }
    return (length - rule.width) / 2;
}

DoorPlacement placeDoor(SlgGraph &graph, const std::vector<Wall> &walls, const DoorRule &rule) {
    VEDUTA_CHECK(rule.width > 0 && rule.wallDistance >= 0, "a door has a width and no negative wall distance");
    const Wall *longest = nullptr;
    double longestLength = 0;
    for (const Wall &wall : walls) {
        if (graph.edge(wall.edge).location != rule.wall) continue;
        double l = wallLength(graph, wall);
        if (longest && l <= longestLength + kSameLength) continue;
        longest = &wall;
        longestLength = l;
    }
    if (!longest) return {DoorOutcome::NoWall};
    if (!takesDoor(longestLength, rule)) return {DoorOutcome::WallTooShort};
    SlgEdgeId door = cutPiece(graph, *longest, doorOffset(rule, longestLength), rule.width).piece;
    graph.relabel(door, rule.door);
    return {DoorOutcome::Placed, door};
}

bool takesWindows(const SlgEdge &edge) {
    return edge.outer && (edge.location == EdgeLocation::Street || edge.location == EdgeLocation::Gap);
}

EdgeLocation windowFacing(EdgeLocation wall) {
    return wall == EdgeLocation::Street ? EdgeLocation::WindowToStreet : EdgeLocation::WindowToGap;
}

double spacingOf(const WindowRule &rule) {
    return rule.arrangement == WindowArrangement::Contiguous ? 0 : rule.spacing;
}

// L2004: the first split leaves the margin, the second the window, and the rest is split again
// for the next window, a spacing on.
int placeWindowsOn(SlgGraph &graph, Wall wall, const WindowRule &rule) {
    double total = wallLength(graph, wall);
    int n = windowsThatFit(rule, total);
    if (n == 0) return 0;
    EdgeLocation window = windowFacing(graph.edge(wall.edge).location);
    double group = n * rule.width + (n - 1) * spacingOf(rule);
    double offset = (total - group) / 2;
    for (int i = 0; i < n; ++i) {
        Cut cut = cutPiece(graph, wall, offset, rule.width);
        graph.relabel(cut.piece, window);
        wall = cut.rest;
        offset = spacingOf(rule);
    }
    return n;
}

WindowPlacement placeWindows(SlgGraph &graph, const std::vector<Wall> &walls, const WindowRule &rule) {
    VEDUTA_CHECK(rule.width > 0 && rule.wallDistance >= 0 && spacingOf(rule) >= 0,
                 "windows have a width and no negative spacing or wall distance");
    WindowPlacement placement;
    for (const Wall &wall : walls) {
        if (!takesWindows(graph.edge(wall.edge))) continue;
        ++placement.walls;
        int n = placeWindowsOn(graph, wall, rule);
        placement.windows += n;
        if (n == 0) ++placement.wallsTooShort;
    }
    return placement;
}

// Sides are straight runs, not edges: the landmarks and the openings cut into a room's walls
// leave more nodes than corners on its path.
bool nearlySquare(const Polygon2d &room, double sideRatio) {
    std::vector<double> sides = straightRuns(room);
    if (sides.size() != 4) return false;
    auto [shortest, longest] = std::ranges::minmax(sides);
    return shortest >= sideRatio * longest;
}

bool hasStairDoorWall(const SlgGraph &graph, const SlgPath &room, const DoorRule &door) {
    for (const Wall &wall : faceWalls(room))
        if (graph.edge(wall.edge).location == door.wall && takesDoor(wallLength(graph, wall), door)) return true;
    return false;
}

bool mayBeStairwell(const SlgGraph &graph, const PlanFace &face, const StairwellRule &rule) {
    Polygon2d room = graph.polygon(face.path);
    return face.isBorder() && signedArea(room) >= rule.minimumArea && nearlySquare(room, rule.sideRatio) &&
        hasStairDoorWall(graph, face.path, rule.door);
}

}  // namespace

DoorRule houseDoor(double width, double wallDistance, EdgeLocation facing) {
    return {facing, EdgeLocation::MainEntrance, width, wallDistance, DoorAlignment::Centre};
}

DoorRule apartmentDoor(double width, double wallDistance) {
    return {EdgeLocation::HouseCorridor, EdgeLocation::InnerMainEntrance, width, wallDistance, DoorAlignment::Centre};
}

DoorRule roomDoor(double width, double wallDistance) {
    return {EdgeLocation::ApartmentCorridor, EdgeLocation::InnerEntrance, width, wallDistance, DoorAlignment::Centre};
}

DoorRule shopDoor(double width, double wallDistance, DoorAlignment alignment) {
    return {EdgeLocation::Street, EdgeLocation::Entrance, width, wallDistance, alignment};
}

DoorRule stairDoor(double width, double wallDistance) {
    return {EdgeLocation::HouseCorridor, EdgeLocation::InnerStairEntrance, width, wallDistance, DoorAlignment::Centre};
}

DoorPlacement insertDoor(SlgGraph &graph, const DoorRule &rule) { return placeDoor(graph, graphWalls(graph), rule); }

DoorPlacement insertDoor(SlgGraph &graph, SlgPath &face, const DoorRule &rule) {
    followSplits(graph, face);  // a wall it shares may have been split from another face
    DoorPlacement placement = placeDoor(graph, faceWalls(face), rule);
    followSplits(graph, face);
    return placement;
}

int windowsThatFit(const WindowRule &rule, double wallLength) {
    double spacing = spacingOf(rule);
    int fit = int(std::floor((wallLength - 2 * rule.wallDistance + spacing) / (rule.width + spacing) + kSameLength));
    if (rule.arrangement == WindowArrangement::Single) fit = std::min(fit, 1);
    return std::max(0, std::min(fit, rule.count.value_or(fit)));
}

WindowPlacement insertWindows(SlgGraph &graph, const WindowRule &rule) {
    return placeWindows(graph, graphWalls(graph), rule);
}

WindowPlacement insertWindows(SlgGraph &graph, SlgPath &face, const WindowRule &rule) {
    followSplits(graph, face);
    WindowPlacement placement = placeWindows(graph, faceWalls(face), rule);
    followSplits(graph, face);
    return placement;
}

std::optional<size_t> insertStairwell(Subdivision &plan, int storeys, const StairwellRule &rule) {
    if (storeys < kStairwellMinimumStoreys) return std::nullopt;
    std::optional<size_t> chosen;
    double smallest = 0;
    for (size_t i = 0; i < plan.faces.size(); ++i) {
        if (!mayBeStairwell(plan.graph, plan.faces[i], rule)) continue;
        double area = signedArea(plan.graph.polygon(plan.faces[i].path));
        if (chosen && area >= smallest) continue;
        chosen = i;
        smallest = area;
    }
    if (!chosen) return std::nullopt;
    insertDoor(plan.graph, plan.faces[*chosen].path, rule.door);
    for (PlanFace &face : plan.faces) followSplits(plan.graph, face.path);
    return chosen;
}

}  // namespace veduta
