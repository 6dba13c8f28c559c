#include "slg/subdivision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "core/check.h"
#include "slg/landmarks.h"

namespace veduta {

namespace {

// Points closer than this (relative to the outline's size) are one node; lengths this much over
// a limit still keep it (rounding, not design).
constexpr double kSameRelative = 1e-9;

struct Ray {
    SlgNodeId landmark = kNoSlgId;
    Vec2d origin, direction;
    double reach = 0;  // to its first hit on the outline
    std::vector<std::pair<double, SlgNodeId>> hits;
};

double outlineSize(const Polygon2d &outline) {
    double size = 0;
    for (Vec2d p : outline) size = std::max({size, std::abs(p.x - outline[0].x), std::abs(p.y - outline[0].y)});
    return size;
}

double firstExit(const Polygon2d &outline, Vec2d origin, Vec2d direction, double tolerance) {
    double reach = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < outline.size(); ++i) {
        Vec2d a = outline[i], b = outline[(i + 1) % outline.size()];
        auto hit = intersectLines(origin, direction, a, b - a);
        if (hit && hit->s > tolerance && hit->t >= 0 && hit->t <= 1) reach = std::min(reach, hit->s);
    }
    return reach;
}

// Whether the segment between two points of the outline runs inside it.
bool staysInside(const Polygon2d &outline, Vec2d a, Vec2d b) {
    if (sideOf(outline, (a + b) * 0.5) != Side::Inside) return false;
    for (size_t i = 0; i < outline.size(); ++i) {
        Vec2d p = outline[i], q = outline[(i + 1) % outline.size()];
        auto hit = intersectLines(a, b - a, p, q - p);
        if (hit && hit->s > 1e-9 && hit->s < 1 - 1e-9 && hit->t > 1e-9 && hit->t < 1 - 1e-9) return false;
    }
    return true;
}

// Two landmarks on opposite sides whose rays cross no other ray (a storey's two apartments, a
// narrow lot's front and back) would leave no inner edge, and neither face a path: the thesis's
// reconstruction makes nothing there. A ray that leaves the outline near such a landmark whose
// ray points back at it, within kChordTurn, is joined to it by a chord instead.
void joinOppositeRays(SlgGraph &graph, const Polygon2d &outline, const std::vector<Ray> &rays) {
    constexpr double kChordTurn = 10;  // degrees
    double tangent = std::tan(kChordTurn * std::numbers::pi / 180);
    for (const Ray &ray : rays) {
        if (!ray.hits.empty() || !std::isfinite(ray.reach)) continue;
        Vec2d exit = ray.origin + ray.direction * ray.reach;
        for (const Ray &other : rays) {
            if (&other == &ray || !other.hits.empty() || graph.edgeBetween(ray.landmark, other.landmark) != kNoSlgId)
                continue;
            bool facing = angle180(ray.direction, other.direction) > 180 - kChordTurn;
            if (facing && length(other.origin - exit) <= tangent * ray.reach &&
                staysInside(outline, ray.origin, other.origin))
                graph.addEdge(ray.landmark, other.landmark, EdgeLocation::Gap, false);
        }
    }
}

// The rays of §2.6 and the inner network: a node where two rays cross inside the outline, an
// inner edge between consecutive nodes along each ray.
void buildInnerNetwork(SlgGraph &graph, const Polygon2d &outline, const std::vector<SlgNodeId> &landmarks,
                       double same) {
    std::vector<Ray> rays;
    for (SlgNodeId l : landmarks) {
        Ray ray;
        ray.landmark = l;
        ray.origin = graph.position(l);
        ray.direction = graph.node(l).ray;
        ray.reach = firstExit(outline, ray.origin, ray.direction, same);
        rays.push_back(ray);
    }
    for (size_t i = 0; i < rays.size(); ++i) {
        for (size_t j = i + 1; j < rays.size(); ++j) {
            auto hit = intersectLines(rays[i].origin, rays[i].direction, rays[j].origin, rays[j].direction);
            if (!hit || hit->s <= same || hit->s >= rays[i].reach - same || hit->t <= same ||
                hit->t >= rays[j].reach - same)
                continue;
            Vec2d p = rays[i].origin + rays[i].direction * hit->s;
            // Three rays through one point meet at one node: it is already on ray i or ray j.
            SlgNodeId node = kNoSlgId;
            for (const Ray *ray : {&rays[i], &rays[j]})
                for (auto [s, n] : ray->hits)
                    if (length(graph.position(n) - p) <= same) node = n;
            if (node == kNoSlgId) node = graph.addNode(p, SlgNodeType::Inner);
            for (auto [ray, s] : {std::pair{&rays[i], hit->s}, std::pair{&rays[j], hit->t}})
                if (std::ranges::none_of(ray->hits, [&](auto h) { return h.second == node; }))
                    ray->hits.emplace_back(s, node);
        }
    }
    joinOppositeRays(graph, outline, rays);
    for (Ray &ray : rays) {
        std::ranges::sort(ray.hits);
        SlgNodeId from = ray.landmark;
        for (auto [s, n] : ray.hits) {
            if (graph.edgeBetween(from, n) == kNoSlgId) graph.addEdge(from, n, EdgeLocation::Gap, false);
            from = n;
        }
    }
}

// The outline from node `from` counter-clockwise to node `to`, a face's seed; from a node to
// itself, the whole outline (the closing node not repeated).
SlgPath outlineBetween(const SlgGraph &graph, SlgNodeId from, SlgNodeId to) {
    SlgPath path;
    SlgNodeId n = from;
    do {
        auto e = std::ranges::find_if(graph.node(n).edges,
                                      [&](SlgEdgeId id) { return graph.edge(id).outer && graph.edge(id).start == n; });
        VEDUTA_CHECK(e != graph.node(n).edges.end(), "the outline is a closed loop");
        path.nodes.push_back(n);
        path.edges.push_back(*e);
        n = graph.edge(*e).end;
    } while (n != to);
    if (from != to) path.nodes.push_back(to);
    return path;
}

// Listing 2: the depth-first search from the face's right landmark back to its left one, over
// inner edges, under the prunings of eq 9–11 and length_max.
class PathSearch {
  public:
    PathSearch(const SlgGraph &graph, const PlanParameters &parameters, const SearchLimits &limits, double same) :
        graph_(graph),
        limits_(limits),
        same_(same),
        maximumRun_(lengthLimits(parameters).maximum),
        parameters_(parameters) {}

