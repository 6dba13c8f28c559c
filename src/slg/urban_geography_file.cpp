#include "slg/urban_geography_file.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <set>
#include <span>
#include <string_view>

#include <fmt/format.h>

#include "io/xml_reader.h"

namespace veduta {

namespace {

constexpr std::array<std::string_view, kCitySizes> kCitySizeNames = {"Landstadt", "Kleinstadt", "Mittelstadt",
                                                                     "Grossstadt"};
constexpr std::array<std::string_view, kLocalities> kLocalityNames = {"Kern", "Mantel", "Rand"};
constexpr std::string_view kAnyLocality = "any";
// Attribute names, hence lower case and without umlauts.
constexpr std::array<std::string_view, kLandUses> kLandUseNames = {"industrie",    "wohnen",      "buero",
                                                                   "einzelhandel", "gastronomie", "freiflaeche"};
constexpr std::array<std::string_view, kDominantUses> kDominantUseNames = {"Industriegebiet", "Gewerbegebiet",
                                                                           "Wohngebiet", "Mischgebiet", "Unbebaut"};
constexpr std::array<std::string_view, kPlanLevels> kPlanLevelNames = {"city", "district", "block", "building",
                                                                       "apartment"};
constexpr std::array<std::string_view, 2> kRuleNames = {"perimeter", "growth"};
constexpr std::array<std::string_view, 4> kGapNames = {"none", "street", "house-corridor", "apartment-corridor"};
constexpr std::array<std::string_view, 3> kGapStartNames = {"none", "street-side", "computed"};
constexpr std::array<std::string_view, kStoreyUses> kStoreyUseNames = {"einzelhandel", "gastronomie", "industrie",
                                                                       "buero", "wohnen"};
constexpr std::array<std::string_view, 2> kFloorNames = {"ground", "upper"};
constexpr std::array<std::string_view, 3> kFitOutNames = {"rooms", "apartments", "storey"};
constexpr std::array<std::string_view, 3> kPlacementNames = {"single", "separated", "contiguous"};
constexpr std::array<std::string_view, 3> kDoorAlignmentNames = {"left", "centre", "right"};
constexpr std::array<std::string_view, 2> kWindowSideNames = {"front", "back"};
constexpr std::array<std::string_view, 3> kDoorKindNames = {"building", "inner", "outer"};
constexpr std::array<std::string_view, 4> kDefaultsLevelNames = {"city", "district", "block", "building"};
constexpr std::array<std::string_view, kRoofOrientations> kRatioAttributes = {"giebelstaendig-ratio",
                                                                              "traufstaendig-ratio"};

constexpr double kMaxArea = 1e9;           // m², about Berlin's
constexpr double kMaxLength = 1000;        // m
constexpr double kMaxWeight = 1e6;         // a land-use weight
constexpr double kMaxFactor = 100;         // eq 39–41, 47
constexpr double kMaxInhabitants = 1e10;   // Table 1
constexpr double kMaxFloorAreaRatio = 20;  // GFZ
constexpr double kMaxExponent = 10;        // eq 20

std::string joined(std::span<const std::string_view> names) {
    std::string text;
    for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
    return text;
}

template <size_t N>
size_t indexNamed(const XmlElement &e, const char *attribute, const std::array<std::string_view, N> &names) {
    std::string value = e.string(attribute);
    auto it = std::find(names.begin(), names.end(), value);
    if (it == names.end())
        e.failAt(attribute, fmt::format("'{}' is not one of {} (attribute '{}')", value, joined(names), attribute));
    return size_t(it - names.begin());
}

std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> result;
    for (size_t pos = text.find_first_not_of(" \t\r\n"); pos != std::string_view::npos;
         pos = text.find_first_not_of(" \t\r\n", pos)) {
        size_t end = std::min(text.find_first_of(" \t\r\n", pos), text.size());
        result.push_back(text.substr(pos, end - pos));
        pos = end;
    }
    return result;
}

double parsePart(const XmlElement &e, const char *attribute, std::string_view text, std::string_view token) {
    double value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        e.failAt(attribute, fmt::format("'{}' is not a number (attribute '{}')", token, attribute));
    return value;
}

// A number, or a fraction such as 2/3, so that the thesis's ratios (1 : 3, eq 51's 5/3) are
// written as it writes them.
double parseNumber(const XmlElement &e, const char *attribute, std::string_view token) {
    size_t slash = token.find('/');
    if (slash == std::string_view::npos) return parsePart(e, attribute, token, token);
    double numerator = parsePart(e, attribute, token.substr(0, slash), token);
    double denominator = parsePart(e, attribute, token.substr(slash + 1), token);
    if (denominator <= 0)
        e.failAt(attribute, fmt::format("'{}' divides by {} (attribute '{}')", token, denominator, attribute));
    return numerator / denominator;
}

std::vector<double> numbers(const XmlElement &e, const char *attribute, size_t count, double lo, double hi) {
    std::string text = e.string(attribute);
    std::vector<double> values;
    for (std::string_view token : words(text)) values.push_back(parseNumber(e, attribute, token));
    if (values.size() != count)
        e.failAt(attribute,
                 fmt::format("attribute '{}' takes {} number{}, not {}", attribute, count, count == 1 ? "" : "s",
                             values.size()));
    for (double value : values)
        if (value < lo || value > hi)
            e.failAt(attribute, fmt::format("attribute '{}' has {}, outside [{}, {}]", attribute, value, lo, hi));
    return values;
}

double number(const XmlElement &e, const char *attribute, double lo, double hi) {
    return numbers(e, attribute, 1, lo, hi)[0];
}

// rand(a, b): two numbers, a ≤ b.
Range range(const XmlElement &e, const char *attribute, double lo, double hi) {
    std::vector<double> ends = numbers(e, attribute, 2, lo, hi);
    if (ends[0] > ends[1])
        e.failAt(attribute,
                 fmt::format("attribute '{}' is a range a b with a <= b, not {} > {}", attribute, ends[0], ends[1]));
    return {ends[0], ends[1]};
}

int integer(const XmlElement &e, const char *attribute, int lo, int hi) {
    if (!e.has(attribute)) e.fail(fmt::format("<{}> needs the attribute '{}'", e.name(), attribute));
    return e.integer(attribute, 0, lo, hi);
}

std::optional<double> canopyDepth(const XmlElement &e) {
    if (!e.has("canopy")) return std::nullopt;
    return number(e, "canopy", 0, kMaxLength);
}

LandUseWeights weights(const XmlElement &e) {
    LandUseWeights result{};
    for (size_t i = 0; i < result.size(); ++i) result[i] = number(e, kLandUseNames[i].data(), 0, kMaxWeight);
    return result;
}

LandUseFactors factors(const XmlElement &e) {
    LandUseFactors result{};
    for (size_t i = 0; i < result.size(); ++i) result[i] = range(e, kLandUseNames[i].data(), 0, kMaxFactor);
    return result;
}

// A mask of eq 44 or 48: the uses it keeps (factor 1), the others dropped (factor 0).
LandUseWeights mask(const XmlElement &e) {
    LandUseWeights result{};
    std::string keeps = e.string("keeps");
    for (std::string_view kept : words(keeps)) {
        auto it = std::find(kLandUseNames.begin(), kLandUseNames.end(), kept);
        if (it == kLandUseNames.end())
            e.failAt("keeps", fmt::format("'{}' is not a land use ({})", kept, joined(kLandUseNames)));
        result[size_t(it - kLandUseNames.begin())] = 1;
    }
    return result;
}

// The localities a row of a table by use and locality fills: one, or all three for "any".
std::vector<size_t> rowLocalities(const XmlElement &e) {
    if (e.string("locality") == kAnyLocality) return {0, 1, 2};
    std::array<std::string_view, kLocalities + 1> names = {kLocalityNames[0], kLocalityNames[1], kLocalityNames[2],
                                                           kAnyLocality};
    return {indexNamed(e, "locality", names)};
}

// A table by dominant use and locality whose every cell one row must fill, once.
template <typename T>
class CellTable {
  public:
    explicit CellTable(ByUseAndLocality<T> &cells) : cells_(cells) {}

