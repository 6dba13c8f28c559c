// Goitowski's simplified Schrader 2007 subdivision (digest-002 §3.2, thesis L1566–1702): markers
// spread round the block by length, a ray inwards from each, lots between neighbouring rays up to
// their frontmost crossings, then shrunk apart by the thesis' margins.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include <fmt/format.h>

#include "city/lot_pieces.h"
#include "city/lot_subdivision.h"

namespace veduta {

namespace {

using lots::ExactKernel;
using lots::ExactPolygon;
using ExactPoint = ExactKernel::Point_2;
using Region = CGAL::Polygon_set_2<ExactKernel>;
// The rays, and the bands the inset takes away, are worked out in double; the markers lie exactly
// on the block's edges (the exact kernel), so that the Boolean operations meet the outline there.
using InexactKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = InexactKernel::Point_2;
using Vector = InexactKernel::Vector_2;

// Rays closer to parallel than this (the sine of their angle) do not cross: float outlines make
// opposite sides of a rectangle a little skew, and their crossing would lie kilometres away.
constexpr double kParallel = 1e-6;
// Points closer than this are one point (front points, O1, and points the Boolean operations
// leave a rounding apart), parallel rays closer than this one line (M2); far below any lot's
// size, far above double rounding.
constexpr double kSamePoint = 1e-6;
// How far a lot's front may lie from its margin line and still count as it (float rounding).
constexpr double kOnFront = 1e-3;

double cross(const Vector &a, const Vector &b) { return a.x() * b.y() - a.y() * b.x(); }
Point inexact(Vec2f p) { return {p.x, p.y}; }
ExactPoint exactPoint(const Point &p) { return {p.x(), p.y()}; }
std::vector<Point> inexactPoints(const ExactPolygon &polygon) {
    std::vector<Point> points;
    for (const ExactPoint &p : polygon.vertices()) points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    return points;
}

// A ray from the `step`-th marker of `edge` (counted from 1), perpendicular to the edge, inwards.
struct Ray {
    size_t edge = 0, step = 0;
    ExactPoint marker;  // exactly on the edge
    Point origin;       // the marker in double
    Vector direction;   // a unit vector
    double reach = 0;   // to its first hit on the outline: the ray is valid up to there (L1659)
    Point at(double depth) const { return origin + direction * depth; }
    Vector alongEdge() const { return {direction.y(), -direction.x()}; }
};

double edgeLength(const Block &block, size_t edge) {
    return std::sqrt(
        (inexact(block.points[(edge + 1) % block.points.size()]) - inexact(block.points[edge])).squared_length());
}

// Thesis step 1: ⌊U / D⌋ markers. D is not given; the mean frontage of the other algorithms.
size_t markerCount(const Block &block, const LotSettings &settings, uint32_t blockId,
                   const std::optional<FileLoc> &loc) {
    double perimeter = 0;
    for (size_t e = 0; e < block.points.size(); ++e) perimeter += edgeLength(block, e);
    double spacing = (double(settings.minBuildingLength) + settings.maxBuildingLength) / 2;
    double count = std::floor(perimeter / spacing);
    if (count > double(kMaxLotsPerBlock)) {
        lots::fail(loc,
                   fmt::format("block {} would be cut into more than {} Schrader lots (a perimeter of {} m, "
                               "markers {} m apart)",
                               blockId, kMaxLotsPerBlock, perimeter, spacing));
    }
    return size_t(count);
}

// Thesis step 2: each marker goes to the edge whose pieces are the longest at the time (the lower
// index on a tie), so that an edge with k markers is cut into k + 1 equal pieces (step 3).
std::vector<size_t> markersPerEdge(const Block &block, size_t markers) {
    size_t n = block.points.size();
    std::vector<size_t> counts(n, 0);
    auto piece = [&](size_t e) { return edgeLength(block, e) / double(counts[e] + 1); };
    auto shorter = [&](size_t a, size_t b) { return piece(a) < piece(b) || (piece(a) == piece(b) && a > b); };
    std::priority_queue<size_t, std::vector<size_t>, decltype(shorter)> edges(shorter);
    for (size_t e = 0; e < n; ++e) edges.push(e);
    for (size_t m = 0; m < markers; ++m) {
        size_t e = edges.top();
        edges.pop();
        ++counts[e];
        edges.push(e);
    }
    return counts;
}

double reachOf(const Ray &ray, const Block &block) {
    size_t n = block.points.size();
    double reach = std::numeric_limits<double>::infinity();
    for (size_t e = 0; e < n; ++e) {
        if (e == ray.edge) continue;
        Point p = inexact(block.points[e]);
        Vector side = inexact(block.points[(e + 1) % n]) - p;
        double denominator = cross(ray.direction, side);
        if (denominator == 0) continue;
        double t = cross(p - ray.origin, side) / denominator, s = cross(p - ray.origin, ray.direction) / denominator;
        if (t > 0 && s >= 0 && s <= 1) reach = std::min(reach, t);
    }
    return reach;
}

// Thesis step 4's rays, in order round the outline.
std::vector<Ray> castRays(const Block &block, const std::vector<size_t> &counts) {
    size_t n = block.points.size();
    std::vector<Ray> rays;
    for (size_t e = 0; e < n; ++e) {
        ExactPoint start(block.points[e].x, block.points[e].y);
        ExactPoint end(block.points[(e + 1) % n].x, block.points[(e + 1) % n].y);
        Vector along = inexact(block.points[(e + 1) % n]) - inexact(block.points[e]);
        Vector inwards = along.perpendicular(CGAL::COUNTERCLOCKWISE) / edgeLength(block, e);
        for (size_t step = 1; step <= counts[e]; ++step) {
            Ray ray;
            ray.edge = e;
            ray.step = step;
            ray.marker = start + (end - start) * (ExactKernel::FT(double(step)) / double(counts[e] + 1));
            ray.origin = {CGAL::to_double(ray.marker.x()), CGAL::to_double(ray.marker.y())};
            ray.direction = inwards;
            ray.reach = reachOf(ray, block);
            rays.push_back(ray);
        }
    }
    return rays;
}

// The depths along `a` and `b` at which they cross, within both their reaches; none for parallel
// rays.
std::optional<std::pair<double, double>> crossing(const Ray &a, const Ray &b) {
    double denominator = cross(a.direction, b.direction);
    if (std::abs(denominator) < kParallel) return std::nullopt;
    Vector between = b.origin - a.origin;
    double t = cross(between, b.direction) / denominator, u = cross(between, a.direction) / denominator;
    if (!(t > 0 && u > 0 && t <= a.reach && u <= b.reach)) return std::nullopt;
    return std::pair{t, u};
}

// M2: rays along one line facing each other meet halfway (the thesis' r1 = r2 = d_offset, whose
// value it does not give). The depth, when they do.
std::optional<double> meetingHalfway(const Ray &a, const Ray &b) {
    if (std::abs(cross(a.direction, b.direction)) >= kParallel || a.direction * b.direction > 0) return std::nullopt;
    Vector between = b.origin - a.origin;
    double apart = between * a.direction;
    if (std::abs(cross(between, a.direction)) >= kSamePoint || apart <= 0 || apart > a.reach + kSamePoint) {
        return std::nullopt;
    }
    return apart / 2;
}

// Thesis step 5: each ray's frontmost crossing with another ray; M1: crossings nearer the outline
// than `nearest` are not kept. None for a ray that keeps no crossing (M3, settled per lot).
std::vector<std::optional<double>> frontDepths(const std::vector<Ray> &rays, double nearest) {
    std::vector<std::optional<double>> fronts(rays.size());
    auto offer = [&](size_t ray, double depth) {
        if (depth >= nearest && (!fronts[ray] || depth < *fronts[ray])) fronts[ray] = depth;
    };
    for (size_t i = 0; i < rays.size(); ++i) {
        for (size_t j = i + 1; j < rays.size(); ++j) {
            if (std::optional<std::pair<double, double>> depths = crossing(rays[i], rays[j])) {
                offer(i, depths->first);
                offer(j, depths->second);
            } else if (std::optional<double> halfway = meetingHalfway(rays[i], rays[j])) {
                offer(i, *halfway);
                offer(j, *halfway);
            }
        }
    }
    return fronts;
}

// The block points the outline passes from a's marker to b's: none when b follows a on its edge,
// all of them when b is a (a block with two markers on one edge and none elsewhere).
std::vector<size_t> pointsBetween(const Block &block, const Ray &a, const Ray &b) {
    std::vector<size_t> points;
    if (a.edge == b.edge && a.step < b.step) return points;
    size_t n = block.points.size();
    for (size_t p = (a.edge + 1) % n;; p = (p + 1) % n) {
        points.push_back(p);
        if (p == b.edge) break;
    }
    return points;
}

bool isLot(const ExactPolygon &polygon) {
    return polygon.size() >= 3 && polygon.is_simple() && polygon.orientation() == CGAL::COUNTERCLOCKWISE;
}

// One lot before the clipping and the inset (thesis step 6), from the outline between the
// markers of `a` and `b` and the rays' front depths; none when neither ray has one (M3).
class LotOutline {
  public:
    LotOutline(const Block &block, const Ray &a, const Ray &b) :
        block_(block), a_(a), b_(b), between_(pointsBetween(block, a, b)) {}

