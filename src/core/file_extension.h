// A file name's extension as formats are chosen by it: ".EXR" and ".exr" are one format.
#pragma once

#include <filesystem>
#include <string>

namespace veduta {

// The extension with its dot, in lower case ASCII; empty when the name has none.
std::string lowercaseExtension(const std::filesystem::path &file);

}  // namespace veduta
