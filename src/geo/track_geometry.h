// A railway's sleepers and rails as geometry on its ballast ribbon, where the camera is near
// enough to see them as solids: concrete sleepers 2.6 × 0.26 m every 0.6 m, 0.1 m high, and rails
// of standard gauge (1.435 m between the heads' inner edges), heads 0.07 m wide, 0.15 m over the
// ballast, as the ballast's texture (geo/pavement_texture.h) draws them farther away. Each track
// lies 4.5 m from the next, about the ribbon's centre line. docs/roads.md.
#pragma once

#include "core/vecmath.h"
#include "scene/mesh.h"

namespace veduta {

struct TrackOptions {
    double reach = 150;  // metres from the camera within which sleepers and rails are solid
};

enum TrackSurface : MaterialId { TrackSleeper = 0, TrackRail = 1 };

// The tracks on `ribbon` (drapeRibbon's mesh of a rail line `width` metres wide with `tracks`
// tracks) within options.reach of `camera`, standing on the ribbon's own triangles; empty when
// none is that near.
Mesh trackGeometry(const Mesh &ribbon, double width, int tracks, Vec3f camera, const TrackOptions &options = {});

}  // namespace veduta
