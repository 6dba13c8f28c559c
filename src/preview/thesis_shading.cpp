#include "preview/thesis_shading.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

// GLSL's reflect(i, n) for a unit n: i mirrored about the plane normal to n.
Vec3f reflect(const Vec3f &i, const Vec3f &n) { return i - 2 * dot(n, i) * n; }

}  // namespace

Vec3f ppsunsShade(const ThesisLight &light, const ThesisMaterial &material, const PpsunsInputs &in) {
    Vec3f l = normalize(in.lightVec);
    Vec3f v = normalize(in.eyeVec);
    Vec3f n = normalize(in.normalTexel * 2.0f - Vec3f(1.0f));
    float diffuse = std::max(dot(l, n), 0.0f);
    Vec3f vDiffuse = light.diffuse * material.diffuse * diffuse;
    float specular = std::pow(std::clamp(dot(reflect(-l, n), v), 0.0f, 1.0f), material.shininess);
    Vec3f vSpecular = light.specular * material.specular * (specular * in.specularTexel);
    Vec3f vAmbient = light.ambient * material.ambient;
    return (vAmbient * 1.5f + in.environment * 0.5f + vDiffuse * 0.5f) * in.baseColor + vSpecular;
}

}  // namespace veduta
