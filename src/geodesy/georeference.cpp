#include "geodesy/georeference.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

// A scene lies on a map grid, so its CRS must be projected.
const Crs &projectedCrs(int epsg) {
    for (const Crs &crs : supportedCrss()) {
        if (crs.epsg == epsg && crs.projected) return crs;
    }
    throw std::invalid_argument(
        fmt::format("EPSG:{} is not supported; use 25832, 25833, 32632, 32633 (UTM) "
                    "or 31466 to 31469 (Gauss-Kruger)",
                    epsg));
}

}  // namespace

std::string_view crsName(int epsg) { return projectedCrs(epsg).name; }

GeographicPoint toGeographic(const Georeference &georef, double easting, double northing) {
    return inverseProjection(projectedCrs(georef.epsg), {easting, northing});
}

ProjectedPoint toProjected(const Georeference &georef, const GeographicPoint &point) {
    return forwardProjection(projectedCrs(georef.epsg), point);
}

double meridianConvergenceDegrees(const Georeference &georef, double easting, double northing) {
    return gridFactors(projectedCrs(georef.epsg), {easting, northing}).convergenceDegrees;
}

double gridAzimuthDegrees(double trueAzimuthDegrees, double convergenceDegrees) {
    double a = std::fmod(trueAzimuthDegrees - convergenceDegrees, 360.0);
    if (a < 0) a += 360;
    return a < 360 ? a : 0;  // −1e−15 + 360 rounds to 360
}

}  // namespace veduta