    // The closed candidate paths of the face from `left` to `right`; `truncated` when the limits
    // stopped the search.
    std::vector<SlgPath> run(SlgNodeId left, SlgNodeId right, bool &truncated) {
        left_ = left;
        frontStart_ = graph_.position(left);
        Vec2d front = graph_.position(right) - frontStart_;
        frontLength_ = length(front);
        frontAxis_ = front * (1 / frontLength_);
        path_ = outlineBetween(graph_, left, right);
        reflexLimit_ = reflexLimit(parameters_, graph_.pathType(path_));
        visited_.assign(graph_.nodes().size(), false);
        for (SlgNodeId n : path_.nodes) visited_[n] = true;
        found_.clear();
        steps_ = 0;
        truncated_ = false;
        SlgEdgeId into = path_.edges.back();
        Vec2d incoming = graph_.along(into, graph_.edge(into).start);
        extend(right, incoming, 0, 0);
        truncated = truncated_;
        return std::move(found_);
    }

  private:
    // Whether turning from `incoming` to `outgoing` at a node is allowed (eq 9); `straight`
    // says it went straight on, `reflex` that it turned right (eq 11 counts those).
    bool turnAllowed(Vec2d before, Vec2d at, Vec2d after, bool &straight, bool &reflex) const {
        straight = goesStraightOn(before, at, after);
        reflex = !straight && turnAt(before, at, after) == Turn::Right;
        if (straight) return true;
        double angle = angle180(at - before, after - at);
        return angle > limits_.minimumTurn && angle < limits_.maximumTurn;
    }

    bool betweenLandmarks(Vec2d p) const {
        double x = dot(p - frontStart_, frontAxis_);
        return x >= -same_ && x <= frontLength_ + same_;
    }

