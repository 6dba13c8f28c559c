#include "slg/building_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_triangulation_decomposition_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include "slg/atlas_uv.h"
#include "slg/ear_clipping.h"
#include "slg/face_sides.h"
#include "slg/stairs.h"

namespace veduta {

namespace {

using Triangles2d = std::vector<std::array<Vec2d, 3>>;

Vec3f at(Vec2d p, double z) { return {float(p.x), float(p.y), float(z)}; }

// Appends triangles to a mesh, each with its material. Texture coordinates count motifs, a
// motif being a square one storey high (§3.3): so a wall texture is one storey of wall, tiled
// along the walls (eq 35's tiled mapping) and up the storeys, and floors and roofs take the
// same squares across the plan; a door's and a pane's image is stretched over it once (the
// simple mapping).
class MeshWriter {
  public:
    MeshWriter(Mesh &mesh, double motif, double base) : mesh_(mesh), motif_(motif), base_(base) {}

    void triangle(Vec3f a, Vec3f b, Vec3f c, Vec2f ua, Vec2f ub, Vec2f uc, MaterialId material) {
        uint32_t first = uint32_t(mesh_.positions.size());
        for (auto [p, uv] : {std::pair{a, ua}, std::pair{b, ub}, std::pair{c, uc}}) {
            mesh_.positions.push_back(p);
            mesh_.uvs.push_back(uv);
        }
        mesh_.indices.insert(mesh_.indices.end(), {first, first + 1, first + 2});
        mesh_.triangleMaterials.push_back(material);
    }

    // A vertical quad over the segment a → b from z0 to z1, facing to the right of a → b, its
    // corners' coordinates in Listing 4's order (bottom left, bottom right, top right, top left).
    // Its two triangles share their diagonal's corners from the start, which leaves welding a
    // third less to do.
    void wall(Vec2d a, Vec2d b, double z0, double z1, const QuadUv &uv, MaterialId material) {
        auto first = uint32_t(mesh_.positions.size());
        mesh_.positions.insert(mesh_.positions.end(), {at(a, z0), at(b, z0), at(b, z1), at(a, z1)});
        for (const Uv &corner : uv) mesh_.uvs.push_back(lookupUv(corner));
        mesh_.indices.insert(mesh_.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
        mesh_.triangleMaterials.insert(mesh_.triangleMaterials.end(), 2, material);
    }

    // The tiled mapping of the stretch of wall from z0 to z1 between `from` and `to` metres
    // along the run of walls: the motif's rows for those heights above the base, counted on up
    // the storeys (the lookup wraps), so that storeys share their corners.
    QuadUv tiled(double from, double to, double z0, double z1) const {
        AtlasRect rows{{0, 1 - (z1 - base_) / motif_}, {1, 1 - (z0 - base_) / motif_}};
        return tiledMapping(rows, motif_, from, to);
    }

    // Counter-clockwise triangles at height z, facing up, or down when `down`.
    void horizontal(const Triangles2d &triangles, double z, bool down, MaterialId material) {
        for (auto [a, b, c] : triangles) {
            if (down) std::swap(b, c);
            triangle(at(a, z), at(b, z), at(c, z), plan(a), plan(b), plan(c), material);
        }
    }

    // A sloped triangle, its texture laid on it from above.
    void slope(Vec3f a, Vec3f b, Vec3f c, MaterialId material) {
        auto uv = [&](Vec3f p) { return plan({p.x, p.y}); };
        triangle(a, b, c, uv(a), uv(b), uv(c), material);
    }

  private:
    Vec2f plan(Vec2d p) const { return {float(p.x / motif_), float(p.y / motif_)}; }
    // The atlas counts v down from the image's top (L2188), the texture lookup up from its bottom.
    static Vec2f lookupUv(Uv uv) { return {float(uv.u), float(1 - uv.v)}; }

    Mesh &mesh_;
    double motif_, base_;
};

// The whole image of a door or a pane, stretched over it.
const QuadUv kStretched = simpleMapping(gridMotif(0, 0, 1, 1));

Triangles2d earTriangles(const Polygon2d &ccw) {
    Triangles2d triangles;
    for (auto [i, j, k] : clipEars(ccw)) triangles.push_back({ccw[i], ccw[j], ccw[k]});
    return triangles;
}

// §3.4's ear clipping takes no holes, and a corridor may run round an apartment: its pieces go
// through CGAL's constrained Delaunay triangulation of their rings, the faces inside kept. Two
// exact corners of a piece can round to one point, a constraint from a vertex to itself that the
// triangulation does not survive: such a point is kept once.
Triangles2d pieceTriangles(const std::vector<Polygon2d> &piece) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    auto ring = [](const Polygon2d &points) {
        CGAL::Polygon_2<Kernel> polygon;
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i] != points[(i + 1) % points.size()]) polygon.push_back({points[i].x, points[i].y});
        return polygon;
    };
    CGAL::Polygon_with_holes_2<Kernel> region(ring(piece.front()));
    for (size_t h = 1; h < piece.size(); ++h) region.add_hole(ring(piece[h]));
    std::vector<CGAL::Polygon_2<Kernel>> parts;
    CGAL::Polygon_triangulation_decomposition_2<Kernel>()(region, std::back_inserter(parts));
    auto point = [](const Kernel::Point_2 &p) { return Vec2d{p.x(), p.y()}; };
    Triangles2d triangles;
    for (const auto &t : parts) triangles.push_back({point(t.vertex(0)), point(t.vertex(1)), point(t.vertex(2))});
    return triangles;
}

