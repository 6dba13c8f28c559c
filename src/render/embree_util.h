// Conversions between our types and Embree's. Included by bvh.cpp and by benchmarks that
// call Embree directly; nothing else should need Embree.
#pragma once

#include <embree3/rtcore.h>

#include "scene/camera.h"

namespace veduta {

inline RTCRayHit toRayHit(const Ray &ray, float tMax) {
    RTCRayHit rh{};
    rh.ray.org_x = ray.origin.x;
    rh.ray.org_y = ray.origin.y;
    rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x;
    rh.ray.dir_y = ray.direction.y;
    rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = 0;
    rh.ray.tfar = tMax;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace veduta
