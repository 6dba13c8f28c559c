#include "render/object_ids.h"

#include "render/first_hits.h"

namespace veduta {

std::vector<uint32_t> objectIdsAtPixelCentres(const RenderScene &scene, const Bvh &bvh) {
    std::vector<uint32_t> ids;
    for (const FirstHit &hit : firstHitsAtPixelCentres(scene, bvh)) ids.push_back(hit.objectId);
    return ids;
}

}  // namespace veduta
