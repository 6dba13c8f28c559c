#include "render/surface_interaction.h"

#include <bit>
#include <cmath>

namespace veduta {

SurfaceLookup::SurfaceLookup(const RenderScene &scene) : scene_(scene) {
    instanceNormalTransforms_.reserve(scene.instances.size());
    for (const Instance &instance : scene.instances) {
        instanceNormalTransforms_.push_back(instance.objectToWorld.normalTransform());
    }
}

SurfaceInteraction SurfaceLookup::at(const Hit &hit, const Vec3f &rayDirection) const {
    const Mesh &mesh = hit.instanced ? scene_.prototypes[scene_.instances[hit.index].prototype]
                                     : scene_.meshes[hit.index].mesh;
    const uint32_t *idx = &mesh.indices[3 * size_t(hit.primitive)];
    const Vec3f &p0 = mesh.positions[idx[0]], &p1 = mesh.positions[idx[1]], &p2 = mesh.positions[idx[2]];
    float w = 1 - hit.u - hit.v;

    // Interpolating the triangle is more exact than origin + t·direction far from the origin.
    Vec3f position = p0 * w + p1 * hit.u + p2 * hit.v;
    Vec3f ng = cross(p1 - p0, p2 - p0);
    Vec3f ns = ng;
    if (!mesh.normals.empty()) ns = mesh.normals[idx[0]] * w + mesh.normals[idx[1]] * hit.u + mesh.normals[idx[2]] * hit.v;

    SurfaceInteraction si;
    si.material = mesh.triangleMaterials[hit.primitive];
    if (hit.instanced) {
        const Instance &instance = scene_.instances[hit.index];
        const Transform &normalTransform = instanceNormalTransforms_[hit.index];
        position = instance.objectToWorld.applyPoint(position);
        ng = normalTransform.applyVector(ng);
        ns = normalTransform.applyVector(ns);
        if (instance.materialOverride != kNoMaterial) si.material = instance.materialOverride;
    }
    si.position = position;
    si.geometricNormal = faceForward(normalize(ng), -rayDirection);
    float nsLength = length(ns);
    si.shadingNormal = nsLength > 0 ? faceForward(ns / nsLength, si.geometricNormal) : si.geometricNormal;
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
