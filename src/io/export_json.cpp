#include "io/export_json.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

std::string jsonNumber(double value) {
    if (!std::isfinite(value)) throw std::invalid_argument(fmt::format("{} has no JSON number", value));
    return fmt::format("{}", value);
}

std::string jsonArray(const Vec3f &v) {
    return fmt::format("[{}, {}, {}]", jsonNumber(v.x), jsonNumber(v.y), jsonNumber(v.z));
}

}  // namespace veduta
