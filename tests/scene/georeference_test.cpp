#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "geodesy/georeference.h"

namespace veduta {
namespace {

constexpr int kSupportedEpsg[] = {25832, 25833, 32632, 32633, 31466, 31467, 31468, 31469};

struct KnownPoint {
    int epsg;
    GeographicPoint geographic;
    ProjectedPoint projected;
    double centralMeridian;
};

// Computed with PROJ 9.1.1's cs2cs, independent of GeographicLib: for UTM from ETRS89 or
// WGS 84 geographic coordinates, e.g. `echo "51.34 12.37" | cs2cs -d 4 EPSG:4258 EPSG:25833`;
// for Gauss-Krüger from DHDN's own geographic CRS (EPSG:4314, so no datum shift), e.g.
// `echo "51.34 12.37" | cs2cs -d 4 EPSG:4314 EPSG:31468`, whose output is northing first.
const KnownPoint kKnownPoints[] = {
    {25833, {51.34, 12.37}, {316820.0631, 5690919.2109}, 15},  // Leipzig, west of zone 33's meridian
    {25832, {51.34, 12.37}, {734709.4523, 5693028.0075}, 9},   // Leipzig, east of zone 32's
    {32633, {51.34, 12.37}, {316820.0631, 5690919.2110}, 15},  {32632, {51.34, 12.37}, {734709.4523, 5693028.0076}, 9},
    {25832, {48.0, 8.0}, {425404.8875, 5316784.0091}, 9},       // Black Forest
    {31466, {50.0, 7.0}, {2571686.3866, 5540758.7877}, 6},      // Eifel
    {31467, {47.42, 10.98}, {3649386.1172, 5255306.3563}, 9},   // Garmisch
    {31468, {51.34, 12.37}, {4525779.6672, 5689391.7658}, 12},  // Leipzig
    {31469, {54.09, 13.38}, {5394013.9136, 5996527.6104}, 15},  // Greifswald
};

TEST(Georeference, KnownPointsMatchProj) {
    for (const KnownPoint &k : kKnownPoints) {
        Georeference g{k.epsg};
        ProjectedPoint p = toProjected(g, k.geographic);
        GeographicPoint q = toGeographic(g, k.projected.easting, k.projected.northing);
        std::printf("EPSG:%d (%.2f, %.2f): easting %.4f (PROJ %.4f), northing %.4f (PROJ %.4f); back %.9f %.9f\n",
                    k.epsg, k.geographic.latitude, k.geographic.longitude, p.easting, k.projected.easting, p.northing,
                    k.projected.northing, q.latitude, q.longitude);
        // cs2cs prints to 0.1 mm; 1 mm is 1e−8° of latitude.
        EXPECT_NEAR(p.easting, k.projected.easting, 1e-3) << k.epsg;
        EXPECT_NEAR(p.northing, k.projected.northing, 1e-3) << k.epsg;
        EXPECT_NEAR(q.latitude, k.geographic.latitude, 1e-8) << k.epsg;
        EXPECT_NEAR(q.longitude, k.geographic.longitude, 1.5e-8) << k.epsg;
    }
}

TEST(Georeference, RoundTripsAcrossGermany) {
    for (int epsg : kSupportedEpsg) {
        Georeference g{epsg};
        for (double latitude = 47; latitude <= 55; latitude += 1) {
            for (double longitude = 6; longitude <= 15; longitude += 1.5) {
                ProjectedPoint p = toProjected(g, {latitude, longitude});
                GeographicPoint q = toGeographic(g, p.easting, p.northing);
                EXPECT_NEAR(q.latitude, latitude, 1e-9) << epsg;
                EXPECT_NEAR(q.longitude, longitude, 1e-9) << epsg;
            }
        }
    }
}

// The grid bearing, clockwise from grid north, of the step from a to b.
double gridBearing(const ProjectedPoint &a, const ProjectedPoint &b) {
    double bearing = std::atan2(b.easting - a.easting, b.northing - a.northing) * 180 / M_PI;
    return bearing < 0 ? bearing + 360 : bearing;
}

double angleBetween(double a, double b) {
    double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360 - d);
}

TEST(Georeference, TrueNorthOnTheGridIsWhereGridAzimuthPutsIt) {
    // Independent of GeographicLib's sign convention for γ: step about 1 km due north along
    // the meridian, project both ends, and read the step's bearing on the grid.
    for (const KnownPoint &k : kKnownPoints) {
        Georeference g{k.epsg};
        GeographicPoint start = k.geographic, end{start.latitude + 0.01, start.longitude};
        ProjectedPoint a = toProjected(g, start), b = toProjected(g, end);
        ProjectedPoint middle{(a.easting + b.easting) / 2, (a.northing + b.northing) / 2};
        double gamma = meridianConvergenceDegrees(g, middle.easting, middle.northing);
        double northOnGrid = gridBearing(a, b);
        double approximate = (start.longitude - k.centralMeridian) * std::sin(start.latitude * M_PI / 180);
        std::printf(
            "EPSG:%d (%.2f, %.2f): gamma %+.5f (approx %+.5f), true north on the grid %.5f, "
            "gridAzimuth(0) %.5f\n",
            k.epsg, start.latitude, start.longitude, gamma, approximate, northOnGrid, gridAzimuthDegrees(0, gamma));
        EXPECT_LT(angleBetween(northOnGrid, gridAzimuthDegrees(0, gamma)), 1e-4) << k.epsg;
        EXPECT_NEAR(gamma, approximate, 0.01) << k.epsg;
        // East of the central meridian grid north leans east of true north.
        EXPECT_EQ(gamma > 0, start.longitude > k.centralMeridian) << k.epsg;
    }
}

TEST(Georeference, GridAzimuthTurnsEveryDirectionAlike) {
    // The sun due south of Leipzig at noon, seen on the UTM 32N grid (γ ≈ +2.64°): grid
    // north leans east, so the sun stands that much west of grid south.
    Georeference g{25832};
    double gamma = meridianConvergenceDegrees(g, 734709.4523, 5693028.0075);
    EXPECT_NEAR(gridAzimuthDegrees(180, gamma), 180 - gamma, 1e-12);
    EXPECT_GT(gamma, 2.6);
    EXPECT_DOUBLE_EQ(gridAzimuthDegrees(0.5, 1.0), 359.5);
    EXPECT_DOUBLE_EQ(gridAzimuthDegrees(359.75, -0.5), 0.25);
    EXPECT_DOUBLE_EQ(gridAzimuthDegrees(720 + 90, 0), 90);
    EXPECT_GE(gridAzimuthDegrees(-1e-15, 0), 0);
    EXPECT_LT(gridAzimuthDegrees(-1e-15, 0), 360);
}

TEST(Georeference, UnknownCrsIsRejected) {
    for (int epsg : {0, 4326, 3857, 25831, 31465, 31470}) {
        EXPECT_THROW(crsName(epsg), std::invalid_argument) << epsg;
        EXPECT_THROW(toGeographic(Georeference{epsg}, 500000, 5000000), std::invalid_argument) << epsg;
        EXPECT_THROW(toProjected(Georeference{epsg}, {51, 12}), std::invalid_argument) << epsg;
        EXPECT_THROW(meridianConvergenceDegrees(Georeference{epsg}, 500000, 5000000), std::invalid_argument) << epsg;
    }
    for (int epsg : kSupportedEpsg) EXPECT_FALSE(crsName(epsg).empty()) << epsg;
    EXPECT_EQ(crsName(31468), "DHDN / 3-degree Gauss-Kruger zone 4");
}

}  // namespace
}  // namespace veduta
