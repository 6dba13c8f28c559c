#include "geodesy/crs.h"

#include <array>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/TransverseMercator.hpp>

#include "geodesy/datum_grid.h"

namespace veduta {

namespace {

using GeographicLib::Geocentric;
using GeographicLib::TransverseMercator;

constexpr double kBesselA = 6377397.155, kBesselF = 1 / 299.1528128;
constexpr double kGrs80A = 6378137, kGrs80F = 1 / 298.257222101;

constexpr Crs gaussKrueger(int zone) {
    constexpr std::string_view names[] = {"DHDN / 3-degree Gauss-Kruger zone 2", "DHDN / 3-degree Gauss-Kruger zone 3",
                                          "DHDN / 3-degree Gauss-Kruger zone 4", "DHDN / 3-degree Gauss-Kruger zone 5"};
    return {31464 + zone, names[zone - 2], Datum::Dhdn,         Ellipsoid::Bessel1841,
            true,         3.0 * zone,      zone * 1e6 + 500000, zone};
}

constexpr Crs utm(int epsg, std::string_view name, Datum datum, Ellipsoid ellipsoid, int zone) {
    return {epsg, name, datum, ellipsoid, true, 6.0 * zone - 183, 500000, 0};
}

constexpr Crs geographic(int epsg, std::string_view name, Datum datum, Ellipsoid ellipsoid) {
    return {epsg, name, datum, ellipsoid, false, 0, 0, 0};
}

constexpr std::array kCatalogue = {
    gaussKrueger(2),
    gaussKrueger(3),
    gaussKrueger(4),
    gaussKrueger(5),
    utm(25832, "ETRS89 / UTM zone 32N", Datum::Etrs89, Ellipsoid::Grs80, 32),
    utm(25833, "ETRS89 / UTM zone 33N", Datum::Etrs89, Ellipsoid::Grs80, 33),
    utm(32632, "WGS 84 / UTM zone 32N", Datum::Etrs89, Ellipsoid::Wgs84, 32),
    utm(32633, "WGS 84 / UTM zone 33N", Datum::Etrs89, Ellipsoid::Wgs84, 33),
    geographic(4314, "DHDN", Datum::Dhdn, Ellipsoid::Bessel1841),
    geographic(4258, "ETRS89", Datum::Etrs89, Ellipsoid::Grs80),
    geographic(4326, "WGS 84", Datum::Etrs89, Ellipsoid::Wgs84),
};

const TransverseMercator &transverseMercator(const Crs &crs) {
    if (!crs.projected) throw std::invalid_argument(fmt::format("EPSG:{} is geographic, not projected", crs.epsg));
    static const TransverseMercator gaussKruegerBessel(kBesselA, kBesselF, 1);
    static const TransverseMercator utmGrs80(kGrs80A, kGrs80F, GeographicLib::Constants::UTM_k0());
    static const TransverseMercator utmWgs84 = TransverseMercator::UTM();
    switch (crs.ellipsoid) {
    case Ellipsoid::Bessel1841: return gaussKruegerBessel;
    case Ellipsoid::Grs80: return utmGrs80;
    case Ellipsoid::Wgs84: return utmWgs84;
    }
    throw std::invalid_argument("unknown ellipsoid");
}

// Earth-centred coordinates on each datum's ellipsoid; WGS 84 latitudes and longitudes,
// being taken as ETRS89, go through GRS80 (the two ellipsoids differ by 0.1 mm in b).
const Geocentric &geocentric(Datum datum) {
    static const Geocentric bessel(kBesselA, kBesselF);
    static const Geocentric grs80(kGrs80A, kGrs80F);
    return datum == Datum::Dhdn ? bessel : grs80;
}

struct Vec3d {
    double x = 0, y = 0, z = 0;
};

struct Mat3d {
    double m[3][3] = {};

