#include "city/osm_import.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <regex>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include <cpl_error.h>
#include <cpl_vsi.h>
#include <fmt/format.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <GeographicLib/LocalCartesian.hpp>

#include "city/footprint.h"
#include "city/osm_config.h"
#include "city/segment_grid.h"
#include "core/hash.h"
#include "core/random_streams.h"
#include "geodesy/map_projection.h"
#include "io/gdal_guard.h"
#include "io/gdal_messages.h"

namespace veduta {

namespace {

// Street points closer than this are one point (metres): ways that share an OSM node meet there.
constexpr double kMergeDistance = 0.01;
// A lot edge faces a street when both its ends lie within half the street's width plus this
// margin (metres) of the street's centreline: sidewalk and front garden.
constexpr double kStreetEdgeMargin = 6;
// How far a building's corner may stand outside its residential area and still belong to it
// (metres), as readCityData allows a lot's corners.
constexpr double kOutsideTolerance = 0.01;

// OpenStreetMap's coordinates: WGS 84 longitude and latitude.
constexpr int kOsmEpsg = 4326;

using Tags = std::map<std::string, std::string, std::less<>>;

std::optional<std::string_view> tag(const Tags &tags, std::string_view key) {
    auto it = tags.find(key);
    return it == tags.end() ? std::nullopt : std::optional<std::string_view>(it->second);
}

// GDAL's all_tags column: "k"=>"v","k2"=>"v2", with \" and \\ escaped inside the quotes. GDAL
// cuts very long tag lists short (with a warning of its own): the pairs before the cut are kept.
class HstoreParser {
  public:
    explicit HstoreParser(std::string_view text) : text_(text) {}

    Tags parse() {
        Tags tags;
        while (pos_ < text_.size()) {
            if (!tags.empty() && !expect(",")) break;
            std::optional<std::string> key = quoted();
            if (!key || !expect("=>")) break;
            std::optional<std::string> value = quoted();
            if (!value) break;
            tags[*key] = std::move(*value);
        }
        return tags;
    }

  private:
    bool expect(std::string_view token) {
        if (text_.substr(pos_, token.size()) != token) return false;
        pos_ += token.size();
        return true;
    }

    std::optional<std::string> quoted() {
        if (!expect("\"")) return std::nullopt;
        std::string out;
        while (pos_ < text_.size() && text_[pos_] != '"') {
            if (text_[pos_] == '\\') ++pos_;
            if (pos_ == text_.size()) return std::nullopt;
            out += text_[pos_++];
        }
        if (!expect("\"")) return std::nullopt;
        return out;
    }

