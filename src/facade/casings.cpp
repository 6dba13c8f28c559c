#include "facade/casings.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_triangulation_decomposition_2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/check.h"
#include "core/polygon_area.h"

namespace veduta {

namespace {

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Exact>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Exact>;
using ExactSet = CGAL::Polygon_set_2<Exact>;
using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr double kSamePoint = 1e-12;  // metres: repeated points
constexpr double kSliver = 1e-12;     // square metres: pieces without area are dropped
constexpr double kTransomHeight = 2.0 / 3.0;
// Bricks along one casing strip: a 3 m strip of 3 mm bricks. More is no casing one could see,
// and each brick is two exact polygons joined into the hole.
constexpr double kMostKlinkerBricksPerStrip = 1000;
constexpr const char *kEdgeNames[] = {"bottom", "right", "top", "left"};

std::vector<Vec2d> withoutRepeats(const std::vector<Vec2d> &points) {
    std::vector<Vec2d> out;
    for (Vec2d p : points) {
        if (out.empty() || length(p - out.back()) > kSamePoint) out.push_back(p);
    }
    while (out.size() > 1 && length(out.back() - out.front()) <= kSamePoint) out.pop_back();
    return out;
}

std::vector<Vec2d> counterClockwise(std::vector<Vec2d> polygon) {
    polygon = withoutRepeats(polygon);
    if (signedArea(polygon) < 0) std::reverse(polygon.begin(), polygon.end());
    return polygon;
}

ExactPolygon toExact(const std::vector<Vec2d> &polygon) {
    ExactPolygon out;
    for (Vec2d p : polygon) out.push_back(Exact::Point_2(p.x, p.y));
    return out;
}

std::vector<Vec2d> fromExact(const ExactPolygon &polygon) {
    std::vector<Vec2d> out;
    for (const Exact::Point_2 &p : polygon.vertices()) out.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
    return counterClockwise(out);
}

bool isSimpleCounterClockwise(const std::vector<Vec2d> &polygon) {
    ExactPolygon p = toExact(polygon);
    return p.is_simple() && p.orientation() == CGAL::COUNTERCLOCKWISE;
}

// The region between a polyline and the same polyline moved by `offset`.
std::vector<Vec2d> stripPolygon(const std::vector<Vec2d> &base, Vec2d offset) {
    std::vector<Vec2d> polygon = base;
    for (auto p = base.rbegin(); p != base.rend(); ++p) polygon.push_back(*p + offset);
    return counterClockwise(polygon);
}

double polylineLength(const std::vector<Vec2d> &points) {
    double sum = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) sum += length(points[i + 1] - points[i]);
    return sum;
}

// The part of a polyline between arc lengths s0 < s1.
std::vector<Vec2d> subPolyline(const std::vector<Vec2d> &points, double s0, double s1) {
    std::vector<Vec2d> out;
    double at = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        double segment = length(points[i + 1] - points[i]), end = at + segment;
        if (end >= s0) {
            if (out.empty()) out.push_back(lerp(points[i], points[i + 1], (s0 - at) / segment));
            if (end >= s1) {
                out.push_back(lerp(points[i], points[i + 1], (s1 - at) / segment));
                return out;
            }
            out.push_back(points[i + 1]);
        }
        at = end;
    }
    return out;
}

// A casing strip before its style cuts it: a polyline and how far the strip reaches from it.
struct Strip {
    std::vector<Vec2d> base;
    Vec2d offset;
    double overhang = 0;
    PieceKind kind = PieceKind::Casing;
};

FacadePiece piece(std::vector<Vec2d> polygon, double back, double front, PieceKind kind) {
    return {counterClockwise(std::move(polygon)), std::min(back, front), front, kind};
}

void checkKlinker(const KlinkerBricks &bricks) {
    if (!(bricks.brickWidth > 0 && std::isfinite(bricks.brickWidth))) {
        throw std::invalid_argument(
            fmt::format("klinker brickWidth {} must be positive and finite", bricks.brickWidth));
    }
    if (!(bricks.spacing >= 0 && std::isfinite(bricks.spacing))) {
        throw std::invalid_argument(fmt::format("klinker spacing {} must be finite and not negative", bricks.spacing));
    }
    if (!std::isfinite(bricks.brickOverhang)) {
        throw std::invalid_argument(fmt::format("klinker brickOverhang {} is not finite", bricks.brickOverhang));
    }
}

