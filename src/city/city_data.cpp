#include "city/city_data.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>

#include "city/footprint.h"
#include "core/hash.h"
#include "core/random_streams.h"
#include "geo/height_grid.h"
#include "geodesy/map_projection.h"
#include "io/xml_reader.h"

namespace veduta {

namespace {

// How far a lot's corner may stand outside its block before it counts as outside (metres):
// lots drawn on a block's outline share its points, give or take the float rounding.
constexpr float kOutsideTolerance = 0.01f;

class CityDataReader {
  public:
    CityDataReader(const XmlDocument &doc, std::filesystem::path baseDirectory, const MapProjection *projection) :
        doc_(doc), baseDirectory_(std::move(baseDirectory)), projection_(projection) {}

    CityData read() {
        XmlElement root(doc_, doc_.root());
        if (root.name() != "CityData")
            root.fail(root.name().ends_with("CityModel")
                          ? fmt::format("the root element is <{}>: this is CityGML, which a scene reads with "
                                        "<citygml file=\"…\"/> (docs/citygml.md), not as a <city>",
                                        root.name())
                          : fmt::format("the root element is <{}>, expected <CityData>", root.name()));
        root.string("xmlns:xsi", "");  // Bilke's files name their schema; nothing to check
        root.string("xsi:noNamespaceSchemaLocation", "");
        root.checkAllRead();
        std::vector<XmlElement> children = root.children();
        // Points first: everything else refers to them, wherever the file puts them.
        for (const XmlElement &e : children)
            if (e.name() == "Points") readPoints(e);
        for (const XmlElement &e : children) {
            std::string_view n = e.name();
            if (n == "Points") continue;
            if (n == "StreetNetwork") {
                readStreetNetwork(e);
            } else if (n == "Blocks") {
                e.checkAllRead();
                for (const XmlElement &block : e.children()) city_.blocks.push_back(readBlock(block));
            } else if (n == "BuildingSettings") {
                city_.settings = readBuildingSettings(e);
            } else if (n == "Rulefiles") {
                readRuleFiles(e);
            } else {
                e.fail(fmt::format("unknown element <{}> in <CityData>", n));
            }
        }
        computeStreetEdges();
        return std::move(city_);
    }

  private:
    // A lot that flags none of its edges gets those that run along a street: parallel to a
    // street within 10° and with its middle within half the street's width and a metre of the
    // street's centreline (Bilke 2009 computes them too, L316-319, without saying how).
    void computeStreetEdges() {
        const float parallel = std::cos(10 * float(M_PI) / 180);
        for (CityBlock &block : city_.blocks)
            for (CityLot &lot : block.lots) {
                if (std::find(lot.streetEdges.begin(), lot.streetEdges.end(), true) != lot.streetEdges.end()) continue;
                size_t n = lot.points.size();
                for (size_t i = 0; i < n; ++i) {
                    Vec2f a = lot.points[i], b = lot.points[(i + 1) % n];
                    Vec2f middle{(a.x + b.x) / 2, (a.y + b.y) / 2};
                    float length = std::hypot(b.x - a.x, b.y - a.y);
                    for (const CityStreet &street : city_.streets) {
                        const CityPoint &s = city_.points[street.start], &t = city_.points[street.end];
                        Vec2f p{float(s.e), float(s.n)}, q{float(t.e), float(t.n)};
                        float streetLength = std::hypot(q.x - p.x, q.y - p.y);
                        if (length <= 0 || streetLength <= 0) continue;
                        float cosine =
                            std::abs((b.x - a.x) * (q.x - p.x) + (b.y - a.y) * (q.y - p.y)) / (length * streetLength);
                        float reach = street.width.value_or(city_.streetWidth) / 2 + 1;
                        if (cosine >= parallel && distanceToSegment(middle, p, q) <= reach) lot.streetEdges[i] = true;
                    }
                }
            }
    }

    void readPoints(const XmlElement &e) {
        e.checkAllRead();
        for (const XmlElement &p : e.children()) {
            if (p.name() != "Point") p.fail(fmt::format("unknown element <{}> in <Points>", p.name()));
            CityPoint point;
            point.loc = p.loc();
            point.id = requiredId(p, "id");
            point.e = coordinate(p, "e", true);
            point.n = coordinate(p, "n", true);
            point.u = coordinate(p, "u", false);
            if (projection_) placeOnMap(point, p);
            checkReach(point, p);
            p.checkLeaf();
            auto [it, fresh] = pointIndex_.emplace(point.id, uint32_t(city_.points.size()));
            if (!fresh)
                p.failAt("id",
                         fmt::format("point id {} is already used at {}", point.id,
                                     city_.points[it->second].loc.toString()));
            city_.points.push_back(point);
        }
    }

    // The point's map coordinates as metres from the scene origin, in double.
    void placeOnMap(CityPoint &point, const XmlElement &p) const {
        try {
            MapPoint local = projection_->toLocal({point.e, point.n});
            point.e = local.easting;
            point.n = local.northing;
        } catch (const std::out_of_range &e) {
            p.failAt("e",
                     fmt::format("({}, {}) is no point of EPSG:{}: {}", point.e, point.n, projection_->source().epsg,
                                 e.what()));
        }
    }

