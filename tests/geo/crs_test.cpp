#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "geodesy/crs.h"
#include "geodesy/datum_grid.h"

namespace veduta {
namespace {

double distance(const CrsCoordinate &a, const CrsCoordinate &b) { return std::hypot(a.x - b.x, a.y - b.y); }

CrsCoordinate convertEpsg(int from, int to, const CrsCoordinate &p) {
    return convert(crsByEpsg(from), crsByEpsg(to), p);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

struct ReferencePoint {
    const char *place;
    CrsCoordinate from;     // in the source CRS
    CrsCoordinate beta;     // PROJ with the BeTA2007 grid
    CrsCoordinate helmert;  // PROJ with EPSG:1777's Helmert parameters (+towgs84)
};

// Ten points across Germany in DHDN / Gauss-Krüger zone 3 (EPSG:31467), whole metres, and
// their ETRS89 / UTM 32N (EPSG:25832) coordinates computed with PROJ 9.1.1 (Debian proj-bin):
//   beta:    cs2cs -f %.4f EPSG:31467 EPSG:25832    (input "northing easting": EPSG axis order)
//            PROJ picks "DHDN to ETRS89 (8)", the NTv2 grid BETA2007.gsb from
//            /usr/share/proj; the explicit +nadgrids=BETA2007.gsb pipeline gives the same
//            values to 0.1 mm, so no point fell back to a Helmert.
//   helmert: cs2cs -f %.4f +proj=tmerc +lon_0=9 +k=1 +x_0=3500000 +ellps=bessel
//              +towgs84=598.1,73.7,418.2,0.202,0.045,-2.455,6.7
//              +to +proj=utm +zone=32 +ellps=GRS80 +towgs84=0,0,0    (input "easting northing")
// The reverse, cs2cs -f %.4f EPSG:25832 EPSG:31467 on the beta values, returns the GK values
// to 0.1 mm, so the same table serves both directions.
const ReferencePoint kGk3ToUtm32[] = {
    {"Flensburg", {3527735, 6072384}, {527656.3437, 6070395.3604}, {527654.1269, 6070394.5187}},
    {"Stralsund", {3766206, 6027706}, {766029.4783, 6025730.8487}, {766029.4768, 6025732.0242}},
    {"Hamburg", {3566350, 5935857}, {566253.1773, 5933921.7760}, {566252.4422, 5933921.6799}},
    {"Berlin", {3798665, 5829874}, {798473.3734, 5827978.7206}, {798473.4810, 5827978.8377}},
    {"Kassel", {3533544, 5686243}, {533456.7514, 5684408.2406}, {533457.3181, 5684407.8548}},
    {"Aachen", {3294148, 5631237}, {294154.8843, 5629425.8519}, {294156.7431, 5629425.8818}},
    {"Koblenz", {3397608, 5581442}, {397573.8526, 5579649.8598}, {397574.8934, 5579649.9992}},
    {"Dresden", {3832374, 5667912}, {832166.5503, 5666081.6658}, {832167.3624, 5666081.4261}},
    {"Freiburg", {3414240, 5317516}, {414198.7451, 5315828.1054}, {414198.0892, 5315829.7469}},
    {"Garmisch", {3658325, 5263421}, {658185.4516, 5261755.4202}, {658184.5813, 5261754.4752}},
};

// BKG's BeTA2007 test points (BETA2007testdaten.csv, as PROJ's test/gie/DHDN_ETRS89.gie
// lists them): longitude and latitude on DHDN and on ETRS89.
struct GeographicPair {
    double dhdnLongitude, dhdnLatitude, etrsLongitude, etrsLatitude;
};
const GeographicPair kBeta2007TestPoints[] = {
    {7.483333333333, 53.500000000000, 7.482506019176, 53.498461143331},
    {10.333333333333, 48.833333333333, 10.332117283303, 48.832327188640},
    {8.000000000000, 50.083333333333, 7.999097344043, 50.082172046476},
    {10.016666666667, 51.033333333333, 10.015460839103, 51.032075951188},
    {10.466666666667, 54.333333333333, 10.465373788153, 54.331696254077},
    {10.750000000000, 53.583333333333, 10.748659705929, 53.581781243436},
    {10.016666666667, 53.500000000000, 10.015444367463, 53.498457503620},
    {11.000000000000, 53.466666666667, 10.998619309575, 53.465127257963},
    {13.466666666667, 53.766666666667, 13.464877774631, 53.765109112396},
    {10.983333333333, 52.766666666667, 10.981965431979, 52.765211787713},
    {13.000000000000, 51.783333333333, 12.998336654827, 51.782006921265},
    {10.466666666667, 52.500000000000, 10.465380298337, 52.498573633365},
    {10.550000000000, 51.466666666667, 10.548711467380, 51.465361979987},
    {10.450000000000, 50.583333333333, 10.448735275612, 50.582129474187},
    {10.416666666667, 49.666666666667, 10.415423634267, 49.665566047661},
    {10.550000000000, 47.750000000000, 10.548775945187, 47.749120260296},
    {13.450000000000, 50.666666666667, 13.448283429558, 50.665476385913},
    {13.550000000000, 51.333333333333, 13.548264242652, 51.332063317958},
    {13.566666666667, 52.050000000000, 13.564906713066, 52.048646469731},
    {13.433333333333, 53.166666666667, 13.431569610583, 53.165185284138},
    {13.466666666667, 52.483333333333, 13.464913254978, 52.481930297429},
    {13.133333333333, 49.066666666667, 13.131706947050, 49.065661709281},
    {8.666666666667, 53.116666666667, 8.665654272188, 53.115169791635},
    {12.950000000000, 47.650000000000, 12.948437185277, 47.649155713893},
    {8.500000000000, 54.716666666667, 8.499027339833, 54.714992333813},
    {7.483333333333, 51.983333333333, 7.482494584516, 51.981965147975},
    {7.516666666667, 51.016666666667, 7.515823996992, 51.015402184493},
    {7.466666666667, 50.500000000000, 7.465834308888, 50.498791390585},
    {7.533333333333, 49.333333333333, 7.532503616986, 49.332250779407},
    {7.250000000000, 49.333333333333, 7.249209260581, 49.332249456364},
    {7.533333333333, 47.666666666667, 7.532530252396, 47.665765608135},
};

// Metres between two nearby points given in degrees (an equirectangular approximation,
// exact to far better than 1 % over the centimetres it measures here).
double metresApart(double longitudeA, double latitudeA, double longitudeB, double latitudeB) {
    constexpr double metresPerDegree = 6371000 * M_PI / 180;
    double east = (longitudeA - longitudeB) * std::cos(latitudeA * M_PI / 180);
    return std::hypot(east, latitudeA - latitudeB) * metresPerDegree;
}

TEST(Crs, DatumChangeMeetsBeta2007TestPointsBothWays) {
    ASSERT_TRUE(beta2007Installed()) << "BETA2007.gsb not found: install Debian's proj-data (./setup.sh does)";
    uint64_t fallbacksBefore = helmertFallbacks();
    std::vector<double> forward, backward;
    for (const GeographicPair &p : kBeta2007TestPoints) {
        CrsCoordinate etrs = convertEpsg(4314, 4258, {p.dhdnLongitude, p.dhdnLatitude});
        CrsCoordinate dhdn = convertEpsg(4258, 4314, {p.etrsLongitude, p.etrsLatitude});
        forward.push_back(metresApart(etrs.x, etrs.y, p.etrsLongitude, p.etrsLatitude));
        backward.push_back(metresApart(dhdn.x, dhdn.y, p.dhdnLongitude, p.dhdnLatitude));
        EXPECT_LT(forward.back(), 0.01) << p.dhdnLongitude << " " << p.dhdnLatitude;
        EXPECT_LT(backward.back(), 0.01) << p.etrsLongitude << " " << p.etrsLatitude;
    }
    std::printf("BeTA2007 test points (%zu): DHDN -> ETRS89 max %.2e m, ETRS89 -> DHDN max %.2e m\n", forward.size(),
                *std::max_element(forward.begin(), forward.end()), *std::max_element(backward.begin(), backward.end()));
    EXPECT_EQ(helmertFallbacks(), fallbacksBefore);
    EXPECT_FALSE(helmertFallbackWarning(fallbacksBefore));
}

TEST(Crs, GaussKrueger3ToUtm32IsBeta2007) {
    std::vector<double> forward, helmert;
    for (const ReferencePoint &r : kGk3ToUtm32) {
        CrsCoordinate utm = convertEpsg(31467, 25832, r.from);
        CrsCoordinate gk = convertEpsg(25832, 31467, r.beta);
        EXPECT_LT(distance(utm, r.beta), 2e-3) << r.place;
        EXPECT_LT(distance(gk, r.from), 2e-3) << r.place;
        forward.push_back(distance(utm, r.beta));
        helmert.push_back(distance(r.helmert, r.beta));
    }
    std::printf(
        "GK3 -> UTM32 against PROJ's BeTA2007 at %zu points: max %.2e m; the Helmert would be off by "
        "max %.3f m, median %.3f m\n",
        forward.size(), *std::max_element(forward.begin(), forward.end()),
        *std::max_element(helmert.begin(), helmert.end()), median(helmert));
}

// GK 3 → UTM 32 by the Helmert alone.
CrsCoordinate gk3ToUtm32ByHelmert(const CrsCoordinate &p) {
    GeographicPoint dhdn = inverseProjection(crsByEpsg(31467), {p.x, p.y});
    MapPoint utm = forwardProjection(crsByEpsg(25832), changeDatumByHelmert(Datum::Dhdn, Datum::Etrs89, dhdn));
    return {utm.easting, utm.northing};
}

TEST(Crs, HelmertIsProjsTowgs84) {
    // The same parameters and convention as PROJ's +towgs84 give the same points; the
    // coordinate-frame convention (rotations reversed) would be off by up to ~100 m.
    for (const ReferencePoint &r : kGk3ToUtm32) {
        CrsCoordinate utm = gk3ToUtm32ByHelmert(r.from);
        EXPECT_NEAR(utm.x, r.helmert.x, 1e-3) << r.place;
        EXPECT_NEAR(utm.y, r.helmert.y, 1e-3) << r.place;
    }
    // echo "7.55913333 50.36368611" | cs2cs -f %.9f +proj=longlat +ellps=bessel
    //   +towgs84=598.1,73.7,418.2,0.202,0.045,-2.455,6.7 +to +proj=longlat +ellps=GRS80 +towgs84=0,0,0
    GeographicPoint etrs = changeDatumByHelmert(Datum::Dhdn, Datum::Etrs89, {50.36368611, 7.55913333});
    EXPECT_NEAR(etrs.longitude, 7.558303839, 2e-9);
    EXPECT_NEAR(etrs.latitude, 50.362493909, 2e-9);
    GeographicPoint back = changeDatumByHelmert(Datum::Etrs89, Datum::Dhdn, etrs);
    EXPECT_NEAR(back.longitude, 7.55913333, 1e-10);
    EXPECT_NEAR(back.latitude, 50.36368611, 1e-10);
}

TEST(Crs, OutsideTheGridTheHelmertIsUsedAndTold) {
    // Paris and Vienna lie outside BeTA2007 (5.5°–15.67° E, 47°–55.3° N).
    for (GeographicPoint p : {GeographicPoint{48.8566, 2.3522}, GeographicPoint{48.2082, 16.3738}}) {
        uint64_t before = helmertFallbacks();
        CrsCoordinate etrs = convertEpsg(4314, 4258, {p.longitude, p.latitude});
        GeographicPoint helmert = changeDatumByHelmert(Datum::Dhdn, Datum::Etrs89, p);
        EXPECT_EQ(etrs.x, helmert.longitude);
        EXPECT_EQ(etrs.y, helmert.latitude);
        EXPECT_EQ(helmertFallbacks(), before + 1);
        std::optional<std::string> warning = helmertFallbackWarning(before);
        ASSERT_TRUE(warning);
        EXPECT_NE(warning->find("1 point outside the BeTA2007 grid"), std::string::npos) << *warning;
    }
}

TEST(Crs, DatumChangeRoundTripsAndKeepsHeights) {
    // Inside BeTA2007 (5.5°–15.67° E, 47°–55.3° N) and outside it (Paris, Vienna, Warsaw).
    // Within a few metres of the grid's edge the way there and the way back may differ,
    // one by the grid and one by the Helmert.
    std::vector<GeographicPoint> points = {{48.8566, 2.3522}, {48.2082, 16.3738}, {52.2297, 21.0122}};
    for (double latitude = 47.5; latitude <= 55; latitude += 1.5) {
        for (double longitude = 6; longitude <= 15; longitude += 3) points.push_back({latitude, longitude});
    }
    for (auto [latitude, longitude] : points) {
        CrsCoordinate p{longitude, latitude, 123.25};
        CrsCoordinate there = convertEpsg(4314, 4326, p);
        CrsCoordinate back = convertEpsg(4326, 4314, there);
        EXPECT_NEAR(back.x, longitude, 1e-10);
        EXPECT_NEAR(back.y, latitude, 1e-10);
        EXPECT_EQ(there.z, 123.25);
        EXPECT_EQ(back.z, 123.25);
        // ETRS89 and WGS 84 are one datum here.
        CrsCoordinate etrs = convertEpsg(4314, 4258, p);
        EXPECT_EQ(etrs.x, there.x);
        EXPECT_EQ(etrs.y, there.y);
    }
    for (const ReferencePoint &r : kGk3ToUtm32) {
        CrsCoordinate back = convertEpsg(25832, 31467, convertEpsg(31467, 25832, r.from));
        EXPECT_LT(distance(back, r.from), 1e-6) << r.place;
    }
}

// From the digest of Rilling 2006 (../shared/seeds/digest-004.md, §1 table and §8 items 1–4),
// computed there with GeographicLib and PROJ; cs2cs -f %.4f EPSG:31467 EPSG:31466 on
// "5588000 3392030" gives 5587944.3165 2605210.9588.
TEST(Crs, GaussKruegerStrip3ToStrip2AndBack) {
    CrsCoordinate strip2 = convertEpsg(31467, 31466, {3392030, 5588000});
    EXPECT_NEAR(strip2.x, 2605210.959, 1e-3);
    EXPECT_NEAR(strip2.y, 5587944.317, 1e-3);
    for (const ReferencePoint &r : kGk3ToUtm32) {
        if (r.from.x > 3450000) continue;  // the west, where zone 2 is used
        CrsCoordinate in2 = convertEpsg(31467, 31466, r.from);
        CrsCoordinate back = convertEpsg(31466, 31467, in2);
        EXPECT_LT(distance(back, r.from), 1e-3) << r.place;
    }
    CrsCoordinate in3 = convertEpsg(31466, 31467, {2605210.959, 5587944.317});
    CrsCoordinate in2 = convertEpsg(31467, 31466, in3);
    EXPECT_LT(distance(in2, {2605210.959, 5587944.317}), 1e-3);
    EXPECT_LT(distance(in3, {3392030, 5588000}), 1e-3);
}

TEST(Crs, ThesisPointOnDhdnAndOnWgs84) {
    // The Koblenz campus entrance (50.36368611 N, 7.55913333 E).
    // echo "50.36368611 7.55913333" | cs2cs -f %.4f EPSG:4314 EPSG:31467 → 5581721.3969 3397491.8680
    CrsCoordinate dhdn = convertEpsg(4314, 31467, {7.55913333, 50.36368611});
    EXPECT_NEAR(dhdn.x, 3397491.868, 1e-3);
    EXPECT_NEAR(dhdn.y, 5581721.397, 1e-3);
    // As WGS 84: BeTA2007, cs2cs EPSG:4326 EPSG:31467 → 5581852.9994 3397554.4983. The
    // digest's Helmert (= PROJ +towgs84) gives 3397553.455 5581852.862, 1.05 m off.
    CrsCoordinate wgs = convertEpsg(4326, 31467, {7.55913333, 50.36368611});
    EXPECT_LT(distance(wgs, {3397554.4983, 5581852.9994}), 2e-3);
}

TEST(Crs, Utm32ToUtm33AndBack) {
    // cs2cs -f %.4f EPSG:25832 EPSG:25833 (both easting first); the same datum, so only the
    // projections differ: PROJ's 0.1 mm rounding is the tolerance's scale.
    struct Pair {
        CrsCoordinate utm32, utm33;
    };
    const Pair pairs[] = {
        {{798473.3734, 5827978.7206}, {391439.5668, 5820079.2368}},  // Berlin
        {{832166.5503, 5666081.6658}, {411682.5813, 5656140.5840}},  // Dresden
        {{766029.4783, 6025730.8487}, {375739.5920, 6019695.9608}},  // Stralsund
    };
    for (const Pair &p : pairs) {
        EXPECT_LT(distance(convertEpsg(25832, 25833, p.utm32), p.utm33), 1e-3);
        EXPECT_LT(distance(convertEpsg(25833, 25832, p.utm33), p.utm32), 1e-3);
        // WGS 84 / UTM differs from ETRS89 / UTM only by the ellipsoid's 0.1 mm.
        EXPECT_LT(distance(convertEpsg(32632, 25833, p.utm32), p.utm33), 1e-3);
    }
}

TEST(Crs, GaussKrueger5ToUtm33AndBack) {
    // cs2cs -f %.4f EPSG:31469 EPSG:25833 (input "northing easting"), BeTA2007; its reverse
    // returns the GK values to 0.1 mm.
    struct Pair {
        const char *place;
        CrsCoordinate gk5, utm33;
    };
    const Pair pairs[] = {
        {"Berlin", {5391532, 5821963}, {391440.3301, 5820079.6561}},
        {"Dresden", {5411785, 5657958}, {411683.1894, 5656140.4515}},
        {"Stralsund", {5375823, 6021660}, {375739.3099, 6019696.0502}},
        {"Goerlitz", {5499438, 5668328}, {499300.9380, 5666505.4281}},
    };
    for (const Pair &p : pairs) {
        double forward = distance(convertEpsg(31469, 25833, p.gk5), p.utm33);
        double backward = distance(convertEpsg(25833, 31469, p.utm33), p.gk5);
        EXPECT_LT(forward, 2e-3) << p.place;
        EXPECT_LT(backward, 2e-3) << p.place;
    }
}

TEST(Crs, GeographicToProjected) {
    // echo "51.34 12.37" | cs2cs -d 4 EPSG:4258 EPSG:25833 (as tests/scene/georeference_test.cpp)
    CrsCoordinate leipzig = convertEpsg(4258, 25833, {12.37, 51.34, 7});
    EXPECT_NEAR(leipzig.x, 316820.0631, 1e-3);
    EXPECT_NEAR(leipzig.y, 5690919.2109, 1e-3);
    EXPECT_EQ(leipzig.z, 7);
    CrsCoordinate back = convertEpsg(25833, 4326, leipzig);
    EXPECT_NEAR(back.x, 12.37, 1e-9);
    EXPECT_NEAR(back.y, 51.34, 1e-9);
}

TEST(Crs, SameCrsIsUnchanged) {
    for (const Crs &crs : supportedCrss()) {
        CrsCoordinate p{crs.projected ? crs.falseEasting + 1234.5 : 9.5, crs.projected ? 5.5e6 : 50.5, 3};
        CrsCoordinate q = convert(crs, crs, p);
        EXPECT_EQ(q.x, p.x) << crs.epsg;
        EXPECT_EQ(q.y, p.y) << crs.epsg;
        EXPECT_EQ(q.z, p.z) << crs.epsg;
    }
}

TEST(Crs, ParsesEpsgCodes) {
    EXPECT_EQ(parseCrs("EPSG:31467").epsg, 31467);
    EXPECT_EQ(parseCrs("epsg:25832").epsg, 25832);
    EXPECT_EQ(parseCrs("31468").epsg, 31468);
    EXPECT_EQ(parseCrs("EPSG:4326").name, "WGS 84");
    EXPECT_FALSE(parseCrs("4314").projected);
    EXPECT_EQ(parseCrs("EPSG:31469").gaussKruegerZone, 5);
    for (const char *bad : {"", "EPSG:", "EPSG", "EPSG:-31467", "-31467", "+31467", "31467 ", " 31467", "EPSG:31467x",
                            "EPSG::31467", "ESRI:31467", "EPSG:3857", "31465", "99999999999"}) {
        EXPECT_THROW(parseCrs(bad), std::invalid_argument) << bad;
    }
    EXPECT_THROW(crsByEpsg(0), std::invalid_argument);
}

TEST(Crs, GaussKruegerZoneOfRechtswert) {
    // Digest §8 item 1: 3397597.0 lies in zone 3, 102 403 m west of 9° E.
    GaussKruegerZone z = gaussKruegerZone(3397597.0);
    EXPECT_EQ(z.zone, 3);
    EXPECT_EQ(z.centralMeridian, 9);
    EXPECT_EQ(z.offsetFromMeridian, -102403.0);
    EXPECT_EQ(gaussKruegerZone(5499438).zone, 5);
    EXPECT_EQ(gaussKruegerCrs(4512345).epsg, 31468);
    EXPECT_EQ(gaussKruegerCrs(2605210.959).epsg, 31466);
    EXPECT_EQ(gaussKruegerZone(3150000).offsetFromMeridian, -350000);  // the limit itself fits
    // A UTM easting, a point too far from the meridian, a zone veduta has no CRS for.
    for (double bad :
         {397597.0, 3100000.0, 3850001.0, 12345678.0, -3397597.0, std::numeric_limits<double>::quiet_NaN()}) {
        EXPECT_THROW(gaussKruegerZone(bad), std::out_of_range) << bad;
    }
    EXPECT_THROW(gaussKruegerCrs(6500000), std::out_of_range);
    EXPECT_THROW(gaussKruegerCrs(1500000), std::out_of_range);
}

TEST(Crs, ChecksAxes) {
    const Crs &gk3 = crsByEpsg(31467), &utm32 = crsByEpsg(25832), &wgs = crsByEpsg(4326);
    EXPECT_NO_THROW(checkAxis(gk3, 0, 3397597));
    EXPECT_NO_THROW(checkAxis(gk3, 1, 5579489));
    EXPECT_THROW(checkAxis(gk3, 0, 4397597), std::out_of_range);  // zone 4's Rechtswert
    EXPECT_THROW(checkAxis(gk3, 0, 397597), std::out_of_range);   // a UTM easting
    EXPECT_THROW(checkAxis(gk3, 1, -1), std::out_of_range);
    EXPECT_NO_THROW(checkAxis(utm32, 0, 832166.55));
    EXPECT_THROW(checkAxis(utm32, 0, 1000000), std::out_of_range);
    EXPECT_THROW(checkAxis(utm32, 0, 3397597), std::out_of_range);
    EXPECT_THROW(checkAxis(utm32, 1, 1e7), std::out_of_range);
    EXPECT_NO_THROW(checkAxis(wgs, 0, -180));
    EXPECT_NO_THROW(checkAxis(wgs, 1, 90));
    EXPECT_THROW(checkAxis(wgs, 0, 180.5), std::out_of_range);
    EXPECT_THROW(checkAxis(wgs, 1, -90.5), std::out_of_range);
    for (const Crs &crs : supportedCrss()) {
        EXPECT_THROW(checkAxis(crs, 0, std::numeric_limits<double>::quiet_NaN()), std::out_of_range) << crs.epsg;
        EXPECT_THROW(checkAxis(crs, 1, std::numeric_limits<double>::quiet_NaN()), std::out_of_range) << crs.epsg;
    }
}

TEST(Crs, ConvergenceAndScale) {
    // Digest §1: at the Koblenz campus γ = −1.11° and k = 1.000129 in zone 3.
    const Crs &gk3 = crsByEpsg(31467);
    GridFactors campus = gridFactors(gk3, {3397491.868, 5581721.397});
    EXPECT_NEAR(campus.convergenceDegrees, -1.11, 0.005);
    EXPECT_NEAR(campus.scale, 1.000129, 1e-6);
    // On the central meridian: no convergence, the CRS's scale there.
    GridFactors meridian = gridFactors(gk3, {3500000, 5581721});
    EXPECT_NEAR(meridian.convergenceDegrees, 0, 1e-12);
    EXPECT_NEAR(meridian.scale, 1, 1e-12);
    EXPECT_NEAR(gridFactors(crsByEpsg(25833), {500000, 5800000}).scale, 0.9996, 1e-12);
    // East of the meridian grid north leans east: Dresden in UTM 32 (13.74° E, 51.05° N).
    GridFactors dresden = gridFactors(crsByEpsg(25832), {832166.5503, 5666081.6658});
    EXPECT_NEAR(dresden.convergenceDegrees, (13.74 - 9) * std::sin(51.05 * M_PI / 180), 0.02);
    EXPECT_GT(dresden.scale, 1.0005);  // 330 km out, 1 + y²/2R² − 0.0004
    EXPECT_THROW(gridFactors(crsByEpsg(4326), {9, 50}), std::invalid_argument);
}

}  // namespace
}  // namespace veduta