    std::string_view text_;
    size_t pos_ = 0;
};

// A positive number, optionally followed by " m" or "m" where `metres` allows it ("7", "7 m",
// "7.5"). Nothing for any other text: other units, commas, ranges.
std::optional<float> positiveNumber(std::string_view text, bool metres) {
    float value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || !std::isfinite(value) || !(value > 0)) return std::nullopt;
    std::string_view rest = text.substr(size_t(end - text.data()));
    if (metres && rest.starts_with(' ')) rest.remove_prefix(1);
    if (metres && rest == "m") rest = {};
    return rest.empty() ? std::optional(value) : std::nullopt;
}

// The width of a street of a highway class without a width tag (metres, docs/osm.md); a link
// road takes its class's. Nothing for the other classes: they take the network's width.
std::optional<float> classWidth(std::string_view highway) {
    if (highway.ends_with("_link")) highway.remove_suffix(5);
    static const std::unordered_map<std::string_view, float> widths = {
        {"motorway", 12.0f}, {"trunk", 12.0f},      {"primary", 12.0f},     {"secondary", 10.0f},
        {"tertiary", 8.0f},  {"residential", 6.0f}, {"unclassified", 6.0f}, {"living_street", 4.0f},
        {"service", 4.0f},   {"footway", 2.0f},     {"path", 2.0f},         {"cycleway", 2.0f}};
    auto it = widths.find(highway);
    return it == widths.end() ? std::nullopt : std::optional(it->second);
}

// Highways that are not (or no longer) on the ground, and platforms, which are no streets.
bool isStreet(std::string_view highway) {
    static const std::vector<std::string_view> notStreets = {"proposed", "construction", "abandoned", "razed",
                                                             "platform"};
    return std::find(notStreets.begin(), notStreets.end(), highway) == notStreets.end();
}

// OSM's roof:shape values with a RoofType setting of their own.
std::optional<std::string_view> roofType(std::string_view shape) {
    static const std::unordered_map<std::string_view, std::string_view> types = {
        {"gabled", "Gable"}, {"hipped", "Hip"},      {"pyramidal", "Pyramid"},  {"skillion", "Shed"},
        {"flat", "Flat"},    {"mansard", "Mansard"}, {"half-hipped", "HalfHip"}};
    auto it = types.find(shape);
    return it == types.end() ? std::nullopt : std::optional(it->second);
}

using GeoRing = std::vector<GeographicPoint>;

// What the import takes from the file, in WGS 84 degrees; `loc` names the file and the way or
// relation.
struct OsmLine {
    FileLoc loc;
    Tags tags;
    GeoRing points;
};

struct OsmArea {
    FileLoc loc;
    Tags tags;
    std::vector<std::vector<GeoRing>> polygons;  // each: the outer ring, then its holes
    uint32_t sourceId = 0;                       // its way or relation (areaIdentity)
};

struct OsmContent {
    std::vector<OsmLine> highways;
    std::vector<OsmArea> residentialAreas, buildings;
};

// The compiled-in driver configuration as a GDAL in-memory file, made once.
const char *osmDriverConfigFile() {
    static const std::string name = [] {
        std::string path = "/vsimem/veduta/osmconf.ini";
        auto *bytes = reinterpret_cast<GByte *>(const_cast<char *>(kOsmDriverConfig));
        VSIFCloseL(VSIFileFromMemBuffer(path.c_str(), bytes, vsi_l_offset(std::strlen(kOsmDriverConfig)), FALSE));
        RegisterOGROSM();
        return path;
    }();
    return name.c_str();
}

GeoRing geoPoints(const OGRSimpleCurve &curve) {
    GeoRing points;
    for (int i = 0; i < curve.getNumPoints(); ++i) points.push_back({curve.getY(i), curve.getX(i)});
    return points;
}

// A polygon ring without the point that closes it.
GeoRing geoRing(const OGRLinearRing &ring) {
    GeoRing points = geoPoints(ring);
    if (points.size() > 1 && points.front().latitude == points.back().latitude &&
        points.front().longitude == points.back().longitude)
        points.pop_back();
    return points;
}

std::vector<std::vector<GeoRing>> geoPolygons(const OGRMultiPolygon &multiPolygon) {
    std::vector<std::vector<GeoRing>> polygons;
    for (const OGRPolygon *polygon : multiPolygon) {
        std::vector<GeoRing> rings{geoRing(*polygon->getExteriorRing())};
        for (int i = 0; i < polygon->getNumInteriorRings(); ++i) rings.push_back(geoRing(*polygon->getInteriorRing(i)));
        polygons.push_back(std::move(rings));
    }
    return polygons;
}

// Where a feature comes from: the file and the way, or the relation of a multipolygon.
FileLoc featureLoc(const std::string &file, std::string_view layer, const OGRFeature &feature) {
    if (layer == "multipolygons") {
        int wayId = feature.GetFieldIndex("osm_way_id");
        if (feature.IsFieldSetAndNotNull(wayId))
            return {fmt::format("{}: way {}", file, feature.GetFieldAsString(wayId)), 0, 0};
        return {fmt::format("{}: relation {}", file, feature.GetFieldAsString("osm_id")), 0, 0};
    }
    return {fmt::format("{}: way {}", file, feature.GetFieldAsString("osm_id")), 0, 0};
}

// A multipolygon feature's identity: a hash of its way's id, or of its relation's.
uint32_t areaIdentity(const OGRFeature &feature) {
    int wayId = feature.GetFieldIndex("osm_way_id");
    bool way = feature.IsFieldSetAndNotNull(wayId);
    auto id = uint64_t(way ? feature.GetFieldAsInteger64(wayId) : feature.GetFieldAsInteger64("osm_id"));
    return hashValues(
        {streamTag(way ? RandomStream::OsmWay : RandomStream::OsmRelation), uint32_t(id), uint32_t(id >> 32)});
}

// Sorts one feature of GDAL's `lines` or `multipolygons` layer into `content`.
void addFeature(const std::string &file, std::string_view layer, const OGRFeature &feature, OsmContent &content) {
    const OGRGeometry *geometry = feature.GetGeometryRef();
    if (!geometry) return;
    FileLoc loc = featureLoc(file, layer, feature);
    Tags tags = HstoreParser(feature.GetFieldAsString("all_tags")).parse();
    OGRwkbGeometryType type = wkbFlatten(geometry->getGeometryType());
    if (layer == "lines" && type == wkbLineString) {
        std::optional<std::string_view> highway = tag(tags, "highway");
        if (highway && isStreet(*highway))
            content.highways.push_back({loc, std::move(tags), geoPoints(*geometry->toLineString())});
    } else if (layer == "multipolygons" && type == wkbMultiPolygon) {
        std::optional<std::string_view> building = tag(tags, "building");
        bool residential = tag(tags, "landuse") == "residential";
        OsmArea area{loc, std::move(tags), geoPolygons(*geometry->toMultiPolygon()), areaIdentity(feature)};
        if (building && building != "no") content.buildings.push_back(area);
        if (residential) content.residentialAreas.push_back(std::move(area));
    }
}

// GDAL's failure as the user's error: its XML parser's "… at line L, column C" becomes the
// place in front ("file:L:C: XML parsing of OSM file failed: not well-formed (invalid
// token)"), and "Failed inserting node N: UNIQUE constraint failed" says what it means (two
// nodes, ways or relations of one id).
InputError gdalFailure(const std::filesystem::path &file, const std::string &failure) {
    static const std::regex place(R"((.*) at line (\d+), column (\d+)$)");
    static const std::regex repeatedId(R"(Failed inserting (node|way|relation) (-?\d+): UNIQUE constraint failed.*)");
    std::smatch match;
    if (std::regex_match(failure, match, place)) {
        std::string what = std::regex_replace(match[1].str(), std::regex(" : "), ": ");
        return InputError({file.string(), std::stoi(match[2]), std::stoi(match[3])}, what);
    }
    if (std::regex_match(failure, match, repeatedId))
        return InputError({file.string()},
                          fmt::format("two {}s have the id {} (GDAL: {})", match[1].str(), match[2].str(), failure));
    return InputError({file.string()}, failure);
}

OsmContent readOsmContent(const std::filesystem::path &file, std::vector<std::string> &warnings) {
    FileLoc fileLoc{file.string(), 0, 0};
    checkFileForGdal(file);
    GdalMessages messages;
    const char *drivers[] = {"OSM", nullptr};
    std::string configOption = fmt::format("CONFIG_FILE={}", osmDriverConfigFile());
    // GDAL's own node index needs the nodes sorted by id, which files saved by editors are not.
    const char *openOptions[] = {configOption.c_str(), "USE_CUSTOM_INDEXING=NO", nullptr};
    OsmContent content;
    {
        GdalDeadline deadline(file);
        GDALDatasetUniquePtr dataset(GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR, drivers, openOptions, nullptr));
        if (!dataset) {
            // Without a message, GDAL's OSM driver did not recognise the file (it looks for
            // an <osm> element within the file's first bytes).
            std::string detail = messages.failures.empty() ? " (GDAL finds no <osm> element at its start)"
                                                           : fmt::format(" ({})", messages.failures.front());
            throw InputError(fileLoc, fmt::format("GDAL cannot read this as an OpenStreetMap XML file{}", detail));
        }
        OGRLayer *layer = nullptr;
        while (messages.failures.empty()) {
            OGRFeatureUniquePtr feature(dataset->GetNextFeature(&layer, nullptr, nullptr, nullptr));
            if (!feature) break;
            addFeature(file.string(), layer->GetName(), *feature, content);
        }
    }
    if (!messages.failures.empty()) throw gdalFailure(file, messages.failures.front());
    for (const std::string &warning : messages.warnings)
        warnings.push_back(fmt::format("{}: GDAL: {}", fileLoc.toString(), warning));
    return content;
}