    bool frontsAStreet() const {
        return block_.streetEdges[a_.edge] ||
            std::any_of(between_.begin(), between_.end(), [&](size_t p) { return block_.streetEdges[p]; });
    }

    std::optional<ExactPolygon> build(std::optional<double> frontA, std::optional<double> frontB) const {
        if (!frontA && !frontB) return std::nullopt;
        // M3: a ray without a front takes its neighbour's depth, as far as it reaches.
        double depthA = frontA ? *frontA : std::min(*frontB, a_.reach);
        double depthB = frontB ? *frontB : std::min(*frontA, b_.reach);
        // O3: between two rays of one edge the back wall runs parallel to the street.
        if (between_.empty()) depthA = depthB = std::min(depthA, depthB);
        ExactPolygon lot = along();
        Point pointA = a_.at(depthA), pointB = b_.at(depthB);
        lot.push_back(exactPoint(pointB));
        if (std::optional<Point> corner = innerCorner(pointA, pointB)) lot.push_back(exactPoint(*corner));
        // O1: rays that meet at one front point (a corner lot) give the lot one point there.
        if (std::sqrt((pointA - pointB).squared_length()) >= kSamePoint) lot.push_back(exactPoint(pointA));
        if (isLot(lot)) return lot;
        // The rays cross before their fronts (M1 dropped the crossing as too near the outline, or
        // M3 borrowed a depth beyond it): the lot ends where they cross.
        std::optional<std::pair<double, double>> depths = crossing(a_, b_);
        if (!depths) return std::nullopt;
        ExactPolygon cornerLot = along();
        cornerLot.push_back(exactPoint(a_.at(depths->first)));
        if (isLot(cornerLot)) return cornerLot;
        return std::nullopt;
    }

