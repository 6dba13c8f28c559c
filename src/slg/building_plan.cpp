#include "slg/building_plan.h"

#include <algorithm>

#include "core/hash.h"
#include "slg/plan_level.h"

namespace veduta {

namespace {

// The plans below a building each hash their level and index with the building's identity.
enum PlanTag : uint32_t { kStoreyPlan = 0x53545259u, kApartmentPlan = 0x41505254u };  // "STRY", "APRT"

PlanRandom planRandom(uint32_t seed, uint32_t identity, PlanTag level, uint32_t index) {
    return PlanRandom(seed, hashValues({identity, uint32_t(level), index}), RandomStream::SlgPlan);
}

bool touches(const SlgGraph &graph, SlgNodeId n, EdgeLocation location) {
    for (SlgEdgeId e : graph.node(n).edges)
        if (graph.edge(e).outer && graph.edge(e).location == location) return true;
    return false;
}

// Where a door goes: of the landmarks on outer edges of the location, the one nearest the middle
// of those edges (their length-weighted mean); of all landmarks, the one nearest the middle of
// the outline when none lies on such an edge.
SlgNodeId doorLandmark(const Subdivision &s, EdgeLocation location) {
    Vec2d middle;
    double total = 0;
    for (const SlgEdge &edge : s.graph.edges()) {
        if (edge.removed || !edge.outer || edge.location != location) continue;
        double weight = length(s.graph.position(edge.end) - s.graph.position(edge.start));
        middle = middle + (s.graph.position(edge.start) + s.graph.position(edge.end)) * (weight / 2);
        total += weight;
    }
    bool anywhere =
        total == 0 || std::ranges::none_of(s.landmarks, [&](SlgNodeId l) { return touches(s.graph, l, location); });
    middle = anywhere ? vertexMean(s.outline) : middle * (1 / total);
    SlgNodeId best = kNoSlgId;
    for (SlgNodeId l : s.landmarks) {
        if (!anywhere && !touches(s.graph, l, location)) continue;
        if (best == kNoSlgId || length(s.graph.position(l) - middle) < length(s.graph.position(best) - middle))
            best = l;
    }
    return best;
}

PlanLosses lossesOf(const Subdivision &s) { return {s.deletedFaces, s.truncatedSearches, 0, 0}; }

PlanLosses lossesOf(const CorridorPlan &plan) { return {0, 0, plan.unreached, plan.tooSmall}; }

// A face of a level subdivided, its faces moved back for the corridor from the door at a landmark
// on its edges of `doorLocation`; a face the rules give fewer than two landmarks stays whole
// (L1228). The subdivision stays for the floor-plan extension: its border faces come first and
// in the order of `faces`, so an index into its faces is one into these.
struct LevelFaces {
    std::vector<PlanShape> faces;
    Vec2d door;
    Subdivision subdivision;
};

LevelFaces planLevel(const PlanShape &outline, PlanLevel level, const PlanParameters &parameters,
                     const CorridorParameters &corridor, EdgeLocation doorLocation, const PlanRandom &random,
                     const SearchLimits &limits, PlanLosses &losses) {
    Subdivision s = subdivide(outline.points, outline.locations, parameters, random, limits);
    labelEdges(s, level);
    losses += lossesOf(s);
    if (s.borderFaces().empty()) return {{outline}, vertexMean(outline.points), std::move(s)};
    SlgNodeId door = doorLandmark(s, doorLocation);
    CorridorPlan plan = makeCorridor(s, door, corridor);
    losses += lossesOf(plan);
    Vec2d entrance = s.graph.position(door);  // before s moves into the result
    return {std::move(plan.faces), entrance, std::move(s)};
}

// The building's stairwell: of the rooms each apartment's rule allows, the smallest (the first
// of equal ones), as insertStairwell compares them, before the corridor took its strips.
struct StairwellChoice {
    size_t apartment = 0, room = 0;
    double area = 0;
};

void offerStairwell(Subdivision &rooms, size_t apartment, int storeys, const StairwellRule &rule,
                    std::optional<StairwellChoice> &best) {
    // The stair door it cuts into the subdivision goes no further: the plan keeps no inner doors.
    std::optional<size_t> room = insertStairwell(rooms, storeys, rule);
    if (!room) return;
    double area = signedArea(rooms.graph.polygon(rooms.faces[*room].path));
    if (best && area >= best->area) return;
    best = StairwellChoice{apartment, *room, area};
}

// The storey's plan of a building whose footprint is placed: apartments round the house
// corridor from the entrance, rooms round each apartment's corridor, as deep as `depth`.
void planStoreys(BuildingPlan &plan, const BuildingPlanParameters &p, uint32_t seed, uint32_t identity,
                 PlanDepth depth) {
    plan.storeys = p.storeys;
    if (depth == PlanDepth::Footprint) return;
    CorridorParameters house{CorridorKind::House, p.houseCorridorWidth, p.doorWidth};
    EdgeLocation entranceSide = p.entranceAtRear ? EdgeLocation::Gap : EdgeLocation::Street;
    LevelFaces storey = planLevel(plan.placement.footprint, PlanLevel::Building, p.storey, house, entranceSide,
                                  planRandom(seed, identity, kStoreyPlan, 0), p.limits, plan.losses);
    plan.storey.entrance = storey.door;
    if (depth == PlanDepth::Entrance) return;

    CorridorParameters inner{CorridorKind::Apartment, p.apartmentCorridorWidth, p.doorWidth};
    std::optional<StairwellChoice> stairwell;
    for (size_t i = 0; i < storey.faces.size(); ++i) {
        // A storey of one apartment has no house corridor: its door is the house door.
        EdgeLocation doorSide = storey.faces.size() > 1 ? EdgeLocation::HouseCorridor : entranceSide;
        LevelFaces rooms = planLevel(storey.faces[i], PlanLevel::Apartment, p.apartment, inner, doorSide,
                                     planRandom(seed, identity, kApartmentPlan, uint32_t(i)), p.limits, plan.losses);
        offerStairwell(rooms.subdivision, i, p.storeys, p.stairwell, stairwell);
        plan.storey.apartments.push_back({std::move(storey.faces[i]), std::move(rooms.faces), rooms.door, {}});
    }
    if (stairwell) plan.storey.apartments[stairwell->apartment].stairwell = stairwell->room;
}

}  // namespace

PlanLosses &PlanLosses::operator+=(const PlanLosses &o) {
    deletedFaces += o.deletedFaces;
    truncatedSearches += o.truncatedSearches;
    unreached += o.unreached;
    tooSmall += o.tooSmall;
    return *this;
}

std::optional<BuildingPlan> planBuilding(const PlanShape &lot, const FaceSides &sides, const BuildingPlanParameters &p,
                                         uint32_t seed, uint32_t identity, PlanDepth depth) {
    auto sidewalk = cutFrontStrip(lot, sides, p.sidewalkWidth, EdgeLocation::Street);
    if (!sidewalk || !sidewalk->behind) return std::nullopt;
    auto placement = placeBuilding(*sidewalk->behind, sidewalk->behindSides, p.placement,
                                   PlanRandom(seed, identity, RandomStream::SlgParameters));
    if (!placement) return std::nullopt;

    BuildingPlan plan;
    plan.sidewalk = std::move(sidewalk->quads);
    plan.placement = std::move(*placement);
    planStoreys(plan, p, seed, identity, depth);
    return plan;
}

BuildingPlan planInFootprint(const PlanShape &footprint, const FaceSides &sides, const BuildingPlanParameters &p,
                             uint32_t seed, uint32_t identity, PlanDepth depth) {
    BuildingPlan plan;
    plan.placement.footprint = footprint;
    plan.placement.sides = sides;
    planStoreys(plan, p, seed, identity, depth);
    return plan;
}

}  // namespace veduta
