#include "app/number_option.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace veduta {

CLI::Validator finiteIn(double min, double max) {
    return CLI::Validator(
        [min, max](const std::string &text) {
            const char *begin = text.data(), *end = text.data() + text.size();
            if (begin != end && *begin == '+') ++begin;  // from_chars takes '-' only
            double value = 0;
            auto [stop, error] = std::from_chars(begin, end, value);
            if (error != std::errc() || stop != end || !std::isfinite(value) || value < min || value > max)
                return fmt::format("'{}' is not a number from {} to {}", text, min, max);
            return std::string();
        },
        fmt::format("NUMBER in [{}, {}]", min, max));
}

}  // namespace veduta
