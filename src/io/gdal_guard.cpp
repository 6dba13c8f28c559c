#include "io/gdal_guard.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "core/error.h"
#include "core/input_file.h"
#include "io/xml_prolog.h"

namespace veduta {

void checkFileForGdal(const std::filesystem::path &file) {
    checkInputFile(file);
    refuseDocumentType(file, "GDAL");
}

std::chrono::milliseconds gdalTimeLimit() {
    if (const char *text = std::getenv("VEDUTA_GDAL_TIME_LIMIT")) {
        char *end = nullptr;
        double seconds = std::strtod(text, &end);
        if (end != text && *end == '\0' && seconds > 0 && seconds < 1e9)
            return std::chrono::milliseconds(int64_t(seconds * 1000));
        throw std::invalid_argument(
            fmt::format("VEDUTA_GDAL_TIME_LIMIT is '{}', not a positive number of seconds such as 600", text));
    }
    return std::chrono::seconds(300);
}

GdalDeadline::GdalDeadline(const std::filesystem::path &file, std::chrono::milliseconds limit) {
    watch_ = std::thread([this, name = file.string(), limit] {
        std::unique_lock lock(mutex_);
        if (finished_.wait_for(lock, limit, [this] { return done_; })) return;
        std::fprintf(stderr,
                     "veduta: %s: GDAL has read this file for %g s without finishing; giving up (a damaged or "
                     "hostile file? VEDUTA_GDAL_TIME_LIMIT sets the limit in seconds)\n",
                     name.c_str(), double(limit.count()) / 1000);
        std::fflush(stderr);
        std::_Exit(1);
    });
}

GdalDeadline::~GdalDeadline() {
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    finished_.notify_one();
    watch_.join();
}

}  // namespace veduta