    void fill(const XmlElement &row, const T &value) {
        size_t use = indexNamed(row, "use", kDominantUseNames);
        for (size_t locality : rowLocalities(row)) {
            if (filled_[use][locality])
                row.fail(fmt::format("<{}> for {} in the {} is given twice", row.name(), kDominantUseNames[use],
                                     kLocalityNames[locality]));
            filled_[use][locality] = true;
            cells_[use][locality] = value;
        }
    }
    void checkComplete(const XmlElement &where, std::string_view rowName) const {
        for (size_t use = 0; use < kDominantUses; ++use)
            for (size_t locality = 0; locality < kLocalities; ++locality)
                if (!filled_[use][locality])
                    where.fail(fmt::format("no <{}> for {} in the {}", rowName, kDominantUseNames[use],
                                           kLocalityNames[locality]));
    }

  private:
    ByUseAndLocality<T> &cells_;
    ByUseAndLocality<bool> filled_{};
};

WindowParameters windowParameters(const XmlElement &e) {
    WindowParameters w;
    w.height = number(e, "height", 0, kMaxLength);
    w.sill = number(e, "sill", 0, kMaxLength);
    w.width = number(e, "width", 0, kMaxLength);
    w.placement = WindowArrangement(indexNamed(e, "placement", kPlacementNames));
    w.spacing = number(e, "spacing", 0, kMaxLength);
    w.wallDistance = number(e, "wall-distance", 0, kMaxLength);
    w.glass = e.boolean("glass", true);
    w.canopyDepth = canopyDepth(e);
    return w;
}

DoorParameters doorParameters(const XmlElement &e) {
    DoorParameters d;
    d.height = number(e, "height", 0, kMaxLength);
    d.width = number(e, "width", 0, kMaxLength);
    d.alignment = DoorAlignment(indexNamed(e, "align", kDoorAlignmentNames));
    d.door = e.boolean("door", true);
    d.canopyDepth = canopyDepth(e);
    return d;
}

class UrbanGeographyReader {
  public:
    explicit UrbanGeographyReader(const XmlDocument &doc) : root_(doc, doc.root()) {}

