#include "scene/environment.h"

namespace veduta {

Vec3f Environment::averageRadiance() const {
    if (!cubemap) return radiance;
    double sum[3] = {0, 0, 0};
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int y = 0; y < cubemap->size(); ++y) {
            for (int x = 0; x < cubemap->size(); ++x) {
                Vec3f weighted = cubemap->texel(face, x, y) * cubemap->texelSolidAngle(x, y);
                for (int c = 0; c < 3; ++c) sum[c] += weighted[c];
            }
        }
    }
    double scale = intensity / (4 * M_PI);
    return {float(sum[0] * scale), float(sum[1] * scale), float(sum[2] * scale)};
}

}  // namespace veduta
