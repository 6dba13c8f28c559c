#include "core/error.h"

#include <fmt/format.h>

namespace veduta {

std::string FileLoc::toString() const {
    std::string name = file.empty() ? std::string("<input>") : file;
    if (line <= 0) return name;
    if (column <= 0) return fmt::format("{}:{}", name, line);
    return fmt::format("{}:{}:{}", name, line, column);
}

}  // namespace veduta
