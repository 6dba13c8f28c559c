#include "slg/building_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "slg/ear_clipping.h"
#include "slg/face_sides.h"

namespace veduta {

namespace {

Vec3f at(Vec2d p, double z) { return {float(p.x), float(p.y), float(z)}; }

// Appends triangles to a mesh, each with its material; texture coordinates are given per corner.
class MeshWriter {
  public:
    explicit MeshWriter(Mesh &mesh) : mesh_(mesh) {}

    void triangle(Vec3f a, Vec3f b, Vec3f c, Vec2f ua, Vec2f ub, Vec2f uc, MaterialId material) {
        uint32_t first = uint32_t(mesh_.positions.size());
        for (auto [p, uv] : {std::pair{a, ua}, std::pair{b, ub}, std::pair{c, uc}}) {
            mesh_.positions.push_back(p);
            mesh_.uvs.push_back(uv);
        }
        mesh_.indices.insert(mesh_.indices.end(), {first, first + 1, first + 2});
        mesh_.triangleMaterials.push_back(material);
    }

    // A vertical quad over the segment a → b from z0 to z1, facing to the right of a → b;
    // u runs along it from `u0` metres, v up from the ground.
    void wall(Vec2d a, Vec2d b, double z0, double z1, double u0, MaterialId material) {
        float u1 = float(u0 + length(b - a));
        Vec3f a0 = at(a, z0), b0 = at(b, z0), b1 = at(b, z1), a1 = at(a, z1);
        Vec2f ua0{float(u0), float(z0)}, ub0{u1, float(z0)}, ub1{u1, float(z1)}, ua1{float(u0), float(z1)};
        triangle(a0, b0, b1, ua0, ub0, ub1, material);
        triangle(a0, b1, a1, ua0, ub1, ua1, material);
    }

    // A counter-clockwise polygon at height z, facing up, or down when `down`.
    void polygon(const Polygon2d &ccw, double z, bool down, MaterialId material) {
        for (auto [i, j, k] : clipEars(ccw)) {
            Vec2d a = ccw[i], b = ccw[down ? k : j], c = ccw[down ? j : k];
            triangle(at(a, z), at(b, z), at(c, z), uvOf(a), uvOf(b), uvOf(c), material);
        }
    }

