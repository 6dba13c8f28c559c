// Text made safe for JSON: the one string escaper of the JSON veduta writes by hand (the compare
// report, Cryptomatte manifests, glTF and the export sidecars).
#pragma once

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace veduta {

// `text` as a JSON string literal, quotes included.
inline std::string jsonString(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        case '\r': out += "\\r"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                out += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

}  // namespace veduta
