#include "geo/road_markings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "geo/mesh_normals.h"
#include "geo/ribbon_frame.h"

namespace veduta {

namespace {

// The nearest point of a ribbon's centre line to p: its distance along and away.
struct Nearest {
    double along = 0, distance = std::numeric_limits<double>::infinity();
    Vec2d direction;
};

Nearest nearestOnCentre(const RibbonFrame &r, Vec2d p) {
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
std::vector<RoadPlan> planJunctions(std::span<const MarkedRoad> roads, const std::vector<RibbonFrame> &ribbons,
                                    const MarkingOptions &options) {
    std::vector<RoadPlan> plans(roads.size());
    for (size_t r = 0; r < roads.size(); ++r) {
        const RibbonFrame &ribbon = ribbons[r];
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
void paintStrip(const RibbonFrame &ribbon, double k0, double k1, Interval stretch, double lift, Mesh &out) {
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

void paintRoad(const MarkedRoad &road, const RibbonFrame &ribbon, const RoadPlan &plan, const MarkingOptions &options,
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
    std::vector<RibbonFrame> ribbons;
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
