// What a ray sees when it leaves the scene. Constant radiance for now; the cubemap
// environment extends this with the materials-and-lights issue.
#pragma once

#include "core/vecmath.h"

namespace veduta {

struct Environment {
    Vec3f radiance{0.0f};  // linear Rec.709 RGB, the same in every direction

    Vec3f radianceTowards(const Vec3f & /*direction*/) const { return radiance; }
};

}  // namespace veduta
