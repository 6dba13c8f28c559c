// The render frame of a georeferenced scene: x grid east and y grid north in metres from the
// scene origin, z the height. Coordinates are subtracted in double and only then made
// float. The frame follows the grid, not true north; the sun is turned by the meridian
// convergence (scene/georeference.h) to match.
#pragma once

#include "core/vecmath.h"
#include "geodesy/map_point.h"

namespace veduta {

// How far from the scene origin a point of the render frame may lie, in metres (10,000 km):
// farther, float steps are metres wide and Embree's bounds overflow. Georeferenced data puts
// the origin near the scene (geodesy/map_projection.h).
constexpr float kFrameLimit = 1e7f;

struct LocalFrame {
    MapPoint origin;

    Vec2f toLocal(const MapPoint &p) const {
        return {float(p.easting - origin.easting), float(p.northing - origin.northing)};
    }
    Vec3f toLocal(const MapPoint &p, double height) const {
        return {float(p.easting - origin.easting), float(p.northing - origin.northing), float(height)};
    }
    MapPoint toMap(const Vec2f &p) const { return {origin.easting + p.x, origin.northing + p.y}; }
};

}  // namespace veduta
