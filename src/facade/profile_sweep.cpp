#include "facade/profile_sweep.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>

#include "core/check.h"
#include "facade/frieze.h"

namespace veduta {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Exact_predicates_tag: a profile may cross itself, and its cap still triangulates.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_2<Kernel>,
        CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>>,
    CGAL::Exact_predicates_tag>;

Vec2d unit(Vec2d v) { return v * (1 / length(v)); }
Vec2d rightOf(Vec2d direction) { return {direction.y, -direction.x}; }
Vec3f toVec3f(Vec2d plan, double z) { return {float(plan.x), float(plan.y), float(z)}; }

// A command's strip of the profile: its points (x out, y up, metres), the normal at each (out
// of the material: right of the travel), the profile length to each, and its textures.
struct Band {
    std::vector<Vec2d> points, normals;
    std::vector<double> along;
    std::array<int, 3> textures{-1, -1, -1};
};

std::vector<Band> bandsOf(const CorniceDescription &cornice, const ProfileOutline &outline) {
    std::vector<Band> bands;
    size_t first = 0;
    double along = 0;
    for (size_t c = 0; c < outline.commandEnds.size(); ++c) {
        Band band;
        band.textures = cornice.profile.commands[c].textures;
        size_t last = outline.commandEnds[c];
        for (size_t i = first; i <= last; ++i) {
            if (i > first) along += length(outline.points[i] - outline.points[i - 1]);
            // Averaging the neighbouring segments' normals within the band: flat on a line,
            // smooth over an arc.
            Vec2d normal{0, 0};
            if (i > first) normal = normal + rightOf(unit(outline.points[i] - outline.points[i - 1]));
            if (i < last) normal = normal + rightOf(unit(outline.points[i + 1] - outline.points[i]));
            band.points.push_back(outline.points[i]);
            band.normals.push_back(unit(normal));
            band.along.push_back(along);
        }
        bands.push_back(band);
        first = last;
    }
    return bands;
}

// A cross section across an edge: a profile point o metres out lies `base + o * slope` along it.
struct Column {
    double base = 0, slope = 0;
};

class CorniceBuilder {
  public:
    CorniceBuilder(const CorniceDescription &cornice, const SweepPath &path, const SweepOptions &options) :
        cornice_(cornice), baseHeight_(path.baseHeight), options_(options) {}

    void addBand(const RunEdge &edge, const Band &band) {
        Column mitreStart{0, edge.startSlope}, mitreEnd{edge.length, edge.endSlope};
        // A band whose profile length is lost in the rounding of the length before it (a step of
        // 1e-8 after 1e8 units of profile) has no height to lay a texture's aspect on: untextured.
        double stripHeight = band.along.back() - band.along.front();
        if (band.textures == std::array<int, 3>{-1, -1, -1} || !(stripHeight > 0)) {
            addPiece(edge, band, mitreStart, mitreEnd, -1);
            return;
        }
        // The straight stretch between the mitres, where the frieze is laid (frieze.h).
        double straightStart = 0, straightEnd = edge.length;
        for (Vec2d point : band.points) {
            straightStart = std::max(straightStart, point.x * edge.startSlope);
            straightEnd = std::min(straightEnd, edge.length + point.x * edge.endSlope);
        }
        std::vector<FriezePiece> pieces = layFrieze(std::max(0.0, straightEnd - straightStart), stripHeight,
                                                    band.textures, cornice_.textures, options_.imageAspect);
        Column from = mitreStart;
        for (size_t i = 0; i < pieces.size(); ++i) {
            Column to = i + 1 == pieces.size() ? mitreEnd : Column{straightStart + pieces[i].to, 0};
            addPiece(edge, band, from, to, pieces[i].texture);
            from = to;
        }
    }

