#include "core/file_extension.h"

#include <algorithm>

namespace veduta {

std::string lowercaseExtension(const std::filesystem::path &file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : char(c); });
    return extension;
}

}  // namespace veduta
