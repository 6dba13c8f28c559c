#include "scene/scene_hash.h"

#include <cstring>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "core/hash.h"

namespace veduta {

namespace {

// 64-bit words through MurmurHash3's finaliser, in order.
class Hasher {
  public:
    void bytes(const void *data, size_t size) {
        const auto *p = static_cast<const unsigned char *>(data);
        word(size);
        for (; size >= 8; size -= 8, p += 8) {
            uint64_t w;
            std::memcpy(&w, p, 8);
            word(w);
        }
        uint64_t tail = 0;
        if (size > 0) std::memcpy(&tail, p, size);  // an empty vector's data() may be null
        word(tail);
    }
    template <typename T>
    void values(const std::vector<T> &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(v.data(), v.size() * sizeof(T));
    }
    void text(const std::string &s) { bytes(s.data(), s.size()); }
    template <typename... T>
    void numbers(T... n) {
        (bytes(&n, sizeof(n)), ...);
    }
    void vec(const Vec3f &v) { numbers(v.x, v.y, v.z); }
    uint64_t value() const { return state_; }

  private:
    void word(uint64_t w) {
        state_ = (state_ ^ mix64(w + 0x9e3779b97f4a7c15ull)) * 0xff51afd7ed558ccdull;
        state_ ^= state_ >> 32;
    }
    uint64_t state_ = 0x243f6a8885a308d3ull;
};

void hashMesh(Hasher &h, const Mesh &m) {
    h.values(m.positions);
    h.values(m.normals);
    h.values(m.uvs);
    h.values(m.indices);
    h.values(m.triangleMaterials);
}

void hashTexture(Hasher &h, const RenderScene &scene, TextureId id) {
    h.numbers(id);
    if (id != kNoTexture && scene.textures) h.text(scene.textures->fingerprint(id));
}

void hashMaterial(Hasher &h, const RenderScene &scene, const Material &m) {
    h.text(m.name);
    h.numbers(int(m.category), m.shininess, m.normalStrength, m.glass, m.ior, m.textureSize.x, m.textureSize.y);
    for (const Vec3f &v : {m.diffuse, m.specular, m.reflectivity, m.glassTint}) h.vec(v);
    for (TextureId t : {m.diffuseMap, m.specularMap, m.normalMap, m.reflectionMap, m.opacityMap}) {
        hashTexture(h, scene, t);
    }
}

// What decides each sample's value. How many samples a pixel takes (the count, adaptive
// sampling) is left out: renders of different sample ranges of one scene must match.
void hashSettings(Hasher &h, const RenderSettings &s) {
    h.numbers(s.maxDepth, s.seed, s.roulette.startDepth, s.roulette.threshold, int(s.filter.kind), s.filter.width,
              int(s.lightSampling));
}

}  // namespace

uint64_t sceneHash(const RenderScene &scene) {
    Hasher h;
    h.numbers(scene.meshes.size());
    for (const BakedMesh &b : scene.meshes) {
        hashMesh(h, b.mesh);
        h.numbers(b.objectId, b.buildingId, b.instanceId);
    }
    h.numbers(scene.prototypes.size());
    for (const Mesh &m : scene.prototypes) hashMesh(h, m);
    h.numbers(scene.instances.size());
    for (const Instance &i : scene.instances) {
        h.bytes(&i.objectToWorld, sizeof(i.objectToWorld));
        h.numbers(i.prototype, i.materialOverride, i.objectId, i.buildingId, i.instanceId);
    }
    h.numbers(scene.materials.size());
    for (const Material &m : scene.materials) hashMaterial(h, scene, m);
    const Camera &c = scene.camera;
    for (const Vec3f &v : {c.position, c.lookAt, c.up}) h.vec(v);
    h.numbers(c.verticalFovDegrees, c.width, c.height, int(c.projection), c.orthoScale, c.shift.x, c.shift.y, c.fNumber,
              c.focusDistance, c.sensorWidth);
    h.vec(scene.sun.direction);
    h.vec(scene.sun.irradiance);
    h.numbers(scene.sun.angularDiameterDegrees);
    h.numbers(scene.fog.density, scene.fog.baseHeight, scene.fog.scaleHeight);
    h.vec(scene.fog.inscatter);
    const Environment &e = scene.environment;
    h.vec(e.radiance);
    h.numbers(e.rotationDegrees, e.intensity, e.cubemap ? e.cubemap->size() : 0);
    if (e.cubemap) {
        for (int face = 0; face < kCubeFaceCount; ++face) {
            for (int y = 0; y < e.cubemap->size(); ++y) {
                h.bytes(&e.cubemap->texel(face, 0, y), sizeof(Vec3f) * size_t(e.cubemap->size()));
            }
        }
    }
    hashSettings(h, scene.settings);
    return h.value();
}

std::string hashText(uint64_t hash) { return fmt::format("{:016x}", hash); }

}  // namespace veduta