    // Caps an open run's end: the profile's cross section closed along the wall.
    void addCap(const RunEdge &edge, const ProfileOutline &outline, bool atEnd) {
        std::vector<Vec2d> polygon = outline.points;
        if (polygon.back().x != 0) polygon.push_back({0, polygon.back().y});
        if (polygon.front().x != 0) polygon.push_back({0, polygon.front().y});
        Cdt cdt;
        for (size_t i = 0; i < polygon.size(); ++i) {
            Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            if (!(a == b)) cdt.insert_constraint(Kernel::Point_2(a.x, a.y), Kernel::Point_2(b.x, b.y));
        }
        markNesting(cdt);
        Vec2d foot = atEnd ? edge.start + edge.direction * edge.length : edge.start;
        Vec3f facing = toVec3f(atEnd ? edge.direction : edge.direction * -1.0, 0);
        for (auto face : cdt.finite_face_handles()) {
            if (face->info() % 2 == 0) continue;
            std::array<Vec3f, 3> corners;
            std::array<Vec2f, 3> uvs;
            for (int k = 0; k < 3; ++k) {
                Kernel::Point_2 p = face->vertex(k)->point();
                corners[k] = toVec3f(foot + edge.normal * p.x(), baseHeight_ + p.y());
                uvs[k] = {float(p.x()), float(p.y())};
            }
            if (dot(cross(corners[1] - corners[0], corners[2] - corners[0]), facing) < 0) {
                std::swap(corners[1], corners[2]);
                std::swap(uvs[1], uvs[2]);
            }
            uint32_t first = uint32_t(mesh().positions.size());
            for (int k = 0; k < 3; ++k) addVertex(corners[k], facing, uvs[k]);
            addTriangle(first, first + 1, first + 2, -1);
        }
    }

    SweptCornice take() { return std::move(result_); }

  private:
    Mesh &mesh() { return result_.mesh; }

    void addVertex(Vec3f position, Vec3f normal, Vec2f uv) {
        mesh().positions.push_back(position);
        mesh().normals.push_back(normal);
        mesh().uvs.push_back(uv);
    }

    void addTriangle(uint32_t a, uint32_t b, uint32_t c, int texture) {
        mesh().indices.insert(mesh().indices.end(), {a, b, c});
        mesh().triangleMaterials.push_back(kNoMaterial);
        result_.triangleTextures.push_back(texture);
    }

    // The band between two columns of one edge: two vertices per profile point, a quad between
    // neighbouring points.
    void addPiece(const RunEdge &edge, const Band &band, Column from, Column to, int texture) {
        uint32_t first = uint32_t(mesh().positions.size());
        for (size_t j = 0; j < band.points.size(); ++j) {
            Vec2d point = band.points[j];
            Vec3f normal = toVec3f(edge.normal * band.normals[j].x, band.normals[j].y);
            for (bool left : {true, false}) {
                Column column = left ? from : to;
                double s = column.base + point.x * column.slope;
                Vec3f position =
                    toVec3f(edge.start + edge.direction * s + edge.normal * point.x, baseHeight_ + point.y);
                addVertex(position, normal, uvAt(edge, band, j, s, texture, left));
            }
        }
        for (uint32_t j = 0; j + 1 < band.points.size(); ++j) {
            uint32_t a = first + 2 * j, b = a + 1, c = a + 3, d = a + 2;
            addTriangle(a, b, c, texture);
            addTriangle(a, c, d, texture);
        }
    }

    Vec2f uvAt(const RunEdge &edge, const Band &band, size_t j, double s, int texture, bool left) const {
        if (texture < 0) return {float(edge.runStart + s), float(band.along[j])};
        const TextureRegion &region = cornice_.textures[size_t(texture)];
        double fraction = (band.along[j] - band.along.front()) / (band.along.back() - band.along.front());
        return {float(left ? region.left : region.right),
                float(region.bottom + (region.top - region.bottom) * fraction)};
    }

