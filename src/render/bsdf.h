// The BSDF at a surface point, built from already looked-up material values: Lambertian
// diffuse, normalised Phong gloss with its energy compensation (render/phong.h), a mirror
// lobe for reflectivity maps (PVSUR's), or a thin glass pane. All directions are world-space
// unit vectors pointing away from the surface: wo towards the viewer, wi towards the light.
#pragma once

#include <optional>

#include "core/vecmath.h"

namespace veduta {

struct BsdfInputs {
    Vec3f diffuse{0.8f};   // k_d, linear RGB
    Vec3f specular{0.0f};  // k_s: colour × intensity × specular map
    float exponent = 32;   // Phong n, clamped to [1, 10⁴]
    Vec3f mirror{0.0f};    // reflectivity × reflection map: a delta reflection lobe
    // A thin dielectric pane (windows): Fresnel reflection and straight transmission, both
    // delta; when set, the lobes above are ignored.
    bool thinGlass = false;
    float ior = 1.5f;
    Vec3f glassTint{1.0f};
};

struct BsdfSample {
    Vec3f wi;
    Vec3f weight;   // f·|cos θi| / pdf; for a delta lobe its reflectance / the lobe's probability
    float pdf = 0;  // solid-angle density of all non-delta lobes; for a delta lobe its probability
    bool delta = false;
    // Straight through a thin pane (wi = −wo): the path goes on as if the pane were not there,
    // only dimmer, so the integrator does not count it as a bounce.
    bool passThrough = false;
};

class Bsdf {
  public:
    // shadingNormal: already normal-mapped and passed through ensureValidReflection for this
    // wo; geometricNormal: faces wo's side.
    //
    // Energy: the mirror takes its share first (k_d and k_s are scaled by 1 − mirror, as PVSUR
    // weights colour by 1 − reflectionFactor), and k_d + k_s is rescaled to at most 1 in every
    // channel, as Mitsuba 0.6's ensureEnergyConservation does.
    Bsdf(const BsdfInputs &inputs, const Vec3f &shadingNormal, const Vec3f &geometricNormal);

    // f · |cos θi| of the non-delta lobes; 0 for wi below the geometric surface (no light
    // leaks through it) or below the shading normal's horizon.
    Vec3f eval(const Vec3f &wo, const Vec3f &wi) const;
    // The density sample() draws wi with, counting only its non-delta lobes (each times the
    // probability of choosing it), for multiple importance sampling.
    float pdf(const Vec3f &wo, const Vec3f &wi) const;
    // uLobe picks a lobe in proportion to what it reflects (luminance), u the direction.
    // None when the direction would be below the surface or nothing is reflected.
    std::optional<BsdfSample> sample(const Vec3f &wo, float uLobe, Vec2f u) const;
    // False for a pure mirror or glass: next-event estimation has nothing to evaluate there.
    bool hasNonDeltaLobe() const;
    bool isThinGlass() const { return thinGlass_; }
    // For the Normal and DiffCol passes: the shading normal, and the diffuse reflectance the
    // BSDF uses (after the energy rescaling; black for glass).
    Vec3f shadingNormal() const { return frame_.n; }
    Vec3f diffuseAlbedo() const { return thinGlass_ ? Vec3f(0.0f) : diffuse_; }

  private:
    struct LobeProbabilities {
        float cosine = 0, phong = 0, mirror = 0;  // cosine: diffuse and Phong compensation
    };
    LobeProbabilities lobeProbabilities(float cosThetaO) const;
    bool aboveSurface(const Vec3f &wo, const Vec3f &wi) const;
    float foldedCosine(const Vec3f &wi) const;
    Vec3f evalLocal(const Vec3f &o, const Vec3f &i, const Vec3f &wi) const;
    float pdfLocal(const Vec3f &o, const Vec3f &i, const Vec3f &wi, const LobeProbabilities &p) const;
    std::optional<BsdfSample> sampleDiffuse(const Vec3f &wo, Vec2f u) const;
    std::optional<BsdfSample> sampleGlass(const Vec3f &wo, float uLobe) const;

    Frame frame_;
    Vec3f geometricNormal_;
    Vec3f diffuse_, specular_, mirror_;
    float exponent_;
    bool thinGlass_;
    bool plainDiffuse_;  // no gloss, mirror or glass: sampled on a shorter path
    float ior_;
    Vec3f glassTint_;
};

// Fresnel reflectance of a smooth dielectric of relative index `ior`, unpolarised light
// arriving from outside at |cos θ|.
float fresnelDielectric(float cosTheta, float ior);

// What a shadow ray keeps when it passes a thin glass pane: straight through, after all the
// bounces between its two faces, T' = 1 − R' with R' = 2R / (1 + R), times the tint.
Vec3f thinGlassTransmittance(float cosTheta, float ior, const Vec3f &tint);

}  // namespace veduta