    UrbanGeography read() {
        if (root_.name() != "urban-geography")
            root_.fail(fmt::format("the root element is <{}>, not <urban-geography>", root_.name()));
        root_.checkAllRead();
        for (const XmlElement &e : root_.children()) readElement(e);
        checkComplete();
        return g_;
    }

  private:
    void readElement(const XmlElement &e) {
        using Read = void (UrbanGeographyReader::*)(const XmlElement &);
        static constexpr std::pair<std::string_view, Read> kReaders[] = {
            {"city-size", &UrbanGeographyReader::readCitySize},
            {"zone", &UrbanGeographyReader::readZone},
            {"child-factors", &UrbanGeographyReader::readChildFactors},
            {"lot-factors", &UrbanGeographyReader::readLotFactors},
            {"block-mask", &UrbanGeographyReader::readBlockMask},
            {"lot-mask", &UrbanGeographyReader::readLotMask},
            {"lot", &UrbanGeographyReader::readLot},
            {"storey-counts", &UrbanGeographyReader::readStoreyCounts},
            {"storeys-per-use", &UrbanGeographyReader::readStoreysPerUse},
            {"plan", &UrbanGeographyReader::readPlan},
            {"defaults", &UrbanGeographyReader::readDefaults},
            {"lot-placement", &UrbanGeographyReader::readLotPlacement},
            {"building", &UrbanGeographyReader::readBuilding},
            {"roof", &UrbanGeographyReader::readRoof},
            {"storey", &UrbanGeographyReader::readStorey},
        };
        for (const auto &[name, readOne] : kReaders)
            if (e.name() == name) return (this->*readOne)(e);
        e.fail(fmt::format("unknown element <{}> in <urban-geography>", e.name()));
    }

