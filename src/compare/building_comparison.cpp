#include "compare/building_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace veduta {

namespace {

// Which building each cell is of: the recorded ground plans where both scenes have them,
// else whose surface is topmost there.
const std::vector<uint32_t> &ownerOf(const HeightMap &map, bool plans) { return plans ? map.plan : map.building; }

bool hasPlan(const HeightMap &map) {
    return std::any_of(map.plan.begin(), map.plan.end(), [](uint32_t id) { return id != 0; });
}

// Each building's cells on the map, with its record's base as the floor of its volume (else
// the lowest surface it tops).
std::map<uint32_t, MeasuredBuilding> measure(const RenderScene &scene, const HeightMap &map, bool plans) {
    std::map<uint32_t, MeasuredBuilding> buildings;
    for (const BuildingRecord &record : scene.buildings) {
        MeasuredBuilding &m = buildings[record.id];
        m.id = record.id;
        m.record = record;
    }
    struct Sums {
        double cells = 0, top = 0, x = 0, y = 0;
        float lowest = std::numeric_limits<float>::infinity();
    };
    std::unordered_map<uint32_t, Sums> sums;
    const GroundGrid &g = map.grid;
    const std::vector<uint32_t> &owner = ownerOf(map, plans);
    for (int j = 0; j < g.height; ++j)
        for (int i = 0; i < g.width; ++i) {
            size_t cell = size_t(j) * size_t(g.width) + size_t(i);
            if (owner[cell] == 0) continue;
            Sums &s = sums[owner[cell]];
            s.cells += 1, s.x += i + 0.5, s.y += j + 0.5;
            if (std::isfinite(map.top[cell])) s.top += map.top[cell], s.lowest = std::min(s.lowest, map.top[cell]);
        }
    double cellArea = g.cell * g.cell;
    for (const auto &[id, s] : sums) {
        MeasuredBuilding &m = buildings[id];
        m.id = id;
        double base = m.record ? m.record->base : s.lowest;
        m.footprintArea = s.cells * cellArea;
        m.volume = std::max(0.0, (s.top - base * s.cells) * cellArea);
        m.centreX = g.x0 + s.x / s.cells * g.cell, m.centreY = g.y0 + s.y / s.cells * g.cell;
    }
    return buildings;
}

uint64_t pairKey(uint32_t a, uint32_t b) { return uint64_t(a) << 32 | b; }

// `overlap` in cells, `cellArea` the area of one.
void addFigures(BuildingPair &pair, const std::unordered_map<uint64_t, uint64_t> &overlap, double cellArea) {
    const MeasuredBuilding &a = *pair.a, &b = *pair.b;
    auto it = overlap.find(pairKey(a.id, b.id));
    // In whole cells, so that equal footprints give exactly 1.
    double both = it == overlap.end() ? 0 : double(it->second);
    double either = std::round(a.footprintArea / cellArea) + std::round(b.footprintArea / cellArea) - both;
    pair.footprintIou = either > 0 ? both / either : 0;
    if (a.record && b.record) {
        pair.eavesError = double(b.record->eaves) - double(a.record->eaves);
        pair.ridgeError = double(b.record->ridge) - double(a.record->ridge);
        if (!a.record->roof.empty() && !b.record->roof.empty()) pair.roofAgrees = a.record->roof == b.record->roof;
    }
    if (a.volume > 0) pair.volumeError = (b.volume - a.volume) / a.volume;
}

void summarise(BuildingComparison &c) {
    double iou = 0, eaves = 0, ridge = 0, volume = 0, roofs = 0;
    size_t matched = 0, heights = 0, volumes = 0, roofPairs = 0;
    for (const BuildingPair &p : c.pairs) {
        if (!p.a || !p.b) continue;
        ++matched, iou += p.footprintIou;
        if (p.eavesError) ++heights, eaves += std::abs(*p.eavesError), ridge += std::abs(*p.ridgeError);
        if (p.volumeError) ++volumes, volume += std::abs(*p.volumeError);
        if (p.roofAgrees) ++roofPairs, roofs += *p.roofAgrees;
    }
    auto mean = [](double sum, size_t n) { return n ? sum / double(n) : 0.0; };
    c.meanFootprintIou = mean(iou, matched);
    c.meanAbsEavesError = mean(eaves, heights), c.meanAbsRidgeError = mean(ridge, heights);
    c.meanAbsVolumeError = mean(volume, volumes);
    c.roofAgreement = mean(roofs, roofPairs);
}

}  // namespace

BuildingComparison compareBuildings(const RenderScene &a, const HeightMap &mapA, const RenderScene &b,
                                    const HeightMap &mapB) {
    if (mapA.grid.width != mapB.grid.width || mapA.grid.height != mapB.grid.height || mapA.grid.x0 != mapB.grid.x0 ||
        mapA.grid.y0 != mapB.grid.y0 || mapA.grid.cell != mapB.grid.cell)
        throw std::invalid_argument("compareBuildings: the height maps are of different grids");
    BuildingComparison c;
    c.groundPlans = hasPlan(mapA) && hasPlan(mapB);
    std::map<uint32_t, MeasuredBuilding> inA = measure(a, mapA, c.groundPlans), inB = measure(b, mapB, c.groundPlans);
    // Area that each pair of buildings share.
    const std::vector<uint32_t> &ownerA = ownerOf(mapA, c.groundPlans), &ownerB = ownerOf(mapB, c.groundPlans);
    std::unordered_map<uint64_t, uint64_t> overlap;
    double cellArea = mapA.grid.cell * mapA.grid.cell;
    for (size_t cell = 0; cell < ownerA.size(); ++cell)
        if (ownerA[cell] != 0 && ownerB[cell] != 0) ++overlap[pairKey(ownerA[cell], ownerB[cell])];

    std::set<uint32_t> takenB;
    for (const auto &[id, building] : inA)
        if (inB.count(id)) takenB.insert(id);
    // For each building of a without a namesake, the free building of b it shares most with.
    std::map<uint32_t, std::pair<uint32_t, uint64_t>> bestB;
    for (const auto &[key, area] : overlap) {
        auto ia = uint32_t(key >> 32), ib = uint32_t(key);
        if (inB.count(ia) || takenB.count(ib)) continue;
        auto &best = bestB[ia];
        if (area > best.second || (area == best.second && ib < best.first)) best = {ib, area};
    }
    for (const auto &[id, building] : inA) {
        BuildingPair pair;
        pair.a = building;
        if (auto it = inB.find(id); it != inB.end()) {
            pair.b = it->second, pair.matchedBy = "id";
            ++c.matchedById;
        } else if (auto best = bestB.find(id); best != bestB.end() && !takenB.count(best->second.first)) {
            pair.b = inB.at(best->second.first), pair.matchedBy = "overlap";
            takenB.insert(best->second.first);
            ++c.matchedByOverlap;
        } else {
            pair.matchedBy = "none";
            ++c.onlyA;
        }
        if (pair.b) addFigures(pair, overlap, cellArea);
        c.pairs.push_back(std::move(pair));
    }
    for (const auto &[id, building] : inB)
        if (!takenB.count(id)) {
            BuildingPair pair;
            pair.b = building, pair.matchedBy = "none";
            ++c.onlyB;
            c.pairs.push_back(std::move(pair));
        }
    summarise(c);
    return c;
}

}  // namespace veduta
