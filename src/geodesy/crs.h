// The coordinate reference systems veduta reads (German Gauss-Krüger on DHDN, UTM on
// ETRS89 and WGS 84, and their geographic CRSs) and conversions between any two of them,
// in double. A conversion goes projected → geographic on the CRS's own datum → datum change
// → target. The one datum change is DHDN ↔ ETRS89, by the official NTv2 grid BeTA2007
// (geodesy/datum_grid.h) and, outside it, by the 7-parameter Helmert transformation
// EPSG:1777; ETRS89 and WGS 84 are taken as one datum (they differ by less than 1 m in
// Germany). Heights pass through unchanged. See docs/coordinates.md.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "geodesy/map_point.h"

namespace veduta {

enum class Datum {
    Dhdn,    // Deutsches Hauptdreiecksnetz: Bessel 1841 ellipsoid, Potsdam datum
    Etrs89,  // ETRS89 and WGS 84, taken as one
};

enum class Ellipsoid { Bessel1841, Grs80, Wgs84 };

struct Crs {
    int epsg = 0;
    std::string_view name;  // as the EPSG registry (and PROJ) spells it
    Datum datum = Datum::Etrs89;
    Ellipsoid ellipsoid = Ellipsoid::Grs80;
    // Transverse Mercator, whose scale on the central meridian follows the ellipsoid: 1 on
    // Bessel (Gauss-Krüger), 0.9996 on GRS80 and WGS 84 (UTM). Otherwise geographic degrees.
    bool projected = false;
    double centralMeridian = 0;  // degrees east; projected only
    double falseEasting = 0;     // metres; every supported CRS has false northing 0
    int gaussKruegerZone = 0;    // the Kennziffer of a Gauss-Krüger CRS, 0 for the others
};

struct GeographicPoint {
    double latitude = 0, longitude = 0;  // degrees, on a datum the context names
};

// A position in some CRS: x is the easting (metres) or the longitude (degrees), y the
// northing or the latitude, z the height, which no conversion changes.
struct CrsCoordinate {
    double x = 0, y = 0, z = 0;
};

// EPSG 31466–31469 (DHDN / Gauss-Krüger zones 2–5), 25832, 25833 (ETRS89 / UTM 32N, 33N),
// 32632, 32633 (WGS 84 / UTM 32N, 33N), 4314 (DHDN), 4258 (ETRS89), 4326 (WGS 84).
std::span<const Crs> supportedCrss();

// The supported CRS of that code; throws std::invalid_argument naming the supported ones.
const Crs &crsByEpsg(int epsg);

// "EPSG:31467" (any case) or "31467" as a supported CRS; throws std::invalid_argument.
const Crs &parseCrs(std::string_view text);

// The conversion between any two supported CRSs; z is copied. Latitude and longitude go
// through the datum change at ellipsoidal height 0, so the result does not depend on z.
CrsCoordinate convert(const Crs &from, const Crs &to, const CrsCoordinate &point);

// Transverse Mercator of a projected CRS, on its own datum (throw std::invalid_argument for
// a geographic CRS).
GeographicPoint inverseProjection(const Crs &crs, const MapPoint &point);
MapPoint forwardProjection(const Crs &crs, const GeographicPoint &point);

// The datum change of latitude and longitude alone (identity for from == to): BeTA2007
// where the grid covers the point and is installed, else changeDatumByHelmert, counted in
// helmertFallbacks.
GeographicPoint changeDatum(Datum from, Datum to, const GeographicPoint &point);
// EPSG:1777's Helmert alone, good to about 3 m in Germany.
GeographicPoint changeDatumByHelmert(Datum from, Datum to, const GeographicPoint &point);

// How many datum changes in this process have fallen back to the Helmert: a scene builder
// reads it before and after and says so in its warnings (helmertFallbackWarning, which is
// std::nullopt when no point fell back since `fallbacksBefore`).
uint64_t helmertFallbacks();
std::optional<std::string> helmertFallbackWarning(uint64_t fallbacksBefore);

// The meridian convergence γ at a point of a projected CRS: the angle from true north
// clockwise to grid north, positive east of the central meridian in the northern
// hemisphere, about (longitude − central meridian) · sin(latitude); and the point scale k,
// grid distance over ellipsoid distance there.
struct GridFactors {
    double convergenceDegrees = 0;
    double scale = 1;
};
GridFactors gridFactors(const Crs &crs, const MapPoint &point);

// The Gauss-Krüger zone of a Rechtswert: its first digit of seven is the Kennziffer, the
// zone's central meridian is 3° times it, and the other six digits are 500 000 m plus the
// distance east of that meridian. Throws std::out_of_range unless the Rechtswert has seven
// digits and lies within kMaxGaussKruegerOffset of the meridian.
struct GaussKruegerZone {
    int zone = 0;
    double centralMeridian = 0;     // degrees east
    double offsetFromMeridian = 0;  // metres east of it, negative west
};
constexpr double kMaxGaussKruegerOffset = 350000;
GaussKruegerZone gaussKruegerZone(double rechtswert);

// The supported Gauss-Krüger CRS that a Rechtswert names by its Kennziffer (zones 2–5);
// throws std::out_of_range otherwise.
const Crs &gaussKruegerCrs(double rechtswert);

// Throws std::out_of_range, saying why, when `value` cannot be the x (axis 0) or y (axis 1)
// of a point of `crs`: a longitude beyond ±180° or latitude beyond ±90°, a Gauss-Krüger
// Rechtswert of another zone or too far from its meridian, a UTM easting more than 500 km
// from the meridian, a northing outside [0, 10 000 km) (veduta's CRSs are northern).
void checkAxis(const Crs &crs, int axis, double value);

}  // namespace veduta
