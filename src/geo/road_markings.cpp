#include "geo/road_markings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "geo/mesh_normals.h"

namespace veduta {

namespace {

// A ribbon read back from drapeRibbon's layout: per cross-section a left and a right vertex
// at one height, pieces of two triangles between cross-sections.
class Ribbon {
  public:
    explicit Ribbon(const Mesh &mesh) : mesh_(mesh) {
        size_t n = mesh.vertexCount() / 2;
        if (n < 2 || mesh.vertexCount() != 2 * n || mesh.triangleCount() != 2 * (n - 1)) return;
        for (size_t i = 0; i < n; ++i) {
            Vec2d left = plan(2 * i), right = plan(2 * i + 1);
            centre_.push_back((left + right) * 0.5);
            across_.push_back((left - right) * 0.5);
            along_.push_back(i == 0 ? 0 : along_.back() + veduta::length(centre_[i] - centre_[i - 1]));
            low_ = {std::min(low_.x, centre_[i].x), std::min(low_.y, centre_[i].y)};
            high_ = {std::max(high_.x, centre_[i].x), std::max(high_.y, centre_[i].y)};
        }
    }

    // Whether p lies within `reach` of the centre line's bounding box: a cheap test before the
    // exact distance, so that a landscape's thousands of roads meet in far less than R² · n.
    bool near(Vec2d p, double reach) const {
        return p.x >= low_.x - reach && p.x <= high_.x + reach && p.y >= low_.y - reach && p.y <= high_.y + reach;
    }

    size_t stations() const { return centre_.size(); }
    double length() const { return along_.empty() ? 0 : along_.back(); }
    double along(size_t i) const { return along_[i]; }
    Vec2d centre(size_t i) const { return centre_[i]; }

    // The point of piece i at fraction t along it and k half widths left of the centre.
    Vec2d at(size_t i, double t, double k) const {
        Vec2d a = centre_[i] + across_[i] * k, b = centre_[i + 1] + across_[i + 1] * k;
        return a + (b - a) * t;
    }

    // The piece and fraction at distance s along the centre line.
    std::pair<size_t, double> pieceAt(double s) const {
        size_t i = size_t(std::upper_bound(along_.begin(), along_.end(), s) - along_.begin());
        i = std::clamp<size_t>(i, 1, along_.size() - 1) - 1;
        double span = along_[i + 1] - along_[i];
        return {i, span > 0 ? std::clamp((s - along_[i]) / span, 0.0, 1.0) : 0.0};
    }

    // Where the line k half widths left of the centre crosses piece i's diagonal (right
    // corner at i to left corner at i + 1), as a fraction of the piece, if inside it.
    std::optional<double> diagonalCrossing(size_t i, double k) const {
        Vec2d from = centre_[i] - across_[i], diagonal = centre_[i + 1] + across_[i + 1] - from;
        Vec2d a = at(i, 0, k), b = at(i, 1, k) - a;
        double denominator = cross(b, diagonal);
        if (std::abs(denominator) < 1e-12) return std::nullopt;
        double t = -cross(a - from, diagonal) / denominator;
        if (!(t > 0 && t < 1)) return std::nullopt;
        return t;
    }

    // The height of piece i's surface at p: the plane of whichever of its two triangles
    // holds p (the one it lies least outside of, against rounding).
    double heightAt(size_t i, Vec2d p) const {
        double best = -std::numeric_limits<double>::infinity(), height = 0;
        for (size_t t = 2 * i; t < 2 * i + 2; ++t) {
            const uint32_t *v = &mesh_.indices[3 * t];
            Vec2d a = plan(v[0]), b = plan(v[1]), c = plan(v[2]);
            double area = cross(b - a, c - a);
            if (area == 0) continue;
            double wb = cross(p - a, c - a) / area, wc = cross(b - a, p - a) / area, wa = 1 - wb - wc;
            double inside = std::min({wa, wb, wc});
            if (inside > best) {
                best = inside;
                height = wa * mesh_.positions[v[0]].z + wb * mesh_.positions[v[1]].z + wc * mesh_.positions[v[2]].z;
            }
        }
        return height;
    }

  private:
    Vec2d plan(size_t v) const { return {mesh_.positions[v].x, mesh_.positions[v].y}; }

