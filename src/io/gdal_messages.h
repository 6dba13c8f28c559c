// GDAL's messages on the current thread, collected while a GdalMessages lives instead of
// printed on standard error, so that readers can turn them into errors or warnings.
#pragma once

#include <string>
#include <vector>

#include <cpl_error.h>

namespace veduta {

class GdalMessages {
  public:
    GdalMessages() { CPLPushErrorHandlerEx(&collect, this); }
    ~GdalMessages() { CPLPopErrorHandler(); }
    GdalMessages(const GdalMessages &) = delete;
    GdalMessages &operator=(const GdalMessages &) = delete;

    std::vector<std::string> failures, warnings;

  private:
    static void CPL_STDCALL collect(CPLErr level, CPLErrorNum, const char *message) {
        auto *self = static_cast<GdalMessages *>(CPLGetErrorHandlerUserData());
        (level >= CE_Failure ? self->failures : self->warnings).push_back(message);
    }
};

}  // namespace veduta
