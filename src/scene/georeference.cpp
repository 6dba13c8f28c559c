#include "scene/georeference.h"

#include <cmath>
#include <stdexcept>

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/TransverseMercator.hpp>
#include <fmt/format.h>

namespace veduta {

namespace {

using GeographicLib::TransverseMercator;

// A transverse Mercator CRS: the ellipsoid and scale on the central meridian live in the
// GeographicLib object, the rest here. The DHDN zones are taken on their own datum: going
// to ETRS89 would move a point some 100 m, which turns the sun by far less than 0.001°.
struct Projection {
    std::string_view name;
    const TransverseMercator &tm;
    double centralMeridian;
    double falseEasting;
};

const TransverseMercator &utmGrs80() {
    // GRS80: a = 6 378 137 m, 1/f = 298.257222101 (GeographicLib names its a, not its f).
    static const TransverseMercator tm(6378137, 1 / 298.257222101, GeographicLib::Constants::UTM_k0());
    return tm;
}

const TransverseMercator &utmWgs84() {
    static const TransverseMercator tm = TransverseMercator::UTM();
    return tm;
}

const TransverseMercator &gaussKruegerBessel() {
    // Bessel 1841: a = 6 377 397.155 m, 1/f = 299.1528128; scale 1 on the central meridian.
    static const TransverseMercator tm(6377397.155, 1 / 299.1528128, 1);
    return tm;
}

Projection projection(int epsg) {
    switch (epsg) {
        case 25832: return {"ETRS89 / UTM zone 32N", utmGrs80(), 9, 500000};
        case 25833: return {"ETRS89 / UTM zone 33N", utmGrs80(), 15, 500000};
        case 32632: return {"WGS 84 / UTM zone 32N", utmWgs84(), 9, 500000};
        case 32633: return {"WGS 84 / UTM zone 33N", utmWgs84(), 15, 500000};
        case 31466: return {"DHDN / 3-degree Gauss-Kruger zone 2", gaussKruegerBessel(), 6, 2500000};
        case 31467: return {"DHDN / 3-degree Gauss-Kruger zone 3", gaussKruegerBessel(), 9, 3500000};
        case 31468: return {"DHDN / 3-degree Gauss-Kruger zone 4", gaussKruegerBessel(), 12, 4500000};
        case 31469: return {"DHDN / 3-degree Gauss-Kruger zone 5", gaussKruegerBessel(), 15, 5500000};
        default:
            throw std::invalid_argument(fmt::format("EPSG:{} is not supported; use 25832, 25833, 32632, 32633 (UTM) "
                                                    "or 31466 to 31469 (Gauss-Kruger)",
                                                    epsg));
    }
}

struct Inverse {
    GeographicPoint point;
    double convergence;
};

Inverse inverse(const Georeference &georef, double easting, double northing) {
    Projection p = projection(georef.epsg);
    Inverse r;
    double scale;
    // All supported CRSs are northern, with false northing 0.
    p.tm.Reverse(p.centralMeridian, easting - p.falseEasting, northing, r.point.latitude, r.point.longitude,
                 r.convergence, scale);
    return r;
}

}  // namespace

std::string_view crsName(int epsg) { return projection(epsg).name; }

GeographicPoint toGeographic(const Georeference &georef, double easting, double northing) {
    return inverse(georef, easting, northing).point;
}

ProjectedPoint toProjected(const Georeference &georef, const GeographicPoint &point) {
    Projection p = projection(georef.epsg);
    ProjectedPoint r;
    p.tm.Forward(p.centralMeridian, point.latitude, point.longitude, r.easting, r.northing);
    r.easting += p.falseEasting;
    return r;
}

double meridianConvergenceDegrees(const Georeference &georef, double easting, double northing) {
    return inverse(georef, easting, northing).convergence;
}

double gridAzimuthDegrees(double trueAzimuthDegrees, double convergenceDegrees) {
    double a = std::fmod(trueAzimuthDegrees - convergenceDegrees, 360.0);
    if (a < 0) a += 360;
    return a < 360 ? a : 0;  // −1e−15 + 360 rounds to 360
}

}  // namespace veduta
