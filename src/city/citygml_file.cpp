#include "city/citygml_file.h"

#include <citygml/citygml.h>
#include <citygml/citygmllogger.h>
#include <citygml/citymodel.h>
#include <citygml/cityobject.h>
#include <citygml/envelope.h>
#include <citygml/geometry.h>
#include <citygml/linearring.h>
#include <citygml/material.h>
#include <citygml/polygon.h>
#include <citygml/texture.h>
#include <citygml/texturecoordinates.h>
#include <citygml/texturetargetdefinition.h>
#include <xercesc/sax/SAXParseException.hpp>
#include <xercesc/util/XMLException.hpp>
#include <xercesc/util/XMLString.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <unordered_set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "city/footprint.h"
#include "core/error.h"
#include "core/input_file.h"
#include "geo/vector_file.h"
#include "io/xml_prolog.h"

namespace veduta {

namespace {

using citygml::CityObject;
using ObjectType = CityObject::CityObjectsType;
using GeometryType = citygml::Geometry::GeometryType;

std::string transcode(const XMLCh *text) {
    if (!text) return {};
    char *chars = xercesc::XMLString::transcode(text);
    std::string result = chars ? chars : "";
    xercesc::XMLString::release(&chars);
    return result;
}

// libcitygml's messages as warnings: "… at  line 15, column 20 in file F (…)" becomes
// "F:15:20: …"; its debug and info chatter is dropped. libcitygml's logger base has no virtual
// destructor; the logger is made by std::make_shared, whose deleter knows its type.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wnon-virtual-dtor"
class WarningLogger final : public citygml::CityGMLLogger {
  public:
    WarningLogger(std::string file, std::vector<std::string> &warnings) :
        CityGMLLogger(LOGLEVEL::LL_WARNING), file_(std::move(file)), warnings_(warnings) {}

    void log(LOGLEVEL, const std::string &message, const char *, int) const override {
        static const std::regex place(R"(^(.*?)\s+at\s+line (\d+), column (\d+) in file .*?(\s*\(.*\))?$)");
        std::smatch match;
        if (std::regex_match(message, match, place))
            warnings_.push_back(fmt::format("{}:{}:{}: {}", file_, match[2].str(), match[3].str(), match[1].str()));
        else warnings_.push_back(fmt::format("{}: {}", file_, message));
    }

