#include "render/surface_interaction.h"

#include <bit>
#include <cmath>

#include "scene/texture_frame.h"

namespace veduta {

SurfaceLookup::SurfaceLookup(const RenderScene &scene) : scene_(scene) {
    instanceNormalTransforms_.reserve(scene.instances.size());
    instanceMirrors_.reserve(scene.instances.size());
    for (const Instance &instance : scene.instances) {
        instanceNormalTransforms_.push_back(instance.objectToWorld.normalTransform());
        instanceMirrors_.push_back(instance.objectToWorld.determinant() < 0);
    }
    for (const Material &m : scene.materials) materialHasMaps_.push_back(m.hasMaps());
}

SurfaceInteraction SurfaceLookup::at(const Hit &hit, const Vec3f &rayDirection) const {
    const Mesh &mesh =
        hit.instanced ? scene_.prototypes[scene_.instances[hit.index].prototype] : scene_.meshes[hit.index].mesh;
    const uint32_t *idx = &mesh.indices[3 * size_t(hit.primitive)];
    const Vec3f &p0 = mesh.positions[idx[0]], &p1 = mesh.positions[idx[1]], &p2 = mesh.positions[idx[2]];
    float w = 1 - hit.u - hit.v;
    auto interpolate = [&](const auto &values) {
        return values[idx[0]] * w + values[idx[1]] * hit.u + values[idx[2]] * hit.v;
    };

    // Interpolating the triangle is more exact than origin + t·direction far from the origin.
    Vec3f position = interpolate(mesh.positions);
    Vec3f e1 = p1 - p0, e2 = p2 - p0;
    Vec3f ns = mesh.normals.empty() ? cross(e1, e2) : interpolate(mesh.normals);

    SurfaceInteraction si;
    si.material = mesh.triangleMaterials[hit.primitive];
    if (hit.instanced && scene_.instances[hit.index].materialOverride != kNoMaterial)
        si.material = scene_.instances[hit.index].materialOverride;
    // Most surfaces are plain: no maps, so no texture coordinates or tangent frame to work out.
    const bool textured = materialHasMaps_[si.material] && mesh.uvs.size() == mesh.positions.size();
    const bool mirrored = hit.instanced && instanceMirrors_[hit.index];
    si.distance = hit.t;
    if (!hit.instanced) {
        const BakedMesh &baked = scene_.meshes[hit.index];
        si.objectId = baked.objectId;
        si.buildingId = baked.buildingId;
        si.instanceId = baked.instanceId;
    }
    if (hit.instanced) {
        const Instance &instance = scene_.instances[hit.index];
        si.objectId = instance.objectId;
        si.buildingId = instance.buildingId;
        si.instanceId = instance.instanceId;
        const Transform &normalTransform = instanceNormalTransforms_[hit.index];
        position = instance.objectToWorld.applyPoint(position);
        e1 = instance.objectToWorld.applyVector(e1);
        e2 = instance.objectToWorld.applyVector(e2);
        ns = normalTransform.applyVector(ns);
    }
    Vec3f ng = cross(e1, e2);
    // A mirroring placement turns cross(e1, e2) inwards; back to the side the mesh faces.
    if (mirrored) ng = -ng;
    si.position = position;
    si.backFacing = dot(ng, rayDirection) > 0;
    si.geometricNormal = faceForward(normalize(ng), -rayDirection);
    float nsLength = length(ns);
    si.shadingNormal = nsLength > 0 ? faceForward(ns / nsLength, si.geometricNormal) : si.geometricNormal;

    if (textured) {
        const Transform *placement = hit.instanced ? &scene_.instances[hit.index].objectToWorld : nullptr;
        TextureFrame frame = textureFrame(mesh, idx, w, hit.u, hit.v, {e1, e2, ng}, placement, mirrored);
        si.uv = frame.uv;
        si.uvPerMetre = frame.uvPerMetre;
        si.tangent = frame.tangent;
        si.bitangentSign = frame.bitangentSign;
    }
    return si;
}

Vec3f offsetRayOrigin(const Vec3f &p, const Vec3f &n) {
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    Vec3f result;
    for (int i = 0; i < 3; ++i) {
        auto offset = int32_t(kIntScale * n[i]);
        auto bits = std::bit_cast<int32_t>(p[i]);
        float shifted = std::bit_cast<float>(bits + (p[i] < 0 ? -offset : offset));
        result[i] = std::abs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : shifted;
    }
    return result;
}

}  // namespace veduta
