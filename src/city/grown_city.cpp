#include "city/grown_city.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/hash.h"
#include "streets/street_blocks.h"
#include "streets/word_graph.h"

namespace veduta {

namespace {

bool onTheGround(const Vec3f &p, const StreetConstraints &constraints) {
    return std::abs(p.z) <= constraints.heightTolerance;
}

// Streets of the ground level as a plane graph; the indices are the street graph's vertex ids.
std::vector<PlanarEdge> groundEdges(const StreetGraph &graph, const StreetConstraints &constraints,
                                    size_t &otherLevel) {
    std::vector<PlanarEdge> edges;
    for (const StreetEdge &e : graph.edges()) {
        if (onTheGround(graph.vertex(e.a).position, constraints) &&
            onTheGround(graph.vertex(e.b).position, constraints))
            edges.emplace_back(e.a, e.b);
        else ++otherLevel;
    }
    return edges;
}

CityData cityOf(const std::vector<PlanarPoint> &points, const std::vector<PlanarEdge> &edges,
                const std::vector<StreetClass> &classes, const StreetHierarchy &hierarchy) {
    CityData city;
    city.streetWidth = hierarchy.minorWidth;
    for (VertexId v = 0; v < points.size(); ++v) city.points.push_back({v, points[v].x, points[v].y, 0, {}});
    for (size_t i = 0; i < edges.size(); ++i) {
        std::optional<float> width;
        if (classes[i] == StreetClass::Major) width = hierarchy.majorWidth;
        city.streets.push_back({uint32_t(i), edges[i].first, edges[i].second, width, {}});
    }
    return city;
}

// The city of a street graph in the rules' frame: its ground level's streets, classified, and
// its blocks, moved to the growth's centre. Fills the report's graph, block and street counts.
CityData cityOfGraph(const StreetGraph &graph, const CityGrowth &growth, std::vector<std::string> &warnings,
                     CityGrowthReport &r) {
    std::vector<PlanarEdge> edges = groundEdges(graph, growth.constraints, r.otherLevelStreets);
    std::vector<PlanarPoint> points;
    // Moved in float, as the blocks' outlines are kept: a point and the block corners on it agree.
    for (const StreetVertex &v : graph.vertices())
        points.push_back({v.position.x + growth.centre.x, v.position.y + growth.centre.y});
    BlockResult found = blocksByArrangement(points, edges);
    std::vector<StreetClass> classes = classifyStreets(points, edges, growth.hierarchy);
    r.majorStreets = size_t(std::count(classes.begin(), classes.end(), StreetClass::Major));
    CityData city = cityOf(points, edges, classes, growth.hierarchy);
    for (const StreetBlock &face : found.blocks) {
        if (!face.holes.empty()) {
            ++r.blocksWithStreetsInside;
            continue;
        }
        CityBlock block;
        for (uint32_t v : face.boundary) block.points.push_back({float(points[v].x), float(points[v].y)});
        // The block's vertex ids are its identity: the same seed grows the same ids.
        block.sourceId = hashSequence(face.boundary);
        city.blocks.push_back(std::move(block));
    }
    r.blocks = city.blocks.size();
    if (r.blocksWithStreetsInside > 0)
        warnings.push_back(
            fmt::format("{} blocks with streets inside them were left without lots", r.blocksWithStreetsInside));
    if (found.nonSimpleFaces + found.invalidFaces > 0)
        warnings.push_back(fmt::format("{} faces of the street graph were no simple polygon and were left without lots",
                                       found.nonSimpleFaces + found.invalidFaces));
    if (r.otherLevelStreets > 0)
        warnings.push_back(
            fmt::format("{} streets above or below the ground level were left out", r.otherLevelStreets));
    r.graph = graph;
    return city;
}

}  // namespace

CityData growCity(const StreetRuleSet &rules, const CityGrowth &growth, std::vector<std::string> &warnings,
                  CityGrowthReport *report) {
    CityGrowthReport local;
    CityGrowthReport &r = report ? *report : local;
    SeededDraws draws(growth.seed);
    WordGraph words(rules.initialWord);
    StreetBuilder streets(words, growth.constraints, growth.environment, growth.roads);
    StreetGrowth grower(words, rules.rules, streets.nodeQuery(), draws, &streets);
    r.growth = grower.grow({{0, 0}, growth.radius}, growth.limits);
    r.streets = streets.counts();
    warnings.insert(warnings.end(), grower.warnings().begin(), grower.warnings().end());
    if (r.growth.stop != GrowthStop::Exhausted)
        warnings.push_back(
            fmt::format("the street growth stopped at a limit after {} expansions, with {} "
                        "placeholders left: the town is smaller than its window",
                        r.growth.expansions, grower.pendingCount()));
    return cityOfGraph(streets.graph(), growth, warnings, r);
}

CityData traceCity(const TensorField &field, const StreamlineSettings &settings, const CityGrowth &growth,
                   std::vector<std::string> &warnings, CityGrowthReport *report) {
    CityGrowthReport local;
    CityGrowthReport &r = report ? *report : local;
    TracedStreets traced =
        traceStreets(field, {{0, 0}, growth.radius}, settings, growth.constraints, growth.environment);
    r.streets = traced.counts;
    r.streamlines = traced.streamlines.size();
    if (traced.limitReached)
        warnings.push_back(
            fmt::format("the tracing stopped at its limit of {} streamlines: the town is smaller "
                        "than its window",
                        settings.maxStreamlines));
    return cityOfGraph(traced.graph, growth, warnings, r);
}

}  // namespace veduta
