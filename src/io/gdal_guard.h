// What veduta checks before it lets GDAL open a file. GDAL's XML drivers (NAS, GML, OSM, VRT,
// KML …) expand the entities a document type declaration defines, without bound: a
// kilobyte "billion laughs" file keeps the NAS reader busy for ever. GDAL reads devices and
// directories as if they were files. Neither reaches GDAL. And since no check before GDAL
// can foresee every way its drivers spin, each read through GDAL runs against a deadline.
#pragma once

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <thread>

namespace veduta {

// Throws InputError naming the file when it is not a regular file, or when it is XML whose
// prolog holds a <!DOCTYPE> (io/xml_prolog.h; the message gives its line and column). Files
// that do not start like XML pass: their drivers do not parse DTDs.
void checkFileForGdal(const std::filesystem::path &file);

// How long GDAL may read one file: VEDUTA_GDAL_TIME_LIMIT seconds if that is set, else 300 s,
// far more than any real file of veduta's formats has needed. Throws std::invalid_argument
// when the variable is no positive number.
std::chrono::milliseconds gdalTimeLimit();

// Held while GDAL opens and reads `file`. A read that outlasts the limit cannot be stopped
// inside GDAL, so the program ends: the message names the file and the limit, the exit status
// is 1 (bad input), and files being written stay as they were (core/atomic_file.h).
class GdalDeadline {
  public:
    explicit GdalDeadline(const std::filesystem::path &file, std::chrono::milliseconds limit = gdalTimeLimit());
    ~GdalDeadline();
    GdalDeadline(const GdalDeadline &) = delete;
    GdalDeadline &operator=(const GdalDeadline &) = delete;

  private:
    std::mutex mutex_;
    std::condition_variable finished_;
    bool done_ = false;
    std::thread watch_;
};

}  // namespace veduta
