#include "city/plinth.h"

namespace veduta {

Mesh plinthMesh(const Footprint &footprint, float depth) {
    Mesh mesh;
    const float top = footprint.base, bottom = footprint.base - depth;
    for (size_t edge = 0; edge < footprint.edgeCount(); ++edge) {
        Vec2f a = footprint.edgeStart(edge), b = footprint.edgeEnd(edge);
        Vec3f normal = footprint.outwardNormal(edge);
        float u0 = footprint.perimeterBefore(edge), u1 = u0 + footprint.edgeLength(edge);
        auto first = uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(),
                              {{a.x, a.y, top}, {b.x, b.y, top}, {b.x, b.y, bottom}, {a.x, a.y, bottom}});
        mesh.normals.insert(mesh.normals.end(), 4, normal);
        mesh.uvs.insert(mesh.uvs.end(), {{u0, 0}, {u1, 0}, {u1, depth}, {u0, depth}});
        // Counter-clockwise seen from outside: a, bottom of a, bottom of b, then b.
        mesh.indices.insert(mesh.indices.end(), {first, first + 3, first + 2, first, first + 2, first + 1});
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), 2, 0);
    }
    return mesh;
}

MaterialId plinthMaterial(RenderSceneBuilder &builder) {
    return builder.findOrAddMaterial(Material::lambertian("plinth", {0.42f, 0.4f, 0.37f}));
}

void addPlinth(const BuildingSpec &spec, RenderSceneBuilder &builder) {
    Mesh plinth = plinthMesh(spec.footprint, kPlinthDepth);
    plinth.setMaterial(plinthMaterial(builder));
    builder.addWorldMesh(std::move(plinth), spec.objectId, spec.id);
}

}  // namespace veduta