  private:
    // The outline from a's marker to b's.
    ExactPolygon along() const {
        ExactPolygon lot;
        lot.push_back(a_.marker);
        for (size_t p : between_) lot.push_back(ExactPoint(block_.points[p].x, block_.points[p].y));
        lot.push_back(b_.marker);
        return lot;
    }

    // O4: where the outline turns clockwise (a reflex corner) the straight link between the fronts
    // would cut the corner off or cross the lot; the lot's back turns the corner instead, through
    // the meeting point of the parallels to the two edges through the front points, when that lies
    // beyond the front of a and before the front of b.
    std::optional<Point> innerCorner(const Point &pointA, const Point &pointB) const {
        Vector edgeA = a_.alongEdge(), edgeB = b_.alongEdge();
        double turn = cross(edgeA, edgeB);
        if (!(turn < 0) || std::abs(turn) < kParallel) return std::nullopt;
        double fromA = cross(pointB - pointA, edgeB) / turn, beforeB = -cross(pointB - pointA, edgeA) / turn;
        if (fromA < 0 || beforeB < 0) return std::nullopt;
        return pointA + edgeA * fromA;
    }

    const Block &block_;
    const Ray &a_, &b_;
    std::vector<size_t> between_;
};

// O5: lots that still overlap are clipped against each other (CGAL's exact Boolean operations
// instead of the thesis' Weiler–Atherton); a lot keeps what no earlier lot round the block took.
class Clipper {
  public:
    explicit Clipper(const Block &block) : block_(lots::toExact(block.points)) {}

    Region place(const ExactPolygon &lot) {
        Region region(lot);
        region.intersection(block_);
        CGAL::Bbox_2 box = lot.bbox();
        for (size_t i = 0; i < placed_.size(); ++i) {
            if (CGAL::do_overlap(box, boxes_[i])) region.difference(placed_[i]);
        }
        placed_.push_back(region);
        boxes_.push_back(box);
        return region;
    }

