#include "city/start_shapes.h"

#include <algorithm>

namespace veduta {

namespace {

// The longest street edge, or the longest edge when no edge faces a street.
size_t frontEdge(const Footprint &footprint) {
    bool anyStreet =
        std::find(footprint.streetEdges.begin(), footprint.streetEdges.end(), true) != footprint.streetEdges.end();
    size_t front = footprint.edgeCount();
    for (size_t e = 0; e < footprint.edgeCount(); ++e) {
        if (anyStreet && !footprint.streetEdges[e]) continue;
        if (front == footprint.edgeCount() || footprint.edgeLength(e) > footprint.edgeLength(front)) front = e;
    }
    return front;
}

std::string edgeSymbol(const Footprint &footprint, size_t edge, size_t front, const StartShapeSettings &settings) {
    if (edge == front) return "FrontFacade";
    if (footprint.streetEdges[edge]) return "Facade";
    if (footprint.edgeLength(edge) < settings.smallFacadeWidth) return "SmallFacade";
    float cosine = dot(footprint.outwardNormal(edge), footprint.outwardNormal(front));
    return cosine <= settings.backFacadeCosine ? "BackFacade" : "SideFacade";
}

// Facade frame → world: x along the edge (the right seen from outside, since the outside lies to
// the edge's right), y up, z outward; origin at the edge's start at the footprint's base.
Transform facadeFrame(const Footprint &footprint, size_t edge) {
    Vec3f right = footprint.edgeDirection(edge), out = footprint.outwardNormal(edge);
    Vec3f origin = lift(footprint.edgeStart(edge), footprint.base);
    return {{right.x, 0, out.x, origin.x, right.y, 0, out.y, origin.y, right.z, 1, out.z, origin.z}};
}

}  // namespace

std::vector<StartShape> makeStartShapes(const Footprint &footprint, float wallHeight,
                                        const StartShapeSettings &settings) {
    size_t front = frontEdge(footprint);
    std::vector<StartShape> shapes;
    shapes.reserve(footprint.edgeCount());
    for (size_t e = 0; e < footprint.edgeCount(); ++e) {
        shapes.push_back({edgeSymbol(footprint, e, front, settings), uint32_t(e), footprint.edgeLength(e), wallHeight,
                          facadeFrame(footprint, e)});
    }
    return shapes;
}

}  // namespace veduta