  private:
    std::string file_;
    std::vector<std::string> &warnings_;
};
#pragma GCC diagnostic pop

std::optional<SurfaceKind> kindOfObject(ObjectType type) {
    switch (type) {
    case ObjectType::COT_WallSurface: return SurfaceKind::Wall;
    case ObjectType::COT_RoofSurface: return SurfaceKind::Roof;
    case ObjectType::COT_GroundSurface: return SurfaceKind::Ground;
    case ObjectType::COT_ClosureSurface: return SurfaceKind::Closure;
    case ObjectType::COT_OuterCeilingSurface:
    case ObjectType::COT_OuterFloorSurface: return SurfaceKind::Other;
    default: return std::nullopt;
    }
}

std::optional<SurfaceKind> kindOfGeometry(GeometryType type) {
    switch (type) {
    case GeometryType::GT_Wall: return SurfaceKind::Wall;
    case GeometryType::GT_Roof: return SurfaceKind::Roof;
    case GeometryType::GT_Ground: return SurfaceKind::Ground;
    case GeometryType::GT_Closure: return SurfaceKind::Closure;
    default: return std::nullopt;
    }
}

// Newell's normal of a ring, unnormalised, in double about its first point.
Vec3d newellNormal(const std::vector<CrsCoordinate> &ring) {
    Vec3d n;
    const CrsCoordinate &o = ring.front();
    for (size_t i = 0; i < ring.size(); ++i) {
        const CrsCoordinate &a = ring[i], &b = ring[(i + 1) % ring.size()];
        double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z;
        double bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
        n.x += (ay - by) * (az + bz);
        n.y += (az - bz) * (ax + bx);
        n.z += (ax - bx) * (ay + by);
    }
    return n;
}

// A surface no thematic surface names, by the way it faces: up a roof, down the ground.
SurfaceKind kindByNormal(const Vec3d &n) {
    double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (n.z > 0.2 * length) return SurfaceKind::Roof;
    if (n.z < -0.2 * length) return SurfaceKind::Ground;
    return SurfaceKind::Wall;
}

// The indices of a ring's points without repeats in a row and without the closing repeat of
// the first.
std::vector<size_t> distinctPoints(const std::vector<TVec3d> &vertices) {
    std::vector<size_t> kept;
    auto same = [&](size_t a, size_t b) {
        return vertices[a].x == vertices[b].x && vertices[a].y == vertices[b].y && vertices[a].z == vertices[b].z;
    };
    for (size_t i = 0; i < vertices.size(); ++i)
        if (kept.empty() || !same(i, kept.back())) kept.push_back(i);
    if (kept.size() > 1 && same(kept.front(), kept.back())) kept.pop_back();
    return kept;
}

std::vector<CrsCoordinate> ringPoints(const citygml::LinearRing &ring) {
    std::vector<CrsCoordinate> points;
    const std::vector<TVec3d> &vertices = ring.getVertices();
    for (size_t i : distinctPoints(vertices)) points.push_back({vertices[i].x, vertices[i].y, vertices[i].z});
    return points;
}

// An imageURI as a path: against the CityGML file's folder unless absolute, with the
// backslashes of files written on Windows read as folder separators.
std::filesystem::path texturePath(const std::filesystem::path &folder, std::string uri) {
    std::replace(uri.begin(), uri.end(), '\\', '/');
    std::filesystem::path path(uri);
    return path.is_absolute() ? path : folder / path;
}

bool isFinite(const CrsCoordinate &p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

class Reader {
  public:
    Reader(const std::filesystem::path &file, const CityGmlOptions &options, std::vector<std::string> themes,
           CityGmlModel &model) :
        file_(file.string()),
        folder_(file.parent_path()),
        options_(options),
        themes_(std::move(themes)),
        model_(model) {}

    void readBuilding(const CityObject &building) {
        // The highest LoD in range that has polygons, over the building and its parts.
        std::set<unsigned> lods;
        collectLods(building, lods);
        auto chosen = std::find_if(lods.rbegin(), lods.rend(),
                                   [&](unsigned lod) { return lod >= options_.minLod && lod <= options_.maxLod; });
        if (chosen == lods.rend()) {
            ++model_.buildingsWithoutGeometry;
            warn(fmt::format("building {} has no polygon of LoD {} to {} (it has LoD {}); it is skipped",
                             building.getId(), options_.minLod, options_.maxLod,
                             lods.empty() ? std::string("none") : fmt::format("{}", fmt::join(lods, ", "))));
            return;
        }
        CityGmlBuilding result;
        result.id = building.getId();
        result.lod = *chosen;
        readAttributes(building, result);
        seen_.clear();
        seenIds_.clear();
        // Thematic surfaces first, so that the solid's polygons they name keep their kind.
        readSurfaces(building, result, false);
        readSurfaces(building, result, true);
        if (result.polygons.empty()) {
            ++model_.buildingsWithoutGeometry;
            warn(fmt::format("building {}: none of its LoD {} polygons is usable; it is skipped", result.id,
                             result.lod));
            return;
        }
        model_.buildings.push_back(std::move(result));
    }

  private:
    void warn(const std::string &message) { model_.warnings.push_back(file_ + ": " + message); }

    static void collectLods(const citygml::Geometry &geometry, std::set<unsigned> &lods) {
        if (geometry.getPolygonsCount() > 0) lods.insert(geometry.getLOD());
        for (unsigned i = 0; i < geometry.getGeometriesCount(); ++i) collectLods(geometry.getGeometry(i), lods);
    }

    static void collectLods(const CityObject &object, std::set<unsigned> &lods) {
        for (unsigned i = 0; i < object.getGeometriesCount(); ++i) collectLods(object.getGeometry(i), lods);
        for (unsigned i = 0; i < object.getChildCityObjectsCount(); ++i)
            collectLods(object.getChildCityObject(i), lods);
    }

    static void readAttributes(const CityObject &building, CityGmlBuilding &result) {
        for (const auto &[name, value] : building.getAttributes()) result.attributes[name] = value.asString();
        auto number = [&](const char *name) -> std::optional<double> {
            auto it = result.attributes.find(name);
            if (it == result.attributes.end()) return std::nullopt;
            double value = 0;
            const std::string &text = it->second;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
            return value;
        };
        auto text = [&](const char *name) {
            auto it = result.attributes.find(name);
            return it == result.attributes.end() ? std::string() : it->second;
        };
        result.measuredHeight = number("bldg:measuredheight");
        if (std::optional<double> storeys = number("bldg:storeysaboveground");
            storeys && *storeys >= 0 && *storeys < 1000 && *storeys == std::floor(*storeys))
            result.storeysAboveGround = int(*storeys);
        result.roofType = text("bldg:rooftype");
        result.function = text("bldg:function");
    }

    // The building's polygons at its LoD: those of thematic surfaces (and the geometries that
    // say their kind) when `solids` is false, the rest when it is true. BuildingParts count
    // as the building; other children (installations, openings) are not read.
    void readSurfaces(const CityObject &object, CityGmlBuilding &building, bool solids) {
        std::optional<SurfaceKind> objectKind = kindOfObject(object.getType());
        for (unsigned i = 0; i < object.getGeometriesCount(); ++i)
            readGeometry(object.getGeometry(i), objectKind, building, solids);
        for (unsigned i = 0; i < object.getChildCityObjectsCount(); ++i) {
            const CityObject &child = object.getChildCityObject(i);
            ObjectType type = child.getType();
            if (type == ObjectType::COT_BuildingPart) {
                if (!solids) ++building.parts;
                readSurfaces(child, building, solids);
            } else if (kindOfObject(type)) {
                readSurfaces(child, building, solids);
            }
        }
    }

    void readGeometry(const citygml::Geometry &geometry, std::optional<SurfaceKind> kind, CityGmlBuilding &building,
                      bool solids) {
        if (!kind) kind = kindOfGeometry(geometry.getType());
        if (geometry.getLOD() == building.lod && kind.has_value() != solids) {
            for (unsigned i = 0; i < geometry.getPolygonsCount(); ++i) {
                std::shared_ptr<const citygml::Polygon> polygon = geometry.getPolygon(i);
                if (!seen_.insert(polygon.get()).second) continue;
                if (!polygon->getId().empty() && !seenIds_.insert(polygon->getId()).second) {
                    ++model_.skippedPolygons;
                    warn(fmt::format("building {}: a second polygon of gml:id {} is left out (gml:ids are unique)",
                                     building.id, polygon->getId()));
                    continue;
                }
                readPolygon(*polygon, kind, building);
            }
        }
        for (unsigned i = 0; i < geometry.getGeometriesCount(); ++i)
            readGeometry(geometry.getGeometry(i), kind, building, solids);
    }

    void readPolygon(const citygml::Polygon &polygon, std::optional<SurfaceKind> kind, CityGmlBuilding &building) {
        CityGmlPolygon result;
        result.id = polygon.getId();
        size_t points = 0;
        if (polygon.exteriorRing()) result.rings.push_back(ringPoints(*polygon.exteriorRing()));
        for (const auto &hole : polygon.interiorRings()) result.rings.push_back(ringPoints(*hole));
        for (const auto &ring : result.rings) points += ring.size();
        if (points > kMaxCityGmlPolygonPoints)
            throw InputError({file_, 0, 0},
                             fmt::format("polygon {} of building {} has {} points, more than the {} "
                                         "veduta reads in one CityGML polygon",
                                         result.id, building.id, points, kMaxCityGmlPolygonPoints));
        Vec3d normal;
        if (auto why = triangulate(result, normal)) {
            ++model_.skippedPolygons;
            warn(fmt::format("building {}: polygon {} {}; it is left out", building.id, result.id, *why));
            return;
        }
        result.kind = kind ? *kind : kindByNormal(normal);
        readAppearance(polygon, building, result);
        building.polygons.push_back(std::move(result));
    }

    // The appearance of the first theme that gives the polygon one: its texture, else its
    // material's colour. A texture whose coordinates do not fit the rings is left out with
    // a warning, and the theme's material (or the next theme) is taken instead.
    void readAppearance(const citygml::Polygon &polygon, const CityGmlBuilding &building, CityGmlPolygon &result) {
        for (const std::string &theme : themes_) {
            if (polygon.getTextureFor(theme) && readTexture(polygon, theme, building, result)) return;
            if (std::shared_ptr<const citygml::Material> material = polygon.getMaterialFor(theme)) {
                TVec3f d = material->getDiffuse();
                if (std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z))
                    result.diffuse =
                        Vec3f{std::clamp(d.x, 0.0f, 1.0f), std::clamp(d.y, 0.0f, 1.0f), std::clamp(d.z, 0.0f, 1.0f)};
                return;
            }
        }
    }

    bool readTexture(const citygml::Polygon &polygon, const std::string &theme, const CityGmlBuilding &building,
                     CityGmlPolygon &result) {
        bool front = polygon.getTextureFor(theme, true) != nullptr;
        std::shared_ptr<const citygml::Texture> texture = polygon.getTextureFor(theme, front);
        std::shared_ptr<const citygml::TextureTargetDefinition> target =
            polygon.getTextureTargetDefinitionForTheme(theme, front);
        auto refuse = [&](const std::string &why) {
            ++model_.untexturedPolygons;
            warn(fmt::format("building {}: polygon {} {}; it is drawn without its texture", building.id, result.id,
                             why));
            return false;
        };
        if (!texture || !target) return refuse("has a texture but no texture target");
        if (texture->getUrl().empty()) return refuse(fmt::format("has texture {} with no imageURI", texture->getId()));
        std::vector<std::shared_ptr<const citygml::LinearRing>> rings;
        if (polygon.exteriorRing()) rings.push_back(polygon.exteriorRing());
        rings.insert(rings.end(), polygon.interiorRings().begin(), polygon.interiorRings().end());
        std::vector<Vec2f> uvs;
        for (const auto &ring : rings) {
            std::shared_ptr<const citygml::TextureCoordinates> coords =
                ring->getId().empty() ? nullptr : target->getTextureCoordinatesForID(ring->getId());
            if (!coords) return refuse(fmt::format("has no texture coordinates for ring '{}'", ring->getId()));
            const std::vector<TVec2f> &uv = coords->getCoords();
            const std::vector<TVec3d> &vertices = ring->getVertices();
            if (uv.size() != vertices.size())
                return refuse(fmt::format("has {} texture coordinates for the {} points of ring {}", uv.size(),
                                          vertices.size(), ring->getId()));
            for (size_t i : distinctPoints(vertices)) {
                if (!std::isfinite(uv[i].x) || !std::isfinite(uv[i].y))
                    return refuse(fmt::format("has a texture coordinate of ring {} that is no number", ring->getId()));
                uvs.push_back({uv[i].x, uv[i].y});
            }
        }
        result.texture = texturePath(folder_, texture->getUrl());
        result.uvs = std::move(uvs);
        return true;
    }

    // Triangles of the polygon in the plane of its outline, whose unit normal goes to `normal`;
    // why not, when it has none.
    static std::optional<std::string> triangulate(CityGmlPolygon &polygon, Vec3d &normal) {
        if (polygon.rings.empty() || polygon.rings.front().size() < 3) return "has no outline of three points";
        for (const auto &ring : polygon.rings)
            for (const CrsCoordinate &p : ring)
                if (!isFinite(p)) return "has a point that is no number";
        Vec3d n = newellNormal(polygon.rings.front());
        double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(length > 0)) return "has no area";
        n = {n.x / length, n.y / length, n.z / length};
        normal = n;
        // A right-handed frame (u, v, n) in the plane, so the outline runs counter-clockwise in (u, v).
        Vec3d helper = std::abs(n.z) < 0.9 ? Vec3d{0, 0, 1} : Vec3d{1, 0, 0};
        Vec3d u{helper.y * n.z - helper.z * n.y, helper.z * n.x - helper.x * n.z, helper.x * n.y - helper.y * n.x};
        double ul = std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
        u = {u.x / ul, u.y / ul, u.z / ul};
        Vec3d v{n.y * u.z - n.z * u.y, n.z * u.x - n.x * u.z, n.x * u.y - n.y * u.x};
        const CrsCoordinate &o = polygon.rings.front().front();
        std::vector<std::vector<Vec2f>> flat;
        for (const auto &ring : polygon.rings) {
            std::vector<Vec2f> &out = flat.emplace_back();
            for (const CrsCoordinate &p : ring) {
                double dx = p.x - o.x, dy = p.y - o.y, dz = p.z - o.z;
                out.push_back({float(dx * u.x + dy * u.y + dz * u.z), float(dx * v.x + dy * v.y + dz * v.z)});
            }
            if (out.size() < 3 || !isSimplePolygon(out)) return "crosses or touches itself, or has a ring of no area";
        }
        try {
            polygon.triangles = triangulatePolygonWithHoles(flat);
        } catch (const std::exception &) {  // CGAL: holes that cross the outline or each other
            return "has rings that cross each other";
        }
        if (polygon.triangles.empty()) return "gives no triangle";
        return std::nullopt;
    }

