#include "city/warning_list.h"

#include <unordered_set>

namespace veduta {

void appendOnce(std::vector<std::string> &warnings, std::vector<std::string> &out) {
    std::unordered_set<std::string> seen(out.begin(), out.end());
    for (std::string &w : warnings)
        if (seen.insert(w).second) out.push_back(std::move(w));
}

}  // namespace veduta