    void extend(SlgNodeId at, Vec2d incoming, double run, int reflexes) {
        if (++steps_ > limits_.maximumSteps || int(found_.size()) >= limits_.maximumPaths) {
            truncated_ = true;
            return;
        }
        Vec2d here = graph_.position(at);
        for (SlgEdgeId e : graph_.node(at).edges) {
            const SlgEdge &edge = graph_.edge(e);
            SlgNodeId next = edge.other(at);
            if (edge.outer || (visited_[next] && next != left_)) continue;
            Vec2d there = graph_.position(next);
            bool straight = false, reflex = false;
            if (!turnAllowed(here - incoming, here, there, straight, reflex) || !betweenLandmarks(there)) continue;
            int nextReflexes = reflexes + (reflex && graph_.node(at).type != SlgNodeType::Landmark ? 1 : 0);
            double nextRun = (straight ? run : 0) + length(there - here);
            if (nextReflexes > reflexLimit_ || nextRun > maximumRun_ * (1 + 1e-9)) continue;
            path_.edges.push_back(e);
            if (next == left_) {
                if (closes(there - here)) found_.push_back(path_);
            } else {
                path_.nodes.push_back(next);
                visited_[next] = true;
                extend(next, there - here, nextRun, nextReflexes);
                visited_[next] = false;
                path_.nodes.pop_back();
            }
            path_.edges.pop_back();
        }
    }

    // The turn at the left landmark, from the last inner edge onto the front, must be allowed
    // too.
    bool closes(Vec2d incoming) const {
        Vec2d at = graph_.position(left_);
        Vec2d onto = graph_.position(path_.nodes[1]);
        bool straight = false, reflex = false;
        return turnAllowed(at - incoming, at, onto, straight, reflex) && !straight;
    }

    const SlgGraph &graph_;
    const SearchLimits &limits_;
    double same_, maximumRun_;
    const PlanParameters &parameters_;
    SlgNodeId left_ = kNoSlgId;
    Vec2d frontStart_, frontAxis_;
    double frontLength_ = 0;
    int reflexLimit_ = 0;
    SlgPath path_;
    std::vector<bool> visited_;
    std::vector<SlgPath> found_;
    int steps_ = 0;
    bool truncated_ = false;
};

std::vector<Vec2d> edgeMidpoints(const Polygon2d &polygon) {
    std::vector<Vec2d> midpoints;
    for (size_t i = 0; i < polygon.size(); ++i)
        midpoints.push_back((polygon[i] + polygon[(i + 1) % polygon.size()]) * 0.5);
    return midpoints;
}

struct Candidate {
    SlgPath path;
    Polygon2d polygon;
    std::vector<Vec2d> midpoints;
    std::vector<SlgEdgeId> sortedEdges;  // to tell the same cycle
    double score = 0;
};

// Whether an edge of face a that face b does not share runs inside b. A shared edge lies on b's
// boundary by construction; its midpoint, rounded, can fall a hair inside.
bool runsInside(const Candidate &a, const Candidate &b) {
    for (size_t i = 0; i < a.midpoints.size(); ++i)
        if (!std::ranges::binary_search(b.sortedEdges, a.path.edges[i]) &&
            sideOf(b.polygon, a.midpoints[i]) == Side::Inside)
            return true;
    return false;
}

// Faces are cycles of one plane graph, so their insides meet exactly when an edge of one runs
// inside the other, or when they are the same cycle.
bool overlaps(const Candidate &a, const Candidate &b) {
    return a.sortedEdges == b.sortedEdges || runsInside(a, b) || runsInside(b, a);
}

// The soft criteria of L1294–1313 as one number, smaller is better: how far the corners are
// from four right angles, and how far the area is from the outline's over the faces' (eq 12).
double softScore(const Polygon2d &polygon, double targetArea) {
    double cornerError = 0;
    int corners = 0;
    size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        Vec2d before = polygon[(i + n - 1) % n], at = polygon[i], after = polygon[(i + 1) % n];
        if (goesStraightOn(before, at, after)) continue;
        ++corners;
        cornerError += std::abs(angle180(at - before, after - at) - 90) / 90;
    }
    return cornerError + std::abs(corners - 4) + std::abs(signedArea(polygon) / targetArea - 1);
}

