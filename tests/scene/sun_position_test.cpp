#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "scene/sun_position.h"

namespace veduta {
namespace {

// The difference a − b of two azimuths, in (−180, 180].
double azimuthDifference(double a, double b) {
    double d = std::fmod(a - b, 360.0);
    if (d > 180) d -= 360;
    if (d <= -180) d += 360;
    return d;
}

struct ReferenceCase {
    const char *name;
    const char *date, *time, *utcOffset;
    double latitude, longitude;
    double azimuth, elevation;  // apparent elevation, refraction included
};

// Reference positions, each from a source independent of this code:
// [SPA] Reda & Andreas 2004, "Solar position algorithm for solar radiation applications"
//       (NREL/TP-560-34302), table A5.1: topocentric zenith 50.11162°, azimuth 194.34024°
//       (at 820 hPa and 11 °C, which changes the refraction by 0.004° against NOAA's).
// [pvlib] pvlib-python, pvlib/tests/test_solarposition.py, expected_solpos_multi: NREL SPA
//       for the same place a day later, apparent elevation 39.521740°, azimuth 194.311132°.
// [spa.c] klausbrunner/solarpositioning, src/test/resources/azimuth_zenith/
//       spa_reference_testdata.csv: NREL's spa.c (revised 2014-09-08) at 1000 hPa, 10 °C,
//       ΔT = 0, as azimuth and apparent zenith; elevation = 90° − zenith.
// [PyEphem] PyEphem 4.1.4 (Debian python3-ephem; VSOP87, ΔT applied), Observer with
//       pressure 1010 hPa and 10 °C, the standard atmosphere NOAA's refraction assumes.
//       PyEphem reproduces the SPA case above to 0.001°.
const ReferenceCase kReferenceCases[] = {
    {"Leipzig 2026-06-21 CEST [PyEphem]", "2026-06-21", "12:00", "+02:00", 51.34, 12.37, 146.6466, 58.8179},
    {"Leipzig 2026-12-21 CET [PyEphem]", "2026-12-21", "12:00", "+01:00", 51.34, 12.37, 177.9643, 15.2560},
    {"Hamburg 2026-03-20 [PyEphem]", "2026-03-20", "08:15", "+01:00", 53.55, 9.99, 112.2409, 15.5268},
    {"Munich 2026-09-23 [PyEphem]", "2026-09-23", "17:40", "+02:00", 48.14, 11.58, 253.4832, 14.0231},
    {"Garmisch 1990-07-01 [PyEphem]", "1990-07-01", "07:30", "+02:00", 47.42, 10.98, 75.6137, 18.5192},
    {"Golden 2003-10-17 [SPA]", "2003-10-17", "12:30:30", "-07:00", 39.742476, -105.1786, 194.34024, 90 - 50.11162},
    {"Golden 2003-10-18 [pvlib]", "2003-10-18", "12:30:30", "-07:00", 39.742476, -105.1786, 194.311132, 39.521740},
    {"Auckland 2010-12-15 [spa.c]", "2010-12-15", "13:30", "+13:00", -36.840556, 174.74, 346.427128, 90 - 13.924050},
    {"Brasilia 2010-06-15 [spa.c]", "2010-06-15", "09:30", "-03:00", -15.793889, -47.882778, 46.250557, 90 - 55.629466},
    {"Longyearbyen 2010-06-15 [spa.c]", "2010-06-15", "12:30", "Z", 78.22, 15.65, 205.702181, 90 - 55.921375},
    {"Singapore 1910-03-15 [spa.c]", "1910-03-15", "11:30", "+08:00", 1.283333, 103.833333, 98.302270, 90 - 26.266337},
};

TEST(SunPosition, NoaaMatchesPublishedPositionsWithinATenthOfADegree) {
    for (const ReferenceCase &c : kReferenceCases) {
        SolarAngles a = solarPositionNoaa(parseCivilTime(c.date, c.time, c.utcOffset), c.latitude, c.longitude);
        double dAz = azimuthDifference(a.azimuthDegrees, c.azimuth), dEl = a.elevationDegrees - c.elevation;
        std::printf("%-34s azimuth %9.4f ref %9.4f diff %+.4f   elevation %8.4f ref %8.4f diff %+.4f\n", c.name,
                    a.azimuthDegrees, c.azimuth, dAz, a.elevationDegrees, c.elevation, dEl);
        EXPECT_LT(std::abs(dAz), 0.1) << c.name;
        EXPECT_LT(std::abs(dEl), 0.1) << c.name;
    }
}

TEST(SunPosition, LeipzigAtTheSolsticeAgreesWithAHandCalculation) {
    // At noon the sun stands at 90° − latitude + declination, and at the June solstice the
    // declination is the obliquity of the ecliptic: 23.4393° − 0.0130°/century since 2000
    // (IAU 2006) = 23.4359°, ± 0.0026° nutation. Refraction at 62° adds 0.0098°.
    const double latitude = 51.34, longitude = 12.37;
    const double handNoonElevation = 90 - latitude + 23.4359 + 0.0098;
    // Solar noon: 12:00 UT less 4 min per degree east, less the equation of time, which is
    // about −1.7 min on 21 June; 13:12.2 CEST.
    const double handNoonMinutes = 14 * 60 - 4 * longitude + 1.7;

    double bestElevation = -90, bestMinutes = 0, bestAzimuth = 0;
    for (int s = 12 * 3600; s <= 14 * 3600; s += 5) {
        CivilTime t{2026, 6, 21, s / 3600, s / 60 % 60, double(s % 60), 2};
        SolarAngles a = solarPositionNoaa(t, latitude, longitude);
        if (a.elevationDegrees > bestElevation) {
            bestElevation = a.elevationDegrees;
            bestMinutes = s / 60.0;
            bestAzimuth = a.azimuthDegrees;
        }
    }
    std::printf("Leipzig noon: elevation %.4f (hand %.4f), at %.2f min CEST (hand %.2f), azimuth %.4f\n", bestElevation,
                handNoonElevation, bestMinutes, handNoonMinutes, bestAzimuth);
    EXPECT_NEAR(bestElevation, handNoonElevation, 0.01);
    EXPECT_NEAR(bestMinutes, handNoonMinutes, 0.5);
    // The azimuth turns about 0.5° per minute at this elevation; the 5 s scan steps allow 0.05°.
    EXPECT_NEAR(bestAzimuth, 180, 0.1);

    // An hour and 12 minutes before solar noon the sun is east of south.
    SolarAngles atTwelve = solarPositionNoaa(parseCivilTime("2026-06-21", "12:00", "+02:00"), latitude, longitude);
    EXPECT_LT(atTwelve.azimuthDegrees, 180);
    EXPECT_LT(atTwelve.elevationDegrees, bestElevation);
}

// PSA's elevation is the true one; add NOAA's refraction to compare it with NOAA's.
SolarAngles psaWithRefraction(const CivilTime &t, double latitude, double longitude) {
    SolarAngles a = solarPositionPsa(t, latitude, longitude);
    a.elevationDegrees += noaaRefractionDegrees(a.elevationDegrees);
    return a;
}

TEST(SunPosition, NoaaAndPsaAgreeInLeipzig) {
    CivilTime t = parseCivilTime("2026-06-21", "12:00", "+02:00");
    SolarAngles noaa = solarPositionNoaa(t, 51.34, 12.37), psa = psaWithRefraction(t, 51.34, 12.37);
    std::printf("Leipzig 2026-06-21 12:00 CEST: NOAA azimuth %.4f elevation %.4f, PSA azimuth %.4f elevation %.4f\n",
                noaa.azimuthDegrees, noaa.elevationDegrees, psa.azimuthDegrees, psa.elevationDegrees);
    EXPECT_NEAR(azimuthDifference(noaa.azimuthDegrees, psa.azimuthDegrees), 0, 0.1);
    EXPECT_NEAR(noaa.elevationDegrees, psa.elevationDegrees, 0.1);
}

TEST(SunPosition, NoaaAndPsaAgreeOverGermanyFrom1950To2050) {
    double worstAzimuth = 0, worstElevation = 0;
    int count = 0;
    for (int year = 1950; year <= 2050; year += 4) {
        for (int month = 1; month <= 12; ++month) {
            for (double latitude : {47.0, 51.0, 55.0}) {
                for (double longitude : {6.0, 10.5, 15.0}) {
                    for (int minute = 0; minute < 24 * 60; minute += 20) {
                        CivilTime t{year, month, 1 + (year + 7 * month) % 28, minute / 60, minute % 60, 0, 0};
                        SolarAngles noaa = solarPositionNoaa(t, latitude, longitude);
                        if (noaa.elevationDegrees <= 0) continue;
                        SolarAngles psa = psaWithRefraction(t, latitude, longitude);
                        worstAzimuth = std::max(worstAzimuth,
                                                std::abs(azimuthDifference(noaa.azimuthDegrees, psa.azimuthDegrees)));
                        worstElevation =
                            std::max(worstElevation, std::abs(noaa.elevationDegrees - psa.elevationDegrees));
                        ++count;
                    }
                }
            }
        }
    }
    std::printf("NOAA vs PSA, %d positions with the sun up: largest difference azimuth %.4f, elevation %.4f\n", count,
                worstAzimuth, worstElevation);
    EXPECT_GT(count, 50000);
    EXPECT_LT(worstAzimuth, 0.1);
    EXPECT_LT(worstElevation, 0.1);
}

TEST(SunPosition, TheSameInstantInAnyOffsetGivesTheSamePosition) {
    SolarAngles cest = solarPositionNoaa(parseCivilTime("2026-06-21", "12:00", "+02:00"), 51.34, 12.37);
    SolarAngles utc = solarPositionNoaa(parseCivilTime("2026-06-21", "10:00", "Z"), 51.34, 12.37);
    SolarAngles nextDay = solarPositionNoaa(parseCivilTime("2026-06-21", "23:30", "+13:30"), 51.34, 12.37);
    SolarAngles dayBefore = solarPositionNoaa(parseCivilTime("2026-06-20", "23:00", "-11:00"), 51.34, 12.37);
    for (const SolarAngles &a : {utc, nextDay, dayBefore}) {
        EXPECT_NEAR(a.azimuthDegrees, cest.azimuthDegrees, 1e-9);
        EXPECT_NEAR(a.elevationDegrees, cest.elevationDegrees, 1e-9);
    }
}

TEST(SunPosition, JulianDaysMatchMeeus) {
    // Meeus, "Astronomical Algorithms", chapter 7: J2000.0 and examples 7.a and 7.b.
    EXPECT_NEAR(julianDay(parseCivilTime("2000-01-01", "12:00", "Z")), 2451545.0, 1e-9);
    CivilTime sputnik = parseCivilTime("1957-10-04", "00:00", "Z");
    sputnik.second = 0.81 * 86400;
    EXPECT_NEAR(julianDay(sputnik), 2436116.31, 1e-6);
    EXPECT_NEAR(julianDay(parseCivilTime("1987-06-19", "12:00", "Z")), 2446966.0, 1e-9);
    EXPECT_NEAR(julianDay(parseCivilTime("1600-01-01", "00:00", "Z")), 2305447.5, 1e-9);
}

TEST(SunPosition, ParsesDatesTimesAndOffsets) {
    CivilTime t = parseCivilTime("2024-02-29", "07:05:30.25", "-05:30");
    EXPECT_EQ(t.year, 2024);
    EXPECT_EQ(t.month, 2);
    EXPECT_EQ(t.day, 29);
    EXPECT_EQ(t.hour, 7);
    EXPECT_EQ(t.minute, 5);
    EXPECT_DOUBLE_EQ(t.second, 30.25);
    EXPECT_DOUBLE_EQ(t.utcOffsetHours, -5.5);
    EXPECT_DOUBLE_EQ(parseCivilTime("2000-02-29", "23:59:59", "Z").utcOffsetHours, 0);
    EXPECT_DOUBLE_EQ(parseCivilTime("2026-06-21", "12:00", "+02:00").utcOffsetHours, 2);
}

TEST(SunPosition, RejectsMalformedOrImpossibleTimes) {
    auto message = [](const char *date, const char *time, const char *offset) {
        try {
            parseCivilTime(date, time, offset);
        } catch (const std::invalid_argument &e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("2026-6-21", "12:00", "Z"), "date '2026-6-21' is not of the form YYYY-MM-DD");
    EXPECT_EQ(message("2026-13-01", "12:00", "Z"), "date '2026-13-01' has no month 13");
    EXPECT_EQ(message("2026-02-29", "12:00", "Z"), "date '2026-02-29' has no day 29 in that month");
    EXPECT_EQ(message("1900-02-29", "12:00", "Z"), "date '1900-02-29' has no day 29 in that month");
    EXPECT_EQ(message("2026-04-31", "12:00", "Z"), "date '2026-04-31' has no day 31 in that month");
    EXPECT_EQ(message("2026-06-21", "12", "Z"), "time '12' is not of the form HH:MM or HH:MM:SS");
    EXPECT_EQ(message("2026-06-21", "12:00:", "Z"), "time '12:00:' is not of the form HH:MM or HH:MM:SS");
    EXPECT_EQ(message("2026-06-21", "12:00:3", "Z"), "time '12:00:3' is not of the form HH:MM or HH:MM:SS");
    EXPECT_EQ(message("2026-06-21", "12:00:30.", "Z"), "time '12:00:30.' is not of the form HH:MM or HH:MM:SS");
    EXPECT_EQ(message("2026-06-21", "12:00:1e1", "Z"), "time '12:00:1e1' is not of the form HH:MM or HH:MM:SS");
    EXPECT_EQ(message("2026-06-21", "24:00", "Z"), "time '24:00' is out of range (00:00 to 23:59:59)");
    EXPECT_EQ(message("2026-06-21", "12:60", "Z"), "time '12:60' is out of range (00:00 to 23:59:59)");
    EXPECT_EQ(message("2026-06-21", "12:00", "+2"), "UTC offset '+2' is not of the form +HH:MM, -HH:MM or Z");
    EXPECT_EQ(message("2026-06-21", "12:00", "+02:00x"), "UTC offset '+02:00x' is not of the form +HH:MM, -HH:MM or Z");
    EXPECT_EQ(message("2026-06-21", "12:00", "z"), "UTC offset 'z' is not of the form +HH:MM, -HH:MM or Z");
    EXPECT_EQ(message("2026-06-21", "12:00", "+15:00"), "UTC offset '+15:00' is out of range");
}

}  // namespace
}  // namespace veduta