    void checkReach(const CityPoint &point, const XmlElement &p) const {
        if (std::abs(point.e) <= kMaxCityReach && std::abs(point.n) <= kMaxCityReach && std::abs(point.u) <= kMaxHeight)
            return;
        // Without a projection, points this far out are mostly map coordinates.
        std::string origin =
            projection_ ? "the scene origin" : "0 0 (map coordinates need the scene's <georeference> to be placed)";
        const char *attribute = std::abs(point.u) > kMaxHeight ? "u" : std::abs(point.e) > kMaxCityReach ? "e" : "n";
        p.failAt(attribute,
                 fmt::format("the point lies at ({:g}, {:g}, {:g}) m from {}; a city's points must lie within "
                             "{:g} km of it (and heights within {:g} km)",
                             point.e, point.n, point.u, origin, kMaxCityReach / 1000, kMaxHeight / 1000));
    }

    static uint32_t requiredId(const XmlElement &e, const char *attribute) {
        if (!e.has(attribute)) e.fail(fmt::format("<{}> needs the attribute '{}'", e.name(), attribute));
        return e.unsignedInteger(attribute, 0);
    }

    static double coordinate(const XmlElement &e, const char *attribute, bool required) {
        if (!e.has(attribute)) {
            if (required) e.fail(fmt::format("<{}> needs the attribute '{}'", e.name(), attribute));
            return 0;
        }
        std::vector<double> values = e.doubles(attribute);
        if (values.size() != 1) e.failAt(attribute, fmt::format("attribute '{}' takes one number", attribute));
        return values[0];
    }

    uint32_t pointRef(const XmlElement &e, const char *attribute) {
        uint32_t id = requiredId(e, attribute);
        auto it = pointIndex_.find(id);
        if (it == pointIndex_.end()) e.failAt(attribute, fmt::format("there is no point with id {}", id));
        return it->second;
    }

    void readStreetNetwork(const XmlElement &e) {
        e.checkAllRead();
        for (const XmlElement &c : e.children()) {
            if (c.name() == "Streets") {
                c.checkAllRead();
                for (const XmlElement &s : c.children()) {
                    if (s.name() != "Street") s.fail(fmt::format("unknown element <{}> in <Streets>", s.name()));
                    CityStreet street;
                    street.loc = s.loc();
                    street.id = requiredId(s, "id");
                    auto [given, fresh] = streetIndex_.emplace(street.id, uint32_t(city_.streets.size()));
                    if (!fresh)
                        s.failAt("id",
                                 fmt::format("street id {} is already used at {}", street.id,
                                             city_.streets[given->second].loc.toString()));
                    street.start = pointRef(s, "startPoint");
                    street.end = pointRef(s, "endPoint");
                    if (street.start == street.end)
                        s.fail(fmt::format("the street starts and ends at point {}", city_.points[street.start].id));
                    if (s.has("width")) street.width = s.number("width", 0, 0.1f, 1000);
                    s.checkLeaf();
                    city_.streets.push_back(street);
                }
            } else if (c.name() == "Width") {
                c.checkLeaf();
                SettingValue width = settingValue(c.text(), c.textLoc());
                if (!width.number || !(*width.number > 0))
                    throw InputError(width.loc,
                                     fmt::format("the street width must be a positive number, not '{}'", width.text));
                city_.streetWidth = *width.number;
            } else {
                c.fail(fmt::format("unknown element <{}> in <StreetNetwork>", c.name()));
            }
        }
    }

    // The <Points> of a block or lot: references in polygon order, with their street flags.
    struct Outline {
        std::vector<Vec2f> points;
        std::vector<bool> streetEdges;
        float base = 0;
        uint32_t sourceId = 0;  // from the ids of its points, in file order
    };

    Outline readOutline(const XmlElement &e, bool lot) {
        e.checkAllRead();
        Outline outline;
        std::vector<double> heights;
        std::vector<uint32_t> identity{streamTag(lot ? RandomStream::CityDataLot : RandomStream::CityDataBlock)};
        for (const XmlElement &p : e.children()) {
            if (p.name() != "Point") p.fail(fmt::format("unknown element <{}> in <Points>", p.name()));
            const CityPoint &point = city_.points[pointRef(p, "id")];
            identity.push_back(point.id);
            outline.points.push_back({float(point.e), float(point.n)});
            heights.push_back(point.u);
            bool street = false;
            if (lot) street = p.boolean("streetEdge", false);
            p.checkLeaf();
            outline.streetEdges.push_back(street);
        }
        if (outline.points.size() < 3)
            e.fail(fmt::format("a {} needs at least 3 points, not {}", lot ? "lot" : "block", outline.points.size()));
        // Bilke 2009 builds on horizontal ground (L235): one height per block and lot.
        for (double h : heights)
            if (h != heights.front())
                e.fail(fmt::format("the points of a {} must share one height u; they have {} and {}",
                                   lot ? "lot" : "block", heights.front(), h));
        outline.base = float(heights.front());
        outline.sourceId = hashSequence(identity);
        return outline;
    }

