#include "render/object_ids.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace veduta {

std::vector<uint32_t> objectIdsAtPixelCentres(const RenderScene &scene, const Bvh &bvh) {
    const Camera &camera = scene.camera;
    CameraRays rays(camera);
    std::vector<uint32_t> ids(size_t(camera.width) * size_t(camera.height), 0);
    tbb::parallel_for(tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int> &rows) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
            for (int x = 0; x < camera.width; ++x) {
                std::optional<Hit> hit = bvh.intersect(rays.generate(float(x) + 0.5f, float(y) + 0.5f), true);
                if (!hit) continue;
                ids[size_t(y) * size_t(camera.width) + size_t(x)] =
                    hit->instanced ? scene.instances[hit->index].objectId : scene.meshes[hit->index].objectId;
            }
        }
    });
    return ids;
}

}  // namespace veduta
