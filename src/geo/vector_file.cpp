#include "geo/vector_file.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <optional>

#include <cpl_vsi.h>
#include <fmt/format.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include "core/error.h"
#include "core/input_file.h"
#include "io/gdal_guard.h"
#include "io/gdal_messages.h"

namespace veduta {

namespace {

struct ClassEntry {
    std::string_view name;
    int aaaCode;  // the class's 5-digit code in the AdV Objektartenkatalog (GeoInfoDok); 0: none
    int type;     // the ATKIS-OK 3.2 Objektart it succeeds
};

// AAA classes of the Basis-DLM and ALKIS mapped to the ATKIS-OK 3.2 Objektart they succeed:
// NAS names them, today's Shape deliveries give OBJART (the code) and OBJART_TXT (the name).
constexpr std::array kNasClasses{
    ClassEntry{"AX_Wohnbauflaeche", 41001, 2111},
    ClassEntry{"AX_IndustrieUndGewerbeflaeche", 41002, 2112},
    ClassEntry{"AX_FlaecheGemischterNutzung", 41006, 2113},
    ClassEntry{"AX_FlaecheBesondererFunktionalerPraegung", 41007, 2114},
    ClassEntry{"AX_SportFreizeitUndErholungsflaeche", 41008, 2227},
    ClassEntry{"AX_Ortslage", 0, 2101},
    ClassEntry{"AX_Strassenverkehr", 42001, 3101},
    ClassEntry{"AX_Strassenachse", 42003, 3101},
    ClassEntry{"AX_Fahrbahnachse", 42005, 3101},
    ClassEntry{"AX_Weg", 42006, 3102},
    ClassEntry{"AX_Fahrwegachse", 42008, 3102},
    ClassEntry{"AX_Wegachse", 0, 3102},
    ClassEntry{"AX_Bahnverkehr", 42010, 3201},
    ClassEntry{"AX_Bahnstrecke", 42014, 3201},
    ClassEntry{"AX_Landwirtschaft", 43001, 4101},
    ClassEntry{"AX_Gruenland", 0, 4102},
    ClassEntry{"AX_Wald", 43002, 4107},
    ClassEntry{"AX_Gehoelz", 43003, 4108},
    ClassEntry{"AX_Heide", 43004, 4104},
    ClassEntry{"AX_Moor", 43005, 4105},
    ClassEntry{"AX_Sumpf", 43006, 4106},
    ClassEntry{"AX_Fliessgewaesser", 44001, 5101},
    ClassEntry{"AX_Gewaesserachse", 44004, 5101},
    ClassEntry{"AX_StehendesGewaesser", 44006, 5112},
};

// AX_Landwirtschaft's Vegetationsmerkmal (VEG) 1020: Grünland, which ATKIS-OK kept apart.
constexpr std::string_view kGrasslandVegetation = "1020";

// AX_Landwirtschaft whose Vegetationsmerkmal (VEG in Shape deliveries, vegetationsmerkmal in
// NAS) says Grünland.
bool isGrassland(const std::map<std::string, std::string> &attributes) {
    for (const char *key : {"VEG", "VEGETATIONSMERKMAL"}) {
        auto it = attributes.find(key);
        if (it != attributes.end() && it->second == kGrasslandVegetation) return true;
    }
    return false;
}

// The ATKIS-OK Objektart of a 5-digit AAA code; 0 for a class the table does not hold.
int aaaCodeType(int code) {
    auto it = std::find_if(kNasClasses.begin(), kNasClasses.end(),
                           [&](const ClassEntry &e) { return e.aaaCode != 0 && e.aaaCode == code; });
    return it == kNasClasses.end() ? 0 : it->type;
}

std::string upper(std::string_view s) {
    std::string out(s);
    for (char &c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// NAS and GML readers write a .gfs schema file beside the file they read; reading a copy in
// GDAL's memory file system keeps them from writing into the user's folders.
class MemoryCopy {
  public:
    MemoryCopy(const std::filesystem::path &file) {
        static std::atomic<int> counter{0};
        folder_ = fmt::format("/vsimem/veduta_vector_{}", counter++);
        name_ = folder_ + "/" + file.filename().string();
        bytes_ = readInputFile(file);
        VSIFCloseL(VSIFileFromMemBuffer(name_.c_str(), reinterpret_cast<GByte *>(bytes_.data()),
                                        vsi_l_offset(bytes_.size()), FALSE));
    }
    ~MemoryCopy() { VSIRmdirRecursive(folder_.c_str()); }
    MemoryCopy(const MemoryCopy &) = delete;
    MemoryCopy &operator=(const MemoryCopy &) = delete;

    const std::string &name() const { return name_; }
    const std::string &bytes() const { return bytes_; }

  private:
    std::string folder_, name_, bytes_;
};

// NAS names its standard CRS in its header (koordinatenangaben, standard = true).
int nasStandardCrs(const std::string &text) {
    size_t standard = text.find("<standard>true</standard>");
    if (standard == std::string::npos) return 0;
    size_t urn = text.rfind("urn:adv:crs:", standard);
    if (urn == std::string::npos) return 0;
    size_t end = text.find_first_of("\"'<", urn);
    return advCrsEpsg(std::string_view(text).substr(urn, end == std::string::npos ? std::string::npos : end - urn));
}

int layerEpsg(OGRLayer &layer) {
    OGRSpatialReference *srs = layer.GetSpatialRef();
    if (!srs) return 0;
    OGRSpatialReference copy(*srs);
    copy.AutoIdentifyEPSG();
    const char *code = copy.GetAuthorityCode(nullptr);
    const char *authority = copy.GetAuthorityName(nullptr);
    if (code && authority && std::string_view(authority) == "EPSG") return std::atoi(code);
    return advCrsEpsg(srs->GetName() ? srs->GetName() : "");
}

MapLine points(const OGRSimpleCurve &curve) {
    MapLine out;
    for (int i = 0; i < curve.getNumPoints(); ++i) {
        MapPoint p{curve.getX(i), curve.getY(i)};
        if (out.empty() || !(out.back() == p)) out.push_back(p);
    }
    return out;
}

struct FeatureGeometry {
    std::vector<MapRing> areas;
    std::vector<MapLine> lines;
    std::vector<MapPoint> points;
    int holes = 0, degenerate = 0;
};

void collect(const OGRGeometry &g, FeatureGeometry &out) {
    switch (wkbFlatten(g.getGeometryType())) {
    case wkbPoint: out.points.push_back({g.toPoint()->getX(), g.toPoint()->getY()}); break;
    case wkbLineString: {
        MapLine line = points(*g.toLineString());
        if (line.size() >= 2) out.lines.push_back(std::move(line));
        else ++out.degenerate;
        break;
    }
    case wkbPolygon: {
        const OGRPolygon *polygon = g.toPolygon();
        if (!polygon->getExteriorRing()) break;
        MapRing ring = points(*polygon->getExteriorRing());
        if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
        if (ring.size() >= 3) out.areas.push_back(std::move(ring));
        else ++out.degenerate;
        out.holes += polygon->getNumInteriorRings();
        break;
    }
    case wkbMultiPoint:
    case wkbMultiLineString:
    case wkbMultiPolygon:
    case wkbGeometryCollection:
        for (const OGRGeometry *part : *g.toGeometryCollection()) collect(*part, out);
        break;
    default: ++out.degenerate; break;
    }
}

class VectorReader {
  public:
    VectorReader(const std::filesystem::path &path, std::vector<std::string> &warnings) :
        path_(path.string()), warnings_(warnings) {}

    AtkisData read(GDALDataset &dataset, int headerEpsg) {
        AtkisData data;
        data.epsg = headerEpsg;
        for (OGRLayer *layer : dataset.GetLayers()) {
            // AtkisData has one CRS: layers of a file that name two are refused, not mixed.
            int epsg = headerEpsg != 0 ? headerEpsg : layerEpsg(*layer);
            if (data.epsg != 0 && epsg != 0 && epsg != data.epsg)
                throw InputError(FileLoc{path_},
                                 fmt::format("layer {} is in EPSG:{}, an earlier layer in EPSG:{}; "
                                             "give the layers of one file one CRS",
                                             layer->GetName(), epsg, data.epsg));
            if (data.epsg == 0) data.epsg = epsg;
            layer->ResetReading();
            for (auto &feature : *layer) addFeature(*layer, *feature, data);
        }
        return data;
    }

  private:
    void addFeature(OGRLayer &layer, const OGRFeature &feature, AtkisData &data) {
        const OGRGeometry *geometry = feature.GetGeometryRef();
        if (!geometry || geometry->IsEmpty()) return;  // NAS relations and other tables
        std::unique_ptr<OGRGeometry> linear(geometry->hasCurveGeometry() ? geometry->getLinearGeometry() : nullptr);
        FeatureGeometry g;
        collect(linear ? *linear : *geometry, g);
        AtkisObject object;
        object.where = fmt::format("{}: layer {}, feature {}", path_, layer.GetName(), feature.GetFID());
        object.typeName = layer.GetName();
        object.type = nasClassType(layer.GetName());
        // No feature id: it is the feature's place in the file, which other features shift.
        std::optional<std::string> objart, objartText;
        for (int i = 0; i < feature.GetFieldCount(); ++i) {
            if (!feature.IsFieldSetAndNotNull(i)) continue;
            std::string name = upper(feature.GetFieldDefnRef(i)->GetNameRef());
            std::string value = feature.GetFieldAsString(i);
            if (name == "OBJART") {
                objart = value;
            } else if (name == "OBJART_TXT") {
                objartText = value;
            } else if (name == "GML_ID") {
                object.id = value;
            } else {
                object.attributes[name] = value;
            }
        }
        if (objart || objartText) {
            object.type = objectType(objart.value_or(""), objartText, object.where);
            object.typeName = objartText.value_or("");
        }
        if (object.type == 4101 && isGrassland(object.attributes)) object.type = 4102;
        auto objid = object.attributes.find("OBJID");  // ATKIS exports' Objektidentifikator
        if (object.id.empty() && objid != object.attributes.end()) object.id = objid->second;
        if (g.holes > 0)
            warnings_.push_back(fmt::format("{}: {} hole{} left out (ATKIS areas have none)", object.where, g.holes,
                                            g.holes == 1 ? "" : "s"));
        if (g.degenerate > 0)
            warnings_.push_back(fmt::format("{}: {} part{} without enough points or of another kind left out",
                                            object.where, g.degenerate, g.degenerate == 1 ? "" : "s"));
        object.geometry = !g.areas.empty() ? AtkisGeometry::Area
            : !g.lines.empty()             ? AtkisGeometry::Line
                                           : AtkisGeometry::Point;
        if (g.areas.empty() && g.lines.empty() && g.points.empty()) return;
        object.areas = std::move(g.areas);
        object.lines = std::move(g.lines);
        object.points = std::move(g.points);
        data.objects.push_back(std::move(object));
    }

    // OBJART as Shape exports write it, maybe with blanks round it: ATKIS-OK's 4-digit code,
    // or the 5-digit AAA code of today's Basis-DLM (with its name in OBJART_TXT), taken to the
    // ATKIS-OK Objektart it succeeds. An AAA class without one keeps its code: the landscape
    // reports it among the kinds it does not draw.
    int objectType(const std::string &value, const std::optional<std::string> &name, const std::string &where) {
        std::string code = value;
        code.erase(std::remove(code.begin(), code.end(), ' '), code.end());
        bool digits =
            !code.empty() && std::all_of(code.begin(), code.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (digits && code.size() == 4) return std::stoi(code);
        if (digits && code.size() == 5) {
            int aaa = std::stoi(code);
            if (int type = aaaCodeType(aaa)) return type;
            if (int type = name ? nasClassType(*name) : 0) return type;
            return aaa;
        }
        if (int type = name ? nasClassType(*name) : 0) return type;
        warnings_.push_back(
            fmt::format("{}: OBJART '{}' is not a 4-digit (ATKIS-OK) or 5-digit (AAA) Objektart", where, value));
        return 0;
    }

    std::string path_;
    std::vector<std::string> &warnings_;
};

}  // namespace

int nasClassType(std::string_view layerName) {
    auto it =
        std::find_if(kNasClasses.begin(), kNasClasses.end(), [&](const ClassEntry &e) { return e.name == layerName; });
    return it == kNasClasses.end() ? 0 : it->type;
}

int advCrsEpsg(std::string_view urn) {
    constexpr std::string_view prefix = "urn:adv:crs:";
    if (urn.substr(0, prefix.size()) == prefix) urn.remove_prefix(prefix.size());
    constexpr std::array<std::pair<std::string_view, int>, 6> known{{
        {"ETRS89_UTM32", 25832},
        {"ETRS89_UTM33", 25833},
        {"DE_DHDN_3GK2", 31466},
        {"DE_DHDN_3GK3", 31467},
        {"DE_DHDN_3GK4", 31468},
        {"DE_DHDN_3GK5", 31469},
    }};
    // "ETRS89_UTM32*DE_DHHN2016_NH" adds a height system; "DE_DHDN_3GK3_NW101" a state's realisation.
    for (const auto &[name, epsg] : known)
        if (urn.substr(0, name.size()) == name &&
            (urn.size() == name.size() || urn[name.size()] == '*' || urn[name.size()] == '_'))
            return epsg;
    return 0;
}

AtkisData readVectorFile(const std::filesystem::path &path, std::vector<std::string> &warnings) {
    FileLoc loc{path.string(), 0, 0};
    checkFileForGdal(path);
    registerGdalDrivers();
    GdalMessages messages;
    GDALDriverH driver = GDALIdentifyDriverEx(path.c_str(), GDAL_OF_VECTOR, nullptr, nullptr);
    std::string driverName = driver ? GDALGetDriverShortName(driver) : "";
    std::optional<MemoryCopy> copy;
    if (driverName == "NAS" || driverName == "GML") copy.emplace(path);
    // GDAL reads CityGML as GML, and none of its features has an Objektart: say what it is
    // rather than read nothing.
    if (driverName == "GML" &&
        std::string_view(copy->bytes()).substr(0, 1 << 20).find("www.opengis.net/citygml") != std::string_view::npos)
        throw InputError(loc,
                         "is CityGML (3D city models), not an ATKIS file: a scene reads it with <citygml "
                         "file=\"…\"/> (docs/citygml.md); an ATKIS layer is NAS, EDBS, a Shapefile or a "
                         "GeoPackage of the Basis-DLM");
    std::string openName = copy ? copy->name() : path.string();
    AtkisData data;
    {
        GdalDeadline deadline(path);
        GDALDatasetUniquePtr dataset(GDALDataset::Open(openName.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
        if (!dataset) {
            std::string detail = messages.failures.empty() ? "" : fmt::format(" ({})", messages.failures.front());
            throw InputError(loc, fmt::format("GDAL cannot read this as a vector file{}", detail));
        }
        // NAS says so when no schema came with the file; it reads on without one.
        std::erase(messages.failures, std::string("No schema information loaded"));
        for (const std::string &m : messages.failures)
            warnings.push_back(fmt::format("{}: GDAL: {}", loc.toString(), m));
        messages.failures.clear();
        int headerEpsg = driverName == "NAS" ? nasStandardCrs(copy->bytes()) : 0;
        data = VectorReader(path, warnings).read(*dataset, headerEpsg);
    }
    if (!messages.failures.empty()) throw InputError(loc, fmt::format("GDAL: {}", messages.failures.front()));
    for (const std::string &m : messages.warnings) warnings.push_back(fmt::format("{}: GDAL: {}", loc.toString(), m));
    return data;
}

}  // namespace veduta
