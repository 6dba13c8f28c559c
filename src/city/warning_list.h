// Warnings as the city generators pass them on: "file:line:col: message", each once, however
// many buildings run into the same rule.
#pragma once

#include <string>
#include <vector>

namespace veduta {

// Moves the warnings not yet in `out` (or earlier in `warnings`) to its end, in order.
void appendOnce(std::vector<std::string> &warnings, std::vector<std::string> &out);

}  // namespace veduta
