// XML parsers that veduta hands files to (GDAL's drivers, libcitygml's Xerces) expand the
// entities a document type declaration defines, without bound: a kilobyte "billion laughs"
// file keeps them busy for ever. The exchange formats they read (NAS, GML, CityGML, OSM)
// have no DTD, so a file with one is refused before any parser sees it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace veduta {

// Throws InputError at the line and column of the <!DOCTYPE> when the file is XML whose
// prolog (before the root element, within the first MiB) holds one, and when a comment or
// processing instruction of the prolog does not end there. `reader` names the parser the
// file was meant for, in the message. Files that do not start like XML pass.
void refuseDocumentType(const std::filesystem::path &file, std::string_view reader);

// The qualified name of the file's root element ("core:CityModel"), from its first MiB; empty
// when the file does not start like XML or a DOCTYPE comes first. Throws InputError as
// refuseDocumentType does for a prolog that does not end.
std::string rootElementName(const std::filesystem::path &file);

}  // namespace veduta