  private:
    Region block_;
    std::vector<Region> placed_;
    std::vector<CGAL::Bbox_2> boxes_;
};

// The indices of the points that are not within kSamePoint of the one kept before them (the
// Boolean operations leave such pairs of points a rounding apart).
std::vector<size_t> distinctPoints(const std::vector<Point> &points) {
    auto apart = [&](size_t i, size_t k) {
        return (points[i] - points[k]).squared_length() >= kSamePoint * kSamePoint;
    };
    std::vector<size_t> distinct;
    for (size_t i = 0; i < points.size(); ++i) {
        if (distinct.empty() || apart(i, distinct.back())) distinct.push_back(i);
    }
    while (distinct.size() > 1 && !apart(distinct.front(), distinct.back())) distinct.pop_back();
    return distinct;
}

// A footprint's outline without points a rounding apart, and without points where it runs
// straight on to within kParallel (O2; the Boolean operations leave some that are straight but
// for rounding).
ExactPolygon tidied(const ExactPolygon &polygon) {
    std::vector<Point> points = inexactPoints(polygon);
    std::vector<size_t> distinct = distinctPoints(points);
    ExactPolygon kept;
    size_t n = distinct.size();
    for (size_t k = 0; k < n; ++k) {
        const Point &here = points[distinct[k]];
        Vector in = here - points[distinct[(k + n - 1) % n]], out = points[distinct[(k + 1) % n]] - here;
        double sine = cross(in, out) / std::sqrt(in.squared_length() * out.squared_length());
        if (std::abs(sine) >= kParallel || in * out < 0) kept.push_back(polygon[distinct[k]]);
    }
    return kept;
}

// Everything within `distance` of the ring on its left, the region's side (a hole runs
// clockwise): a strip along each edge, and where the ring turns right or back, the wedge the
// strips leave open, cut off by tangents to the disc of that radius at most 90° apart (one mitre
// up to 90°, as the straight-skeleton offset has). The strips reach 2 · kSamePoint beyond their
// edges' ends and outside, so that the points merged into their neighbours leave no sliver.
void addBand(const ExactPolygon &ring, double distance, std::vector<ExactPolygon> &band) {
    std::vector<Point> all = inexactPoints(ring), points;
    for (size_t i : distinctPoints(all)) points.push_back(all[i]);
    size_t n = points.size();
    // A part within kSamePoint of one point has no edge; rounding to float removes it.
    if (n < 2) return;
    auto inwards = [&](size_t edge) {
        Vector along = points[(edge + 1) % n] - points[edge];
        return along.perpendicular(CGAL::COUNTERCLOCKWISE) * (distance / std::sqrt(along.squared_length()));
    };
    for (size_t i = 0; i < n; ++i) {
        const Point &here = points[i], &next = points[(i + 1) % n];
        Vector out = inwards(i), in = inwards((i + n - 1) % n);
        Vector beyond = (next - here) * (2 * kSamePoint / std::sqrt((next - here).squared_length()));
        Vector outside = beyond.perpendicular(CGAL::CLOCKWISE);
        band.push_back(ExactPolygon());
        for (const Point &corner :
             {here - beyond + outside, next + beyond + outside, next + beyond + out, here - beyond + out}) {
            band.back().push_back(exactPoint(corner));
        }
        // The strips' reach beyond their ends closes the wedge of a nearly straight corner.
        double turn = std::atan2(cross(in, out), in * out);
        if (!(turn < -kParallel)) continue;
        int steps = int(std::ceil(-turn / (std::numbers::pi / 2)));
        double step = turn / steps;
        ExactPolygon wedge;
        wedge.push_back(exactPoint(here));
        Vector tangent = in;
        for (int k = 1; k <= steps; ++k) {
            Vector following = k == steps ? out
                                          : Vector(in.x() * std::cos(step * k) - in.y() * std::sin(step * k),
                                                   in.x() * std::sin(step * k) + in.y() * std::cos(step * k));
            wedge.push_back(exactPoint(here + tangent));
            // Where the tangents at `tangent` and `following` meet.
            wedge.push_back(exactPoint(
                here + (tangent + following) * (distance * distance / (distance * distance + tangent * following))));
            tangent = following;
        }
        wedge.push_back(exactPoint(here + out));
        wedge.reverse_orientation();
        band.push_back(wedge);
    }
}

// The region less everything within `distance` of its outline (thesis L1696–1702), with exact
// Boolean operations: the thesis moves each vertex along its edges' normals, which kinks at nearly
// straight corners (its O2) and crosses itself where a lot is narrower than the shift, and CGAL's
// straight-skeleton offset gives up on the slivers the clipping leaves. Every point left is at
// least `distance` from the outline: exactly that along the edges, more at the mitres of reflex
// corners.
Region eroded(Region region, double distance) {
    if (distance == 0) return region;
    std::vector<CGAL::Polygon_with_holes_2<ExactKernel>> parts;
    region.polygons_with_holes(std::back_inserter(parts));
    std::vector<ExactPolygon> band;
    for (const auto &part : parts) {
        addBand(part.outer_boundary(), distance, band);
        for (const ExactPolygon &hole : part.holes()) addBand(hole, distance, band);
    }
    Region near;
    near.join(band.begin(), band.end());
    region.difference(near);
    return region;
}

// Whether the segment from p to q runs along the block's edge from s to t, `margin` inside the
// block: both ends that far from the edge's line, its middle in front of the edge.
bool runsAlong(Vec2f p, Vec2f q, Vec2f s, Vec2f t, double margin) {
    Vector edge = inexact(t) - inexact(s);
    double length = std::sqrt(edge.squared_length());
    Vector inwards = edge.perpendicular(CGAL::COUNTERCLOCKWISE) / length;
    auto inside = [&](Vec2f x) { return (inexact(x) - inexact(s)) * inwards; };
    double middle = (CGAL::midpoint(inexact(p), inexact(q)) - inexact(s)) * edge / length;
    return std::abs(inside(p) - margin) < kOnFront && std::abs(inside(q) - margin) < kOnFront && middle >= 0 &&
        middle <= length;
}

// The last step: each lot loses what lies within half BuildingMargin of its outline, so that
// neighbours are BuildingMargin apart, and what lies within RoadMargin of the block's. A lot's
// edges that face a street then lie the larger of the two inside it.
class Inset {
  public:
    Inset(const Block &block, const LotSettings &settings) :
        block_(block),
        half_(settings.buildingMargin / 2.0),
        front_(std::max<double>(settings.roadMargin, half_)),
        inside_(eroded(Region(lots::toExact(block.points)), settings.roadMargin)) {}

