// Surface materials. This is the diffuse model; Phong lobes and maps come with the
// materials issue and extend this struct.
#pragma once

#include <string>

#include "core/vecmath.h"

namespace veduta {

struct Material {
    std::string name;
    Vec3f diffuse{0.8f};  // Lambertian albedo, linear Rec.709 RGB
};

}  // namespace veduta