// The centre of the latitude/longitude box round everything imported; nothing when it is empty.
std::optional<GeographicPoint> boundsCentre(const OsmContent &content) {
    double south = 90, north = -90, west = 180, east = -180;
    auto extend = [&](const GeoRing &points) {
        for (const GeographicPoint &p : points) {
            south = std::min(south, p.latitude), north = std::max(north, p.latitude);
            west = std::min(west, p.longitude), east = std::max(east, p.longitude);
        }
    };
    for (const OsmLine &line : content.highways) extend(line.points);
    for (const auto *areas : {&content.residentialAreas, &content.buildings})
        for (const OsmArea &area : *areas)
            for (const std::vector<GeoRing> &polygon : area.polygons) extend(polygon.front());
    if (south > north) return std::nullopt;
    return GeographicPoint{(south + north) / 2, (west + east) / 2};
}

// The cells of the street-edge search (metres): about a street's reach.
constexpr float kStreetCell = 32;

class OsmImporter {
  public:
    OsmImporter(std::optional<MapProjection> projection, GeographicPoint tangentOrigin,
                std::vector<std::string> warnings) :
        projection_(std::move(projection)), tangentPlane_(tangentOrigin.latitude, tangentOrigin.longitude, 0) {
        city_.warnings = std::move(warnings);
    }

