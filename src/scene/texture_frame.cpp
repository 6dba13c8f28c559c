#include "scene/texture_frame.h"

#include <cmath>

namespace veduta {

TextureFrame textureFrame(const Mesh &mesh, const uint32_t *idx, float w, float u, float v, const WorldTriangle &world,
                          const Transform *objectToWorld, bool mirrored) {
    auto interpolate = [&](const auto &values) { return values[idx[0]] * w + values[idx[1]] * u + values[idx[2]] * v; };
    Vec3f tangent = mesh.tangents.empty() ? Vec3f(0.0f) : interpolate(mesh.tangents);
    float sign = mesh.bitangentSigns.empty() ? 1.0f : mesh.bitangentSigns[idx[0]];
    if (objectToWorld) tangent = objectToWorld->applyVector(tangent);
    // A mirroring placement turns the (t, b, n) frame's handedness around.
    if (mirrored) sign = -sign;

    TextureFrame frame;
    const Vec2f &t0 = mesh.uvs[idx[0]], &t1 = mesh.uvs[idx[1]], &t2 = mesh.uvs[idx[2]];
    frame.uv = {t0.x * w + t1.x * u + t2.x * v, t0.y * w + t1.y * u + t2.y * v};
    float du1 = t1.x - t0.x, dv1 = t1.y - t0.y, du2 = t2.x - t0.x, dv2 = t2.y - t0.y;
    float uvArea = du1 * dv2 - dv1 * du2;  // twice the triangle's area in (u, v), signed
    float worldArea = length(world.ng);
    if (uvArea != 0 && worldArea > 0) {
        frame.uvPerMetre = std::sqrt(std::abs(uvArea) / worldArea);
        if (length(tangent) == 0) {
            // No vertex tangents (a faceted mesh): the triangle's own ∂p/∂u and handedness.
            Vec3f dpdu = (world.e1 * dv2 - world.e2 * dv1) / uvArea;
            Vec3f dpdv = (world.e2 * du1 - world.e1 * du2) / uvArea;
            tangent = dpdu;
            sign = dot(cross(world.ng, dpdu), dpdv) < 0 ? -1.0f : 1.0f;
        }
    }
    float tangentLength = length(tangent);
    if (tangentLength > 0) {
        frame.tangent = tangent / tangentLength;
        frame.bitangentSign = sign;
    }
    return frame;
}

}  // namespace veduta