    CityBlock readBlock(const XmlElement &e) {
        if (e.name() != "Block") e.fail(fmt::format("unknown element <{}> in <Blocks>", e.name()));
        e.checkAllRead();
        CityBlock block;
        block.loc = e.loc();
        const XmlElement *lots = nullptr;
        std::vector<XmlElement> children = e.children();
        for (const XmlElement &c : children) {
            if (c.name() == "Points") {
                Outline outline = readOutline(c, false);
                block.points = std::move(outline.points);
                block.base = outline.base;
                block.sourceId = outline.sourceId;
                checkBlockShape(block, c);
            } else if (c.name() == "Lots") {
                lots = &c;
            } else if (c.name() == "BuildingSettings") {
                block.settings = readBuildingSettings(c);
            } else {
                c.fail(fmt::format("unknown element <{}> in <Block>", c.name()));
            }
        }
        if (block.points.empty()) e.fail("<Block> needs its <Points>");
        if (lots) {
            lots->checkAllRead();
            for (const XmlElement &lot : lots->children()) block.lots.push_back(readLot(lot, block));
        }
        return block;
    }

    // Bilke 2009 reverses a clockwise block with a warning (subdivideLotRectangular, L384).
    void checkBlockShape(CityBlock &block, const XmlElement &points) {
        if (!isSimplePolygon(block.points))
            points.fail("the block's outline crosses or touches itself, or has no area");
        if (isCounterClockwise(block.points)) return;
        std::reverse(block.points.begin(), block.points.end());
        city_.warnings.push_back(fmt::format("{}: the block runs clockwise; its points are taken in reverse order",
                                             points.loc().toString()));
    }

    CityLot readLot(const XmlElement &e, const CityBlock &block) {
        if (e.name() != "Lot") e.fail(fmt::format("unknown element <{}> in <Lots>", e.name()));
        e.checkAllRead();
        CityLot lot;
        lot.loc = e.loc();
        bool hasPoints = false;
        for (const XmlElement &c : e.children()) {
            if (c.name() == "Points") {
                Outline outline = readOutline(c, true);
                Footprint footprint{std::move(outline.points), std::move(outline.streetEdges), outline.base};
                if (auto warning = normaliseFootprint(footprint, c.loc())) city_.warnings.push_back(*warning);
                for (Vec2f p : footprint.points)
                    if (!covers(block.points, p, kOutsideTolerance))
                        c.fail(fmt::format("the lot's point ({} {}) lies outside its block", p.x, p.y));
                if (std::optional<size_t> edge = edgeLeaving(footprint.points, block.points, kOutsideTolerance)) {
                    Vec2f a = footprint.edgeStart(*edge), b = footprint.edgeEnd(*edge);
                    c.fail(fmt::format("the lot's edge from ({} {}) to ({} {}) leaves its block", a.x, a.y, b.x, b.y));
                }
                lot.points = std::move(footprint.points);
                lot.streetEdges = std::move(footprint.streetEdges);
                lot.sourceId = outline.sourceId;
                lot.base = footprint.base;
                hasPoints = true;
            } else if (c.name() == "BuildingSettings") {
                lot.settings = readBuildingSettings(c);
            } else {
                c.fail(fmt::format("unknown element <{}> in <Lot>", c.name()));
            }
        }
        if (!hasPoints) e.fail("<Lot> needs its <Points>");
        return lot;
    }

    void readRuleFiles(const XmlElement &e) {
        e.checkAllRead();
        for (const XmlElement &r : e.children()) {
            if (r.name() != "Rulefile") r.fail(fmt::format("unknown element <{}> in <Rulefiles>", r.name()));
            r.checkLeaf();
            std::filesystem::path file = r.text();
            if (file.empty()) r.fail("<Rulefile> names no file");
            city_.ruleFiles.push_back(file.is_absolute() ? file : baseDirectory_ / file);
        }
    }

    const XmlDocument &doc_;
    std::filesystem::path baseDirectory_;
    const MapProjection *projection_;
    CityData city_;
    std::unordered_map<uint32_t, uint32_t> pointIndex_;
    std::unordered_map<uint32_t, uint32_t> streetIndex_;
};

}  // namespace

CityData readCityData(const std::filesystem::path &file, const MapProjection *projection) {
    XmlDocument doc = XmlDocument::fromFile(file);
    return CityDataReader(doc, file.parent_path(), projection).read();
}

CityData parseCityData(std::string xml, std::string name, const std::filesystem::path &baseDirectory,
                       const MapProjection *projection) {
    XmlDocument doc = XmlDocument::fromString(std::move(xml), std::move(name));
    return CityDataReader(doc, baseDirectory, projection).read();
}

SettingsStack settingsFor(const CityData &city, const CityBlock &block, const CityLot *lot,
                          const SettingsMap &ruleFileSettings) {
    std::vector<const SettingsMap *> layers;
    if (lot) layers.push_back(&lot->settings);
    layers.insert(layers.end(), {&block.settings, &city.settings, &ruleFileSettings, &defaultBuildingSettings()});
    return SettingsStack(std::move(layers));
}

}  // namespace veduta