  private:
    static Vec2f uvOf(Vec2d p) { return {float(p.x), float(p.y)}; }
    Mesh &mesh_;
};

double topOf(const BuildingPlan &plan, const BuildingShape &shape) {
    return shape.base + plan.storeys * shape.storeyHeight;
}

void boxWalls(MeshWriter &out, const Polygon2d &footprint, const std::vector<size_t> &corners, double z0, double z1,
              MaterialId material) {
    for (size_t c = 0; c < corners.size(); ++c)
        out.wall(footprint[corners[c]], footprint[corners[(c + 1) % corners.size()]], z0, z1, 0, material);
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
        Vec2f flat{0, 0};
        out.triangle(at(q(0), z), at(q(1), z), at(m0, ridge), flat, flat, flat, material);
        out.triangle(at(q(2), z), at(q(3), z), at(m2, ridge), flat, flat, flat, material);
        for (auto [a, b, top, back] : {std::array{q(1), q(2), m2, m0}, std::array{q(3), q(0), m0, m2}}) {
            out.triangle(at(a, z), at(b, z), at(top, ridge), flat, flat, flat, material);
            out.triangle(at(a, z), at(top, ridge), at(back, ridge), flat, flat, flat, material);
        }
        return;
    }
    Vec2d apex = vertexMean(footprint);
    if (shape.roof != RoofKind::Flat && sideOf(footprint, apex) == Side::Inside) {
        Vec2f flat{0, 0};
        for (size_t c = 0; c < corners.size(); ++c)
            out.triangle(at(footprint[corners[c]], z), at(footprint[corners[(c + 1) % corners.size()]], z),
                         at(apex, ridge), flat, flat, flat, material);
        return;
    }
    out.polygon(footprint, z, false, material);
}

// One storey of a wall from a to b: windows centred as a group (plan_extension's rule), each a
// sill, a pane and a lintel, wall between.
void windowedWall(MeshWriter &out, Vec2d a, Vec2d b, double z0, const BuildingShape &shape,
                  const BuildingMaterials &m) {
    double total = length(b - a), z1 = z0 + shape.storeyHeight;
    int n = windowsThatFit(shape.windows, total);
    if (n == 0) {
        out.wall(a, b, z0, z1, 0, m.wall);
        return;
    }
    double spacing = shape.windows.arrangement == WindowArrangement::Contiguous ? 0 : shape.windows.spacing;
    double width = shape.windows.width, group = n * width + (n - 1) * spacing;
    Vec2d along = (b - a) * (1 / total);
    auto point = [&](double s) { return a + along * s; };
    double s = (total - group) / 2;
    out.wall(a, point(s), z0, z1, 0, m.wall);
    double sill = z0 + shape.sill, lintel = std::min(sill + shape.windowHeight, z1);
    for (int i = 0; i < n; ++i) {
        Vec2d p = point(s), q = point(s + width);
        if (shape.sill > 0) out.wall(p, q, z0, sill, s, m.wall);
        out.wall(p, q, sill, lintel, s, m.glass);
        if (lintel < z1) out.wall(p, q, lintel, z1, s, m.wall);
        s += width;
        double next = i + 1 < n ? s + spacing : total;
        if (next > s) out.wall(q, point(next), z0, z1, s, m.wall);
        s = next;
    }
}

bool takesWindows(EdgeLocation location) { return location == EdgeLocation::Street || location == EdgeLocation::Gap; }

// The outer walls storey by storey. On the ground floor the wall with the house door has it
// where the plan's entrance is, and windows on either side of it.
void storeyWalls(MeshWriter &out, const BuildingPlan &plan, const BuildingShape &shape, const BuildingMaterials &m) {
    const PlanShape &footprint = plan.placement.footprint;
    for (int storey = 0; storey < plan.storeys; ++storey) {
        double z0 = shape.base + storey * shape.storeyHeight;
        for (size_t e = 0; e < footprint.size(); ++e) {
            Vec2d a = footprint.start(e), b = footprint.end(e);
            if (!takesWindows(footprint.locations[e])) {
                out.wall(a, b, z0, z0 + shape.storeyHeight, 0, m.wall);
                continue;
            }
            double s = dot(plan.storey.entrance - a, b - a) / length(b - a);
            bool door = storey == 0 && distanceToBoundary({a, b}, plan.storey.entrance) < 1e-6 &&
                s - shape.doorWidth / 2 > 0 && s + shape.doorWidth / 2 < length(b - a);
            if (!door) {
                windowedWall(out, a, b, z0, shape, m);
                continue;
            }
            Vec2d along = (b - a) * (1 / length(b - a));
            Vec2d p = a + along * (s - shape.doorWidth / 2), q = a + along * (s + shape.doorWidth / 2);
            double top = std::min(z0 + shape.doorHeight, z0 + shape.storeyHeight);
            windowedWall(out, a, p, z0, shape, m);
            out.wall(p, q, z0, top, 0, m.door);
            out.wall(p, q, top, z0 + shape.storeyHeight, 0, m.wall);
            windowedWall(out, q, b, z0, shape, m);
        }
    }
}

// §3.5's interiors: each room's floor, ceiling and walls, the walls facing into the room; a
// room stands the whole wall thickness inside the shell and half of it from its neighbours.
void rooms(MeshWriter &out, const BuildingPlan &plan, const BuildingShape &shape, const BuildingMaterials &m) {
    const PlanShape &shell = plan.placement.footprint;
    auto onShell = [&](Vec2d a, Vec2d b) {
        return distanceToBoundary(shell.points, a) < 1e-6 && distanceToBoundary(shell.points, b) < 1e-6 &&
            distanceToBoundary(shell.points, (a + b) * 0.5) < 1e-6;
    };
    for (const ApartmentPlan &apartment : plan.storey.apartments) {
        for (const PlanShape &room : apartment.rooms) {
            std::vector<double> inset;
            for (size_t e = 0; e < room.size(); ++e)
                inset.push_back(onShell(room.start(e), room.end(e)) ? shape.wallThickness : shape.wallThickness / 2);
            auto inner = moveEdges(room, inset, EdgeLocation::NeighbourRoom);
            if (!inner) continue;  // a room narrower than its walls
            const Polygon2d &floor = inner->shape.points;
            for (int storey = 0; storey < plan.storeys; ++storey) {
                // The ceiling lies a slab below the next floor: under the top storey's flat roof
                // it would otherwise share the roof's plane.
                double z0 = shape.base + storey * shape.storeyHeight, z1 = z0 + shape.storeyHeight - shape.slab;
                out.polygon(floor, z0, false, m.interior);
                out.polygon(floor, z1, true, m.interior);
                for (size_t i = 0; i < floor.size(); ++i)
                    out.wall(floor[(i + 1) % floor.size()], floor[i], z0, z1, 0, m.interior);
            }
        }
    }
}

}  // namespace

Mesh buildingMesh(const BuildingPlan &plan, const BuildingShape &shape, BuildingLod lod,
                  const BuildingMaterials &materials) {
    Mesh mesh;
    MeshWriter out(mesh);
    const Polygon2d &footprint = plan.placement.footprint.points;
    // From point 0, the front's left end: a corner, where the first wall starts.
    std::vector<size_t> corners = turningPoints(footprint);
    double top = topOf(plan, shape);
    if (lod == BuildingLod::Box) boxWalls(out, footprint, corners, shape.base, top, materials.wall);
    else storeyWalls(out, plan, shape, materials);
    if (lod == BuildingLod::Rooms) rooms(out, plan, shape, materials);
    roof(out, footprint, corners, shape, top, materials.roof);
    return mesh;
}

}  // namespace veduta
