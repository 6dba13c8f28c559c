// What veduta checks before it lets GDAL open a file. GDAL's XML drivers (NAS, GML, OSM, VRT,
// KML …) expand the entities a document type declaration defines, without bound: a
// kilobyte "billion laughs" file keeps the NAS reader busy for ever. GDAL reads devices and
// directories as if they were files. Neither reaches GDAL.
#pragma once

#include <filesystem>

namespace veduta {

// Throws InputError naming the file when it is not a regular file, or when it is XML whose
// prolog holds a <!DOCTYPE> (the message gives its line and column). Files that do not start
// like XML pass: their drivers do not parse DTDs.
void checkFileForGdal(const std::filesystem::path &file);

}  // namespace veduta
