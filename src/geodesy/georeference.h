// Where the scene lies on the Earth: a projected CRS (UTM or German Gauss-Krüger) and the
// easting/northing of the scene origin. The sun needs it for latitude, longitude and the
// meridian convergence; GIS data will need it to place itself.
#pragma once

#include <string_view>

#include "geodesy/crs.h"
#include "geodesy/map_point.h"

namespace veduta {

// The scene origin (0, 0) sits at (originEasting, originNorthing) of the CRS `epsg`; scene
// +x is grid east and +y grid north.
struct Georeference {
    int epsg = 0;
    double originEasting = 0, originNorthing = 0;
};

using ProjectedPoint = MapPoint;

// The projected CRSs of geo/crs.h: EPSG 25832, 25833 (ETRS89 / UTM 32N, 33N), 32632, 32633
// (WGS 84 / UTM 32N, 33N), 31466–31469 (DHDN / 3-degree Gauss-Krüger zones 2–5). Every
// function here throws std::invalid_argument for any other code, a geographic one included;
// the scene reader calls crsName to check.
std::string_view crsName(int epsg);

// Latitude and longitude on the CRS's own datum (DHDN for Gauss-Krüger): a datum shift would
// move a point some 100 m, which turns the sun by far less than 0.001°.
GeographicPoint toGeographic(const Georeference &georef, double easting, double northing);
ProjectedPoint toProjected(const Georeference &georef, const GeographicPoint &point);

// The meridian convergence γ at a point: the angle from true north clockwise to grid north.
// Positive east of the central meridian in the northern hemisphere, about
// (longitude − central meridian) · sin(latitude).
double meridianConvergenceDegrees(const Georeference &georef, double easting, double northing);

// An azimuth clockwise from true north as an azimuth clockwise from grid north (scene +y),
// in [0, 360): true north itself lies at −γ on the grid.
double gridAzimuthDegrees(double trueAzimuthDegrees, double convergenceDegrees);

}  // namespace veduta