// Eq 35's tiled mapping: a wall from a to b whose u is `u0` metres at a and runs on along it, so
// that the pieces cut from it (windows, a door) and the wall after it take the texture up where
// it left off.
struct WallRun {
    Vec2d a, b;
    double u0 = 0;

    double length() const { return veduta::length(b - a); }
    // Exactly a and b at the ends, so that neighbouring walls share their corners.
    Vec2d point(double s) const {
        double t = s / length();
        return a * (1 - t) + b * t;
    }
};

void piece(MeshWriter &out, const WallRun &wall, double s0, double s1, double z0, double z1, MaterialId material) {
    out.wall(wall.point(s0), wall.point(s1), z0, z1, out.tiled(wall.u0 + s0, wall.u0 + s1, z0, z1), material);
}

// Walls round a closed loop, each facing to the right of the way round; u runs on from the first
// point, its seam there.
void wallLoop(MeshWriter &out, const Polygon2d &loop, double z0, double z1, MaterialId material) {
    double u = 0;
    for (size_t i = 0; i < loop.size(); ++i) {
        WallRun wall{loop[i], loop[(i + 1) % loop.size()], u};
        piece(out, wall, 0, wall.length(), z0, z1, material);
        u += wall.length();
    }
}

double floorOf(int storey, const BuildingShape &shape) { return shape.base + storey * shape.storeyHeight; }

// A room's ceiling lies a slab below the next floor: under the top storey's flat roof it would
// otherwise share the roof's plane.
double ceilingOf(int storey, const BuildingShape &shape) { return floorOf(storey + 1, shape) - shape.slab; }

double topOf(const BuildingPlan &plan, const BuildingShape &shape) { return floorOf(plan.storeys, shape); }

void boxWalls(MeshWriter &out, const Polygon2d &footprint, const std::vector<size_t> &corners, double z0, double z1,
              MaterialId material) {
    Polygon2d sides;
    for (size_t c : corners) sides.push_back(footprint[c]);
    wallLoop(out, sides, z0, z1, material);
}

