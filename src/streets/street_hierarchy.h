// Which streets of a network are main streets: the thesis' rules draw every street alike
// (Goitowski 2010 has one street width), so the hierarchy is read from the network's shape, as
// in the "natural streets" of Thomson & Richardson (1999) and Jiang et al. (2008): edges that
// continue one another straight through a vertex join into strokes, and the longest strokes,
// the roads a traveller follows furthest, are the main streets. docs/grown-city.md.
#pragma once

#include <span>
#include <vector>

#include "streets/street_blocks.h"

namespace veduta {

enum class StreetClass : uint8_t { Minor, Major };

struct StreetHierarchy {
    // Two edges at a vertex continue one another when the second turns off the first's line by
    // at most this much (Jiang et al.'s threshold of "good continuation").
    float continuationDegrees = 30;
    // The longest strokes are main streets until they hold this share of the network's length.
    float majorShare = 0.25f;
    float majorWidth = 12;  // kerb to kerb: a four-lane Hauptverkehrsstraße (RASt 06)
    float minorWidth = 7;   // a two-lane Wohnstraße with parking on one side
};

// An edge's stroke: the edges it continues into on both sides, in order along the stroke.
using Stroke = std::vector<uint32_t>;

// The strokes of a plane graph, each edge in exactly one. At every vertex the pairs of edges
// that continue one another best (the smallest turn first, ties by edge index) are joined,
// each edge at most once per end. Strokes are ordered by their first edge.
std::vector<Stroke> strokesOf(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges,
                              float continuationDegrees);

// The class of each edge: Major for the edges of the longest strokes (ties by their first
// edge) as long as those hold less than `majorShare` of the total length, Minor for the rest.
std::vector<StreetClass> classifyStreets(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges,
                                         const StreetHierarchy &hierarchy);

}  // namespace veduta
