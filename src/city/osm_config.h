// GDAL's OSM driver configuration for the OSM import: src/city/osmconf.ini, compiled in so that
// the program needs no file beside it.
#pragma once

namespace veduta {

extern const char *const kOsmDriverConfig;

}  // namespace veduta