    // Each table, or each keyed row of one, once; checkComplete() asks for the keys it needs.
    void once(const XmlElement &e, const std::string &key) {
        if (!seen_.insert(key).second) e.fail(fmt::format("{} is given twice", key));
    }
    void require(const std::string &key) const {
        if (!seen_.contains(key)) root_.fail(fmt::format("<urban-geography> has no {}", key));
    }

    template <size_t N>
    size_t keyed(const XmlElement &e, const char *attribute, const std::array<std::string_view, N> &names) {
        size_t index = indexNamed(e, attribute, names);
        once(e, key(e.name(), attribute, names[index]));
        return index;
    }
    static std::string key(std::string_view element, std::string_view attribute, std::string_view value) {
        return fmt::format("<{} {}=\"{}\">", element, attribute, value);
    }

    void readCitySize(const XmlElement &e) {
        size_t size = keyed(e, "name", kCitySizeNames);
        g_.inhabitantsAbove[size] = number(e, "inhabitants-above", 0, kMaxInhabitants);
        e.checkLeaf();
    }

    void readZone(const XmlElement &e) {
        BaunvoZone zone{e.string("name"), number(e, "grz", 0, 1), number(e, "gfz", 0, kMaxFloorAreaRatio)};
        once(e, key("zone", "name", zone.name));
        g_.zones.push_back(zone);
        e.checkLeaf();
    }

    void readChildFactors(const XmlElement &e) {
        g_.childFactors[keyed(e, "locality", kLocalityNames)] = factors(e);
        e.checkLeaf();
    }

    void readLotFactors(const XmlElement &e) {
        once(e, "<lot-factors>");
        g_.lotFactors = factors(e);
        e.checkLeaf();
    }

    void readBlockMask(const XmlElement &e) {
        g_.blockMasks[keyed(e, "use", kDominantUseNames)] = mask(e);
        e.checkLeaf();
    }

    void readLotMask(const XmlElement &e) {
        g_.lotMasks[keyed(e, "use", kDominantUseNames)] = mask(e);
        e.checkLeaf();
    }

    void readLot(const XmlElement &e) {
        LotTable lot;
        lot.lotArea = number(e, "area", 0, kMaxArea);
        if (lot.lotArea <= 0) e.failAt("area", "a lot needs an area above 0");
        lot.buildingArea = number(e, "building-area", 0, kMaxArea);
        if (e.has("zone")) lot.zone = zoneNamed(e, e.string("zone"));
        lots_.fill(e, lot);
        e.checkLeaf();
    }

    size_t zoneNamed(const XmlElement &e, const std::string &name) const {
        for (size_t i = 0; i < g_.zones.size(); ++i)
            if (g_.zones[i].name == name) return i;
        e.failAt("zone", fmt::format("no <zone name=\"{}\"> comes before this", name));
    }

    void readStoreyCounts(const XmlElement &e) {
        size_t city = keyed(e, "city", kCitySizeNames);
        e.checkAllRead();
        CellTable<StoreyRange> counts(g_.storeyCounts[city]);
        for (const XmlElement &row : e.children()) {
            if (row.name() != "count") row.fail(fmt::format("<{}> cannot stand inside <storey-counts>", row.name()));
            StoreyRange storeys{integer(row, "base", 0, kMaxStoreys), integer(row, "extra", 0, kMaxStoreys)};
            if (storeys.base + storeys.extra > kMaxStoreys)
                row.fail(
                    fmt::format("base + extra is {} storeys, more than {}", storeys.base + storeys.extra, kMaxStoreys));
            counts.fill(row, storeys);
            row.checkLeaf();
        }
        counts.checkComplete(e, "count");
    }

    void readStoreysPerUse(const XmlElement &e) {
        once(e, "<storeys-per-use>");
        g_.einzelhandelStoreysAtMost = integer(e, "einzelhandel-at-most", 0, kMaxStoreys);
        g_.gastronomieStoreysAtMost = integer(e, "gastronomie-at-most", 0, kMaxStoreys);
        e.checkLeaf();
    }