// §3.2's roofs: a gable (a wedge on four corners, its gables on the sides for eaves to the
// street, on the front and back for the gable to the street), a tent to the vertex mean where
// that lies inside, else flat.
void roof(MeshWriter &out, const Polygon2d &footprint, const std::vector<size_t> &corners, const BuildingShape &shape,
          double z, MaterialId material) {
    double ridge = z + shape.roofHeight;
    if (shape.roof == RoofKind::Gable && corners.size() == 4) {
        size_t k = shape.orientation == RoofOrientation::Giebelstaendig ? 0 : 1;
        auto q = [&](size_t i) { return footprint[corners[(k + i) % 4]]; };
        Vec2d m0 = (q(0) + q(1)) * 0.5, m2 = (q(2) + q(3)) * 0.5;
        out.slope(at(q(0), z), at(q(1), z), at(m0, ridge), material);
        out.slope(at(q(2), z), at(q(3), z), at(m2, ridge), material);
        for (auto [a, b, top, back] : {std::array{q(1), q(2), m2, m0}, std::array{q(3), q(0), m0, m2}}) {
            out.slope(at(a, z), at(b, z), at(top, ridge), material);
            out.slope(at(a, z), at(top, ridge), at(back, ridge), material);
        }
        return;
    }
    Vec2d apex = vertexMean(footprint);
    if (shape.roof != RoofKind::Flat && sideOf(footprint, apex) == Side::Inside) {
        for (size_t c = 0; c < corners.size(); ++c)
            out.slope(at(footprint[corners[c]], z), at(footprint[corners[(c + 1) % corners.size()]], z),
                      at(apex, ridge), material);
        return;
    }
    out.horizontal(earTriangles(footprint), z, false, material);
}

// A stretch along a wall, in metres from its start.
struct Opening {
    double from = 0, to = 0;
};

// The windows of the stretch [from, to] of a wall: centred in it as a group (plan_extension's
// rule).
std::vector<Opening> windowLayout(const WindowRule &rule, double from, double to) {
    int n = windowsThatFit(rule, to - from);
    double spacing = rule.arrangement == WindowArrangement::Contiguous ? 0 : rule.spacing;
    double s = from + (to - from - (n * rule.width + (n - 1) * spacing)) / 2;
    std::vector<Opening> windows;
    for (int i = 0; i < n; ++i, s += rule.width + spacing) windows.push_back({s, s + rule.width});
    return windows;
}

bool takesWindows(EdgeLocation location) { return location == EdgeLocation::Street || location == EdgeLocation::Gap; }

// The house door in footprint edge e on a storey: on the ground floor, where the plan's
// entrance is, when the door fits in the edge.
std::optional<Opening> houseDoor(const BuildingPlan &plan, const BuildingShape &shape, int storey, size_t e) {
    const PlanShape &footprint = plan.placement.footprint;
    Vec2d a = footprint.start(e), b = footprint.end(e);
    double total = length(b - a), s = dot(plan.storey.entrance - a, b - a) / total;
    Opening door{s - shape.doorWidth / 2, s + shape.doorWidth / 2};
    if (storey != 0 || !takesWindows(footprint.locations[e]) || door.from <= 0 || door.to >= total ||
        distanceToBoundary({a, b}, plan.storey.entrance) >= 1e-6)
        return std::nullopt;
    return door;
}

// The windows of footprint edge e on a storey, either side of the house door where it has it.
std::vector<Opening> shellWindows(const BuildingPlan &plan, const BuildingShape &shape, int storey, size_t e) {
    const PlanShape &footprint = plan.placement.footprint;
    if (!takesWindows(footprint.locations[e])) return {};
    double total = length(footprint.end(e) - footprint.start(e));
    std::optional<Opening> door = houseDoor(plan, shape, storey, e);
    if (!door) return windowLayout(shape.windows, 0, total);
    std::vector<Opening> windows = windowLayout(shape.windows, 0, door->from);
    std::ranges::copy(windowLayout(shape.windows, door->to, total), std::back_inserter(windows));
    return windows;
}