    Vec3d operator*(const Vec3d &v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
};

Mat3d inverse(const Mat3d &a) {
    const auto &m = a.m;
    double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    return {
        {{c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
         {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
         {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det}}};
}

// EPSG:1777, DHDN to ETRS89 (and WGS 84), 7 parameters in the position-vector convention
// (EPSG method 9606, PROJ's +towgs84 and +convention=position_vector):
// X_etrs = T + (1 + s) · R · X_dhdn with R = [[1, −rz, ry], [rz, 1, −rx], [−ry, rx, 1]].
// The coordinate-frame convention (9607) transposes R, which would move points ~100 m.
struct Helmert {
    Vec3d translation;
    Mat3d forward;   // (1 + s) · R
    Mat3d backward;  // its inverse
};

const Helmert &helmert() {
    static const Helmert h = [] {
        constexpr double arcSecond = M_PI / (180.0 * 3600.0);
        double rx = 0.202 * arcSecond, ry = 0.045 * arcSecond, rz = -2.455 * arcSecond;
        double s = 1 + 6.7e-6;
        Mat3d m{{{s, -s * rz, s * ry}, {s * rz, s, -s * rx}, {-s * ry, s * rx, s}}};
        return Helmert{{598.1, 73.7, 418.2}, m, inverse(m)};
    }();
    return h;
}

Vec3d toGeocentric(Datum datum, const GeographicPoint &p) {
    Vec3d r;
    geocentric(datum).Forward(p.latitude, p.longitude, 0, r.x, r.y, r.z);
    return r;
}

GeographicPoint fromGeocentric(Datum datum, const Vec3d &r) {
    GeographicPoint p;
    double height = 0;
    geocentric(datum).Reverse(r.x, r.y, r.z, p.latitude, p.longitude, height);
    return p;
}

GeographicPoint dhdnToEtrs89(const GeographicPoint &point) {
    const Helmert &h = helmert();
    Vec3d r = h.forward * toGeocentric(Datum::Dhdn, point);
    return fromGeocentric(Datum::Etrs89, {r.x + h.translation.x, r.y + h.translation.y, r.z + h.translation.z});
}

// Both directions start at ellipsoidal height 0, so the inverse Helmert alone is not quite the
// inverse of dhdnToEtrs89: the DHDN point it finds lies some 50 m off the ellipsoid, and
// starting again from height 0 moves it by up to 1 mm. One correction by how far the
// forward image misses makes the pair inverse to about 1e−13°.
GeographicPoint etrs89ToDhdn(const GeographicPoint &point) {
    const Helmert &h = helmert();
    Vec3d r = toGeocentric(Datum::Etrs89, point);
    GeographicPoint guess = fromGeocentric(
        Datum::Dhdn, h.backward * Vec3d{r.x - h.translation.x, r.y - h.translation.y, r.z - h.translation.z});
    GeographicPoint image = dhdnToEtrs89(guess);
    return {guess.latitude + (point.latitude - image.latitude), guess.longitude + (point.longitude - image.longitude)};
}

GeographicPoint onOwnDatum(const Crs &crs, const CrsCoordinate &p) {
    return crs.projected ? inverseProjection(crs, {p.x, p.y}) : GeographicPoint{p.y, p.x};
}

// `prefix` in lower case.
bool startsWithIgnoringCase(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
    }
    return true;
}

std::string_view direction(double offset) { return offset < 0 ? "west" : "east"; }

std::atomic<uint64_t> helmertCount{0};

}  // namespace

std::span<const Crs> supportedCrss() { return kCatalogue; }

const Crs &crsByEpsg(int epsg) {
    for (const Crs &crs : kCatalogue) {
        if (crs.epsg == epsg) return crs;
    }
    throw std::invalid_argument(
        fmt::format("EPSG:{} is not supported; veduta knows EPSG:31466 to 31469 (DHDN / Gauss-Kruger zones 2 to 5), "
                    "25832, 25833 (ETRS89 / UTM 32N, 33N), 32632, 32633 (WGS 84 / UTM 32N, 33N), "
                    "4314 (DHDN), 4258 (ETRS89) and 4326 (WGS 84)",
                    epsg));
}

const Crs &parseCrs(std::string_view text) {
    std::string_view code = text;
    if (startsWithIgnoringCase(code, "epsg:")) code.remove_prefix(5);
    int epsg = 0;
    auto [end, error] = std::from_chars(code.data(), code.data() + code.size(), epsg);
    // from_chars takes a leading minus sign; a code is digits only.
    if (code.empty() || code[0] == '-' || error != std::errc() || end != code.data() + code.size()) {
        throw std::invalid_argument(
            fmt::format("'{}' is not a CRS; write EPSG:<code> or the code, e.g. EPSG:31467", text));
    }
    return crsByEpsg(epsg);
}

GeographicPoint inverseProjection(const Crs &crs, const MapPoint &point) {
    GeographicPoint r;
    transverseMercator(crs).Reverse(crs.centralMeridian, point.easting - crs.falseEasting, point.northing, r.latitude,
                                    r.longitude);
    return r;
}

MapPoint forwardProjection(const Crs &crs, const GeographicPoint &point) {
    MapPoint r;
    transverseMercator(crs).Forward(crs.centralMeridian, point.latitude, point.longitude, r.easting, r.northing);
    r.easting += crs.falseEasting;
    return r;
}

GeographicPoint changeDatum(Datum from, Datum to, const GeographicPoint &point) {
    if (from == to) return point;
    std::optional<GeographicPoint> byGrid =
        from == Datum::Dhdn ? beta2007DhdnToEtrs89(point) : beta2007Etrs89ToDhdn(point);
    if (byGrid) return *byGrid;
    helmertCount.fetch_add(1, std::memory_order_relaxed);
    return changeDatumByHelmert(from, to, point);
}

GeographicPoint changeDatumByHelmert(Datum from, Datum to, const GeographicPoint &point) {
    if (from == to) return point;
    return from == Datum::Dhdn ? dhdnToEtrs89(point) : etrs89ToDhdn(point);
}

uint64_t helmertFallbacks() { return helmertCount.load(std::memory_order_relaxed); }

std::optional<std::string> helmertFallbackWarning(uint64_t fallbacksBefore) {
    uint64_t count = helmertFallbacks() - fallbacksBefore;
    if (count == 0) return std::nullopt;
    if (!beta2007Installed()) {
        return fmt::format(
            "BETA2007.gsb was not found (Debian package proj-data), so {} point{} went between DHDN "
            "and ETRS89 by the 7-parameter Helmert EPSG:1777, which is up to 3 m off",
            count, count == 1 ? "" : "s");
    }
    return fmt::format(
        "{} point{} outside the BeTA2007 grid went between DHDN and ETRS89 by the 7-parameter "
        "Helmert EPSG:1777, which is up to 3 m off and jumps by as much at the grid's edge",
        count, count == 1 ? "" : "s");
}

CrsCoordinate convert(const Crs &from, const Crs &to, const CrsCoordinate &point) {
    if (from.epsg == to.epsg) return point;
    GeographicPoint g = changeDatum(from.datum, to.datum, onOwnDatum(from, point));
    if (!to.projected) return {g.longitude, g.latitude, point.z};
    MapPoint m = forwardProjection(to, g);
    return {m.easting, m.northing, point.z};
}

GridFactors gridFactors(const Crs &crs, const MapPoint &point) {
    GridFactors r;
    double latitude = 0, longitude = 0;
    transverseMercator(crs).Reverse(crs.centralMeridian, point.easting - crs.falseEasting, point.northing, latitude,
                                    longitude, r.convergenceDegrees, r.scale);
    return r;
}

GaussKruegerZone gaussKruegerZone(double rechtswert) {
    if (!(rechtswert >= 1e6 && rechtswert < 1e7)) {
        throw std::out_of_range(
            fmt::format("{} is no Gauss-Kruger Rechtswert: it has seven digits before the point, "
                        "the first the zone",
                        rechtswert));
    }
    GaussKruegerZone z;
    z.zone = int(rechtswert / 1e6);
    z.centralMeridian = 3.0 * z.zone;
    z.offsetFromMeridian = rechtswert - z.zone * 1e6 - 500000;
    if (std::abs(z.offsetFromMeridian) > kMaxGaussKruegerOffset) {
        throw std::out_of_range(
            fmt::format("Rechtswert {} lies {:.0f} km {} of zone {}'s central meridian ({}° E); "
                        "no more than {:.0f} km fit a zone",
                        rechtswert, std::abs(z.offsetFromMeridian) / 1000, direction(z.offsetFromMeridian), z.zone,
                        z.centralMeridian, kMaxGaussKruegerOffset / 1000));
    }
    return z;
}

const Crs &gaussKruegerCrs(double rechtswert) {
    int zone = gaussKruegerZone(rechtswert).zone;
    if (zone < 2 || zone > 5) {
        throw std::out_of_range(
            fmt::format("Rechtswert {} is in Gauss-Kruger zone {}; veduta knows zones 2 to 5", rechtswert, zone));
    }
    return crsByEpsg(31464 + zone);
}

void checkAxis(const Crs &crs, int axis, double value) {
    if (!crs.projected) {
        double limit = axis == 0 ? 180 : 90;
        if (!(std::abs(value) <= limit)) {
            throw std::out_of_range(
                fmt::format("{} {} is beyond ±{}°", axis == 0 ? "longitude" : "latitude", value, limit));
        }
    } else if (axis == 1) {
        if (!(value >= 0 && value < 1e7)) {
            throw std::out_of_range(fmt::format("northing {} is outside 0 to 10 000 000 m", value));
        }
    } else if (crs.gaussKruegerZone != 0) {
        int zone = gaussKruegerZone(value).zone;
        if (zone != crs.gaussKruegerZone) {
            throw std::out_of_range(fmt::format("Rechtswert {} is in Gauss-Kruger zone {}, not in zone {} of EPSG:{}",
                                                value, zone, crs.gaussKruegerZone, crs.epsg));
        }
    } else {
        double offset = value - crs.falseEasting;
        if (!(std::abs(offset) < 500000)) {
            throw std::out_of_range(
                fmt::format("easting {} lies more than 500 km from the central meridian of EPSG:{}", value, crs.epsg));
        }
    }
}

}  // namespace veduta
