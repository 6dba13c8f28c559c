#include "streets/tensor_streets.h"

#include <cmath>
#include <deque>
#include <optional>
#include <unordered_map>

namespace veduta {

namespace {

// The traced points of one family, bucketed by square cells for the distance tests.
class PointGrid {
  public:
    explicit PointGrid(float cell) : cell_(cell) {}

    void add(Vec2f p) { cells_[key(cellOf(p.x), cellOf(p.y))].push_back(p); }

    bool near(Vec2f p, float distance) const {
        int64_t x0 = cellOf(p.x - distance), x1 = cellOf(p.x + distance);
        int64_t y0 = cellOf(p.y - distance), y1 = cellOf(p.y + distance);
        for (int64_t x = x0; x <= x1; ++x)
            for (int64_t y = y0; y <= y1; ++y) {
                auto it = cells_.find(key(x, y));
                if (it == cells_.end()) continue;
                for (Vec2f q : it->second)
                    if (std::hypot(p.x - q.x, p.y - q.y) < distance) return true;
            }
        return false;
    }

  private:
    int64_t cellOf(float v) const { return int64_t(std::floor(v / cell_)); }
    static uint64_t key(int64_t x, int64_t y) { return (uint64_t(uint32_t(x)) << 32) | uint32_t(y); }

    float cell_;
    std::unordered_map<uint64_t, std::vector<Vec2f>> cells_;
};

Vec2f turnLeft(Vec2f d) { return {-d.y, d.x}; }
float distance(Vec2f a, Vec2f b) { return std::hypot(a.x - b.x, a.y - b.y); }
Vec3f onGround(Vec2f p) { return {p.x, p.y, 0}; }

struct Seed {
    Vec2f point;
    bool major;
};

class Tracer {
  public:
    Tracer(const TensorField &field, const GrowthWindow &window, const StreamlineSettings &settings,
           const StreetEnvironment *environment) :
        field_(field),
        window_(window),
        settings_(settings),
        environment_(environment),
        grids_{PointGrid(settings.majorSeparation), PointGrid(settings.minorSeparation)} {}

    std::vector<Streamline> trace(bool &limitReached) {
        std::vector<Streamline> lines;
        std::deque<Seed> seeds{{window_.centre, true}, {window_.centre, false}};
        while (!seeds.empty()) {
            if (lines.size() >= settings_.maxStreamlines) {
                limitReached = true;
                break;
            }
            Seed seed = seeds.front();
            seeds.pop_front();
            if (!window_.contains(onGround(seed.point)) ||
                grid(seed.major).near(seed.point, 0.9f * separation(seed.major)))
                continue;
            std::optional<Streamline> line = streamlineFrom(seed);
            if (!line) continue;
            for (Vec2f p : line->points) grid(line->major).add(p);
            addSeedsAlong(*line, seeds);
            lines.push_back(std::move(*line));
        }
        return lines;
    }

  private:
    float separation(bool major) const { return major ? settings_.majorSeparation : settings_.minorSeparation; }
    PointGrid &grid(bool major) { return grids_[major ? 0 : 1]; }

    // The family's direction at p, turned to agree with `previous`.
    std::optional<Vec2f> directionAt(Vec2f p, bool major, Vec2f previous) const {
        std::optional<Vec2f> d = field_.majorDirection(p);
        if (!d) return std::nullopt;
        Vec2f direction = major ? *d : turnLeft(*d);
        return dot(direction, previous) < 0 ? direction * -1.0f : direction;
    }

    // One half of a streamline from the seed, heading along `heading`, until it leaves the
    // window, meets its family's streets closer than half their separation, reaches a
    // degenerate point or ground it may not cross, or comes back to its seed (a ring).
    std::vector<Vec2f> half(Vec2f seed, Vec2f heading, bool major, bool &closed) {
        std::vector<Vec2f> points{seed};
        Vec2f p = seed, previous = heading;
        float h = settings_.step, travelled = 0, maxLength = 8 * window_.radius;
        while (travelled < maxLength) {
            std::optional<Vec2f> d1 = directionAt(p, major, previous);
            if (!d1) break;
            std::optional<Vec2f> d2 = directionAt(p + *d1 * (h / 2), major, *d1);
            if (!d2) break;
            Vec2f next = p + *d2 * h;
            if (travelled > 2 * separation(major) && distance(next, seed) < h) {
                points.push_back(seed);
                closed = true;
                break;
            }
            if (!window_.contains(onGround(next)) || grid(major).near(next, 0.5f * separation(major))) break;
            if (environment_) {
                float free = environment_->freeLength(onGround(p), onGround(*d2), h);
                if (free < h) {
                    if (free > 0) points.push_back(p + *d2 * free);
                    break;
                }
            }
            points.push_back(next);
            p = next, previous = *d2, travelled += h;
        }
        return points;
    }

    std::optional<Streamline> streamlineFrom(const Seed &seed) {
        std::optional<Vec2f> d = directionAt(seed.point, seed.major, {1, 0});
        if (!d) return std::nullopt;
        bool closed = false;
        std::vector<Vec2f> forward = half(seed.point, *d, seed.major, closed);
        Streamline line{{}, seed.major};
        if (!closed) {
            std::vector<Vec2f> backward = half(seed.point, *d * -1.0f, seed.major, closed);
            line.points.assign(backward.rbegin(), backward.rend() - 1);
        }
        line.points.insert(line.points.end(), forward.begin(), forward.end());
        if (float(line.points.size() - 1) * settings_.step < settings_.segment) return std::nullopt;
        return line;
    }