// One storey of the stretch [from, to] of a wall with its windows: each a sill, a pane and a
// lintel, wall between.
void windowedWall(MeshWriter &out, const WallRun &wall, double from, double to, const std::vector<Opening> &windows,
                  double z0, const BuildingShape &shape, const BuildingMaterials &m) {
    double z1 = z0 + shape.storeyHeight, sill = z0 + shape.sill, lintel = std::min(sill + shape.windowHeight, z1);
    double s = from;
    for (const Opening &window : windows) {
        if (window.from < from || window.to > to) continue;
        if (window.from > s) piece(out, wall, s, window.from, z0, z1, m.wall);
        if (shape.sill > 0) piece(out, wall, window.from, window.to, z0, sill, m.wall);
        out.wall(wall.point(window.from), wall.point(window.to), sill, lintel, kStretched, m.glass);
        if (lintel < z1) piece(out, wall, window.from, window.to, lintel, z1, m.wall);
        s = window.to;
    }
    if (to > s) piece(out, wall, s, to, z0, z1, m.wall);
}

// The outer walls storey by storey, u running on round each storey from the footprint's first
// point. On the ground floor the wall with the house door has it where the plan's entrance is,
// and windows on either side of it; the door's image is stretched over it.
void storeyWalls(MeshWriter &out, const BuildingPlan &plan, const BuildingShape &shape, const BuildingMaterials &m) {
    const PlanShape &footprint = plan.placement.footprint;
    for (int storey = 0; storey < plan.storeys; ++storey) {
        double z0 = floorOf(storey, shape), z1 = z0 + shape.storeyHeight, u = 0;
        for (size_t e = 0; e < footprint.size(); ++e) {
            WallRun wall{footprint.start(e), footprint.end(e), u};
            double total = wall.length();
            u += total;
            std::vector<Opening> windows = shellWindows(plan, shape, storey, e);
            std::optional<Opening> door = houseDoor(plan, shape, storey, e);
            if (!door) {
                windowedWall(out, wall, 0, total, windows, z0, shape, m);
                continue;
            }
            double top = std::min(z0 + shape.doorHeight, z1);
            windowedWall(out, wall, 0, door->from, windows, z0, shape, m);
            out.wall(wall.point(door->from), wall.point(door->to), z0, top, kStretched, m.door);
            piece(out, wall, door->from, door->to, top, z1, m.wall);
            windowedWall(out, wall, door->to, total, windows, z0, shape, m);
        }
    }
}

// A flight up from z0: each step its riser, facing down the flight, and its tread.
void stairs(MeshWriter &out, const Flight &flight, double z0, MaterialId material) {
    for (int i = 0; i < flight.risers; ++i) {
        Polygon2d step = tread(flight, i);
        double lower = z0 + i * flight.riser, upper = z0 + (i + 1) * flight.riser;
        out.wall(step[3], step[0], lower, upper, out.tiled(0, flight.width, lower, upper), material);
        out.horizontal(earTriangles(step), upper, false, material);
    }
}

// A room's wall from a to b with holes where windows of the shell lie behind it: each hole lined
// by its reveal, the wall's thickness round the window between the wall and the glass, `out`
// from the wall to the shell.
void wallWithHoles(MeshWriter &out, const WallRun &wall, const std::vector<Opening> &holes, double z0, double z1,
                   double sill, double lintel, Vec2d outward, MaterialId material) {
    double s = 0;
    for (const Opening &hole : holes) {
        piece(out, wall, s, hole.from, z0, z1, material);
        piece(out, wall, hole.from, hole.to, z0, sill, material);
        piece(out, wall, hole.from, hole.to, lintel, z1, material);
        Vec2d p = wall.point(hole.from), q = wall.point(hole.to);
        QuadUv jamb = out.tiled(0, length(outward), sill, lintel);
        out.wall(p, p + outward, sill, lintel, jamb, material);
        out.wall(q + outward, q, sill, lintel, jamb, material);
        Triangles2d reveal = earTriangles({p, q, q + outward, p + outward});
        out.horizontal(reveal, sill, false, material);
        out.horizontal(reveal, lintel, true, material);
        s = hole.to;
    }
    piece(out, wall, s, wall.length(), z0, z1, material);
}

