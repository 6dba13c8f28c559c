#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "core/error.h"
#include "geodesy/crs.h"

namespace veduta {

namespace {

struct CrsArgs {
    std::string from, to;
    std::vector<std::string> coordinates;
};

// One whitespace-separated field of an input line and its 1-based column.
struct Field {
    std::string_view text;
    int column = 0;
};

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<Field> splitFields(std::string_view line) {
    std::vector<Field> fields;
    size_t i = 0;
    while (i < line.size()) {
        if (isBlank(line[i])) {
            ++i;
            continue;
        }
        size_t start = i;
        while (i < line.size() && !isBlank(line[i])) ++i;
        fields.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return fields;
}

// Throws std::invalid_argument unless the whole text is a finite number.
double parseNumber(std::string_view text) {
    double value = 0;
    const char *begin = text.data(), *end = text.data() + text.size();
    if (begin != end && *begin == '+') ++begin;  // from_chars takes '-' only
    auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || stop != end || !std::isfinite(value)) {
        throw std::invalid_argument(fmt::format("'{}' is not a number", text));
    }
    return value;
}

// What is wrong with the field beginning at `column`.
struct FieldError : std::runtime_error {
    FieldError(int column_, const std::string &message) : std::runtime_error(message), column(column_) {}
    int column;
};

// Converts the fields X Y [Z]; throws FieldError.
CrsCoordinate convertFields(const std::vector<Field> &fields, const Crs &from, const Crs &to) {
    if (fields.size() < 2 || fields.size() > 3) {
        // The column where Y should begin, or where a fourth field does.
        int column = fields.size() < 2 ? fields[0].column + int(fields[0].text.size()) + 1 : fields[3].column;
        throw FieldError(column,
                         fields.size() < 2 ? "expected X Y [Z], found one field" : "expected X Y [Z], found more");
    }
    double values[3] = {0, 0, 0};
    for (size_t axis = 0; axis < fields.size(); ++axis) {
        try {
            values[axis] = parseNumber(fields[axis].text);
            if (axis < 2) checkAxis(from, int(axis), values[axis]);
        } catch (const std::logic_error &e) {  // invalid_argument and out_of_range
            throw FieldError(fields[axis].column, e.what());
        }
    }
    return convert(from, to, {values[0], values[1], values[2]});
}

void printCoordinate(const Crs &crs, const CrsCoordinate &p) {
    int decimals = crs.projected ? 3 : 9;  // 1 mm, and 1e−9° ≈ 0.1 mm
    fmt::print("{:.{}f} {:.{}f} {:.3f}\n", p.x, decimals, p.y, decimals, p.z);
}

// Lines of standard input, each converted as it is read; blank lines and comments (#) are
// copied so that output line n answers input line n.
void convertStandardInput(const Crs &from, const Crs &to) {
    std::string line;
    for (int number = 1; std::getline(std::cin, line); ++number) {
        std::vector<Field> fields = splitFields(line);
        if (fields.empty() || fields[0].text[0] == '#') {
            fmt::print("{}\n", line);
            continue;
        }
        try {
            printCoordinate(to, convertFields(fields, from, to));
        } catch (const FieldError &e) {
            throw InputError(FileLoc{"<stdin>", number, e.column}, e.what());
        }
    }
    std::fflush(stdout);
}

void warnOfHelmertFallbacks(uint64_t fallbacksBefore) {
    if (std::optional<std::string> fallback = helmertFallbackWarning(fallbacksBefore))
        std::fprintf(stderr, "veduta: warning: %s\n", fallback->c_str());
}

int runCrs(const CrsArgs &args) {
    const Crs &from = parseCrs(args.from), &to = parseCrs(args.to);
    uint64_t fallbacksBefore = helmertFallbacks();
    if (args.coordinates.empty()) {
        int status = runGuarded([&] { convertStandardInput(from, to); });
        warnOfHelmertFallbacks(fallbacksBefore);
        return status;
    }
    if (args.coordinates.size() > 3 || args.coordinates.size() < 2) {
        std::fprintf(stderr, "veduta: error: give X Y [Z], or none to read lines of standard input\n");
        return kExitBadUsage;
    }
    std::vector<Field> fields;
    for (const std::string &text : args.coordinates) fields.push_back({text, int(fields.size()) + 1});
    try {
        printCoordinate(to, convertFields(fields, from, to));
    } catch (const FieldError &e) {
        // A coordinate on the command line is a usage error; a field's column is its number.
        std::fprintf(stderr, "veduta: error: coordinate argument %d: %s\n", e.column, e.what());
        return kExitBadUsage;
    }
    warnOfHelmertFallbacks(fallbacksBefore);
    return kExitOk;
}

// CLI11 validator: an empty string accepts the text.
std::string checkCrs(const std::string &text) {
    try {
        parseCrs(text);
        return {};
    } catch (const std::invalid_argument &e) {
        return e.what();
    }
}

constexpr const char *kFooter =
    "Coordinates are always easting before northing, and longitude before latitude, whatever\n"
    "order the EPSG registry gives the axes (cs2cs follows that order: northing first for\n"
    "Gauss-Kruger, latitude first for degrees). Projected values are printed to 3 decimals (mm),\n"
    "degrees to 9; Z is copied unchanged (0 when not given). Without coordinate arguments\n"
    "each line of standard input holds X Y [Z]; blank lines and lines starting with # are copied.\n"
    "The first bad line stops the conversion: <stdin>:LINE:COLUMN: what is wrong, exit code 1.\n"
    "CRSs: EPSG:31466-31469 (DHDN / Gauss-Kruger zones 2-5), 25832, 25833 (ETRS89 / UTM 32N, 33N),\n"
    "32632, 32633 (WGS 84 / UTM), 4314 (DHDN), 4258 (ETRS89), 4326 (WGS 84). DHDN <-> ETRS89 is\n"
    "the Helmert transformation EPSG:1777 (about 1-2.5 m from BeTA2007); ETRS89 = WGS 84.\n"
    "Exit codes: 0 converted, 1 a bad input line, 2 a bad command line (unknown CRS, bad coordinate\n"
    "argument). See docs/coordinates.md.";

}  // namespace

void addCrsCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<CrsArgs>();
    CLI::App *cmd = app.add_subcommand("crs", "Convert coordinates between Gauss-Kruger, UTM and geographic CRSs");
    cmd->add_option("--from", args->from, "CRS of the input, e.g. EPSG:31467")
        ->required()
        ->check(CLI::Validator(checkCrs, "EPSG:CODE"));
    cmd->add_option("--to", args->to, "CRS of the output, e.g. EPSG:25832")
        ->required()
        ->check(CLI::Validator(checkCrs, "EPSG:CODE"));
    cmd->add_option("coordinates", args->coordinates, "X Y [Z] to convert; without them, lines of standard input");
    cmd->footer(kFooter);
    cmd->callback([args, &exitCode] { exitCode = runCrs(*args); });
}

}  // namespace veduta