    // Gives each face the number of constraints crossed from the outside: odd = inside.
    static void markNesting(Cdt &cdt) {
        for (auto face : cdt.all_face_handles()) face->info() = -1;
        std::deque<std::pair<Cdt::Face_handle, int>> queue{{cdt.infinite_face(), 0}};
        while (!queue.empty()) {
            auto [face, level] = queue.front();
            queue.pop_front();
            if (face->info() != -1) continue;
            face->info() = level;
            for (int i = 0; i < 3; ++i) {
                Cdt::Face_handle next = face->neighbor(i);
                if (next->info() != -1) continue;
                if (cdt.is_constrained({face, i})) queue.push_back({next, level + 1});
                else queue.push_front({next, level});
            }
        }
    }

    const CorniceDescription &cornice_;
    double baseHeight_;
    const SweepOptions &options_;
    SweptCornice result_;
};

}  // namespace

std::vector<RunEdge> runEdges(const SweepPath &path) {
    size_t count = path.points.size();
    VEDUTA_CHECK(count >= (path.closed ? 3u : 2u), "a run has enough points");
    std::vector<RunEdge> edges;
    std::vector<Vec2d> points = path.points;
    if (path.outward == OutwardSide::Left) std::reverse(points.begin(), points.end());
    size_t edgeCount = path.closed ? count : count - 1;
    double along = 0;
    for (size_t i = 0; i < edgeCount; ++i) {
        Vec2d step = points[(i + 1) % count] - points[i];
        VEDUTA_CHECK(length(step) > 0, "a run has no repeated points");
        RunEdge edge{points[i], unit(step), rightOf(unit(step)), length(step), along};
        along += edge.length;
        edges.push_back(edge);
    }
    double leastCos = std::cos(kSweepTurnLimit / 2 * std::numbers::pi / 180);
    // The mitre between edges a and b: the bisector of their normals, and each edge's slope.
    auto mitre = [&](RunEdge &before, RunEdge &after) {
        Vec2d bisector = before.normal + after.normal;
        VEDUTA_CHECK(length(bisector) > 0, "a run does not turn back on itself");
        bisector = unit(bisector);
        double stretch = dot(bisector, after.normal);
        VEDUTA_CHECK(stretch >= leastCos, "a run turns by at most kSweepTurnLimit");
        before.endSlope = dot(bisector, before.direction) / stretch;
        after.startSlope = dot(bisector, after.direction) / stretch;
    };
    for (size_t i = 0; i + 1 < edgeCount; ++i) mitre(edges[i], edges[i + 1]);
    if (path.closed) mitre(edges.back(), edges.front());
    return edges;
}

std::vector<Vec2d> offsetLine(const SweepPath &path, double offset) {
    std::vector<RunEdge> edges = runEdges(path);
    std::vector<Vec2d> line;
    for (const RunEdge &edge : edges)
        line.push_back(edge.start + edge.direction * (offset * edge.startSlope) + edge.normal * offset);
    if (!path.closed) {
        const RunEdge &last = edges.back();
        line.push_back(last.start + last.direction * (last.length + offset * last.endSlope) + last.normal * offset);
    }
    if (path.outward == OutwardSide::Left) std::reverse(line.begin(), line.end());
    return line;
}

SweptCornice sweepCornice(const CorniceDescription &cornice, const ProfileOutline &outline, const SweepPath &path,
                          const SweepOptions &options) {
    VEDUTA_CHECK(outline.commandEnds.size() == cornice.profile.commands.size(), "the outline is the cornice's");
    VEDUTA_CHECK(options.imageAspect > 0, "images have an aspect");
    std::vector<RunEdge> edges = runEdges(path);
    std::vector<Band> bands = bandsOf(cornice, outline);
    CorniceBuilder builder(cornice, path, options);
    for (const RunEdge &edge : edges)
        for (const Band &band : bands) builder.addBand(edge, band);
    if (options.closeEnds && !path.closed) {
        builder.addCap(edges.front(), outline, false);
        builder.addCap(edges.back(), outline, true);
    }
    return builder.take();
}

}  // namespace veduta
