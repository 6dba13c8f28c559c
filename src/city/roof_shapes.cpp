#include "city/roof_shapes.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "city/roof_faces.h"
#include "city/roof_gables.h"
#include "core/check.h"

namespace veduta {

namespace {

using Ring = std::vector<Vec2f>;

// A builder's result: the roof, or why the footprint cannot take its type.
using Attempt = std::variant<Mesh, std::string>;

const Vec3f kUp{0, 0, 1};
constexpr double kOnOutline = 1e-4;  // metres: a ring drawn on another's line, give or take rounding

std::vector<Ring> ringsOf(const RoofFootprint &footprint) {
    std::vector<Ring> rings{footprint.outer};
    rings.insert(rings.end(), footprint.holes.begin(), footprint.holes.end());
    return rings;
}

Vec3f direction(Vec2f from, Vec2f to) { return normalize(lift(to, 0) - lift(from, 0)); }

// Horizontal, away from the building: it lies to the left of every edge.
Vec3f outwardNormal(Vec2f from, Vec2f to) { return cross(direction(from, to), kUp); }

// Calls visit(a, b, metres along the ring before a) for every edge of every ring.
void forEachEdge(const RoofFootprint &footprint, const std::function<void(Vec2f, Vec2f, float)> &visit) {
    for (const Ring &ring : ringsOf(footprint)) {
        float before = 0;
        for (size_t i = 0; i < ring.size(); ++i) {
            Vec2f a = ring[i], b = ring[(i + 1) % ring.size()];
            visit(a, b, before);
            before += length(lift(b, 0) - lift(a, 0));
        }
    }
}

bool isFinite(const Ring &ring) {
    return std::all_of(ring.begin(), ring.end(), [](Vec2f p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

bool isValid(const RoofFootprint &footprint) {
    const Ring &outer = footprint.outer;
    if (outer.size() < 3 || !isFinite(outer) || !isSimplePolygon(outer) || !isCounterClockwise(outer)) return false;
    for (size_t h = 0; h < footprint.holes.size(); ++h) {
        const Ring &hole = footprint.holes[h];
        if (hole.size() < 3 || !isFinite(hole) || !isSimplePolygon(hole) || isCounterClockwise(hole)) return false;
        if (!liesInside(hole, outer)) return false;
        for (size_t other = 0; other < h; ++other) {
            if (!areDisjoint(hole, footprint.holes[other])) return false;
        }
    }
    return true;
}

RoofFootprint offsetFootprint(const RoofFootprint &footprint, float distance) {
    RoofFootprint moved{offsetPolygon(footprint.outer, distance), {}, footprint.base};
    for (const Ring &hole : footprint.holes) moved.holes.push_back(offsetPolygon(hole, distance));
    return moved;
}

// Each edge moved outwards (into the courtyard on a hole) by its own reach: `reach` runs over the
// outline's edges, then each hole's.
RoofFootprint movedOut(const RoofFootprint &footprint, const std::vector<float> &reach) {
    RoofFootprint moved{{}, {}, footprint.base};
    size_t first = 0;
    for (const Ring &ring : ringsOf(footprint)) {
        std::span<const float> distances(reach.data() + first, ring.size());
        (moved.outer.empty() ? moved.outer : moved.holes.emplace_back()) = offsetPolygon(ring, distances);
        first += ring.size();
    }
    return moved;
}

bool keepsDirections(const Ring &original, const Ring &moved) {
    for (size_t e = 0; e < original.size(); ++e) {
        Vec2f a = original[e], b = original[(e + 1) % original.size()];
        Vec2f movedA = moved[e], movedB = moved[(e + 1) % moved.size()];
        if (dot(lift(movedB, 0) - lift(movedA, 0), direction(a, b)) <= 0) return false;
    }
    return true;
}

// Whether `moved` is `original` offset by `distance` as it should be: a valid footprint whose
// every edge runs as before, each ring strictly beyond (distance > 0) or within its original.
bool isCleanOffset(const RoofFootprint &original, const RoofFootprint &moved, float distance) {
    if (!isValid(moved)) return false;
    std::vector<Ring> before = ringsOf(original), after = ringsOf(moved);
    for (size_t r = 0; r < before.size(); ++r) {
        if (!keepsDirections(before[r], after[r])) return false;
        // The outline grows outwards, a hole shrinks: the smaller ring lies in the larger.
        bool grows = (r == 0) == (distance > 0);
        if (!(grows ? liesInside(before[r], after[r]) : liesInside(after[r], before[r]))) return false;
    }
    return true;
}

// The same for edges moved out by reaches that may be zero, where the rings share a line.
bool isCleanMoveOut(const RoofFootprint &original, const RoofFootprint &moved) {
    if (!isValid(moved)) return false;
    std::vector<Ring> before = ringsOf(original), after = ringsOf(moved);
    for (size_t r = 0; r < before.size(); ++r) {
        if (!keepsDirections(before[r], after[r])) return false;
        const Ring &smaller = r == 0 ? before[r] : after[r], &larger = r == 0 ? after[r] : before[r];
        for (Vec2f p : smaller)
            if (!covers(larger, p, kOnOutline)) return false;
        if (edgeLeaving(smaller, larger, kOnOutline)) return false;
    }
    return true;
}

// Where a roof rests: the footprint with its edges moved out, and its height above the base.
struct Eaves {
    RoofFootprint footprint;
    float aboveBase = 0;
};

// The eaves of a roof whose slopes pass over the wall tops at `slope`, its edges reaching
// `reach` beyond the walls (the overhang, or none where a gable or shed wall stands flush with
// the house's): lowered by overhang · slope. A footprint that cannot take it keeps its walls'
// outline, with a note.
Eaves eavesFor(const RoofFootprint &footprint, float wallTop, float slope, float overhang,
               const std::vector<float> &reach, std::vector<std::string> &notes) {
    if (overhang == 0) return {footprint, wallTop};
    RoofFootprint moved = movedOut(footprint, reach);
    if (isCleanMoveOut(footprint, moved)) return {std::move(moved), wallTop - overhang * slope};
    notes.push_back(fmt::format("the footprint cannot take an overhang of {} m; built without", overhang));
    return {footprint, wallTop};
}

size_t edgeCount(const RoofFootprint &footprint) {
    size_t count = footprint.outer.size();
    for (const Ring &hole : footprint.holes) count += hole.size();
    return count;
}

std::vector<float> everyEdge(const RoofFootprint &footprint, float overhang) {
    return std::vector<float>(edgeCount(footprint), overhang);
}

// A horizontal or sloping cover over the footprint, corners at heightAt above `eavesZ`.
void addCover(Mesh &m, const RoofFootprint &footprint, float eavesZ, const std::function<float(Vec2f)> &heightAt,
              const Vec3f &normal, const UvPlane &uv) {
    std::vector<std::vector<Vec3f>> rings;
    for (const Ring &ring : ringsOf(footprint)) {
        rings.emplace_back();
        for (Vec2f p : ring) rings.back().push_back(lift(p, eavesZ + heightAt(p)));
    }
    addProjectedFace(m, rings, normal, uv, RoofCovering);
}

void addFlatCover(Mesh &m, const RoofFootprint &footprint, float z) {
    addCover(
        m, footprint, z, [](Vec2f) { return 0.0f; }, kUp, UvPlane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
}

// The parapet's inner outline: the footprint moved in by the parapet's thickness, halved until
// it fits; none when the footprint cannot take even the last.
std::optional<RoofFootprint> parapetInside(const RoofFootprint &footprint) {
    float thickness = kParapetThickness;
    for (int halvings = 0; halvings <= kParapetHalvings; ++halvings, thickness /= 2) {
        RoofFootprint inside = offsetFootprint(footprint, -thickness);
        if (isCleanOffset(footprint, inside, -thickness)) return inside;
    }
    return std::nullopt;
}

// The deck at the eaves, inside a parapet: outer walls up from the eaves, a flat top, inner
// walls down to the deck. Without a parapet (or room for one), the footprint flat at the eaves.
Mesh flatRoof(const RoofFootprint &footprint, float eavesAboveBase, float parapetHeight) {
    float eavesZ = footprint.base + eavesAboveBase, topZ = eavesZ + parapetHeight;
    Mesh m;
    std::optional<RoofFootprint> inside = parapetHeight > 0 ? parapetInside(footprint) : std::nullopt;
    if (!inside) {
        addFlatCover(m, footprint, eavesZ);
        return m;
    }
    std::vector<Ring> outerRings = ringsOf(footprint), innerRings = ringsOf(*inside);
    const UvPlane groundUv{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (size_t r = 0; r < outerRings.size(); ++r) {
        const Ring &outer = outerRings[r], &inner = innerRings[r];
        float before = 0;
        for (size_t i = 0; i < outer.size(); ++i) {
            size_t j = (i + 1) % outer.size();
            Vec2f a = outer[i], b = outer[j], innerA = inner[i], innerB = inner[j];
            Vec3f along = direction(a, b);
            addFace(m, {lift(a, eavesZ), lift(b, eavesZ), lift(b, topZ), lift(a, topZ)},
                    wallUvPlane(a, along, before, footprint.base), RoofGableWall);
            addFace(m, {lift(a, topZ), lift(b, topZ), lift(innerB, topZ), lift(innerA, topZ)}, groundUv, RoofGableWall);
            addFace(m, {lift(innerB, eavesZ), lift(innerA, eavesZ), lift(innerA, topZ), lift(innerB, topZ)},
                    wallUvPlane(innerB, -along, 0, footprint.base), RoofGableWall);
            before += length(lift(b, 0) - lift(a, 0));
        }
    }
    addFlatCover(m, *inside, eavesZ);
    return m;
}

std::optional<std::string> joined(const std::vector<std::string> &notes) {
    if (notes.empty()) return std::nullopt;
    std::string text = notes[0];
    for (size_t i = 1; i < notes.size(); ++i) text = fmt::format("{}; {}", text, notes[i]);
    return text;
}

constexpr double kCoverageTolerance = 1e-5;  // relative: float corners of roofs tens of metres wide

Attempt hipRoof(const Eaves &eaves, float slope) {
    std::optional<SkeletonRoof> roof = skeletonRoof(eaves.footprint, eaves.footprint.base + eaves.aboveBase, slope);
    if (!roof) return std::string("CGAL could not build the footprint's straight skeleton");
    return roofMesh(*roof);
}

// Whether the covering's triangles, seen from above, add up to the footprint: a gable end
// whose stretched slopes fold over a neighbouring face passes roof_gables' checks face by face
// but leaves slivers uncovered beside the walls.
bool coversFootprintOnce(const Mesh &m, const RoofFootprint &footprint) {
    double covered = 0, expected = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != RoofCovering) continue;
        const uint32_t *i = &m.indices[3 * t];
        Vec3f a = m.positions[i[0]], b = m.positions[i[1]], c = m.positions[i[2]];
        covered += (double(b.x - a.x) * (c.y - a.y) - double(c.x - a.x) * (b.y - a.y)) / 2;
    }
    for (const Ring &ring : ringsOf(footprint)) expected += signedArea(ring);
    return std::abs(covered - expected) <= kCoverageTolerance * expected;
}

Attempt checkedCover(Attempt attempt, const RoofFootprint &footprint) {
    const Mesh *mesh = std::get_if<Mesh>(&attempt);
    if (mesh && !coversFootprintOnce(*mesh, footprint)) return std::string("its slopes would fold over one another");
    return attempt;
}

// Gable or half-hip ends (roof_gables.h) on the hip roof over `eaves`: on the edges `only`
// names, each of which must take one, or else on every end of a ridge, shortest edge first,
// where an end whose apex an earlier gable took stays hipped by rule and one the geometry
// refuses stays hipped with a note.
struct GabledRoof {
    Attempt roof;
    std::vector<size_t> gables;         // the edges that got one
    std::vector<std::string> refusals;  // why the others did not
};

GabledRoof gableEnds(const Eaves &eaves, float slope, const std::optional<std::vector<size_t>> &only,
                     std::optional<float> halfHipFraction) {
    std::optional<SkeletonRoof> roof = skeletonRoof(eaves.footprint, eaves.footprint.base + eaves.aboveBase, slope);
    if (!roof) return {std::string("CGAL could not build the footprint's straight skeleton"), {}, {}};
    GabledRoof gabled{Mesh{}, {}, {}};
    for (size_t edge : only ? *only : ridgeEnds(*roof)) {
        if (!endsARidge(*roof, edge)) {
            if (only)
                gabled.refusals.push_back(fmt::format("edge {} ends no ridge: its hip face is no triangle", edge));
        } else if (auto refusal = addGableEnd(*roof, edge, halfHipFraction)) {
            gabled.refusals.push_back(fmt::format("edge {} stays hipped: {}", edge, *refusal));
        } else {
            gabled.gables.push_back(edge);
        }
    }
    if (gabled.gables.empty() || (only && !gabled.refusals.empty())) {
        gabled.roof = gabled.refusals.empty() ? std::string("no edge ends a ridge: no hip face is a triangle")
                                              : *joined(gabled.refusals);
    } else {
        gabled.roof = checkedCover(roofMesh(*roof), eaves.footprint);
    }
    return gabled;
}

// The gables stand flush with the house's walls: their edges take no overhang, the others do.
// They are found without one first; an overhang that moves them elsewhere is left out.
Attempt gabledRoof(const RoofFootprint &footprint, float wallTop, float slope, float overhang,
                   const std::optional<std::vector<size_t>> &only, std::optional<float> halfHipFraction,
                   std::vector<std::string> &notes) {
    GabledRoof chosen = gableEnds({footprint, wallTop}, slope, only, halfHipFraction);
    if (overhang > 0 && std::holds_alternative<Mesh>(chosen.roof)) {
        std::vector<float> reach = everyEdge(footprint, overhang);
        for (size_t edge : chosen.gables) reach[edge] = 0;
        size_t notesBefore = notes.size();  // eavesFor adds one when the footprint cannot take it
        Eaves eaves = eavesFor(footprint, wallTop, slope, overhang, reach, notes);
        if (notes.size() == notesBefore) {
            GabledRoof over = gableEnds(eaves, slope, chosen.gables, halfHipFraction);
            if (std::holds_alternative<Mesh>(over.roof)) {
                chosen = std::move(over);
            } else {
                notes.push_back(fmt::format(
                    "the gable ends do not keep their edges under an overhang of {} m; built without", overhang));
            }
        }
    }
    if (std::holds_alternative<Mesh>(chosen.roof))
        notes.insert(notes.end(), chosen.refusals.begin(), chosen.refusals.end());
    return std::move(chosen.roof);
}

// The apex stands over the centroid as high as the pitch rises over the nearest edge; the faces
// over edges farther off are shallower, so their eaves reach out farther for the overhang to
// lower them all alike.
Attempt pyramidRoof(const RoofFootprint &footprint, float wallTop, float slope, float overhang,
                    std::vector<std::string> &notes) {
    const Ring &outer = footprint.outer;
    std::vector<RoofKernel::Point_2> points;
    for (Vec2f p : outer) points.emplace_back(p.x, p.y);
    if (!footprint.holes.empty()) return std::string("a pyramid needs a footprint without courtyards");
    if (!CGAL::is_convex_2(points.begin(), points.end(), RoofKernel()))
        return std::string("a pyramid needs a convex footprint");
    Vec2f centre = areaCentroid(outer);
    std::vector<float> reach;
    forEachEdge(footprint, [&](Vec2f a, Vec2f b, float) {
        reach.push_back(dot(lift(a, 0) - lift(centre, 0), outwardNormal(a, b)));
    });
    float nearest = *std::min_element(reach.begin(), reach.end());
    Vec3f apex = lift(centre, footprint.base + wallTop + nearest * slope);
    for (float &r : reach) r *= overhang / nearest;
    Eaves eaves = eavesFor(footprint, wallTop, slope, overhang, reach, notes);
    float eavesZ = footprint.base + eaves.aboveBase;
    Mesh m;
    forEachEdge(eaves.footprint, [&](Vec2f a, Vec2f b, float) {
        std::vector<Vec3f> corners{lift(a, eavesZ), lift(b, eavesZ), apex};
        addFace(m, corners, slopeUvPlane(corners), RoofCovering);
    });
    return m;
}

size_t longestEdge(const Ring &ring) {
    size_t longest = 0;
    float longestLength = 0;
    for (size_t e = 0; e < ring.size(); ++e) {
        float edgeLength = length(lift(ring[(e + 1) % ring.size()], 0) - lift(ring[e], 0));
        if (edgeLength > longestLength) longest = e, longestLength = edgeLength;
    }
    return longest;
}

// Whether every corner lies on the inner side of the line of outline edge `edge`, or on it.
bool liesBehindEdge(const RoofFootprint &footprint, size_t edge) {
    const Ring &outer = footprint.outer;
    Vec2f a = outer[edge], b = outer[(edge + 1) % outer.size()];
    for (const Ring &ring : ringsOf(footprint)) {
        for (Vec2f p : ring)
            if (dot(lift(p, 0) - lift(a, 0), outwardNormal(a, b)) > kOnOutline) return false;
    }
    return true;
}

// One plane rising from the low edge's line at the pitch, lifted so that the footprint's lowest
// point (the low edge's, on a convex footprint) lies at the eaves; walls close it down to the
// eaves wherever it stands higher.
Mesh shedRoof(const Eaves &eaves, float slope, size_t lowEdge) {
    const RoofFootprint &footprint = eaves.footprint;
    float eavesAboveBase = eaves.aboveBase;
    const Ring &outer = footprint.outer;
    Vec2f low = outer[lowEdge], lowEnd = outer[(lowEdge + 1) % outer.size()];
    Vec3f inwards = -outwardNormal(low, lowEnd);
    auto rise = [&](Vec2f p) { return dot(lift(p, 0) - lift(low, 0), inwards); };
    float lowest = 0;
    for (const Ring &ring : ringsOf(footprint)) {
        for (Vec2f p : ring) lowest = std::min(lowest, rise(p));
    }
    auto heightAt = [&](Vec2f p) {
        float height = (rise(p) - lowest) * slope;
        return height < kMinShedWallHeight ? 0.0f : height;
    };
    float eavesZ = footprint.base + eavesAboveBase;
    Vec3f normal = normalize(-inwards * slope + kUp), along = direction(low, lowEnd);
    Mesh m;
    addCover(m, footprint, eavesZ, heightAt, normal,
             UvPlane{lift(low, eavesZ + heightAt(low)), along, cross(normal, along)});
    forEachEdge(footprint, [&](Vec2f a, Vec2f b, float before) {
        float heightA = heightAt(a), heightB = heightAt(b);
        if (heightA == 0 && heightB == 0) return;
        std::vector<Vec3f> corners{lift(a, eavesZ), lift(b, eavesZ)};
        if (heightB > 0) corners.push_back(lift(b, eavesZ + heightB));
        if (heightA > 0) corners.push_back(lift(a, eavesZ + heightA));
        addFace(m, corners, wallUvPlane(a, direction(a, b), before, footprint.base), RoofGableWall);
    });
    return m;
}

// roofs.h's mansard, its slopes reaching kMansardInset in at the pitch (steeper where the inset
// had to be halved).
Attempt mansardOverFootprint(const Eaves &eaves, float slope) {
    const RoofFootprint &footprint = eaves.footprint;
    float eavesAboveBase = eaves.aboveBase;
    if (!footprint.holes.empty()) return std::string("a mansard needs a footprint without courtyards");
    Footprint plain{footprint.outer, std::vector<bool>(footprint.outer.size(), false), footprint.base};
    MansardRoof roof = mansardRoof(plain, eavesAboveBase, kMansardInset * slope, kMansardInset);
    if (roof.inset == 0) return std::string("the footprint is too narrow for a mansard's slopes");
    // A halved inset must keep the pitch: buildRoof lowered the eaves for it under an overhang.
    if (roof.inset < kMansardInset) roof = mansardRoof(plain, eavesAboveBase, roof.inset * slope, roof.inset);
    return std::move(roof.mesh);
}

// The types tried before the last resort, Flat, in order.
std::vector<RoofType> attemptOrder(RoofType type) {
    switch (type) {
    case RoofType::Flat: return {};
    case RoofType::Pyramid: return {RoofType::Pyramid, RoofType::Hip};
    case RoofType::Gable: return {RoofType::Gable, RoofType::Hip};
    case RoofType::HalfHip: return {RoofType::HalfHip, RoofType::Hip};
    default: return {type};
    }
}

// Hip and mansard roofs overhang on every edge; a shed only at its low edge, its walls flush
// with the house's; pyramids and gables work out their own.
Attempt buildSloped(RoofType type, const RoofFootprint &footprint, float wallTop, float slope,
                    const RoofOptions &options, std::vector<std::string> &notes) {
    float overhang = options.overhang;
    std::optional<std::vector<size_t>> gableEdge;
    if (options.gableEdge >= 0) gableEdge = std::vector<size_t>{size_t(options.gableEdge)};
    switch (type) {
    case RoofType::Hip:
        return hipRoof(eavesFor(footprint, wallTop, slope, overhang, everyEdge(footprint, overhang), notes), slope);
    case RoofType::Mansard:
        return mansardOverFootprint(
            eavesFor(footprint, wallTop, slope, overhang, everyEdge(footprint, overhang), notes), slope);
    case RoofType::Pyramid: return pyramidRoof(footprint, wallTop, slope, overhang, notes);
    case RoofType::Gable: return gabledRoof(footprint, wallTop, slope, overhang, gableEdge, std::nullopt, notes);
    case RoofType::HalfHip:
        return gabledRoof(footprint, wallTop, slope, overhang, gableEdge, options.halfHipFraction, notes);
    case RoofType::Shed: {
        size_t low = options.gableEdge >= 0 ? size_t(options.gableEdge) : longestEdge(footprint.outer);
        // Where part of the footprint lies below the low edge's line, walls stand on that edge
        // too, and they must stay flush with the house's.
        float lowOverhang = liesBehindEdge(footprint, low) ? overhang : 0;
        if (lowOverhang < overhang)
            notes.push_back("the shed's low edge is not its lowest line; built without an overhang");
        std::vector<float> reach(edgeCount(footprint), 0.0f);
        reach[low] = lowOverhang;
        return shedRoof(eavesFor(footprint, wallTop, slope, lowOverhang, reach, notes), slope, low);
    }
    case RoofType::Flat: break;
    }
    VEDUTA_UNREACHABLE("a flat roof is not sloped");
}

void checkArguments(const RoofFootprint &footprint, const RoofOptions &options) {
    if (!isValid(footprint)) {
        throw std::invalid_argument(
            "a roof footprint needs a simple counter-clockwise outline with simple clockwise holes inside it and "
            "apart");
    }
    if (options.type != RoofType::Flat && !(options.pitchDegrees > 0 && options.pitchDegrees < 90)) {
        throw std::invalid_argument(fmt::format("a roof pitch of {}° is not between 0° and 90°", options.pitchDegrees));
    }
    if (!(options.overhang >= 0) || !std::isfinite(options.overhang)) {
        throw std::invalid_argument(fmt::format("a roof overhang of {} m is not a length", options.overhang));
    }
    if (!(options.parapetHeight >= 0) || !std::isfinite(options.parapetHeight)) {
        throw std::invalid_argument(fmt::format("a parapet of {} m is not a height", options.parapetHeight));
    }
    if (options.gableEdge < -1 || options.gableEdge >= int(footprint.outer.size())) {
        throw std::invalid_argument(fmt::format("the footprint has no edge {}", options.gableEdge));
    }
    if (!(options.halfHipFraction > 0 && options.halfHipFraction < 1)) {
        throw std::invalid_argument(
            fmt::format("a half-hip fraction of {} is not between 0 and 1", options.halfHipFraction));
    }
}

}  // namespace

std::string_view roofTypeName(RoofType type) {
    switch (type) {
    case RoofType::Flat: return "flat";
    case RoofType::Hip: return "hip";
    case RoofType::Pyramid: return "pyramid";
    case RoofType::Shed: return "shed";
    case RoofType::Gable: return "gable";
    case RoofType::HalfHip: return "halfhip";
    case RoofType::Mansard: return "mansard";
    }
    return "unknown";
}

std::optional<RoofType> roofTypeFromName(std::string_view name) {
    std::string lower;
    for (char c : name) lower += char(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "half-hip") return RoofType::HalfHip;
    for (RoofType type : kRoofTypes) {
        if (roofTypeName(type) == lower) return type;
    }
    return std::nullopt;
}

RoofResult buildRoof(const RoofFootprint &footprint, float eavesHeight, const RoofOptions &options) {
    checkArguments(footprint, options);
    std::vector<std::string> notes;
    float slope = std::tan(radians(options.pitchDegrees));
    for (RoofType type : attemptOrder(options.type)) {
        std::vector<std::string> tried;
        Attempt attempt = buildSloped(type, footprint, eavesHeight, slope, options, tried);
        if (Mesh *mesh = std::get_if<Mesh>(&attempt)) {
            notes.insert(notes.end(), tried.begin(), tried.end());
            return {std::move(*mesh), type, joined(notes)};
        }
        notes.push_back(fmt::format("no {} roof: {}", roofTypeName(type), std::get<std::string>(attempt)));
    }
    // A flat deck is not lowered: its parapet, not a slope, closes the walls.
    Eaves deck = eavesFor(footprint, eavesHeight, 0, options.overhang, everyEdge(footprint, options.overhang), notes);
    return {flatRoof(deck.footprint, eavesHeight, options.parapetHeight), RoofType::Flat, joined(notes)};
}

}  // namespace veduta
