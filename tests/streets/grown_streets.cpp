#include "streets/grown_streets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta::test {

std::string patternText(const std::string &name) {
    std::ifstream file(sourceFile("rules/streets/" + name + ".txt"));
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

GrownStreets::GrownStreets(const std::string &rulesText, RandomDraws &draws, const StreetEnvironment *environment) :
    rules(parseStreetRules(rulesText, "rules.txt")),
    words(rules.initialWord),
    streets(words, {}, environment),
    growth(words, rules.rules, streets.nodeQuery(), draws, &streets) {}

GrowthResult GrownStreets::grow(float radius, size_t expansions) {
    GrowthLimits limits;
    limits.maxExpansions = expansions;
    return growth.grow({{0, 0}, radius}, limits);
}

namespace {

struct Flat {
    double x, y;
};
Flat flat(const Vec3f &p) { return {p.x, p.y}; }
double cross(Flat o, Flat a, Flat b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Whether the closed segments pq and rs share a point (in the ground plane).
bool segmentsMeet(Flat p, Flat q, Flat r, Flat s) {
    double d1 = cross(p, q, r), d2 = cross(p, q, s), d3 = cross(r, s, p), d4 = cross(r, s, q);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    auto onSegment = [](Flat a, Flat b, Flat c) {
        return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
            c.y <= std::max(a.y, b.y);
    };
    return (d1 == 0 && onSegment(p, q, r)) || (d2 == 0 && onSegment(p, q, s)) || (d3 == 0 && onSegment(r, s, p)) ||
        (d4 == 0 && onSegment(r, s, q));
}

}  // namespace

void expectSoundNetwork(const StreetGraph &graph, const StreetConstraints &constraints) {
    const auto &edges = graph.edges();
    auto at = [&](VertexId v) { return graph.vertex(v).position; };
    for (EdgeId e = 0; e < edges.size(); ++e) {
        EXPECT_GE(length(at(edges[e].a) - at(edges[e].b)), constraints.minLength - 1e-4f) << "edge " << e;
        for (EdgeId f = e + 1; f < edges.size(); ++f) {
            const StreetEdge &a = edges[e], &b = edges[f];
            if (a.a == b.a || a.a == b.b || a.b == b.a || a.b == b.b) continue;
            EXPECT_FALSE(segmentsMeet(flat(at(a.a)), flat(at(a.b)), flat(at(b.a)), flat(at(b.b))))
                << "edges " << e << " and " << f << " cross";
        }
    }
    float cosMin = std::cos(radians(constraints.minAngleDegrees));
    for (VertexId v = 0; v < graph.vertices().size(); ++v) {
        const std::vector<EdgeId> &around = graph.vertex(v).edges;
        for (size_t i = 0; i < around.size(); ++i)
            for (size_t j = i + 1; j < around.size(); ++j) {
                Vec3f u = normalize(at(edges[around[i]].other(v)) - at(v));
                Vec3f w = normalize(at(edges[around[j]].other(v)) - at(v));
                EXPECT_LE(dot(u, w), cosMin + 1e-5f) << "vertex " << v;
            }
    }
}

}  // namespace veduta::test
