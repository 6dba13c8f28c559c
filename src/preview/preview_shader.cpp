#include "preview/preview_shader.h"

#include <algorithm>
#include <cmath>

#include "scene/shading_normal.h"

namespace veduta {

namespace {

// A glass pane mostly shows the sky's reflection and a dark room: in the shaded and thesis modes
// a dim tint stands for it. (The albedo pass holds black for glass, and so does the albedo mode.)
constexpr float kGlassShade = 0.15f;
// Bilke's base material colours (L1190): gl_FrontMaterial's ambient and diffuse.
constexpr float kThesisAmbient = 0.4f, kThesisDiffuse = 0.65f;
// The exponents the path tracer's Phong lobe keeps to (render/phong.h).
constexpr float kMinExponent = 1.0f, kMaxExponent = 1.0e4f;

// The normalised Phong lobe, (n + 2)/(2π) cosⁿα, α between wi and the mirror image of wo about
// the normal; 0 when either direction lies below the surface, as the path tracer's.
float phongLobe(const Vec3f &normal, const Vec3f &wo, const Vec3f &wi, float exponent) {
    float cosO = dot(normal, wo), cosI = dot(normal, wi);
    if (cosO <= 0 || cosI <= 0) return 0;
    Vec3f mirrored = normal * (2 * cosO) - wo;
    float cosAlpha = std::max(dot(mirrored, wi), 0.0f);
    float n = std::clamp(exponent, kMinExponent, kMaxExponent);
    return (n + 2) * (0.5f * kInvPi) * std::pow(cosAlpha, n);
}

bool isZero(const Vec3f &v) { return v.x == 0 && v.y == 0 && v.z == 0; }

}  // namespace

PreviewShader::PreviewShader(const RenderScene &scene, PreviewMode mode) :
    scene_(scene),
    mode_(mode),
    maps_(scene.textures.get()),
    skyRadiance_(scene.environment.averageRadiance()),
    sunDirection_(scene.sun.direction) {
    // gl_LightSource[0] is the sun: its diffuse and specular colours what a white Lambert surface
    // facing it reflects, its ambient the sky's mean radiance (the thesis leaves them open).
    Vec3f sun = scene.sun.irradiance * kInvPi;
    thesisLight_ = {skyRadiance_, sun, sun};
    for (const Material &m : scene.materials) {
        MaterialShading shading;
        shading.hasMaps = m.hasMaps();
        // A mirror shows the environment in the direction it reflects: the same everywhere only
        // when that is the same in every direction.
        bool viewDependent =
            !m.glass && (!isZero(m.specular) || (!isZero(m.reflectivity) && scene.environment.cubemap));
        shading.uniform = !shading.hasMaps && !viewDependent;
        shading.plain = m.glass ? LobeWeights{m.glassTint * kGlassShade, Vec3f(0.0f), Vec3f(0.0f)}
                                : lobeWeights(m.diffuse, m.specular, m.reflectivity);
        shading.albedo = m.glass ? Vec3f(0.0f) : shading.plain.diffuse;
        shading.sunTerm = shading.plain.diffuse * kInvPi * scene.sun.irradiance;
        // A uniform mirror reflects a uniform environment.
        shading.skyTerm = (shading.plain.diffuse + shading.plain.specular) * skyRadiance_ +
            shading.plain.mirror * scene.environment.radiance;
        materials_.push_back(shading);
    }
}

bool PreviewShader::cutAway(const PreviewSurface &s) const {
    return maps_.cutAway(scene_.materials[s.material], s.map);
}

Vec3f PreviewShader::background(const Vec3f &direction) const {
    return showsEnvironment() ? scene_.environment.radianceTowards(direction) : Vec3f(0.0f);
}

Vec3f PreviewShader::mappedNormal(const PreviewSurface &s, const Material &m) const {
    if (m.normalMap == kNoTexture || isZero(s.tangent)) return s.normal;
    // The map is relative to the side the mesh faces; seen from behind it is mirrored.
    Vec3f facing = s.backFacing ? -s.normal : s.normal;
    Vec3f mapped = normalFromMap(maps_.normalTexel(m, s.map), facing, s.tangent, s.bitangentSign, m.normalStrength);
    return s.backFacing ? -mapped : mapped;
}

Vec3f PreviewShader::shadingNormal(const PreviewSurface &s, const Material &m) const {
    if (m.glass) return s.geometricNormal;
    return ensureValidReflection(s.geometricNormal, s.toEye, mappedNormal(s, m));
}

Vec3f PreviewShader::color(const PreviewSurface &s, bool sunVisible) const {
    const Material &m = scene_.materials[s.material];
    const MaterialShading &shading = materials_[s.material];
    if (mode_ != PreviewMode::Normal && fromNormalAlone(s.material, true))
        return colorFromNormal(s.material, s.normal, sunVisible);
    if (mode_ == PreviewMode::Normal) return shadingNormal(s, m) * 0.5f + Vec3f(0.5f);
    if (mode_ == PreviewMode::Albedo) {
        if (m.glass) return Vec3f(0.0f);
        if (!shading.hasMaps) return shading.plain.diffuse;
        SurfaceColors c = maps_.colors(m, s.map);
        return lobeWeights(c.diffuse, c.specular, c.mirror).diffuse;
    }
    if (mode_ == PreviewMode::Thesis) {
        return thesis(s, m, m.glass || !shading.hasMaps ? shading.plain.diffuse : maps_.colors(m, s.map).diffuse);
    }
    if (m.glass || !shading.hasMaps) return shaded(s, m, shading.plain, sunVisible);
    SurfaceColors c = maps_.colors(m, s.map);
    return shaded(s, m, lobeWeights(c.diffuse, c.specular, c.mirror), sunVisible);
}

// Sunlight through the diffuse and Phong lobes, the sky's mean radiance on both, and a mirror's
// reflection of the environment (not of the scene).
Vec3f PreviewShader::shaded(const PreviewSurface &s, const Material &m, const LobeWeights &w, bool sunVisible) const {
    Vec3f n = shadingNormal(s, m);
    Vec3f color = (w.diffuse + w.specular) * skyRadiance_;
    if (!isZero(w.mirror)) color += w.mirror * scene_.environment.radianceTowards(n * (2 * dot(n, s.toEye)) - s.toEye);
    const Sun &sun = scene_.sun;
    float cosine = std::max(0.0f, dot(n, sun.direction));
    if (!sunVisible) cosine = 0;
    Vec3f f = w.diffuse * kInvPi;
    if (!isZero(w.specular)) f += w.specular * phongLobe(n, s.toEye, sun.direction, m.shininess);
    return f * sun.irradiance * cosine + color;
}

// Seed 000's PPSUNS with the sun for gl_LightSource[0], the material's base colour (k_d × its
// map), normal and specular maps, its k_s and shininess for gl_FrontMaterial's specular, and the
// sky's mean radiance for the pre-blurred diffuse environment cubemap.
Vec3f PreviewShader::thesis(const PreviewSurface &s, const Material &m, const Vec3f &base) const {
    bool mapped = !m.glass && !isZero(s.tangent);
    PpsunsInputs in;
    in.baseColor = base;
    in.normalTexel = mapped && m.normalMap != kNoTexture ? maps_.normalTexel(m, s.map) : Vec3f(0.5f, 0.5f, 1.0f);
    in.specularTexel = 1;
    if (!m.glass && m.specularMap != kNoTexture) maps_.lookup(m.specularMap, m, s.map, &in.specularTexel, 1);
    // The tangent frame of the side the mesh faces. Seen from behind, light and eye are turned
    // around with the normal, which leaves every dot product the shader takes as it is.
    Vec3f n = s.backFacing ? -s.normal : s.normal;
    Vec3f t = mapped ? s.tangent - n * dot(n, s.tangent) : Vec3f(0.0f);
    t = length(t) > 1e-6f ? normalize(t) : Frame::fromNormal(n).s;
    Vec3f b = cross(n, t) * (mapped && s.bitangentSign < 0 ? -1.0f : 1.0f);
    float side = s.backFacing ? -1.0f : 1.0f;
    auto tangentSpace = [&](const Vec3f &v) { return Vec3f(dot(v, t), dot(v, b), dot(v, n)) * side; };
    in.lightVec = tangentSpace(scene_.sun.direction);
    in.eyeVec = tangentSpace(s.toEye);
    in.environment = skyRadiance_;
    ThesisMaterial material{Vec3f(kThesisAmbient), Vec3f(kThesisDiffuse), m.glass ? Vec3f(0.0f) : m.specular,
                            m.shininess};
    return ppsunsShade(thesisLight_, material, in);
}

}  // namespace veduta