// The half-edge walk of the graph of the outline and the selected faces: each bounded face of
// it that is not a selected face is an inner face (§2.2 step 6).
std::vector<SlgPath> innerFaces(const SlgGraph &graph, const std::vector<PlanFace> &selected) {
    std::vector<bool> used(graph.edges().size(), false);
    for (SlgEdgeId e = 0; e < graph.edges().size(); ++e) used[e] = graph.edge(e).outer && !graph.edge(e).removed;
    for (const PlanFace &face : selected)
        for (SlgEdgeId e : face.path.edges) used[e] = true;
    std::set<std::set<SlgEdgeId>> taken;
    for (const PlanFace &face : selected) taken.insert({face.path.edges.begin(), face.path.edges.end()});

    // At each node, the used edges sorted counter-clockwise by direction.
    std::vector<std::vector<SlgEdgeId>> around(graph.nodes().size());
    for (SlgNodeId n = 0; n < graph.nodes().size(); ++n) {
        for (SlgEdgeId e : graph.node(n).edges)
            if (used[e]) around[n].push_back(e);
        std::ranges::sort(around[n], [&](SlgEdgeId a, SlgEdgeId b) {
            Vec2d u = graph.along(a, n), v = graph.along(b, n);
            return std::atan2(u.y, u.x) < std::atan2(v.y, v.x);
        });
    }
    // Half-edge (e, from): e walked from `from`. The face on its left continues at the other
    // node with the edge next clockwise from e there.
    std::set<std::pair<SlgEdgeId, SlgNodeId>> walked;
    std::vector<SlgPath> faces;
    for (SlgEdgeId first = 0; first < graph.edges().size(); ++first) {
        if (!used[first]) continue;
        for (SlgNodeId firstFrom : {graph.edge(first).start, graph.edge(first).end}) {
            if (walked.count({first, firstFrom})) continue;
            SlgPath path;
            SlgEdgeId e = first;
            SlgNodeId from = firstFrom;
            while (walked.insert({e, from}).second) {
                path.nodes.push_back(from);
                path.edges.push_back(e);
                SlgNodeId at = graph.edge(e).other(from);
                const std::vector<SlgEdgeId> &ring = around[at];
                size_t i = std::ranges::find(ring, e) - ring.begin();
                e = ring[(i + ring.size() - 1) % ring.size()];
                from = at;
            }
            if (signedArea(graph.polygon(path)) <= 0) continue;  // the outside
            if (taken.count({path.edges.begin(), path.edges.end()})) continue;
            faces.push_back(std::move(path));
        }
    }
    return faces;
}

// What the selection leaves between two neighbouring landmarks whose pair it dropped (L1313):
// where a face of the graph runs along the outline from one landmark to the next and has no
// other landmark, it is the face the pair lacked — a plan keeps the apartment or the room
// rather than a hole of corridor — with its front from the first. Other faces stay inner.
PlanFace asBorderFace(const SlgGraph &graph, SlgPath path) {
    std::vector<size_t> at;
    for (size_t i = 0; i < path.nodes.size(); ++i)
        if (graph.node(path.nodes[i]).type == SlgNodeType::Landmark) at.push_back(i);
    if (at.size() != 2) return PlanFace{std::move(path)};
    size_t n = path.nodes.size();
    for (auto [from, to] : {std::pair{at[0], at[1]}, std::pair{at[1], at[0]}}) {
        bool alongOutline = true;
        for (size_t i = from; i != to && alongOutline; i = (i + 1) % n) alongOutline = graph.edge(path.edges[i]).outer;
        bool behind = false;
        for (size_t i = to; i != from && !behind; i = (i + 1) % n) behind = graph.edge(path.edges[i]).outer;
        if (!alongOutline || behind) continue;
        std::rotate(path.nodes.begin(), path.nodes.begin() + long(from), path.nodes.end());
        std::rotate(path.edges.begin(), path.edges.begin() + long(from), path.edges.end());
        SlgNodeId left = path.nodes[0], right = path.nodes[(to + n - from) % n];
        return PlanFace{std::move(path), left, right};
    }
    return PlanFace{std::move(path)};
}

void removeUnusedInnerEdges(SlgGraph &graph, const std::vector<PlanFace> &faces) {
    std::vector<bool> used(graph.edges().size(), false);
    for (const PlanFace &face : faces)
        for (SlgEdgeId e : face.path.edges) used[e] = true;
    for (SlgEdgeId e = 0; e < graph.edges().size(); ++e)
        if (!graph.edge(e).outer && !used[e]) graph.removeEdge(e);
}

}  // namespace

std::vector<const PlanFace *> Subdivision::borderFaces() const {
    std::vector<const PlanFace *> border;
    for (const PlanFace &face : faces)
        if (face.isBorder()) border.push_back(&face);
    return border;
}