    CityData import(const OsmContent &content, const OsmImportOptions &options) {
        city_.streetWidth = options.defaultStreetWidth;
        city_.ruleFiles = options.ruleFiles;
        for (const OsmLine &line : content.highways) addStreet(line);
        for (const OsmArea &area : content.residentialAreas) addBlocks(area);
        size_t residentialBlocks = city_.blocks.size();
        for (const CityBlock &block : city_.blocks) blockBoxes_.push_back(boxOf(block.points));
        for (const OsmArea &area : content.buildings) addBuilding(area, residentialBlocks);
        return std::move(city_);
    }

  private:
    // East and north of the scene origin on the scene's grid, or else on the tangent plane at
    // the data's origin, whose up of the ellipsoid below the plane is dropped.
    std::pair<double, double> eastNorth(const GeographicPoint &p) const {
        if (projection_) {
            MapPoint local = projection_->toLocal({p.longitude, p.latitude});
            return {local.easting, local.northing};
        }
        double e = 0, n = 0, u = 0;
        tangentPlane_.Forward(p.latitude, p.longitude, 0, e, n, u);
        return {e, n};
    }

    void warn(const FileLoc &loc, const std::string &message) {
        city_.warnings.push_back(fmt::format("{}: {}", loc.toString(), message));
    }

    // The index of the street point at (e, n), a new one unless one lies within kMergeDistance.
    uint32_t streetPoint(double e, double n, const FileLoc &loc) {
        int64_t cellE = std::llround(e / kMergeDistance), cellN = std::llround(n / kMergeDistance);
        for (int64_t de = -1; de <= 1; ++de)
            for (int64_t dn = -1; dn <= 1; ++dn) {
                auto cell = pointCells_.find({cellE + de, cellN + dn});
                if (cell == pointCells_.end()) continue;
                for (uint32_t index : cell->second) {
                    const CityPoint &q = city_.points[index];
                    if (std::hypot(q.e - e, q.n - n) <= kMergeDistance) return index;
                }
            }
        auto index = uint32_t(city_.points.size());
        city_.points.push_back({index, e, n, 0, loc});
        pointCells_[{cellE, cellN}].push_back(index);
        return index;
    }