    std::string file_;
    std::filesystem::path folder_;  // where the file's texture images are found
    const CityGmlOptions &options_;
    std::vector<std::string> themes_;  // the appearance themes, in the file's order
    CityGmlModel &model_;
    // The polygons of the building read so far: a solid names its thematic surfaces' polygons
    // through xlink:href, which libcitygml resolves to the same object. A file that gives two
    // polygons one gml:id is broken; the second is left out with a warning.
    std::unordered_set<const citygml::Polygon *> seen_;
    std::unordered_set<std::string> seenIds_;
};

// libcitygml keeps only the last MiB of a longer text (Xerces hands it over in pieces): a
// posList of more than about 20,000 points would lose its first ones without a word. No real
// CityGML text comes near this, so a file with one is refused.
constexpr size_t kMaxTextRun = 1'000'000;

void checkTextRuns(const std::filesystem::path &file) {
    std::ifstream in(file, std::ios::binary);
    std::vector<char> block(size_t(1) << 20);
    FileLoc at{file.string(), 1, 1}, start = at;
    size_t run = 0;
    while (in.read(block.data(), std::streamsize(block.size())) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            char c = block[size_t(i)];
            if (c == '<' || c == '>') {
                run = 0;
            } else if (run++ == 0) {
                start = at;
            } else if (run > kMaxTextRun) {
                throw InputError(start,
                                 fmt::format("a text of more than {} characters starts here (a posList of "
                                             "some 20,000 points or more); libcitygml would read only its "
                                             "end, so veduta does not read the file",
                                             kMaxTextRun));
            }
            if (c == '\n') {
                ++at.line;
                at.column = 1;
            } else {
                ++at.column;
            }
        }
    }
}

