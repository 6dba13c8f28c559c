// A point in a projected CRS (Gauss-Krüger or UTM): easting and northing in metres, kept in
// double until it is made local to the scene origin (float32 at Gauss-Krüger magnitudes
// resolves only about 0.5 m).
#pragma once

#include <vector>

namespace veduta {

struct MapPoint {
    double easting = 0, northing = 0;

    friend bool operator==(const MapPoint &, const MapPoint &) = default;
};

using MapRing = std::vector<MapPoint>;  // a closed outline, the first point not repeated at the end
using MapLine = std::vector<MapPoint>;  // an open polyline

}  // namespace veduta