// Klinker: joints at both ends and between equal bricks (see the header); with no spacing the
// bricks touch and there are no joints, which would have no area.
void appendKlinker(const Strip &strip, const KlinkerBricks &bricks, std::vector<FacadePiece> &pieces) {
    double total = polylineLength(strip.base), s = bricks.spacing;
    double fit = std::round((total - s) / (bricks.brickWidth + s));
    if (fit > kMostKlinkerBricksPerStrip) {
        throw std::invalid_argument(
            fmt::format("klinker brickWidth {} and spacing {} ask {} bricks along a {} m casing strip, more than {}",
                        bricks.brickWidth, s, fit, total, kMostKlinkerBricksPerStrip));
    }
    auto count = size_t(std::max(1.0, fit));
    double brick = (total - double(count + 1) * s) / double(count);
    auto append = [&](double from, double to, double front, PieceKind kind) {
        pieces.push_back(piece(stripPolygon(subPolyline(strip.base, from, to), strip.offset), 0, front, kind));
    };
    if (brick <= 0) {
        append(0, total, strip.overhang, PieceKind::KlinkerMortar);
        return;
    }
    double at = 0;
    for (size_t i = 0; i < count; ++i) {
        if (s > 0) append(at, at + s, strip.overhang, PieceKind::KlinkerMortar);
        double start = at + s, end = s == 0 && i + 1 == count ? total : start + brick;
        append(start, end, strip.overhang + bricks.brickOverhang, PieceKind::KlinkerBrick);
        at = end;
    }
    if (s > 0) append(at, total, strip.overhang, PieceKind::KlinkerMortar);
}

PieceKind kindOf(CasingStyle style) { return style == CasingStyle::Einfach ? PieceKind::Casing : PieceKind::Cornice; }

// How far edge k's refinement and casing reach into the opening, as a fraction across it.
double reach(const RefinedEdge &edge, const EdgeCasing &casing) {
    return edge.distB + edge.size + (edge.size > 0 ? 0 : casing.thickness);
}

// The strips of an edge with a `size` band: they stay inside F_Kantenzug (Def 5.14).
void appendBandStrips(const RefinedEdge &edge, const EdgeCasing &casing, CasingStyle style, const char *name,
                      std::vector<Strip> &strips, std::vector<FacadePiece> &infill) {
    double t = casing.thickness / edge.size;  // the casing as a fraction of the band
    Vec2d offset = edge.outward * t;
    if (style == CasingStyle::Doppelgesims) {
        if (2 * t > 1) throw std::invalid_argument(fmt::format("{} edge: two casings do not fit its size band", name));
        strips.push_back({{edge.l, edge.r}, offset, casing.overhang, PieceKind::Cornice});
        std::vector<Vec2d> gable = edge.polyline(1 - 2 * t, t);
        strips.push_back({gable, offset, casing.overhang, PieceKind::GableCornice});
        if (std::abs(signedArea(gable)) > kSliver) infill.push_back(piece(gable, 0, 0, PieceKind::Infill));
        return;
    }
    if (t > 1) throw std::invalid_argument(fmt::format("{} edge: its casing does not fit its size band", name));
    strips.push_back({withoutRepeats(edge.polyline(1 - t, 0)), offset, casing.overhang, kindOf(style)});
}

// The strip of a straight edge, inward from the refined edge; a non-dominant one shrinks by the
// casings of its neighbours that lie inside the opening (L1351).
Strip straightStrip(const RefinedOpening &opening, const Casing &casing, int k) {
    const RefinedEdge &edge = opening.edges[size_t(k)];
    Vec2d l = edge.l, r = edge.r;
    if (!edge.dominant) {
        size_t before = size_t((k + 3) % 4), after = size_t((k + 1) % 4);
        if (opening.edges[before].size == 0) l = l + opening.inward[before] * casing.edges[before].thickness;
        if (opening.edges[after].size == 0) r = r + opening.inward[after] * casing.edges[after].thickness;
        if (dot(r - l, edge.r - edge.l) <= 0) {
            throw std::invalid_argument(
                fmt::format("{} edge: the neighbouring casings leave it no length", kEdgeNames[k]));
        }
    }
    const EdgeCasing &c = casing.edges[size_t(k)];
    return {{l, r}, opening.inward[size_t(k)] * c.thickness, c.overhang, kindOf(casing.style)};
}

