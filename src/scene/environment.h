// What a ray sees when it leaves the scene: a constant radiance, or a cubemap (image files
// or a baked sky) turned about the vertical and scaled.
#pragma once

#include <cmath>
#include <memory>

#include "core/vecmath.h"
#include "scene/cubemap.h"

namespace veduta {

struct Environment {
    Vec3f radiance{0.0f};  // linear Rec.709 RGB, the same in every direction; used without a cubemap
    std::shared_ptr<const Cubemap> cubemap;
    float rotationDegrees = 0;  // counter-clockwise seen from above: +90 turns the map's east to north
    float intensity = 1;        // scales the cubemap

    Vec3f radianceTowards(const Vec3f &direction) const {
        if (!cubemap) return radiance;
        return cubemap->lookup(toMap(direction)) * intensity;
    }
    // A world direction in the cubemap's own frame, and back.
    Vec3f toMap(const Vec3f &d) const { return rotateAboutZ(d, -rotationDegrees); }
    Vec3f toWorld(const Vec3f &d) const { return rotateAboutZ(d, rotationDegrees); }
    // The radiance averaged over all directions, for the preview's ambient term.
    Vec3f averageRadiance() const;

  private:
    static Vec3f rotateAboutZ(const Vec3f &d, float degrees) {
        if (degrees == 0) return d;
        float c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
        return {c * d.x - s * d.y, s * d.x + c * d.y, d.z};
    }
};

}  // namespace veduta