// The walls of a room on a storey, up to z1, facing into it, u running on round it. Where a wall
// runs inside the shell, the shell's windows on that storey leave holes in it, so that the room
// shows through the glass (§3.5) rather than the back of its wall.
void roomWalls(MeshWriter &out, const SpaceFloor &floor, const BuildingPlan &plan, const BuildingShape &shape,
               int storey, double z1, MaterialId material) {
    const PlanShape &shell = plan.placement.footprint;
    double z0 = floorOf(storey, shape), sill = z0 + shape.sill;
    double lintel = std::min(sill + shape.windowHeight, z0 + shape.storeyHeight);
    size_t n = floor.points.size();
    double u = 0;
    // Counter-clockwise edge k runs as its shell edge does; the wall facing in goes the other way.
    for (size_t k = n; k-- > 0;) {
        WallRun wall{floor.points[(k + 1) % n], floor.points[k], u};
        u += wall.length();
        std::vector<Opening> holes;
        Vec2d along = normalized(wall.b - wall.a);
        if (std::optional<size_t> e = floor.shellEdges[k]) {
            Vec2d start = shell.start(*e), direction = normalized(shell.end(*e) - start);
            double at = dot(wall.a - start, direction);
            if (std::abs(cross(along, direction)) < 1e-9)
                for (const Opening &window : shellWindows(plan, shape, storey, *e)) {
                    Opening hole{std::max(at - window.to, 0.0), std::min(at - window.from, wall.length())};
                    if (hole.to > hole.from) holes.insert(holes.begin(), hole);
                }
        }
        wallWithHoles(out, wall, holes, z0, z1, sill, lintel, leftNormal(along) * shape.wallThickness, material);
    }
}

// §3.5's interiors: a room's floor, ceiling and walls on every storey, the walls facing into it.
// The stairwell, where its flight fits, is open from the ground floor's floor to the top
// storey's ceiling as the thesis draws it (§3.2: a floor only at the bottom, a ceiling only at
// the top): each flight stands over the one below, so a floor on the storeys between would be cut
// where that one comes up, and the shaft's walls run on through the slabs between storeys to
// close it. A flight goes up from every storey but the top.
void room(MeshWriter &out, const SpaceFloor &floor, bool stairwell, const BuildingPlan &plan,
          const BuildingShape &shape, MaterialId material) {
    Triangles2d triangles = earTriangles(floor.points);
    std::optional<Flight> flight = stairwell ? straightFlight(floor.points, shape.storeyHeight) : std::nullopt;
    for (int storey = 0; storey < plan.storeys; ++storey) {
        bool up = flight && storey + 1 < plan.storeys, fromBelow = flight && storey > 0;
        double z0 = floorOf(storey, shape), z1 = up ? floorOf(storey + 1, shape) : ceilingOf(storey, shape);
        if (!fromBelow) out.horizontal(triangles, z0, false, material);
        if (!up) out.horizontal(triangles, z1, true, material);
        roomWalls(out, floor, plan, shape, storey, z1, material);
        if (up) stairs(out, *flight, z0, material);
    }
}

void rooms(MeshWriter &out, const BuildingPlan &plan, const BuildingShape &shape, MaterialId material) {
    for (const ApartmentPlan &apartment : plan.storey.apartments)
        for (size_t r = 0; r < apartment.rooms.size(); ++r)
            if (auto floor = insideWalls(apartment.rooms[r], plan.placement.footprint, shape.wallThickness))
                room(out, *floor, apartment.stairwell == r, plan, shape, material);
}

