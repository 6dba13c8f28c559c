// The result codes of the environment queries ?I and ?E (Goitowski 2010, L4860–4867). A rule's
// condition reads them as numbers (`insertion == NN`), so each code is a number as well.
#pragma once

#include <optional>
#include <string_view>

namespace veduta {

enum class QueryResult : int {
    Normal = 0,               // NORMAL: the segment fits as proposed
    Failed = 1,               // FAILED: no segment can be placed
    ForwardIntersection = 2,  // FWD_INTSCT: it meets an edge beyond its own length
    Intersection = 3,         // INTSCT: it meets an edge and was cut there
    NearestNeighbour = 4,     // NN: it was bent to a close existing node
};

// The code a rule file names (NORMAL, FAILED, FWD_INTSCT, INTSCT, NN), if `name` is one.
inline std::optional<QueryResult> queryResultNamed(std::string_view name) {
    if (name == "NORMAL") return QueryResult::Normal;
    if (name == "FAILED") return QueryResult::Failed;
    if (name == "FWD_INTSCT") return QueryResult::ForwardIntersection;
    if (name == "INTSCT") return QueryResult::Intersection;
    if (name == "NN") return QueryResult::NearestNeighbour;
    return std::nullopt;
}

}  // namespace veduta
