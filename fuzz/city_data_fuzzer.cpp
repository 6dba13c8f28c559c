// The CityData reader (docs/citydata.md) on any text, the streets and lots of what it reads, and
// the writer: what veduta writes of a city it read reads back as it was, without an error.
#include <cstdlib>
#include <optional>

#include "city/city_data_writer.h"
#include "city_layout.h"
#include "fuzz_input.h"

namespace {

using namespace veduta;

bool sameOutlines(const std::vector<Vec2f> &a, const std::vector<Vec2f> &b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
}

bool sameLayout(const CityData &a, const CityData &b) {
    if (a.streets.size() != b.streets.size() || a.blocks.size() != b.blocks.size() || a.streetWidth != b.streetWidth ||
        a.settings.size() != b.settings.size() || a.ruleFiles.size() != b.ruleFiles.size())
        return false;
    for (size_t i = 0; i < a.streets.size(); ++i) {
        const CityPoint &as = a.points[a.streets[i].start], &bs = b.points[b.streets[i].start];
        const CityPoint &ae = a.points[a.streets[i].end], &be = b.points[b.streets[i].end];
        if (as.e != bs.e || as.n != bs.n || ae.e != be.e || ae.n != be.n || a.streets[i].width != b.streets[i].width)
            return false;
    }
    for (size_t i = 0; i < a.blocks.size(); ++i) {
        const CityBlock &x = a.blocks[i], &y = b.blocks[i];
        if (!sameOutlines(x.points, y.points) || x.base != y.base || x.lots.size() != y.lots.size()) return false;
        for (size_t l = 0; l < x.lots.size(); ++l)
            if (!sameOutlines(x.lots[l].points, y.lots[l].points) || x.lots[l].streetEdges != y.lots[l].streetEdges)
                return false;
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::optional<CityData> city;
    fuzz::expectInputError(
        [&] { city = parseCityData(fuzz::inputText(data, size), "input.xml", fuzz::emptyFolder()); });
    if (!city) return 0;
    // Outside expectInputError: an error reading back what was written is the writer's bug.
    CityData again = parseCityData(cityDataXml(*city, {}, fuzz::emptyFolder()), "written.xml", fuzz::emptyFolder());
    if (!sameLayout(*city, again)) std::abort();
    fuzz::expectInputError([&] { fuzz::layOutCity(*city); });
    return 0;
}
