// The CRS argument parser (docs/crs.md) and a conversion between what it names: the input is
// "FROM\nTO\nX Y [Z]". A point that checkAxis lets through must convert to a finite point.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "fuzz_input.h"
#include "geodesy/crs.h"

namespace {

std::string_view nextLine(std::string_view &text) {
    size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    return line;
}

// The next number of `text` into `value`, which stays as it was unless it is a finite number.
bool readNumber(std::string_view &text, double &value) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    double read = 0;
    auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), read);
    if (error != std::errc() || !std::isfinite(read)) return false;
    value = read;
    text.remove_prefix(size_t(stop - text.data()));
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    std::string_view text(reinterpret_cast<const char *>(data), size);
    try {
        const Crs &from = parseCrs(nextLine(text));
        const Crs &to = parseCrs(nextLine(text));
        std::string_view line = nextLine(text);
        CrsCoordinate point;
        if (!readNumber(line, point.x) || !readNumber(line, point.y)) return 0;
        readNumber(line, point.z);
        checkAxis(from, 0, point.x);
        checkAxis(from, 1, point.y);
        CrsCoordinate converted = convert(from, to, point);
        if (!std::isfinite(converted.x) || !std::isfinite(converted.y) || converted.z != point.z) std::abort();
    } catch (const std::logic_error &) {  // invalid_argument and out_of_range: what the command reports
    }
    return 0;
}
