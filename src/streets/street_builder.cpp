#include "streets/street_builder.h"

#include <algorithm>

namespace veduta {

namespace {

float lengthOf(const Word &f) { return f.parameters.empty() ? 1.0f : f.parameters[0]; }

// Closer than this, a turtle stands on a vertex (float rounding of the same moves).
constexpr float kSamePoint = 1e-3f;

}  // namespace

StreetBuilder::StreetBuilder(const WordGraph &words, const StreetConstraints &constraints,
                             const StreetEnvironment *environment, std::span<const std::vector<Vec2f>> roads) :
    words_(words), constraints_(constraints), environment_(environment) {
    vertexOf_.assign(words.size(), kNoVertex);
    cutOff_.assign(words.size(), false);
    if (words.size() == 0) return;
    // The root stands where the turtle starts; the initial word's streets are drawn from there.
    vertexOf_[0] = graph_.addVertex(Turtle{}.position);
    for (const std::vector<Vec2f> &road : roads) addRoad(road);
    for (NodeId id = 0; id < words.size(); ++id)
        if (words.node(id).word.symbol == 'F' && !cutOff_[id]) draw(kNoNode, words.node(id));
}

NodeQuery StreetBuilder::nodeQuery() {
    return [this](const WordNode &asking, char kind, std::span<float> inOut) { return query(asking, kind, inOut); };
}

QueryResult StreetBuilder::query(const WordNode &asking, char kind, std::span<float> inOut) {
    return kind == 'E' ? queryGround(asking, inOut) : queryGraph(asking, inOut);
}

// The first answer for a node stands for the whole expansion: a second rule asking gets the
// same code and the same corrected angle and length, whatever it proposed.
QueryResult StreetBuilder::queryGraph(const WordNode &asking, std::span<float> inOut) {
    for (const Answer &answer : answers_)
        if (answer.asking == asking.id && answer.graphSize == graphSize()) {
            std::ranges::copy(answer.inOut, inOut.begin());
            return answer.code;
        }
    SegmentStart start = startOf(asking.id, asking.turtle.position);
    float angle = inOut[0], length = inOut[1];
    Vec3f heading = moveTurtle(asking.turtle, Word{'&', {angle}}).heading;
    SegmentPlan plan = planSegment(graph_, start, heading, length, constraints_);
    limitByGround(start.position, plan);
    if (plan.code != QueryResult::Failed) {
        inOut[0] = angle + plan.turnDegrees;
        inOut[1] = plan.length;
    }
    Vec3f corrected = moveTurtle(asking.turtle, Word{'&', {inOut[0]}}).heading;
    answers_.push_back({asking.id, {inOut.begin(), inOut.end()}, plan.code, corrected, graphSize(), plan});
    return plan.code;
}

// The ground shortens a street to where it must stop (INTSCT), or refuses one that would stay
// shorter than minLength.
QueryResult StreetBuilder::queryGround(const WordNode &asking, std::span<float> inOut) const {
    if (!environment_) return QueryResult::Normal;
    float angle = inOut[0], length = inOut[1];
    Vec3f heading = normalize(moveTurtle(asking.turtle, Word{'&', {angle}}).heading);
    float free = environment_->freeLength(asking.turtle.position, heading, length);
    if (free >= length) return QueryResult::Normal;
    if (free < constraints_.minLength) return QueryResult::Failed;
    inOut[1] = free;
    return QueryResult::Intersection;
}

void StreetBuilder::expanded(NodeId placeholder, NodeId firstNew) {
    vertexOf_.resize(words_.size(), kNoVertex);
    cutOff_.resize(words_.size(), false);
    // Reading order: the placeholder's id holds the successor's first word.
    std::vector<NodeId> chain{placeholder};
    for (NodeId id = firstNew; id < words_.size(); ++id) chain.push_back(id);
    for (NodeId id : chain) {
        const WordNode &node = words_.node(id);
        if (node.word.symbol == 'F' && !cutOff_[id]) draw(placeholder, node);
    }
    answers_.clear();
}

bool StreetBuilder::isCutOff(NodeId id) const { return id < cutOff_.size() && cutOff_[id]; }

VertexId StreetBuilder::vertexOf(NodeId id) const { return id < vertexOf_.size() ? vertexOf_[id] : kNoVertex; }

// Where the street of `id` (or the one it asks about) starts, at `position`: on the vertex of
// the nearest draw node above when it stands there, else (after an `f`) at a free point. The
// root's own vertex counts for the root, whose F moves it on.
SegmentStart StreetBuilder::startOf(NodeId id, const Vec3f &position) const {
    const WordNode *node = &words_.node(id);
    while (!node->predecessors.empty()) {
        node = &words_.node(node->predecessors.front());
        if (words_.isDrawNode(node->id)) break;
    }
    VertexId v = vertexOf(node->id);
    if (v != kNoVertex && length(graph_.vertex(v).position - position) <= kSamePoint) return {position, v};
    return {position};
}

namespace {

constexpr float kSameRoadPoint = 1e-3f;

}  // namespace

void StreetBuilder::addRoad(std::span<const Vec2f> road) {
    VertexId previous = kNoVertex;
    for (Vec2f p : road) {
        Vec3f at{p.x, p.y, 0};
        VertexId v = kNoVertex;
        for (VertexId near : graph_.verticesNear(at, at, kSameRoadPoint))
            if (length(graph_.vertex(near).position - at) < kSameRoadPoint && graph_.vertex(near).isStatic) v = near;
        if (v == kNoVertex) v = graph_.addVertex(at, true);
        if (previous != kNoVertex && v != previous) graph_.addEdge(previous, v);
        previous = v;
    }
}

void StreetBuilder::draw(NodeId placeholder, const WordNode &f) {
    NodeId before = f.predecessors.empty() ? kNoNode : f.predecessors.front();
    SegmentStart start = startOf(f.id, before == kNoNode ? Turtle{}.position : words_.node(before).turtle.position);
    SegmentPlan plan = planFor(placeholder, start, f);
    if (plan.target == SegmentTarget::None) {
        ++counts_.refused;
        cutOff(f.id);
        return;
    }
    VertexId from = start.vertex != kNoVertex ? start.vertex : graph_.addVertex(start.position);
    switch (plan.target) {
    case SegmentTarget::NewVertex:
        // The turtle's own end, so that the words after the F stand on the vertex.
        vertexOf_[f.id] = graph_.addVertex(f.turtle.position);
        ++counts_.proposed;
        break;
    case SegmentTarget::Vertex:
        vertexOf_[f.id] = plan.vertex;
        ++counts_.snapped;
        cutOffBeyond(f.id);
        break;
    case SegmentTarget::Ground:
        vertexOf_[f.id] = graph_.addVertex(plan.end);
        ++counts_.stopped;
        cutOffBeyond(f.id);
        break;
    default:
        vertexOf_[f.id] = graph_.splitEdge(plan.edge, plan.end);
        ++counts_.split;
        cutOffBeyond(f.id);
        break;
    }
    graph_.addEdge(from, vertexOf_[f.id]);
}

SegmentPlan StreetBuilder::planFor(NodeId placeholder, const SegmentStart &start, const WordNode &f) const {
    float length = lengthOf(f.word);
    for (const Answer &answer : answers_)
        if (answer.asking == placeholder && answer.heading == f.turtle.heading && answer.inOut[1] == length &&
            answer.graphSize == graphSize())
            return answer.plan;
    SegmentPlan plan = planSegment(graph_, start, f.turtle.heading, length, constraints_);
    limitByGround(start.position, plan);
    return plan;
}

// The ground stops a street as a street met does: where it leaves less than minLength the street
// is refused, else it ends where the ground stops it, with nothing beyond.
void StreetBuilder::limitByGround(const Vec3f &from, SegmentPlan &plan) const {
    if (!environment_ || plan.target == SegmentTarget::None || plan.length <= 0) return;
    Vec3f direction = (plan.end - from) / plan.length;
    float free = environment_->freeLength(from, direction, plan.length);
    if (free >= plan.length) return;
    if (free < constraints_.minLength) {
        plan = SegmentPlan{};
        return;
    }
    plan.code = QueryResult::Intersection;
    plan.target = SegmentTarget::Ground;
    plan.end = from + direction * free;
    plan.length = free;
    plan.vertex = kNoVertex;
    plan.edge = UINT32_MAX;
}

void StreetBuilder::cutOff(NodeId id) {
    cutOff_[id] = true;
    cutOffBeyond(id);
}

// Explicit stack: a long chain must not exhaust the call stack.
void StreetBuilder::cutOffBeyond(NodeId id) {
    std::vector<NodeId> stack(words_.node(id).successors.begin(), words_.node(id).successors.end());
    while (!stack.empty()) {
        NodeId next = stack.back();
        stack.pop_back();
        cutOff_[next] = true;
        const std::vector<NodeId> &successors = words_.node(next).successors;
        stack.insert(stack.end(), successors.begin(), successors.end());
    }
}

}  // namespace veduta