Subdivision subdivide(const Polygon2d &outline, const std::vector<EdgeLocation> &locations,
                      const PlanParameters &parameters, const PlanRandom &random, const SearchLimits &limits) {
    Subdivision result;
    result.outline = outline;
    result.graph = outlineGraph(outline, locations);
    SlgGraph &graph = result.graph;
    result.landmarks = placeLandmarks(graph, parameters, random);
    if (result.landmarks.empty()) {
        result.faces.push_back(PlanFace{outlineBetween(graph, 0, 0)});
        return result;
    }
    double same = kSameRelative * std::max(outlineSize(outline), 1.0);
    buildInnerNetwork(graph, outline, result.landmarks, same);

    double targetArea = signedArea(outline) / double(result.landmarks.size());
    double shortest = lengthLimits(parameters).minimum * (1 - 1e-9);
    PathSearch search(graph, parameters, limits, same);
    std::vector<Candidate> chosen;
    size_t count = result.landmarks.size();
    for (size_t i = 0; i < count; ++i) {
        SlgNodeId left = result.landmarks[i], right = result.landmarks[(i + 1) % count];
        bool truncated = false;
        std::vector<SlgPath> paths = search.run(left, right, truncated);
        result.truncatedSearches += truncated ? 1 : 0;
        std::vector<Candidate> candidates;
        for (SlgPath &path : paths) {
            Candidate c;
            c.path = std::move(path);
            c.polygon = graph.polygon(c.path);
            std::vector<double> runs = straightRuns(c.polygon);
            if (runs.size() < 3 || *std::ranges::min_element(runs) < shortest) continue;  // hard criterion 2
            c.midpoints = edgeMidpoints(c.polygon);
            c.sortedEdges = c.path.edges;
            std::ranges::sort(c.sortedEdges);
            c.score = softScore(c.polygon, targetArea);
            candidates.push_back(std::move(c));
        }
        // The search's order breaks ties, so the choice is the same on every run.
        std::ranges::stable_sort(candidates, {}, &Candidate::score);
        auto best = std::ranges::find_if(candidates, [&](const Candidate &c) {
            return std::ranges::none_of(chosen, [&](const Candidate &o) { return overlaps(c, o); });  // hard 1
        });
        if (best == candidates.end()) {
            ++result.deletedFaces;
            continue;
        }
        result.faces.push_back(PlanFace{best->path, left, right});
        chosen.push_back(std::move(*best));
    }
    std::vector<PlanFace> inner;
    for (SlgPath &path : innerFaces(graph, result.faces)) {
        PlanFace face = asBorderFace(graph, std::move(path));
        if (face.isBorder()) {
            --result.deletedFaces;
            ++result.keptLeftovers;
        }
        (face.isBorder() ? result.faces : inner).push_back(std::move(face));
    }
    std::ranges::stable_sort(result.faces, {}, [&](const PlanFace &f) {
        return std::ranges::find(result.landmarks, f.left) - result.landmarks.begin();
    });
    std::ranges::move(inner, std::back_inserter(result.faces));
    removeUnusedInnerEdges(graph, result.faces);
    return result;
}

PlanShape faceShape(const Subdivision &subdivision, const PlanFace &face) {
    PlanShape shape{subdivision.graph.polygon(face.path), {}};
    for (SlgEdgeId e : face.path.edges) shape.locations.push_back(subdivision.graph.edge(e).location);
    return shape;
}

size_t frontEdges(const PlanFace &face) {
    if (!face.isBorder()) return 0;
    return std::ranges::find(face.path.nodes, face.right) - face.path.nodes.begin();
}

std::vector<Polygon2d> facePolygons(const Subdivision &subdivision) {
    std::vector<Polygon2d> polygons;
    for (const PlanFace &face : subdivision.faces) polygons.push_back(subdivision.graph.polygon(face.path));
    return polygons;
}

std::vector<double> straightRuns(const Polygon2d &polygon) {
    size_t n = polygon.size();
    std::vector<size_t> corners;
    for (size_t i = 0; i < n; ++i)
        if (!goesStraightOn(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n])) corners.push_back(i);
    std::vector<double> runs;
    for (size_t c = 0; c < corners.size(); ++c) {
        double run = 0;
        for (size_t i = corners[c]; i != corners[(c + 1) % corners.size()]; i = (i + 1) % n)
            run += length(polygon[(i + 1) % n] - polygon[i]);
        runs.push_back(run);
    }
    return runs;
}

}  // namespace veduta