    const Mesh &mesh_;
    std::vector<Vec2d> centre_, across_;
    std::vector<double> along_;
    Vec2d low_{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2d high_{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
};

// The nearest point of a ribbon's centre line to p: its distance along and away.
struct Nearest {
    double along = 0, distance = std::numeric_limits<double>::infinity();
    Vec2d direction;
};

Nearest nearestOnCentre(const Ribbon &r, Vec2d p) {
    Nearest best;
    for (size_t i = 0; i + 1 < r.stations(); ++i) {
        Vec2d a = r.centre(i), d = r.centre(i + 1) - a;
        double span = dot(d, d);
        double t = span > 0 ? std::clamp(dot(p - a, d) / span, 0.0, 1.0) : 0.0;
        double distance = length(a + d * t - p);
        if (distance < best.distance) best = {r.along(i) + t * (r.along(i + 1) - r.along(i)), distance, d};
    }
    return best;
}

struct Interval {
    double from = 0, to = 0;
};

// What happens at one end of a road.
struct RoadEnd {
    double cut = 0;  // metres of the end its lines leave unpainted
    bool stopLine = false;
};

struct RoadPlan {
    RoadEnd ends[2];                    // at the start, at the end
    std::vector<Interval> openings[2];  // stretches of the left (0) and right (1) edge lines left open
};

bool moreImportant(RoadRank a, RoadRank b) { return int(a) < int(b); }

// The junctions: every end of every road against every other road's centre line.
std::vector<RoadPlan> planJunctions(std::span<const MarkedRoad> roads, const std::vector<Ribbon> &ribbons,
                                    const MarkingOptions &options) {
    std::vector<RoadPlan> plans(roads.size());
    for (size_t r = 0; r < roads.size(); ++r) {
        const Ribbon &ribbon = ribbons[r];
        if (ribbon.stations() < 2) continue;
        for (int end = 0; end < 2; ++end) {
            Vec2d p = ribbon.centre(end == 0 ? 0 : ribbon.stations() - 1);
            double widest = 0;
            int meetings = 0, continuations = 0;
            bool stop = false;
            for (size_t q = 0; q < roads.size(); ++q) {
                if (q == r || ribbons[q].stations() < 2 || !ribbons[q].near(p, options.junctionTolerance)) continue;
                Nearest n = nearestOnCentre(ribbons[q], p);
                if (n.distance > options.junctionTolerance) continue;
                ++meetings;
                widest = std::max(widest, roads[q].style.width / 2);
                bool interior =
                    n.along > options.junctionTolerance && n.along < ribbons[q].length() - options.junctionTolerance;
                RoadRank mine = roads[r].style.rank, theirs = roads[q].style.rank;
                if (!interior && !moreImportant(theirs, mine) && !moreImportant(mine, theirs)) ++continuations;
                if (interior ? !moreImportant(mine, theirs) : moreImportant(theirs, mine)) stop = true;
                if (interior) {
                    // The side of q this road comes from, judged a little way into it.
                    double into = std::min(ribbon.length(), roads[q].style.width / 2 + 2.0);
                    auto [i, t] = ribbon.pieceAt(end == 0 ? into : ribbon.length() - into);
                    double side = cross(n.direction, ribbon.at(i, t, 0) - p);
                    double half = roads[r].style.width / 2 + 1.0;
                    plans[q].openings[side > 0 ? 0 : 1].push_back({n.along - half, n.along + half});
                }
            }
            if (meetings == 0 || (meetings == 1 && continuations == 1)) continue;
            RoadEnd &e = plans[r].ends[end];
            e.cut = widest + options.stopLineSetback;
            e.stopLine = stop && roads[r].style.stopLineWidth > 0;
        }
    }
    return plans;
}

// The painted stretches of a line: its dashes within [from, to], less the openings.
std::vector<Interval> paintedStretches(const MarkingLine &line, double from, double to,
                                       const std::vector<Interval> &openings) {
    std::vector<Interval> dashes;
    if (line.dash > 0) {
        double period = line.dash + line.gap;
        for (double start = std::floor(from / period) * period; start < to; start += period)
            dashes.push_back({std::max(start, from), std::min(start + line.dash, to)});
    } else {
        dashes.push_back({from, to});
    }
    std::vector<Interval> painted;
    for (Interval d : dashes) {
        std::vector<Interval> pieces{d};
        for (const Interval &o : openings) {
            std::vector<Interval> next;
            for (Interval p : pieces) {
                if (o.to <= p.from || o.from >= p.to) {
                    next.push_back(p);
                    continue;
                }
                if (o.from > p.from) next.push_back({p.from, o.from});
                if (o.to < p.to) next.push_back({o.to, p.to});
            }
            pieces = std::move(next);
        }
        for (Interval p : pieces) {
            if (p.to - p.from > 1e-3) painted.push_back(p);
        }
    }
    return painted;
}

// One painted strip between k0 and k1 half widths left of the centre over [s0, s1] of the
// centre line, with a cross-section wherever the ribbon has one or its diagonal meets an edge
// of the strip, each vertex `lift` above the ribbon's triangle under it.
void paintStrip(const Ribbon &ribbon, double k0, double k1, Interval stretch, double lift, Mesh &out) {
    struct Section {
        size_t piece;
        double t;
    };
    std::vector<Section> sections;
    auto [firstPiece, firstT] = ribbon.pieceAt(stretch.from);
    auto [lastPiece, lastT] = ribbon.pieceAt(stretch.to);
    for (size_t i = firstPiece; i <= lastPiece; ++i) {
        double lo = i == firstPiece ? firstT : 0, hi = i == lastPiece ? lastT : 1;
        sections.push_back({i, lo});
        std::vector<double> crossings;
        for (double k : {k0, k1}) {
            if (std::optional<double> t = ribbon.diagonalCrossing(i, k); t && *t > lo && *t < hi)
                crossings.push_back(*t);
        }
        std::sort(crossings.begin(), crossings.end());
        for (double t : crossings) sections.push_back({i, t});
        if (i == lastPiece && hi > lo) sections.push_back({i, hi});
    }
    uint32_t first = uint32_t(out.positions.size());
    for (const Section &s : sections) {
        for (double k : {k0, k1}) {
            Vec2d p = ribbon.at(s.piece, s.t, k);
            out.positions.push_back({float(p.x), float(p.y), float(ribbon.heightAt(s.piece, p) + lift)});
        }
    }
    for (uint32_t j = 0; j + 1 < sections.size(); ++j) {
        uint32_t a0 = first + 2 * j, a1 = a0 + 1, b0 = a0 + 2, b1 = a0 + 3;
        out.indices.insert(out.indices.end(), {a0, b0, b1, a0, b1, a1});
    }
}

void paintRoad(const MarkedRoad &road, const Ribbon &ribbon, const RoadPlan &plan, const MarkingOptions &options,
               Mesh &out) {
    double half = road.style.width / 2;
    const RoadEnd &start = plan.ends[0], &end = plan.ends[1];
    double stop = road.style.stopLineWidth;
    double from = start.cut + (start.stopLine ? stop : 0), to = ribbon.length() - end.cut - (end.stopLine ? stop : 0);
    for (const MarkingLine &line : road.style.lines) {
        // Openings are made in the edge lines alone: the outermost line of each side.
        bool edge = std::abs(line.offset) > half - 0.5;
        const std::vector<Interval> none;
        const std::vector<Interval> &openings = edge ? plan.openings[line.offset > 0 ? 0 : 1] : none;
        for (Interval stretch : paintedStretches(line, from, to, openings)) {
            double k0 = (line.offset - line.width / 2) / half, k1 = (line.offset + line.width / 2) / half;
            paintStrip(ribbon, k0, k1, stretch, options.lift, out);
        }
    }
    // A stop line spans the lane that arrives: on the right going towards the end, on the
    // left going towards the start, from the centre line's edge to the edge line's.
    double inner = 0.06, outer = half - 0.05;
    if (end.stopLine && end.cut + stop < ribbon.length())
        paintStrip(ribbon, -outer / half, -inner / half, {ribbon.length() - end.cut - stop, ribbon.length() - end.cut},
                   options.lift, out);
    if (start.stopLine && start.cut + stop < ribbon.length())
        paintStrip(ribbon, inner / half, outer / half, {start.cut, start.cut + stop}, options.lift, out);
}

}  // namespace

Mesh roadMarkings(std::span<const MarkedRoad> roads, const MarkingOptions &options) {
    std::vector<Ribbon> ribbons;
    ribbons.reserve(roads.size());
    for (const MarkedRoad &road : roads) ribbons.emplace_back(*road.ribbon);
    std::vector<RoadPlan> plans = planJunctions(roads, ribbons, options);
    Mesh out;
    for (size_t r = 0; r < roads.size(); ++r) {
        if (ribbons[r].stations() < 2 || roads[r].style.width <= 0) continue;
        paintRoad(roads[r], ribbons[r], plans[r], options, out);
    }
    out.normals = areaWeightedNormals(out);
    out.triangleMaterials.assign(out.triangleCount(), 0);
    return out;
}

}  // namespace veduta
