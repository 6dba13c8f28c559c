#include "render/lights.h"

#include "render/sampling.h"

namespace veduta {

namespace {

bool isBlack(const Cubemap &map) {
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int y = 0; y < map.size(); ++y) {
            for (int x = 0; x < map.size(); ++x) {
                if (maxComponent(map.texel(face, x, y)) > 0) return false;
            }
        }
    }
    return true;
}

}  // namespace

SunLight::SunLight(const Sun &sun) :
    sun_(sun),
    isDisc_(sun.angularDiameterDegrees > 0),
    oneMinusCosRadius_(sun.oneMinusCosRadius()),
    frame_(Frame::fromNormal(sun.direction)),
    discRadiance_(isDisc_ ? sun.discRadiance() : Vec3f(0.0f)),
    conePdf_(isDisc_ ? uniformConePdf(oneMinusCosRadius_) : 0.0f) {}

LightSample SunLight::sample(Vec2f u) const {
    if (!isDisc_) return {sun_.direction, sun_.irradiance, 0.0f};
    return {frame_.toWorld(sampleUniformCone(u, oneMinusCosRadius_)), discRadiance_, conePdf_};
}

EnvironmentLight::EnvironmentLight(const Environment &environment) : environment_(environment) {
    if (environment.cubemap && environment.intensity > 0 && !isBlack(*environment.cubemap)) {
        distribution_ = std::make_unique<CubemapDistribution>(*environment.cubemap);
    }
}

LightSample EnvironmentLight::sample(Vec2f u) const {
    EnvironmentSample s = distribution_->sample(u);
    Vec3f wi = environment_.toWorld(s.direction);
    return {wi, environment_.radianceTowards(wi), s.pdf};
}

float EnvironmentLight::pdf(const Vec3f &wi) const {
    return distribution_ ? distribution_->pdf(environment_.toMap(wi)) : 0.0f;
}

}  // namespace veduta
