#include "render/first_hits.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/path_tracer.h"

namespace veduta {

std::vector<FirstHit> firstHitsAtPixelCentres(const RenderScene &scene, const Bvh &bvh) {
    const Camera &camera = scene.camera;
    CameraRays rays(camera);
    PathTracer tracer(scene, bvh);
    std::vector<FirstHit> hits(size_t(camera.width) * size_t(camera.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int> &rows) {
        RayCounts counts;
        for (int y = rows.begin(); y != rows.end(); ++y) {
            for (int x = 0; x < camera.width; ++x) {
                hits[size_t(y) * size_t(camera.width) + size_t(x)] =
                    tracer.firstHit(rays.generate(float(x) + 0.5f, float(y) + 0.5f), counts);
            }
        }
    });
    return hits;
}

}  // namespace veduta
