// The two lights of a scene as the integrator samples them: the sun, a disc sampled as a cone
// (or a direction, when its diameter is 0), and the environment, importance-sampled over its
// cubemap texels. Both are at infinity, so a sample is a direction.
#pragma once

#include <memory>
#include <optional>

#include "render/cubemap_distribution.h"
#include "scene/environment.h"
#include "scene/sun.h"

namespace veduta {

struct LightSample {
    Vec3f wi;        // towards the light, unit
    Vec3f radiance;  // arriving along wi; for a delta light the irradiance it gives
    float pdf = 0;   // solid-angle density; 0 marks a delta light (only this sample could find it)
};

class SunLight {
  public:
    explicit SunLight(const Sun &sun);

    bool enabled() const { return sun_.enabled(); }
    LightSample sample(Vec2f u) const;
    // Radiance and density towards wi, for rays that BSDF sampling sends there.
    Vec3f radiance(const Vec3f &wi) const { return isDisc_ && sun_.discContains(wi) ? discRadiance_ : Vec3f(0.0f); }
    float pdf(const Vec3f &wi) const { return isDisc_ && sun_.discContains(wi) ? conePdf_ : 0.0f; }

  private:
    Sun sun_;
    bool isDisc_;
    float oneMinusCosRadius_;
    Frame frame_;
    Vec3f discRadiance_;
    float conePdf_;
};

// A constant environment is not sampled: BSDF sampling already follows the only thing that
// varies, the BSDF, and light samples would only add noise.
class EnvironmentLight {
  public:
    explicit EnvironmentLight(const Environment &environment);

    // Whether next-event estimation samples it: a cubemap with light in it.
    bool sampled() const { return distribution_ != nullptr; }
    LightSample sample(Vec2f u) const;
    Vec3f radiance(const Vec3f &wi) const { return environment_.radianceTowards(wi); }
    float pdf(const Vec3f &wi) const;  // 0 when not sampled

  private:
    const Environment &environment_;
    std::unique_ptr<CubemapDistribution> distribution_;  // over the cubemap's texels
};

// Veach's power heuristic (β = 2) for one sample of each of two strategies.
inline float powerHeuristic(float pdf, float otherPdf) {
    float a = pdf * pdf, b = otherPdf * otherPdf;
    return a + b > 0 ? a / (a + b) : 0.0f;
}

}  // namespace veduta
