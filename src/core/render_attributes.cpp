#include "core/render_attributes.h"

#include <fmt/format.h>

namespace veduta {

std::string blenderRenderTime(double seconds) {
    int hours = int(seconds / 3600);
    int minutes = int(seconds / 60) % 60;
    double rest = seconds - 3600.0 * hours - 60.0 * minutes;
    if (hours > 0) return fmt::format("{:02d}:{:02d}:{:05.2f}", hours, minutes, rest);
    return fmt::format("{:02d}:{:05.2f}", minutes, rest);
}

}  // namespace veduta