    // Every separation along the streamline: a seed for the other family on it (so the two
    // cross), and seeds for its own family a separation to either side.
    void addSeedsAlong(const Streamline &line, std::deque<Seed> &seeds) const {
        size_t every = std::max<size_t>(1, size_t(separation(line.major) / settings_.step));
        for (size_t i = 0; i + 1 < line.points.size(); i += every) {
            Vec2f p = line.points[i], along = line.points[i + 1] - p;
            Vec2f side = turnLeft(along * (1 / std::max(1e-6f, std::hypot(along.x, along.y))));
            seeds.push_back({p, !line.major});
            seeds.push_back({p + side * separation(line.major), line.major});
            seeds.push_back({p - side * separation(line.major), line.major});
        }
    }

    const TensorField &field_;
    GrowthWindow window_;
    StreamlineSettings settings_;
    const StreetEnvironment *environment_;
    PointGrid grids_[2];
};

// The streamline's points every `segment` metres along it, its ends kept; a last piece shorter
// than `minLength` is joined to the one before.
std::vector<Vec2f> resample(const std::vector<Vec2f> &points, float segment, float minLength) {
    std::vector<Vec2f> out{points.front()};
    float along = 0;
    for (size_t i = 1; i < points.size(); ++i) {
        along += distance(points[i - 1], points[i]);
        if (along >= segment) out.push_back(points[i]), along = 0;
    }
    if (along > 0) {
        if (along < minLength && out.size() > 1) out.back() = points.back();
        else out.push_back(points.back());
    }
    return out;
}

VertexId vertexNear(const StreetGraph &graph, Vec2f p, float within) {
    for (VertexId v : graph.verticesNear(onGround(p), onGround(p), within)) {
        const Vec3f &q = graph.vertex(v).position;
        if (std::hypot(q.x - p.x, q.y - p.y) < within) return v;
    }
    return kNoVertex;
}

// Draws a resampled streamline piece by piece through the local constraints: a piece that meets
// a street ends on it and the next goes on from there; a refused piece leaves a gap.
void draw(const std::vector<Vec2f> &points, const StreetConstraints &constraints, StreetGraph &graph,
          StreetCounts &counts) {
    VertexId from = vertexNear(graph, points.front(), constraints.minLength);
    Vec3f at = from != kNoVertex ? graph.vertex(from).position : onGround(points.front());
    for (size_t i = 1; i < points.size(); ++i) {
        Vec3f target = onGround(points[i]);
        // A piece cut short at a crossing goes on towards its target: a few times at most.
        for (int tries = 0; tries < 4; ++tries) {
            Vec3f d = target - at;
            float length = std::hypot(d.x, d.y);
            if (length < constraints.minLength) break;
            SegmentPlan plan = planSegment(graph, {at, from}, d, length, constraints);
            if (plan.target == SegmentTarget::None) {
                ++counts.refused;
                from = kNoVertex, at = target;
                break;
            }
            VertexId start = from != kNoVertex ? from : graph.addVertex(at);
            VertexId end = kNoVertex;
            switch (plan.target) {
            case SegmentTarget::NewVertex: end = graph.addVertex(plan.end), ++counts.proposed; break;
            case SegmentTarget::Vertex: end = plan.vertex, ++counts.snapped; break;
            case SegmentTarget::EdgeSplit: end = graph.splitEdge(plan.edge, plan.end), ++counts.split; break;
            default: end = graph.addVertex(plan.end), ++counts.stopped; break;
            }
            if (end != start) graph.addEdge(start, end);
            from = end, at = graph.vertex(end).position;
            if (plan.target == SegmentTarget::NewVertex) break;
        }
    }
}

// A streamline stops half a separation short of its family's next street: where a street lies
// ahead within `reach`, the dead end is led on to it (a crossing or a snap), as Chen et al.
// join their dangling streets. Dead ends with nothing ahead stay as they are.
void joinDeadEnds(float reach, const StreetConstraints &constraints, StreetGraph &graph, StreetCounts &counts) {
    size_t vertices = graph.vertices().size();
    for (VertexId v = 0; v < vertices; ++v) {
        if (graph.vertex(v).edges.size() != 1) continue;
        const Vec3f &at = graph.vertex(v).position;
        Vec3f heading = at - graph.vertex(graph.edge(graph.vertex(v).edges.front()).other(v)).position;
        if (std::hypot(heading.x, heading.y) == 0) continue;
        SegmentPlan plan = planSegment(graph, {at, v}, heading, reach, constraints);
        if (plan.target == SegmentTarget::Vertex && plan.vertex != v) {
            graph.addEdge(v, plan.vertex);
            ++counts.snapped;
        } else if (plan.target == SegmentTarget::EdgeSplit) {
            graph.addEdge(v, graph.splitEdge(plan.edge, plan.end));
            ++counts.split;
        }
    }
}

}  // namespace

TracedStreets traceStreets(const TensorField &field, const GrowthWindow &window, const StreamlineSettings &settings,
                           const StreetConstraints &constraints, const StreetEnvironment *environment) {
    TracedStreets traced;
    traced.streamlines = Tracer(field, window, settings, environment).trace(traced.limitReached);
    for (const Streamline &line : traced.streamlines)
        draw(resample(line.points, settings.segment, constraints.minLength), constraints, traced.graph, traced.counts);
    joinDeadEnds(0.6f * settings.majorSeparation, constraints, traced.graph, traced.counts);
    return traced;
}

}  // namespace veduta