    std::optional<float> streetWidth(const OsmLine &line) {
        std::string_view highway = *tag(line.tags, "highway");
        if (std::optional<std::string_view> width = tag(line.tags, "width")) {
            if (std::optional<float> metres = positiveNumber(*width, true)) return metres;
            warn(line.loc,
                 fmt::format("width '{}' is not a length in metres; the street takes highway={}'s width", *width,
                             highway));
        }
        return classWidth(highway);
    }

    // The points east and north of the origin, each projected once; nothing (with a warning
    // that the way is skipped) when one lies beyond a city's reach of the origin (kMaxCityReach).
    std::optional<std::vector<std::pair<double, double>>> projected(const std::vector<GeographicPoint> &points,
                                                                    const FileLoc &loc) {
        std::vector<std::pair<double, double>> result;
        result.reserve(points.size());
        for (const GeographicPoint &p : points) {
            auto [e, n] = eastNorth(p);
            if (!(std::abs(e) <= kMaxCityReach && std::abs(n) <= kMaxCityReach)) {
                warn(loc,
                     fmt::format("its node at {:.7f} {:.7f} lies {:.0f} km from the data's origin, beyond the "
                                 "{:g} km a city reaches; it is skipped",
                                 p.latitude, p.longitude, std::hypot(e, n) / 1000, kMaxCityReach / 1000));
                return std::nullopt;
            }
            result.emplace_back(e, n);
        }
        return result;
    }

    void addStreet(const OsmLine &line) {
        std::optional<std::vector<std::pair<double, double>>> points = projected(line.points, line.loc);
        if (!points) return;
        std::optional<float> width = streetWidth(line);
        float reach = width.value_or(city_.streetWidth) / 2 + float(kStreetEdgeMargin);
        auto way = uint32_t(streetWays_++);
        uint32_t previous = 0;
        for (size_t i = 0; i < points->size(); ++i) {
            uint32_t point = streetPoint((*points)[i].first, (*points)[i].second, line.loc);
            if (i > 0) {
                const CityPoint &p = city_.points[previous], &q = city_.points[point];
                streetSegments_.add({{float(p.e), float(p.n)}, {float(q.e), float(q.n)}, reach, way});
                if (point != previous)
                    city_.streets.push_back({uint32_t(city_.streets.size()), previous, point, width, line.loc});
            }
            previous = point;
        }
    }

    // A ring in the local frame, counter-clockwise; nothing (with a warning) when it is no
    // simple polygon.
    std::optional<std::vector<Vec2f>> outline(const GeoRing &ring, const FileLoc &loc) {
        std::optional<std::vector<std::pair<double, double>>> projectedRing = projected(ring, loc);
        if (!projectedRing) return std::nullopt;
        std::vector<Vec2f> points;
        for (auto [e, n] : *projectedRing) points.push_back({float(e), float(n)});
        if (points.size() < 3) {
            warn(loc, fmt::format("an outline of {} points is no polygon; it is skipped", points.size()));
            return std::nullopt;
        }
        if (!isSimplePolygon(points)) {
            warn(loc, "the outline crosses or touches itself, or has no area; it is skipped");
            return std::nullopt;
        }
        // OSM has no rule for the direction of a ring: either is right.
        if (!isCounterClockwise(points)) std::reverse(points.begin(), points.end());
        return points;
    }

    // A polygon of an area is known by the area and its place among the area's polygons.
    void addBlocks(const OsmArea &area) {
        for (uint32_t part = 0; part < area.polygons.size(); ++part) {
            const std::vector<GeoRing> &polygon = area.polygons[part];
            if (polygon.size() > 1)
                warn(area.loc,
                     fmt::format("blocks have no holes: the residential area's {} inner ring(s) are ignored",
                                 polygon.size() - 1));
            std::optional<std::vector<Vec2f>> points = outline(polygon.front(), area.loc);
            if (!points) continue;
            CityBlock block;
            block.points = std::move(*points);
            block.loc = area.loc;
            block.sourceId = hashValues({area.sourceId, part});
            city_.blocks.push_back(std::move(block));
        }
    }

