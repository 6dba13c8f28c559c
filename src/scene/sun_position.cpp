#include "scene/sun_position.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

constexpr double kDegrees = 180.0 / M_PI;
constexpr double kRadians = M_PI / 180.0;

double sinDeg(double d) { return std::sin(d * kRadians); }
double cosDeg(double d) { return std::cos(d * kRadians); }
double tanDeg(double d) { return std::tan(d * kRadians); }
double positiveModulo(double x, double m) { return x - m * std::floor(x / m); }

// The value of `count` decimal digits at `pos`, or −1 when they are not all digits.
int digitsAt(std::string_view text, size_t pos, size_t count) {
    if (pos + count > text.size()) return -1;
    int value = 0;
    for (size_t i = pos; i < pos + count; ++i) {
        if (text[i] < '0' || text[i] > '9') return -1;
        value = value * 10 + (text[i] - '0');
    }
    return value;
}

bool isLeapYear(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int daysInMonth(int year, int month) {
    constexpr int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return month == 2 && isLeapYear(year) ? 29 : days[month - 1];
}

void parseDate(std::string_view text, CivilTime &t) {
    t.year = digitsAt(text, 0, 4);
    t.month = digitsAt(text, 5, 2);
    t.day = digitsAt(text, 8, 2);
    if (text.size() != 10 || text[4] != '-' || text[7] != '-' || t.year < 0 || t.month < 0 || t.day < 0)
        throw std::invalid_argument(fmt::format("date '{}' is not of the form YYYY-MM-DD", text));
    if (t.month < 1 || t.month > 12)
        throw std::invalid_argument(fmt::format("date '{}' has no month {}", text, t.month));
    if (t.day < 1 || t.day > daysInMonth(t.year, t.month))
        throw std::invalid_argument(fmt::format("date '{}' has no day {} in that month", text, t.day));
}

void parseTime(std::string_view text, CivilTime &t) {
    t.hour = digitsAt(text, 0, 2);
    t.minute = digitsAt(text, 3, 2);
    bool form = text.size() >= 5 && text[2] == ':' && t.hour >= 0 && t.minute >= 0;
    t.second = 0;
    if (form && text.size() > 5) {
        // ":SS" with an optional fraction; from_chars alone would also take "5" or "1e1".
        std::string_view s = text.substr(6);
        form = text[5] == ':' && digitsAt(s, 0, 2) >= 0 && (s.size() == 2 || (s.size() > 3 && s[2] == '.'));
        for (size_t i = 3; form && i < s.size(); ++i) form = s[i] >= '0' && s[i] <= '9';
        if (form) std::from_chars(s.data(), s.data() + s.size(), t.second);
    }
    if (!form) throw std::invalid_argument(fmt::format("time '{}' is not of the form HH:MM or HH:MM:SS", text));
    if (t.hour > 23 || t.minute > 59 || t.second >= 60)
        throw std::invalid_argument(fmt::format("time '{}' is out of range (00:00 to 23:59:59)", text));
}

double parseUtcOffset(std::string_view text) {
    if (text == "Z") return 0;
    int hours = digitsAt(text, 1, 2), minutes = digitsAt(text, 4, 2);
    if (text.size() != 6 || (text[0] != '+' && text[0] != '-') || text[3] != ':' || hours < 0 || minutes < 0)
        throw std::invalid_argument(fmt::format("UTC offset '{}' is not of the form +HH:MM, -HH:MM or Z", text));
    // Offsets in use run from −12:00 to +14:00.
    if (hours > 14 || minutes > 59) throw std::invalid_argument(fmt::format("UTC offset '{}' is out of range", text));
    return (text[0] == '-' ? -1 : 1) * (hours + minutes / 60.0);
}

double decimalHours(const CivilTime &t) { return t.hour + t.minute / 60.0 + t.second / 3600.0; }

// Apparent elevation and azimuth from the zenith angle and hour angle, both geometric.
SolarAngles anglesFromZenith(double zenith, double hourAngle, double declination, double latitude) {
    // NOAA writes the azimuth with acos and a sign test on the hour angle; atan2 is the
    // same angle and stays defined with the sun at the zenith.
    double azimuth =
        std::atan2(sinDeg(hourAngle), cosDeg(hourAngle) * sinDeg(latitude) - tanDeg(declination) * cosDeg(latitude)) *
            kDegrees +
        180;
    double elevation = 90 - zenith;
    return {positiveModulo(azimuth, 360), elevation};
}

}  // namespace

CivilTime parseCivilTime(std::string_view date, std::string_view time, std::string_view utcOffset) {
    CivilTime t;
    parseDate(date, t);
    parseTime(time, t);
    t.utcOffsetHours = parseUtcOffset(utcOffset);
    return t;
}

double julianDay(const CivilTime &t) {
    // Meeus, chapter 7, for the Gregorian calendar.
    int y = t.year, m = t.month;
    if (m <= 2) {
        y -= 1;
        m += 12;
    }
    int a = y / 100;
    int b = 2 - a + a / 4;
    double day0 = std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + t.day + b - 1524.5;
    return day0 + (decimalHours(t) - t.utcOffsetHours) / 24.0;
}

