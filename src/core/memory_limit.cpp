#include "core/memory_limit.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

namespace veduta {

std::optional<uint64_t> parseMemorySize(std::string_view text) {
    double value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || !(value > 0) || !std::isfinite(value)) return std::nullopt;
    std::string_view unit = text.substr(size_t(end - text.data()));
    double scale = 1;
    if (unit.size() == 1) {
        switch (std::toupper(static_cast<unsigned char>(unit[0]))) {
        case 'K': scale = 1024.0; break;
        case 'M': scale = 1024.0 * 1024; break;
        case 'G': scale = 1024.0 * 1024 * 1024; break;
        case 'T': scale = 1024.0 * 1024 * 1024 * 1024; break;
        default: return std::nullopt;
        }
    } else if (!unit.empty()) {
        return std::nullopt;
    }
    double bytes = value * scale;
    if (bytes < 1 || bytes > 9e18) return std::nullopt;
    return uint64_t(bytes);
}

uint64_t memoryBudget() {
    if (const char *text = std::getenv("VEDUTA_MAX_MEMORY")) {
        if (std::optional<uint64_t> bytes = parseMemorySize(text)) return *bytes;
        throw std::invalid_argument(
            fmt::format("VEDUTA_MAX_MEMORY is '{}', not a size such as 8G, 512M or a number of bytes", text));
    }
    long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return UINT64_MAX;
    return uint64_t(double(pages) * double(pageSize) * 0.9);
}

uint64_t limitMemory(uint64_t bytes) {
    rlimit limit{};
    if (getrlimit(RLIMIT_DATA, &limit) != 0) return UINT64_MAX;
    if (limit.rlim_cur != RLIM_INFINITY && uint64_t(limit.rlim_cur) <= bytes) return uint64_t(limit.rlim_cur);
    limit.rlim_cur = rlim_t(bytes);
    if (limit.rlim_max != RLIM_INFINITY && limit.rlim_cur > limit.rlim_max) limit.rlim_cur = limit.rlim_max;
    if (setrlimit(RLIMIT_DATA, &limit) != 0) return UINT64_MAX;
    return uint64_t(limit.rlim_cur);
}

std::optional<uint64_t> memoryLimit() {
    rlimit limit{};
    if (getrlimit(RLIMIT_DATA, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    return uint64_t(limit.rlim_cur);
}

std::string memorySizeText(uint64_t bytes) { return fmt::format("{:.1f} GB", double(bytes) / (1024.0 * 1024 * 1024)); }

}  // namespace veduta