std::shared_ptr<const citygml::CityModel> parse(const std::filesystem::path &file,
                                                std::shared_ptr<citygml::CityGMLLogger> logger) {
    citygml::ParserParams params;
    params.tesselate = false;    // veduta triangulates, after checking each polygon's size
    params.keepVertices = true;  // so that the rings keep their points
    try {
        return citygml::load(file.string(), params, logger);
    } catch (const xercesc::SAXParseException &e) {
        throw InputError({file.string(), int(e.getLineNumber()), int(e.getColumnNumber())},
                         "the XML parser stops here: " + transcode(e.getMessage()));
    } catch (const xercesc::XMLException &e) {
        throw InputError({file.string(), 0, 0}, "the XML parser stops: " + transcode(e.getMessage()));
    } catch (const std::exception &e) {
        throw InputError({file.string(), 0, 0}, std::string("libcitygml cannot read the file: ") + e.what());
    }
}

}  // namespace

const char *surfaceKindName(SurfaceKind kind) {
    switch (kind) {
    case SurfaceKind::Wall: return "wall";
    case SurfaceKind::Roof: return "roof";
    case SurfaceKind::Ground: return "ground";
    case SurfaceKind::Closure: return "closure";
    case SurfaceKind::Other: return "other";
    }
    return "other";
}

