// What the path tracer's passes record for one camera ray through each pixel centre: the surface
// it meets first (cut-outs passed through), with its maps looked up at the camera's footprint
// (pixel spread × distance), its normal-mapped shading normal, diffuse albedo and ids. One ray per
// pixel and no filter, so that comparisons with the preview test what each draws at a point,
// not anti-aliasing.
#pragma once

#include <vector>

#include "film/film.h"
#include "render/bvh.h"

namespace veduta {

// Top row first; a pixel whose ray leaves the scene holds FirstHit{}.
std::vector<FirstHit> firstHitsAtPixelCentres(const RenderScene &scene, const Bvh &bvh);

}  // namespace veduta