    void readPlan(const XmlElement &e) {
        size_t level = keyed(e, "level", kPlanLevelNames);
        PlanParameters &p = g_.plans[level].parameters;
        p.rule = LandmarkRule(indexNamed(e, "rule", kRuleNames));
        // A block's faces are its lots, whose area eq 45 gives; every other level names its own.
        if (PlanLevel(level) == PlanLevel::Block) {
            if (e.has("area")) e.failAt("area", "a block's average lot area comes from its <lot> rows (eq 45)");
        } else {
            p.averageArea = number(e, "area", 0, kMaxArea);
            if (p.averageArea <= 0) e.failAt("area", "a face needs an average area above 0");
        }
        p.sideRatio = number(e, "side-ratio", 0, 1);
        if (p.sideRatio <= 0) e.failAt("side-ratio", "a side ratio needs to be above 0");
        p.scale = number(e, "scale", 0, kMaxArea);
        p.exponent = number(e, "exponent", 0, kMaxExponent);
        if (p.rule == LandmarkRule::Growth && p.scale <= 0)
            e.failAt("scale", "the growth rule (eq 20) divides by the scale: it needs to be above 0");
        if (p.rule == LandmarkRule::Growth && p.exponent < 1)
            e.failAt("exponent", "the growth rule (eq 20) grows ever slower (Fig. 49): its exponent is at least 1");
        p.minimumCount = integer(e, "minimum", 0, kMaxLandmarks);
        p.jitter = number(e, "jitter", 0, 0.5);
        if (p.jitter >= 0.5) e.failAt("jitter", "a jitter of half the spacing or more lets landmarks swap places");
        p.gap = GapType(indexNamed(e, "gap", kGapNames));
        p.gapWidth = number(e, "gap-width", 0, kMaxLength);
        std::vector<double> reflex = numbers(e, "reflex", 3, 0, kMaxReflexCorners);
        for (size_t i = 0; i < reflex.size(); ++i) {
            if (reflex[i] != std::floor(reflex[i])) e.failAt("reflex", "reflex limits are whole numbers");
            p.reflexLimits[i] = int(reflex[i]);
        }
        g_.plans[level].gapStart = GapStart(indexNamed(e, "start", kGapStartNames));
        e.checkLeaf();
    }

    void readDefaults(const XmlElement &e) {
        std::array<Geography *, kDefaultsLevelNames.size()> defaults = {&g_.cityDefaults, &g_.districtDefaults,
                                                                        &g_.blockDefaults, &g_.buildingDefaults};
        Geography &geography = *defaults[keyed(e, "level", kDefaultsLevelNames)];
        geography.weights = weights(e);
        if (e.has("locality")) geography.locality = Locality(indexNamed(e, "locality", kLocalityNames));
        e.checkLeaf();
    }

    void readLotPlacement(const XmlElement &e) {
        once(e, "<lot-placement>");
        g_.sidewalkWidth = range(e, "sidewalk-width", 0, kMaxLength);
        for (size_t i = 0; i < g_.sideRatios.size(); ++i) {
            g_.sideRatios[i] = range(e, kRatioAttributes[i].data(), 0, kMaxFactor);
            if (g_.sideRatios[i].low <= 0) e.failAt(kRatioAttributes[i].data(), "a side ratio needs to be above 0");
        }
        e.checkLeaf();
    }

    void readBuilding(const XmlElement &e) {
        once(e, "<building>");
        g_.wallThickness = number(e, "wall-thickness", 0, kMaxLength);
        g_.stairwellArea = number(e, "stairwell-area", 0, kMaxArea);
        e.checkLeaf();
    }

    void readRoof(const XmlElement &e) {
        once(e, "<roof>");
        g_.roof.height = range(e, "height", 0, kMaxLength);
        g_.roof.thickness = number(e, "thickness", 0, kMaxLength);
        g_.roof.gableOverhang = range(e, "gable-overhang", 0, kMaxLength);
        g_.roof.eavesOverhang = range(e, "eaves-overhang", 0, kMaxLength);
        e.checkLeaf();
    }