double noaaRefractionDegrees(double trueElevation) {
    double arcseconds = 0;
    if (trueElevation > 85) {
        arcseconds = 0;
    } else if (trueElevation > 5) {
        double t = tanDeg(trueElevation);
        arcseconds = 58.1 / t - 0.07 / (t * t * t) + 0.000086 / std::pow(t, 5);
    } else if (trueElevation > -0.575) {
        double e = trueElevation;
        arcseconds = 1735 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
    } else {
        arcseconds = -20.772 / tanDeg(trueElevation);
    }
    return arcseconds / 3600;
}

SolarAngles solarPositionNoaa(const CivilTime &time, double latitude, double longitude) {
    double T = (julianDay(time) - 2451545.0) / 36525.0;  // Julian centuries since J2000.0
    double meanLongitude = positiveModulo(280.46646 + T * (36000.76983 + T * 0.0003032), 360);
    double meanAnomaly = 357.52911 + T * (35999.05029 - 0.0001537 * T);
    double eccentricity = 0.016708634 - T * (0.000042037 + 0.0000001267 * T);
    double centre = sinDeg(meanAnomaly) * (1.914602 - T * (0.004817 + 0.000014 * T)) +
        sinDeg(2 * meanAnomaly) * (0.019993 - 0.000101 * T) + sinDeg(3 * meanAnomaly) * 0.000289;
    double trueLongitude = meanLongitude + centre;
    double omega = 125.04 - 1934.136 * T;
    double apparentLongitude = trueLongitude - 0.00569 - 0.00478 * sinDeg(omega);
    double meanObliquity = 23 + (26 + (21.448 - T * (46.815 + T * (0.00059 - T * 0.001813))) / 60) / 60;
    double obliquity = meanObliquity + 0.00256 * cosDeg(omega);
    double declination = std::asin(sinDeg(obliquity) * sinDeg(apparentLongitude)) * kDegrees;

    double y = tanDeg(obliquity / 2) * tanDeg(obliquity / 2);
    double L = meanLongitude * kRadians, M = meanAnomaly * kRadians, e = eccentricity;
    double equationOfTimeMinutes = 4 * kDegrees *
        (y * std::sin(2 * L) - 2 * e * std::sin(M) + 4 * e * y * std::sin(M) * std::cos(2 * L) -
         0.5 * y * y * std::sin(4 * L) - 1.25 * e * e * std::sin(2 * M));

    double utcMinutes = (decimalHours(time) - time.utcOffsetHours) * 60;
    double trueSolarTime = positiveModulo(utcMinutes + equationOfTimeMinutes + 4 * longitude, 1440);
    double hourAngle = trueSolarTime / 4 - 180;

    double cosZenith =
        sinDeg(latitude) * sinDeg(declination) + cosDeg(latitude) * cosDeg(declination) * cosDeg(hourAngle);
    double zenith = std::acos(std::clamp(cosZenith, -1.0, 1.0)) * kDegrees;
    SolarAngles angles = anglesFromZenith(zenith, hourAngle, declination, latitude);
    angles.elevationDegrees += noaaRefractionDegrees(angles.elevationDegrees);
    return angles;
}

SolarAngles solarPositionPsa(const CivilTime &time, double latitude, double longitude) {
    // The paper's names and constants; angles in radians, n in days since J2000.0.
    double n = julianDay(time) - 2451545.0;
    double omega = 2.1429 - 0.0010394594 * n;
    double meanLongitude = 4.8950630 + 0.017202791698 * n;
    double meanAnomaly = 6.2400600 + 0.0172019699 * n;
    double eclipticLongitude = meanLongitude + 0.03341607 * std::sin(meanAnomaly) +
        0.00034894 * std::sin(2 * meanAnomaly) - 0.0001134 - 0.0000203 * std::sin(omega);
    double obliquity = 0.4090928 - 6.2140e-9 * n + 0.0000396 * std::cos(omega);

    double sinLongitude = std::sin(eclipticLongitude);
    double rightAscension = std::atan2(std::cos(obliquity) * sinLongitude, std::cos(eclipticLongitude));
    double declination = std::asin(std::sin(obliquity) * sinLongitude);

    double utcHours = decimalHours(time) - time.utcOffsetHours;
    double greenwichSiderealHours = 6.6974243242 + 0.0657098283 * n + utcHours;
    double hourAngle = (greenwichSiderealHours * 15 + longitude) * kRadians - rightAscension;

    double lat = latitude * kRadians;
    double cosZenith =
        std::cos(lat) * std::cos(hourAngle) * std::cos(declination) + std::sin(declination) * std::sin(lat);
    double zenith = std::acos(std::clamp(cosZenith, -1.0, 1.0));
    constexpr double kEarthMeanRadiusKm = 6371.01, kAstronomicalUnitKm = 149597890;
    zenith += kEarthMeanRadiusKm / kAstronomicalUnitKm * std::sin(zenith);  // parallax

    return anglesFromZenith(zenith * kDegrees, hourAngle * kDegrees, declination * kDegrees, latitude);
}

}  // namespace veduta
