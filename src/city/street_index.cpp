#include "city/street_index.h"

#include <algorithm>

namespace veduta {

StreetIndex::StreetIndex(const StreetNetwork &network) {
    for (uint32_t s = 0; s < network.streets.size(); ++s) {
        const StreetNetwork::Street &street = network.streets[s];
        grid_.add({network.nodes[street.from], network.nodes[street.to], street.width / 2, s});
    }
}

std::vector<uint32_t> StreetIndex::near(Vec2f low, Vec2f high, float extra) const {
    // A metre more, so that no rounding of the reaches leaves out a street that reaches the box.
    float pad = extra + 1;
    std::vector<uint32_t> found;
    grid_.forEachNear({low.x - pad, low.y - pad}, {high.x + pad, high.y + pad},
                      [&](const SegmentGrid::Segment &segment) { found.push_back(segment.owner); });
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

}  // namespace veduta
