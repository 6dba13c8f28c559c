// GDAL reports problems through a global error handler that prints to standard error; the
// readers that use GDAL collect them instead, to put them into an InputError or a warning.
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include <cpl_error.h>
#include <gdal.h>

namespace veduta {

// GDAL's drivers, registered once per process before the first file is opened.
inline void registerGdalDrivers() {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
}

// GDAL's messages on this thread while it lives, instead of on standard error.
class GdalMessages {
  public:
    GdalMessages() { CPLPushErrorHandlerEx(&collect, this); }
    ~GdalMessages() { CPLPopErrorHandler(); }
    GdalMessages(const GdalMessages &) = delete;
    GdalMessages &operator=(const GdalMessages &) = delete;

    std::vector<std::string> failures, warnings;

    // ": first failure" or "", to end a message with what GDAL said.
    std::string detail() const { return failures.empty() ? std::string() : ": " + failures.front(); }

  private:
    static void CPL_STDCALL collect(CPLErr level, CPLErrorNum, const char *message) {
        auto *self = static_cast<GdalMessages *>(CPLGetErrorHandlerUserData());
        (level >= CE_Failure ? self->failures : self->warnings).push_back(message);
    }
};

}  // namespace veduta