    void readStorey(const XmlElement &e) {
        StoreyParameters s;
        size_t use = indexNamed(e, "use", kStoreyUseNames);
        size_t floor = indexNamed(e, "floor", kFloorNames);
        once(e, fmt::format("<storey use=\"{}\" floor=\"{}\">", kStoreyUseNames[use], kFloorNames[floor]));
        s.use = StoreyUse(use);
        s.groundFloor = floor == 0;
        s.height = number(e, "height", 0, kMaxLength);
        if (s.height <= 0) e.failAt("height", "a storey needs a height above 0");
        s.fitOut = FitOut(indexNamed(e, "fit-out", kFitOutNames));
        e.checkAllRead();
        std::array<WindowParameters *, kWindowSideNames.size()> windows = {&s.frontWindows, &s.backWindows};
        std::array<DoorParameters *, kDoorKindNames.size()> doors = {&s.buildingDoor, &s.innerDoor, &s.outerDoor};
        std::set<std::string> given;
        for (const XmlElement &part : e.children()) {
            auto onlyOnce = [&](std::string_view attribute, std::string_view value) {
                if (!given.insert(key(part.name(), attribute, value)).second)
                    part.fail(fmt::format("{} is given twice", key(part.name(), attribute, value)));
            };
            if (part.name() == "windows") {
                size_t side = indexNamed(part, "side", kWindowSideNames);
                onlyOnce("side", kWindowSideNames[side]);
                *windows[side] = windowParameters(part);
            } else if (part.name() == "door") {
                size_t kind = indexNamed(part, "kind", kDoorKindNames);
                onlyOnce("kind", kDoorKindNames[kind]);
                *doors[kind] = doorParameters(part);
            } else {
                part.fail(fmt::format("<{}> cannot stand inside <storey>", part.name()));
            }
            part.checkLeaf();
        }
        for (std::string_view side : kWindowSideNames)
            if (!given.contains(key("windows", "side", side)))
                e.fail(fmt::format("no {}", key("windows", "side", side)));
        for (std::string_view kind : kDoorKindNames)
            if (!given.contains(key("door", "kind", kind))) e.fail(fmt::format("no {}", key("door", "kind", kind)));
        g_.storeys.push_back(s);
    }

    void checkComplete() const {
        for (std::string_view size : kCitySizeNames) require(key("city-size", "name", size));
        for (size_t i = 1; i < g_.inhabitantsAbove.size(); ++i)
            if (g_.inhabitantsAbove[i] <= g_.inhabitantsAbove[i - 1])
                root_.fail(
                    fmt::format("a {} needs more inhabitants than a {}", kCitySizeNames[i], kCitySizeNames[i - 1]));
        for (std::string_view locality : kLocalityNames) require(key("child-factors", "locality", locality));
        require("<lot-factors>");
        for (std::string_view use : kDominantUseNames) {
            require(key("block-mask", "use", use));
            require(key("lot-mask", "use", use));
        }
        lots_.checkComplete(root_, "lot");
        for (std::string_view size : kCitySizeNames) require(key("storey-counts", "city", size));
        require("<storeys-per-use>");
        for (std::string_view level : kPlanLevelNames) require(key("plan", "level", level));
        for (std::string_view level : kDefaultsLevelNames) require(key("defaults", "level", level));
        require("<lot-placement>");
        require("<building>");
        require("<roof>");
    }

    XmlElement root_;
    UrbanGeography g_;
    std::set<std::string> seen_;
    CellTable<LotTable> lots_{g_.lots};
};

}  // namespace

UrbanGeography readUrbanGeography(const std::filesystem::path &file) {
    XmlDocument doc = XmlDocument::fromFile(file);
    return UrbanGeographyReader(doc).read();
}

UrbanGeography parseUrbanGeography(std::string text, std::string name) {
    XmlDocument doc = XmlDocument::fromString(std::move(text), std::move(name));
    return UrbanGeographyReader(doc).read();
}

}  // namespace veduta
