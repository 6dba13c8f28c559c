// What a road, path or railway line looks like, read from its ATKIS attributes: its rank (the
// Widmung), its pavement (the Oberflächenmaterial), its lanes (the Anzahl der Fahrstreifen, or
// what its width holds) and the lines German roads of that rank are painted with (RMS, the
// Richtlinien für die Markierung von Straßen). docs/roads.md.
#pragma once

#include <string_view>
#include <vector>

#include "geo/atkis.h"

namespace veduta {

// From the most important down; Path and Rail carry no markings.
enum class RoadRank { Motorway, Federal, State, District, Municipal, Unclassified, Path, Rail };

enum class Pavement { Asphalt, Cobbles, Concrete, Gravel, Ballast };

// A line painted along the ribbon: `offset` metres left of the centre line (negative: right),
// `width` metres across. Dashed when dash > 0: `dash` metres painted, then `gap` metres not,
// repeating from the line's start.
struct MarkingLine {
    double offset = 0;
    double width = 0.12;
    double dash = 0;
    double gap = 0;
};

struct RoadStyle {
    RoadRank rank = RoadRank::Unclassified;
    Pavement pavement = Pavement::Asphalt;
    int lanes = 2;
    int tracks = 1;                  // a railway's (trackCount)
    double width = 5.5;              // metres, as ribbonWidth
    std::vector<MarkingLine> lines;  // centre, lane and edge lines; empty for paths and rails
    // Where the line ends at a junction with a road of the same or higher rank, its own
    // lines stop short and a stop line (Haltlinie) of this width crosses its approach lane.
    double stopLineWidth = 0;  // 0: none (paths, rails)
};

// The style of a road, path or rail object (landClass Road, Path or Rail).
RoadStyle roadStyle(const AtkisObject &object);

std::string_view roadRankName(RoadRank rank);      // "motorway", "federal", …
std::string_view pavementName(Pavement pavement);  // "asphalt", "cobbles", …

}  // namespace veduta