    // Each part of a building is a lot of the residential block holding it, else a block of its own.
    void addBuilding(const OsmArea &area, size_t residentialBlocks) {
        SettingsMap settings = buildingSettings(area);
        for (uint32_t part = 0; part < area.polygons.size(); ++part) {
            const std::vector<GeoRing> &polygon = area.polygons[part];
            if (polygon.size() > 1)
                warn(
                    area.loc,
                    fmt::format("lots have no holes: the building's {} inner ring(s) are ignored", polygon.size() - 1));
            std::optional<std::vector<Vec2f>> points = outline(polygon.front(), area.loc);
            if (!points) continue;
            CityLot lot;
            lot.streetEdges = streetEdges(*points);
            lot.points = std::move(*points);
            lot.settings = settings;
            lot.loc = area.loc;
            lot.sourceId = hashValues({area.sourceId, part});
            if (CityBlock *block = blockHolding(lot, residentialBlocks)) {
                block->lots.push_back(std::move(lot));
                continue;
            }
            CityBlock own;
            own.points = lot.points;
            own.loc = lot.loc;
            own.sourceId = lot.sourceId;
            own.lots.push_back(std::move(lot));
            city_.blocks.push_back(std::move(own));
        }
    }

    // The residential block whose outline holds the lot's centroid, when it covers the whole lot.
    CityBlock *blockHolding(const CityLot &lot, size_t residentialBlocks) {
        Vec2f centre = areaCentroid(lot.points);
        for (size_t b = 0; b < residentialBlocks; ++b) {
            CityBlock &block = city_.blocks[b];
            // The box first: a town has hundreds of blocks, and covers() walks a block's outline.
            if (!blockBoxes_[b].holds(centre, kOutsideTolerance) || !covers(block.points, centre, kOutsideTolerance))
                continue;
            bool cornersIn = std::all_of(lot.points.begin(), lot.points.end(),
                                         [&](Vec2f p) { return covers(block.points, p, kOutsideTolerance); });
            if (cornersIn && !edgeLeaving(lot.points, block.points, kOutsideTolerance)) return &block;
            warn(lot.loc,
                 fmt::format("the building reaches outside the residential area of {}; it stands in a "
                             "block of its own",
                             block.loc.toString()));
            return nullptr;
        }
        return nullptr;
    }

    // The highway ways that pass within their reach of `p`.
    std::vector<uint32_t> waysNear(Vec2f p) const {
        std::vector<uint32_t> ways;
        streetSegments_.forEachNear(p, [&](const SegmentGrid::Segment &s) {
            if (distanceToSegment(p, s.a, s.b) <= s.reach) ways.push_back(s.owner);
        });
        std::sort(ways.begin(), ways.end());
        ways.erase(std::unique(ways.begin(), ways.end()), ways.end());
        return ways;
    }

    // An edge faces a street when both its ends lie near the centreline of one highway way.
    std::vector<bool> streetEdges(const std::vector<Vec2f> &points) const {
        std::vector<std::vector<uint32_t>> near;
        for (Vec2f p : points) near.push_back(waysNear(p));
        std::vector<bool> flags(points.size(), false);
        for (size_t i = 0; i < points.size(); ++i) {
            const std::vector<uint32_t> &a = near[i], &b = near[(i + 1) % points.size()];
            std::vector<uint32_t> both;
            std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
            flags[i] = !both.empty();
        }
        return flags;
    }