std::vector<FacadePiece> casingPieces(const RefinedOpening &opening, const Casing &casing) {
    for (int k = 0; k < 4; ++k) {
        double t = casing.edges[size_t(k)].thickness;
        if (!(t >= 0 && t <= 1)) {
            throw std::invalid_argument(fmt::format("{} edge: casing thickness {} is outside [0,1]", kEdgeNames[k], t));
        }
        double o = casing.edges[size_t(k)].overhang;
        if (!std::isfinite(o)) {
            throw std::invalid_argument(fmt::format("{} edge: casing overhang {} is not finite", kEdgeNames[k], o));
        }
    }
    if (casing.style == CasingStyle::Klinker) checkKlinker(casing.klinker);
    for (int k = 0; k < 2; ++k) {
        size_t o = size_t(k + 2);
        if (reach(opening.edges[size_t(k)], casing.edges[size_t(k)]) + reach(opening.edges[o], casing.edges[o]) >= 1) {
            throw std::invalid_argument(
                fmt::format("the {} and {} casings meet inside the opening", kEdgeNames[k], kEdgeNames[k + 2]));
        }
    }
    std::vector<Strip> strips;
    std::vector<FacadePiece> pieces;
    for (int k = 0; k < 4; ++k) {
        const RefinedEdge &edge = opening.edges[size_t(k)];
        const EdgeCasing &c = casing.edges[size_t(k)];
        if (c.thickness == 0) continue;
        if (edge.size > 0) {
            appendBandStrips(edge, c, casing.style, kEdgeNames[k], strips, pieces);
        } else {
            strips.push_back(straightStrip(opening, casing, k));
        }
    }
    for (const Strip &strip : strips) {
        if (casing.style == CasingStyle::Klinker) {
            appendKlinker(strip, casing.klinker, pieces);
        } else {
            pieces.push_back(piece(stripPolygon(strip.base, strip.offset), 0, strip.overhang, strip.kind));
        }
    }
    for (const FacadePiece &p : pieces) {
        // Exactly, as the polygon sets need it: a sliver's orientation can be lost in rounding.
        if (p.polygon.size() < 3 || !isSimpleCounterClockwise(p.polygon)) {
            throw std::invalid_argument("a casing piece crosses itself or has no area");
        }
    }
    return pieces;
}

std::vector<ExactPolygonWithHoles> polygonsOf(const ExactSet &set) {
    std::vector<ExactPolygonWithHoles> out;
    set.polygons_with_holes(std::back_inserter(out));
    return out;
}

// Drops points where the outline runs straight on, so that each frame edge is a whole side.
std::vector<Vec2d> withoutStraightPoints(const std::vector<Vec2d> &polygon) {
    std::vector<Vec2d> out;
    size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        Vec2d a = polygon[(i + n - 1) % n], b = polygon[i], c = polygon[(i + 1) % n];
        Vec2d in = b - a, on = c - b;
        bool straight = std::abs(cross(in, on)) <= 1e-9 * length(in) * length(on) && dot(in, on) > 0;
        if (!straight) out.push_back(b);
    }
    return out;
}

// The clear opening moved inward by `inset[i]` along each edge i, with mitred corners.
std::vector<Vec2d> insetPolygon(const std::vector<Vec2d> &polygon, const std::vector<double> &inset) {
    size_t n = polygon.size();
    std::vector<Vec2d> out;
    for (size_t i = 0; i < n; ++i) {
        size_t h = (i + n - 1) % n;
        Vec2d d0 = polygon[i] - polygon[h], d1 = polygon[(i + 1) % n] - polygon[i];
        Vec2d n0 = Vec2d{-d0.y, d0.x} * (1 / length(d0)), n1 = Vec2d{-d1.y, d1.x} * (1 / length(d1));
        // The point p with dot(p − polygon[i], n0) = inset[h] and dot(p − polygon[i], n1) = inset[i].
        double det = n0.x * n1.y - n0.y * n1.x;
        Vec2d p{(inset[h] * n1.y - n0.y * inset[i]) / det, (n0.x * inset[i] - inset[h] * n1.x) / det};
        // Edges that turn back on each other (a sliver the casing leaves) have no mitre point.
        if (!(std::isfinite(p.x) && std::isfinite(p.y))) {
            throw std::invalid_argument("the frame cannot follow a corner of the clear opening that turns back");
        }
        out.push_back(polygon[i] + p);
    }
    return out;
}