// A face grown by half a wall all round: the space beside it keeps clear of that. The face
// itself where growing it folds.
PlanShape withWalls(const PlanShape &face, double wallThickness) {
    auto grown = moveEdges(face, std::vector<double>(face.size(), -wallThickness / 2), EdgeLocation::NeighbourRoom);
    return grown ? std::move(grown->shape) : face;
}

// What `faces` leave of `outline`, inside the walls: the outline moved in as a room's, less the
// faces with their walls.
void addCorridor(const PlanShape &outline, const std::vector<PlanShape> &faces, const PlanShape &shell,
                 double wallThickness, Triangles2d &triangles) {
    auto inside = insideWalls(outline, shell, wallThickness);
    if (!inside) return;
    std::vector<PlanShape> walled;
    for (const PlanShape &face : faces) walled.push_back(withWalls(face, wallThickness));
    for (const std::vector<Polygon2d> &piece : corridorPieces(inside->points, walled))
        std::ranges::copy(pieceTriangles(piece), std::back_inserter(triangles));
}

// §3.5's floors and ceilings of the corridors on every storey, as the rooms': the house
// corridor is what the apartments leave of the footprint, an apartment's corridor what its
// rooms leave of it.
void corridors(MeshWriter &out, const BuildingPlan &plan, const BuildingShape &shape, MaterialId material) {
    const PlanShape &shell = plan.placement.footprint;
    Triangles2d triangles;
    std::vector<PlanShape> apartments;
    for (const ApartmentPlan &apartment : plan.storey.apartments) {
        apartments.push_back(apartment.outline);
        addCorridor(apartment.outline, apartment.rooms, shell, shape.wallThickness, triangles);
    }
    addCorridor(shell, apartments, shell, shape.wallThickness, triangles);
    for (int storey = 0; storey < plan.storeys; ++storey) {
        out.horizontal(triangles, floorOf(storey, shape), false, material);
        out.horizontal(triangles, ceilingOf(storey, shape), true, material);
    }
}

}  // namespace

std::optional<size_t> shellEdgeUnder(const PlanShape &shell, Vec2d a, Vec2d b) {
    for (size_t e = 0; e < shell.size(); ++e) {
        Polygon2d edge{shell.start(e), shell.end(e)};
        if (distanceToBoundary(edge, a) < 1e-6 && distanceToBoundary(edge, b) < 1e-6) return e;
    }
    return std::nullopt;
}

std::optional<SpaceFloor> insideWalls(const PlanShape &space, const PlanShape &shell, double wallThickness) {
    std::vector<std::optional<size_t>> under;
    std::vector<double> inset;
    for (size_t e = 0; e < space.size(); ++e) {
        under.push_back(shellEdgeUnder(shell, space.start(e), space.end(e)));
        inset.push_back(under.back() ? wallThickness : wallThickness / 2);
    }
    auto inner = moveEdges(space, inset, EdgeLocation::NeighbourRoom);
    if (!inner) return std::nullopt;
    SpaceFloor floor{std::move(inner->shape.points), {}};
    for (size_t source : inner->source) floor.shellEdges.push_back(under[source]);
    return floor;
}

Mesh buildingMesh(const BuildingPlan &plan, const BuildingShape &shape, BuildingLod lod,
                  const BuildingMaterials &materials) {
    Mesh mesh;
    MeshWriter out(mesh, shape.storeyHeight, shape.base);
    const Polygon2d &footprint = plan.placement.footprint.points;
    // From point 0, the front's left end: a corner, where the first wall starts.
    std::vector<size_t> corners = turningPoints(footprint);
    double top = topOf(plan, shape);
    if (lod == BuildingLod::Box) boxWalls(out, footprint, corners, shape.base, top, materials.wall);
    else storeyWalls(out, plan, shape, materials);
    if (lod == BuildingLod::Rooms) {
        rooms(out, plan, shape, materials.interior);
        corridors(out, plan, shape, materials.interior);
    }
    roof(out, footprint, corners, shape, top, materials.roof);
    return weldVertices(mesh);
}

}  // namespace veduta
