// Where the sun stands for a date, time and place: the NOAA Solar Calculator's algorithm, which
// the scene uses, and the PSA algorithm, which only checks it.
#pragma once

#include <string_view>

namespace veduta {

// A wall-clock reading and the UTC offset it was read in (+2 for CEST, −7 for MST).
struct CivilTime {
    int year = 2000, month = 1, day = 1;
    int hour = 0, minute = 0;
    double second = 0;
    double utcOffsetHours = 0;
};

// Reads "2026-06-21", "12:00" or "12:00:30" (seconds may have a fraction) and "+02:00",
// "-05:30" or "Z". Throws std::invalid_argument with a plain message, without a file
// position, on anything else, including impossible dates such as 2026-02-29.
CivilTime parseCivilTime(std::string_view date, std::string_view time, std::string_view utcOffset);

// The Julian day of the instant a civil time names (days since noon UT, 1 January 4713 BC).
double julianDay(const CivilTime &time);

struct SolarAngles {
    double azimuthDegrees = 0;    // clockwise from true north, in [0, 360)
    double elevationDegrees = 0;  // above the horizon
};

// The NOAA Solar Calculator (NOAA Global Monitoring Laboratory, spreadsheet version, after
// Meeus, "Astronomical Algorithms"): apparent elevation, refraction included as NOAA
// reports it. NOAA states an accuracy of about 0.0167° for 1800–2100 at latitudes within
// ±72°; it ignores ΔT and the observer's height.
SolarAngles solarPositionNoaa(const CivilTime &time, double latitudeDegrees, double longitudeDegrees);

// NOAA's atmospheric refraction for a true (geometric) elevation, in degrees.
double noaaRefractionDegrees(double trueElevationDegrees);

// Blanco-Muriel et al. 2001, "Computing the solar vector" (Solar Energy 70(5), the PSA
// algorithm), with its parallax correction. Its elevation is the TRUE one, without
// refraction: add noaaRefractionDegrees to compare it with solarPositionNoaa. Fitted for
// 1999–2015; kept here as an independent check of the NOAA code, not for rendering.
SolarAngles solarPositionPsa(const CivilTime &time, double latitudeDegrees, double longitudeDegrees);

}  // namespace veduta
