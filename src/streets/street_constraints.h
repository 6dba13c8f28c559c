// The local constraints (Goitowski 2010, §4.2.4–4.2.6, digest §2.5–2.6): where a proposed street
// from a vertex may go in the street graph: as proposed, bent to a near vertex, cut at the first
// street it meets (or led to that street's end), or not at all. docs/street-rules.md ("Local
// constraints") gives the order of the tests and the choices where the thesis is silent.
#pragma once

#include "core/vecmath.h"
#include "streets/query_result.h"
#include "streets/street_graph.h"

namespace veduta {

// The thesis' defaults (its Listings 4.6–4.9), in the rules' length unit.
struct StreetConstraints {
    float minLength = 3.0f;        // minimalDrawLength: no edge is shorter
    float minAngleDegrees = 45;    // minimalCrossingAngle: no two edges at a vertex meet closer
    float collisionOffset = 2.5f;  // how far past its end a street looks for one to meet
    float snapFraction = 0.25f;    // the snap hull's half-width, as a fraction of the length [GAP]
    float heightTolerance = 0.5f;  // points closer in height are on one level [GAP]
    float maxLength = 10000;       // longer proposals fail: the look-ups stay bounded
};

// Where the street ends.
enum class SegmentTarget {
    None,       // Failed: nothing is built
    NewVertex,  // Normal: a new street end at `end`
    Vertex,     // NN, or an intersection led to an end of the street it met: `vertex`
    EdgeSplit,  // an intersection: `edge` is cut at `end`
    Ground,     // an intersection with ground it must not cross (StreetEnvironment): a new end at `end`
};

struct SegmentPlan {
    QueryResult code = QueryResult::Failed;
    SegmentTarget target = SegmentTarget::None;
    Vec3f end;
    VertexId vertex = kNoVertex;
    EdgeId edge = UINT32_MAX;
    float length = 0;  // from the start to `end`
    // How far the street's direction was turned in the ground plane, in the rules' degrees:
    // positive to the right, as `&` turns (word_graph.h).
    float turnDegrees = 0;
};

// Where a street starts: at a vertex of the graph, or (after an `f`) at a free point.
struct SegmentStart {
    Vec3f position;
    VertexId vertex = kNoVertex;  // at `position` when there is one
};

// The plan for a street from `start` along `direction` (need not be unit) for `length`; a start
// or direction that is not finite fails (the rules' arithmetic may overflow). Pure: the graph
// is not changed.
SegmentPlan planSegment(const StreetGraph &graph, const SegmentStart &start, const Vec3f &direction, float length,
                        const StreetConstraints &constraints);

}  // namespace veduta
