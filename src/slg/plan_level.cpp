#include "slg/plan_level.h"

#include <vector>

namespace veduta {

namespace {

struct InnerLocations {
    EdgeLocation shared, single;
};

InnerLocations innerLocations(PlanLevel level) {
    switch (level) {
    case PlanLevel::City:
    case PlanLevel::District: return {EdgeLocation::Street, EdgeLocation::Street};
    case PlanLevel::Block: return {EdgeLocation::NeighbourArea, EdgeLocation::Gap};
    case PlanLevel::Building: return {EdgeLocation::NeighbourApartment, EdgeLocation::HouseCorridor};
    default: return {EdgeLocation::NeighbourRoom, EdgeLocation::ApartmentCorridor};
    }
}

}  // namespace

void labelEdges(Subdivision &subdivision, PlanLevel level) {
    SlgGraph &graph = subdivision.graph;
    std::vector<int> faces(graph.edges().size(), 0);
    for (const PlanFace *face : subdivision.borderFaces())
        for (SlgEdgeId e : face->path.edges) ++faces[e];
    InnerLocations inner = innerLocations(level);
    bool streets = level == PlanLevel::City || level == PlanLevel::District;
    for (SlgEdgeId e = 0; e < graph.edges().size(); ++e) {
        const SlgEdge &edge = graph.edge(e);
        if (edge.removed || (edge.outer && !streets)) continue;
        graph.relabel(e, faces[e] >= 2 ? inner.shared : inner.single);
    }
}

}  // namespace veduta