// Whether edge i of a counter-clockwise outline is a door's threshold: level, at the bottom.
bool isThreshold(const std::vector<Vec2d> &polygon, size_t i) {
    Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    double bottom = std::min_element(polygon.begin(), polygon.end(), [](Vec2d p, Vec2d q) { return p.y < q.y; })->y;
    return b.x > a.x && std::abs(a.y - bottom) <= 1e-9 && std::abs(b.y - bottom) <= 1e-9;
}

void appendSetPieces(const ExactSet &set, double back, double front, PieceKind kind, std::vector<FacadePiece> &pieces) {
    for (const ExactPolygonWithHoles &p : polygonsOf(set)) {
        VEDUTA_CHECK(p.number_of_holes() == 0, "a bar or pane has a hole");
        std::vector<Vec2d> polygon = fromExact(p.outer_boundary());
        if (signedArea(polygon) > kSliver) pieces.push_back({polygon, back, front, kind});
    }
}

ExactPolygon rectangle(double x0, double y0, double x1, double y1) {
    return toExact({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

// Frame, bars and glass, or frame and door, in the clear opening (Def 5.15).
void appendWindow(const std::vector<Vec2d> &clearOutline, const RefinedOpening &opening, const WindowFrame &frame,
                  std::vector<FacadePiece> &pieces) {
    if (!(frame.thickness >= 0 && frame.thickness <= 1)) {
        throw std::invalid_argument(fmt::format("frame thickness {} is outside [0,1]", frame.thickness));
    }
    if (!std::isfinite(frame.overhang) || !std::isfinite(frame.paneDepth)) {
        throw std::invalid_argument(
            fmt::format("frame overhang {} and paneDepth {} must be finite", frame.overhang, frame.paneDepth));
    }
    bool door = opening.kind == OpeningKind::Door;
    std::vector<Vec2d> clear = withoutStraightPoints(clearOutline);
    double width = frame.thickness * length(opening.coarse.br - opening.coarse.bl);
    std::vector<double> inset(clear.size(), width);
    for (size_t i = 0; i < clear.size(); ++i) {
        if (door && isThreshold(clear, i)) inset[i] = 0;
    }
    std::vector<Vec2d> inner = width > 0 ? insetPolygon(clear, inset) : clear;
    if (!isSimpleCounterClockwise(inner)) throw std::invalid_argument("the frame is too thick for the opening");
    for (size_t i = 0; i < clear.size() && width > 0; ++i) {
        if (inset[i] == 0) continue;
        size_t j = (i + 1) % clear.size();
        std::vector<Vec2d> side{clear[i], clear[j], inner[j], inner[i]};
        if (!isSimpleCounterClockwise(side)) throw std::invalid_argument("the frame is too thick for the opening");
        pieces.push_back({side, frame.paneDepth, frame.overhang, PieceKind::Frame});
    }
    if (door) {
        pieces.push_back({inner, frame.paneDepth, frame.paneDepth, PieceKind::Door});
        return;
    }
    ExactSet glass(toExact(inner));
    if (width > 0) {
        auto [minX, maxX] = std::minmax_element(inner.begin(), inner.end(), [](Vec2d p, Vec2d q) { return p.x < q.x; });
        auto [minY, maxY] = std::minmax_element(inner.begin(), inner.end(), [](Vec2d p, Vec2d q) { return p.y < q.y; });
        double midX = (minX->x + maxX->x) / 2, transomY = lerp(*minY, *maxY, kTransomHeight).y;
        ExactPolygon mullion = rectangle(midX - width / 2, minY->y, midX + width / 2, maxY->y);
        ExactPolygon transom = rectangle(minX->x, transomY - width / 2, maxX->x, transomY + width / 2);
        ExactSet verticalBar(glass), horizontalBar(glass);
        verticalBar.intersection(mullion);
        horizontalBar.intersection(transom);
        horizontalBar.difference(mullion);
        glass.difference(mullion);
        glass.difference(transom);
        appendSetPieces(verticalBar, frame.paneDepth, frame.overhang, PieceKind::Bar, pieces);
        appendSetPieces(horizontalBar, frame.paneDepth, frame.overhang, PieceKind::Bar, pieces);
    }
    appendSetPieces(glass, frame.paneDepth, frame.paneDepth, PieceKind::Pane, pieces);
}

MaterialId materialOf(PieceKind kind, const PieceMaterials &m) {
    switch (kind) {
    case PieceKind::Casing: return m.casing;
    case PieceKind::Cornice:
    case PieceKind::GableCornice: return m.cornice;
    case PieceKind::Infill: return m.wall;
    case PieceKind::KlinkerBrick: return m.brick;
    case PieceKind::KlinkerMortar: return m.mortar;
    case PieceKind::Frame:
    case PieceKind::Bar: return m.frame;
    case PieceKind::Pane: return m.pane;
    case PieceKind::Door: return m.door;
    }
    VEDUTA_UNREACHABLE("piece kind");
}

Vec3f pointOf(const WallFrame3d &f, Vec3f outward, Vec2d p, double depth) {
    return f.origin + f.along * float(p.x) + f.up * float(p.y) + outward * float(depth);
}

void appendTriangle(Mesh &mesh, Vec3f a, Vec3f b, Vec3f c, MaterialId material) {
    auto first = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
    mesh.triangleMaterials.push_back(material);
}

void appendFrontFace(Mesh &mesh, const FacadePiece &p, const WallFrame3d &f, Vec3f outward, MaterialId material) {
    CGAL::Polygon_2<Inexact> polygon;
    for (Vec2d v : p.polygon) polygon.push_back(Inexact::Point_2(v.x, v.y));
    std::vector<CGAL::Polygon_2<Inexact>> triangles;
    CGAL::Polygon_triangulation_decomposition_2<Inexact>()(CGAL::Polygon_with_holes_2<Inexact>(polygon),
                                                           std::back_inserter(triangles));
    for (const auto &t : triangles) {
        std::array<Vec3f, 3> corners;
        for (size_t i = 0; i < 3; ++i) corners[i] = pointOf(f, outward, {t[int(i)].x(), t[int(i)].y()}, p.front);
        if (t.orientation() == CGAL::CLOCKWISE) std::swap(corners[1], corners[2]);
        appendTriangle(mesh, corners[0], corners[1], corners[2], material);
    }
}

bool isFinite(Vec2d p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// refineOpening gives finite points, but a profile may still make the outline cross itself,
// which the polygon sets below cannot take; a hand-made RefinedOpening may hold anything.
void checkOpening(const RefinedOpening &opening) {
    for (int k = 0; k < 4; ++k) {
        const RefinedEdge &e = opening.edges[size_t(k)];
        bool finite = isFinite(e.l) && isFinite(e.r) && isFinite(e.outward) && isFinite(opening.inward[size_t(k)]) &&
            std::all_of(e.profile.begin(), e.profile.end(), isFinite);
        if (!finite) throw std::invalid_argument(fmt::format("{} edge: a point is not finite", kEdgeNames[k]));
    }
    std::vector<Vec2d> outline = opening.outline();
    if (outline.size() < 3 || !isSimpleCounterClockwise(outline)) {
        throw std::invalid_argument("the opening's outline crosses itself or has no area");
    }
}

}  // namespace

OpeningPieces buildOpeningPieces(const RefinedOpening &opening, const Casing &casing, const WindowFrame &frame) {
    checkOpening(opening);
    OpeningPieces result;
    result.pieces = casingPieces(opening, casing);
    ExactSet hole(toExact(opening.outline()));
    for (const FacadePiece &p : result.pieces) hole.join(toExact(p.polygon));
    std::vector<ExactPolygonWithHoles> holeParts = polygonsOf(hole);
    // A profile that turns back can make a band's casing leave the opening or close a gap beside it.
    if (holeParts.size() != 1 || holeParts[0].number_of_holes() > 0) {
        throw std::invalid_argument("the casing pieces and the opening do not make one hole without gaps");
    }
    result.hole = fromExact(holeParts[0].outer_boundary());

    ExactSet clear(hole);
    for (const FacadePiece &p : result.pieces) clear.difference(toExact(p.polygon));
    std::vector<ExactPolygonWithHoles> clearParts = polygonsOf(clear);
    if (clearParts.empty()) throw std::invalid_argument("the casing fills the whole opening");
    std::sort(clearParts.begin(), clearParts.end(), [](const auto &a, const auto &b) {
        return CGAL::abs(a.outer_boundary().area()) > CGAL::abs(b.outer_boundary().area());
    });
    for (const ExactPolygonWithHoles &part : clearParts) {
        if (part.number_of_holes() > 0) throw std::invalid_argument("the casing leaves an island in the opening");
    }
    appendWindow(fromExact(clearParts[0].outer_boundary()), opening, frame, result.pieces);
    // Gaps the casing leaves beside the clear opening (where a neighbour's refinement juts out)
    // are glazed too, so the hole shows no wall behind it.
    for (size_t i = 1; i < clearParts.size(); ++i) {
        std::vector<Vec2d> gap = fromExact(clearParts[i].outer_boundary());
        if (signedArea(gap) > kSliver)
            result.pieces.push_back({gap, frame.paneDepth, frame.paneDepth, PieceKind::Pane});
    }
    return result;
}

Mesh extrudePieces(const std::vector<FacadePiece> &pieces, const WallFrame3d &frame, const PieceMaterials &materials) {
    for (Vec3f v : {frame.origin, frame.along, frame.up}) {
        if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
            throw std::invalid_argument("wall frame: a vector is not finite");
        }
    }
    // The triangulation takes only simple polygons; NaN would reach the mesh.
    for (size_t i = 0; i < pieces.size(); ++i) {
        const FacadePiece &p = pieces[i];
        bool finite = std::isfinite(p.back) && std::isfinite(p.front) &&
            std::all_of(p.polygon.begin(), p.polygon.end(), isFinite);
        if (!finite || p.polygon.size() < 3 || !isSimpleCounterClockwise(p.polygon)) {
            throw std::invalid_argument(fmt::format("piece {}: not a finite simple counter-clockwise polygon", i));
        }
    }
    Mesh mesh;
    Vec3f outward = cross(frame.along, frame.up);
    for (const FacadePiece &p : pieces) {
        MaterialId material = materialOf(p.kind, materials);
        appendFrontFace(mesh, p, frame, outward, material);
        if (p.front == p.back) continue;
        for (size_t i = 0; i < p.polygon.size(); ++i) {
            Vec2d a = p.polygon[i], b = p.polygon[(i + 1) % p.polygon.size()];
            Vec3f a0 = pointOf(frame, outward, a, p.back), b0 = pointOf(frame, outward, b, p.back);
            Vec3f a1 = pointOf(frame, outward, a, p.front), b1 = pointOf(frame, outward, b, p.front);
            appendTriangle(mesh, a0, b0, b1, material);
            appendTriangle(mesh, a0, b1, a1, material);
        }
    }
    return mesh;
}

Mesh revealMesh(const std::vector<Vec2d> &hole, const WallFrame3d &frame, double depth, MaterialId material) {
    FacadePiece back{hole, -depth, -depth, PieceKind::Infill};
    PieceMaterials materials;
    materials.wall = material;
    Mesh mesh = extrudePieces({back}, frame, materials);
    Vec3f outward = cross(frame.along, frame.up);
    // Each side seen from inside the opening: the reverse of extrudePieces's outward winding.
    for (size_t i = 0; i < hole.size(); ++i) {
        Vec2d a = hole[i], b = hole[(i + 1) % hole.size()];
        Vec3f a0 = pointOf(frame, outward, a, 0), b0 = pointOf(frame, outward, b, 0);
        Vec3f a1 = pointOf(frame, outward, a, -depth), b1 = pointOf(frame, outward, b, -depth);
        appendTriangle(mesh, a0, b0, b1, material);
        appendTriangle(mesh, a0, b1, a1, material);
    }
    return mesh;
}

}  // namespace veduta
