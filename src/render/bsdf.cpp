#include "render/bsdf.h"

#include <algorithm>
#include <cmath>

#include "core/color.h"
#include "render/phong.h"
#include "render/sampling.h"
#include "scene/lobe_weights.h"

namespace veduta {

namespace {

Vec3f reflect(const Vec3f &w, const Vec3f &n) { return n * (2 * dot(n, w)) - w; }

// The mirror image of w in the plane perpendicular to n.
Vec3f mirrorAcross(const Vec3f &w, const Vec3f &n) { return w - n * (2 * dot(n, w)); }

// R' = R + T²R / (1 − R²) = 2R / (1 + R): the light a pane returns after any number of bounces
// between its faces, with T = 1 − R at each (no absorption inside).
float thinGlassReflectance(float cosTheta, float ior) {
    float r = fresnelDielectric(cosTheta, ior);
    return 2 * r / (1 + r);
}

}  // namespace

float fresnelDielectric(float cosTheta, float ior) {
    float cosI = std::min(std::abs(cosTheta), 1.0f);
    float sin2T = (1 - cosI * cosI) / (ior * ior);
    float cosT = std::sqrt(std::max(0.0f, 1 - sin2T));
    float rs = (cosI - ior * cosT) / (cosI + ior * cosT);
    float rp = (ior * cosI - cosT) / (ior * cosI + cosT);
    return 0.5f * (rs * rs + rp * rp);
}

Vec3f thinGlassTransmittance(float cosTheta, float ior, const Vec3f &tint) {
    return tint * (1 - thinGlassReflectance(cosTheta, ior));
}

Bsdf::Bsdf(const BsdfInputs &inputs, const Vec3f &shadingNormal, const Vec3f &geometricNormal) :
    frame_(Frame::fromNormal(shadingNormal)),
    geometricNormal_(geometricNormal),
    exponent_(std::clamp(inputs.exponent, kMinPhongExponent, kMaxPhongExponent)),
    thinGlass_(inputs.thinGlass),
    ior_(inputs.ior),
    glassTint_(inputs.glassTint) {
    LobeWeights weights = lobeWeights(inputs.diffuse, inputs.specular, inputs.mirror);
    diffuse_ = weights.diffuse;
    specular_ = weights.specular;
    mirror_ = weights.mirror;
    plainDiffuse_ =
        !thinGlass_ && maxComponent(specular_) <= 0 && maxComponent(mirror_) <= 0 && maxComponent(diffuse_) > 0;
}

// Both directions above the geometric surface. wo always is; checking it too keeps eval
// symmetric in its arguments.
bool Bsdf::aboveSurface(const Vec3f &wo, const Vec3f &wi) const {
    return dot(wo, geometricNormal_) > 0 && dot(wi, geometricNormal_) > 0;
}

// The diffuse lobe around a tilted shading normal ns. Part of ns's cosine lobe lies below the
// geometric surface, where no light may come from (it would leak through the surface) and
// where rejecting it would darken the surface and, at the shading normal's horizon, leave
// black edges. That part is folded back: a direction w below the surface counts as its mirror
// image in the geometric plane. The lobe, cos⁺(ns, w) + cos⁺(ns, mirror(w)), then integrates
// over the upper hemisphere to exactly what ns's full lobe gives, π, so the albedo stays k_d
// for every tilt; and sampling ns's cosine lobe, mirroring what falls below, draws exactly this
// density, so each sample carries k_d and a white furnace shows no noise at all. Chiang et
// al.'s terminator term (Cycles 3.4) or renormalised rejection would darken or add noise. The
// price is reciprocity under tilted normals, which unidirectional path tracing does not need.
float Bsdf::foldedCosine(const Vec3f &wi) const {
    const Vec3f &ns = frame_.n;
    return std::max(0.0f, dot(ns, wi)) + std::max(0.0f, dot(ns, mirrorAcross(wi, geometricNormal_)));
}

bool Bsdf::hasNonDeltaLobe() const {
    return !thinGlass_ && (maxComponent(diffuse_) > 0 || maxComponent(specular_) > 0);
}

Bsdf::LobeProbabilities Bsdf::lobeProbabilities(float cosThetaO) const {
    float specular = luminance(specular_);
    float albedo = specular > 0 ? phongAlbedo(cosThetaO, exponent_) : 0.0f;
    LobeProbabilities p{luminance(diffuse_) + specular * (1 - albedo), specular * albedo, luminance(mirror_)};
    float total = p.cosine + p.phong + p.mirror;
    if (total <= 0) return {};
    return {p.cosine / total, p.phong / total, p.mirror / total};
}

Vec3f Bsdf::eval(const Vec3f &wo, const Vec3f &wi) const {
    if (thinGlass_ || !aboveSurface(wo, wi)) return Vec3f(0.0f);
    Vec3f o = frame_.toLocal(wo);
    if (o.z <= 0) return Vec3f(0.0f);
    return evalLocal(o, frame_.toLocal(wi), wi);
}

float Bsdf::pdf(const Vec3f &wo, const Vec3f &wi) const {
    if (thinGlass_ || !aboveSurface(wo, wi)) return 0;
    Vec3f o = frame_.toLocal(wo);
    if (o.z <= 0) return 0;
    if (plainDiffuse_) return kInvPi * foldedCosine(wi);
    return pdfLocal(o, frame_.toLocal(wi), wi, lobeProbabilities(o.z));
}

// o and i are wo and wi in the shading frame, wo above it and both above the surface.
Vec3f Bsdf::evalLocal(const Vec3f &o, const Vec3f &i, const Vec3f &wi) const {
    Vec3f result = diffuse_ * (kInvPi * foldedCosine(wi));
    // Most surfaces are plain diffuse: no Phong lobe to evaluate.
    if (i.z > 0 && maxComponent(specular_) > 0) {
        result += specular_ * ((phongLobe(o, i, exponent_) + phongCompensation(o.z, i.z, exponent_)) * i.z);
    }
    return result;
}

float Bsdf::pdfLocal(const Vec3f &o, const Vec3f &i, const Vec3f &wi, const LobeProbabilities &p) const {
    float density = p.cosine * kInvPi * foldedCosine(wi);
    if (i.z > 0 && p.phong > 0) density += p.phong * phongPdf(o, i, exponent_);
    return density;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3f &wo, float uLobe, Vec2f u) const {
    if (thinGlass_) return sampleGlass(wo, uLobe);
    Vec3f o = frame_.toLocal(wo);
    if (o.z <= 0) return std::nullopt;
    if (plainDiffuse_) return sampleDiffuse(wo, u);
    LobeProbabilities p = lobeProbabilities(o.z);
    if (uLobe >= p.cosine + p.phong) {
        if (p.mirror <= 0) return std::nullopt;
        Vec3f wi = reflect(wo, frame_.n);
        if (dot(wi, geometricNormal_) <= 0) return std::nullopt;
        return BsdfSample{wi, mirror_ / p.mirror, p.mirror, true};
    }
    Vec3f wi;
    if (uLobe < p.cosine) {
        wi = frame_.toWorld(sampleCosineHemisphere(u));
        if (dot(wi, geometricNormal_) < 0) wi = mirrorAcross(wi, geometricNormal_);  // see foldedCosine
    } else if (std::optional<Vec3f> s = samplePhong(o, exponent_, u)) {
        wi = frame_.toWorld(*s);
    } else {
        return std::nullopt;
    }
    if (!aboveSurface(wo, wi)) return std::nullopt;
    Vec3f i = frame_.toLocal(wi);
    float density = pdfLocal(o, i, wi, p);
    if (density <= 0) return std::nullopt;
    return BsdfSample{wi, evalLocal(o, i, wi) / density, density, false};
}

// Most surfaces: the folded cosine lobe alone, whose samples carry k_d exactly.
std::optional<BsdfSample> Bsdf::sampleDiffuse(const Vec3f &wo, Vec2f u) const {
    Vec3f wi = frame_.toWorld(sampleCosineHemisphere(u));
    if (dot(wi, geometricNormal_) < 0) wi = mirrorAcross(wi, geometricNormal_);
    if (!aboveSurface(wo, wi)) return std::nullopt;
    float density = kInvPi * foldedCosine(wi);
    if (density <= 0) return std::nullopt;
    return BsdfSample{wi, diffuse_, density, false};
}

std::optional<BsdfSample> Bsdf::sampleGlass(const Vec3f &wo, float uLobe) const {
    float reflectance = thinGlassReflectance(dot(wo, frame_.n), ior_);
    if (uLobe < reflectance) {
        Vec3f wi = reflect(wo, frame_.n);
        if (dot(wi, geometricNormal_) <= 0) return std::nullopt;
        return BsdfSample{wi, Vec3f(1.0f), reflectance, true};
    }
    return BsdfSample{-wo, glassTint_, 1 - reflectance, true, true};
}

}  // namespace veduta
