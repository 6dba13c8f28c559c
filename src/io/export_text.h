// Text the exporters print straight into one growing buffer (OBJ, MTL, glTF's JSON, PLY's
// header): no intermediate strings per number, which is most of an export's time.
#pragma once

#include <iterator>
#include <utility>

#include <fmt/format.h>

namespace veduta {

using TextBuffer = fmt::memory_buffer;

template <typename... Args>
void put(TextBuffer &out, fmt::format_string<Args...> format, Args &&...args) {
    fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
}

}  // namespace veduta