    // A building's tags as settings: height, building:levels, roof:shape and roof:height as
    // Bilke's, every other tag (and one that does not read) as osm:<key> (docs/osm.md).
    SettingsMap buildingSettings(const OsmArea &area) {
        SettingsMap settings;
        for (const auto &[key, value] : area.tags) settings[fmt::format("osm:{}", key)] = settingValue(value, area.loc);
        auto set = [&](const char *name, const char *fromKey, std::string text) {
            settings[name] = settingValue(std::move(text), area.loc);
            settings.erase(fmt::format("osm:{}", fromKey));
        };
        std::optional<float> height = metresTag(area, "height");
        std::optional<float> roofHeight = metresTag(area, "roof:height");
        if (roofHeight) set("RoofHeight", "roof:height", fmt::format("{}", *roofHeight));
        if (height && roofHeight && *roofHeight >= *height) {
            warn(area.loc,
                 fmt::format("roof:height {} is not below height {}; height is not used", *roofHeight, *height));
        } else if (height) {
            set("BuildingHeight", "height", fmt::format("{}", *height - roofHeight.value_or(0)));
        } else if (std::optional<std::string_view> levels = tag(area.tags, "building:levels")) {
            if (std::optional<float> count = positiveNumber(*levels, false))
                set("BuildingHeight", "building:levels", fmt::format("{}", *count * defaultFloorHeight()));
            else
                warn(area.loc,
                     fmt::format("building:levels '{}' is not a number; kept as osm:building:levels", *levels));
        }
        if (std::optional<std::string_view> shape = tag(area.tags, "roof:shape")) {
            if (std::optional<std::string_view> type = roofType(*shape))
                set("RoofType", "roof:shape", std::string(*type));
            else warn(area.loc, fmt::format("roof:shape '{}' has no RoofType; kept as osm:roof:shape", *shape));
        }
        return settings;
    }

    std::optional<float> metresTag(const OsmArea &area, const char *key) {
        std::optional<std::string_view> text = tag(area.tags, key);
        if (!text) return std::nullopt;
        std::optional<float> metres = positiveNumber(*text, true);
        if (!metres) warn(area.loc, fmt::format("{} '{}' is not a length in metres; kept as osm:{}", key, *text, key));
        return metres;
    }

    // building:levels counts floors of the built-in FloorHeight: the rule file that will set a
    // building's own is not known here.
    static float defaultFloorHeight() { return *defaultBuildingSettings().at("FloorHeight").number; }

    struct CellHash {
        size_t operator()(const std::pair<int64_t, int64_t> &cell) const {
            return std::hash<int64_t>()(cell.first * 73856093 ^ cell.second * 19349663);
        }
    };

    std::optional<MapProjection> projection_;
    GeographicLib::LocalCartesian tangentPlane_;  // without a projection
    CityData city_;
    std::unordered_map<std::pair<int64_t, int64_t>, std::vector<uint32_t>, CellHash> pointCells_;
    struct Box {
        Vec2f low, high;
        bool holds(Vec2f p, double tolerance) const {
            return p.x >= low.x - tolerance && p.x <= high.x + tolerance && p.y >= low.y - tolerance &&
                p.y <= high.y + tolerance;
        }
    };
    static Box boxOf(const std::vector<Vec2f> &points) {
        Box box{points[0], points[0]};
        for (Vec2f p : points) {
            box.low = {std::min(box.low.x, p.x), std::min(box.low.y, p.y)};
            box.high = {std::max(box.high.x, p.x), std::max(box.high.y, p.y)};
        }
        return box;
    }

    SegmentGrid streetSegments_{kStreetCell};
    std::vector<Box> blockBoxes_;  // of the residential blocks
    size_t streetWays_ = 0;
};

}  // namespace

CityData importOsm(const std::filesystem::path &file, const OsmImportOptions &options) {
    if (options.georeference && options.origin)
        throw std::invalid_argument("an OSM import takes an origin only without a georeference");
    std::vector<std::string> warnings;
    OsmContent content = readOsmContent(file, warnings);
    std::optional<GeographicPoint> origin = options.origin ? options.origin : boundsCentre(content);
    if (!origin) {
        warnings.push_back(fmt::format("{}: it holds no highways, residential areas or buildings", file.string()));
        origin = GeographicPoint{};
    }
    std::optional<MapProjection> projection;
    if (options.georeference) projection.emplace(crsByEpsg(kOsmEpsg), *options.georeference);
    return OsmImporter(std::move(projection), *origin, std::move(warnings)).import(content, options);
}

}  // namespace veduta
