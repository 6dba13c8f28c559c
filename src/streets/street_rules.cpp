#include "streets/street_rules.h"

#include <fmt/format.h>

namespace veduta {

std::string toString(std::span<const Word> words) {
    std::string text;
    for (const Word &word : words) {
        text += word.symbol;
        if (word.parameters.empty()) continue;
        // {:.6g}: a float's meaningful digits, so 0.5 * 3 * 0.312 prints 0.468, not 0.46800002.
        for (size_t i = 0; i < word.parameters.size(); ++i) {
            text += fmt::format("{}{:.6g}", i == 0 ? "(" : ",", word.parameters[i]);
        }
        text += ')';
    }
    return text;
}

}  // namespace veduta