    void addLots(const Region &lot, std::vector<Footprint> &lots) const {
        Region kept = eroded(lot, half_);
        kept.intersection(inside_);
        std::vector<CGAL::Polygon_with_holes_2<ExactKernel>> parts;
        kept.polygons_with_holes(std::back_inserter(parts));
        for (const auto &part : parts) {
            // A lot round a hole cannot be a footprint; one arises only where an earlier lot lies
            // wholly inside a later one.
            if (part.has_holes()) continue;
            lots::Piece points = lots::toPiece(tidied(part.outer_boundary()));
            // Without margins a lot can keep a neck narrower than float rounding (where a front
            // point lies on the outline), which rounding closes.
            if (points.size() < 3 || !isSimplePolygon(points)) continue;
            std::vector<bool> flags = frontFlags(points);
            if (std::find(flags.begin(), flags.end(), true) == flags.end()) continue;
            lots.push_back({std::move(points), std::move(flags), block_.base});
        }
    }

  private:
    std::vector<bool> frontFlags(const lots::Piece &piece) const {
        size_t n = piece.size(), m = block_.points.size();
        std::vector<bool> flags(n, false);
        for (size_t i = 0; i < n; ++i) {
            for (size_t e = 0; e < m && !flags[i]; ++e) {
                flags[i] = block_.streetEdges[e] &&
                    runsAlong(piece[i], piece[(i + 1) % n], block_.points[e], block_.points[(e + 1) % m], front_);
            }
        }
        return flags;
    }

    const Block &block_;
    double half_, front_;
    Region inside_;
};

}  // namespace

std::vector<Footprint> schraderLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                    const std::optional<FileLoc> &loc) {
    if (!lots::checkedAndOnAStreet(block, settings, loc)) return {};
    std::vector<Ray> rays = castRays(block, markersPerEdge(block, markerCount(block, settings, blockId, loc)));
    // A lot lies between two rays.
    if (rays.size() < 2) return {};
    // M1's threshold: rays from a slanted neighbouring edge sweep low over a street's rays; lots
    // are to be as deep as the perimeter ring's houses.
    std::vector<std::optional<double>> fronts = frontDepths(rays, settings.minBuildingDepth);
    Clipper clipper(block);
    Inset inset(block, settings);
    std::vector<Footprint> lots;
    for (size_t i = 0; i < rays.size(); ++i) {
        size_t next = (i + 1) % rays.size();
        LotOutline outline(block, rays[i], rays[next]);
        // Lots along edges without a street are not built, and take no ground from the others.
        if (!outline.frontsAStreet()) continue;
        if (std::optional<ExactPolygon> lot = outline.build(fronts[i], fronts[next])) {
            inset.addLots(clipper.place(*lot), lots);
        }
    }
    return filterLots(std::move(lots), settings, seed, blockId);
}

}  // namespace veduta