int gmlSrsEpsg(std::string_view srsName) {
    if (srsName.starts_with("urn:adv:crs:")) return advCrsEpsg(srsName);
    // A compound CRS names its horizontal part first.
    size_t at = srsName.find("EPSG");
    if (at == std::string_view::npos) at = srsName.find("epsg");
    if (at == std::string_view::npos) return 0;
    std::string_view rest = srsName.substr(at + 4);
    size_t end = rest.find(',');
    if (end != std::string_view::npos) rest = rest.substr(0, end);
    // The code is the last number: "::25832", ":6.12:25832", "/0/25832", ":25832".
    size_t digits = rest.find_last_not_of("0123456789");
    std::string_view code = digits == std::string_view::npos ? rest : rest.substr(digits + 1);
    if (code.empty() || (digits != std::string_view::npos && rest[digits] != ':' && rest[digits] != '/')) return 0;
    int epsg = 0;
    auto [ptr, error] = std::from_chars(code.data(), code.data() + code.size(), epsg);
    return error == std::errc() ? epsg : 0;
}

CityGmlModel readCityGml(const std::filesystem::path &file, const CityGmlOptions &options) {
    checkInputFile(file);
    refuseDocumentType(file, "libcitygml");
    checkTextRuns(file);
    CityGmlModel model;
    auto logger = std::make_shared<WarningLogger>(file.string(), model.warnings);
    std::shared_ptr<const citygml::CityModel> city = parse(file, logger);
    if (!city) throw InputError({file.string(), 0, 0}, "libcitygml finds no CityGML model in the file");

    const citygml::Envelope &envelope = city->getEnvelope();
    model.srsName = !city->getSRSName().empty() ? city->getSRSName() : envelope.srsName();
    model.epsg = gmlSrsEpsg(model.srsName);
    if (envelope.validBounds()) {
        const TVec3d &low = envelope.getLowerBound(), &high = envelope.getUpperBound();
        model.envelopeLow = CrsCoordinate{low.x, low.y, low.z};
        model.envelopeHigh = CrsCoordinate{high.x, high.y, high.z};
    }
    Reader reader(file, options, city->themes(), model);
    for (const CityObject *object : city->getRootCityObjects()) {
        if (object->getType() == ObjectType::COT_Building) reader.readBuilding(*object);
        else ++model.otherObjects;
    }
    return model;
}

}  // namespace veduta
