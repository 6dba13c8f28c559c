#include "geo/atkis.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>

namespace veduta {

namespace {

struct TypeEntry {
    int code;
    std::string_view name;
};

// Rilling 2006, §3.2 (tables 2–5 of the thesis, the duplicate 3203 read as 3203/3204) and the
// settlement, garden and water codes it names from ATKIS-OK 3.2 (docs/atkis.md).
constexpr std::array kTypes{
    TypeEntry{1000, "Präsentation"},
    TypeEntry{2000, "Siedlung"},
    TypeEntry{2101, "Ortslage"},
    TypeEntry{2111, "Wohnbaufläche"},
    TypeEntry{2112, "Industrie- und Gewerbefläche"},
    TypeEntry{2113, "Fläche gemischter Nutzung"},
    TypeEntry{2114, "Fläche besonderer funktionaler Prägung"},
    TypeEntry{2227, "Grünanlage"},
    TypeEntry{3000, "Verkehr"},
    TypeEntry{3100, "Straßenverkehr"},
    TypeEntry{3101, "Straße"},
    TypeEntry{3102, "Weg"},
    TypeEntry{3200, "Schienenverkehr"},
    TypeEntry{3201, "Schienenbahn"},
    TypeEntry{3202, "Seilbahn, Schwebebahn"},
    TypeEntry{3203, "Bahnkörper"},
    TypeEntry{3204, "Bahnstrecke"},
    TypeEntry{3300, "Flugverkehr"},
    TypeEntry{3400, "Schiffsverkehr"},
    TypeEntry{3500, "Anlagen und Bauwerke für Verkehr, Transport und Kommunikation"},
    TypeEntry{3501, "Bahnhofsanlage"},
    TypeEntry{4000, "Vegetation"},
    TypeEntry{4101, "Ackerland"},
    TypeEntry{4102, "Grünland"},
    TypeEntry{4103, "Gartenland"},
    TypeEntry{4104, "Heide"},
    TypeEntry{4105, "Moor, Moos"},
    TypeEntry{4106, "Sumpf, Ried"},
    TypeEntry{4107, "Wald, Forst"},
    TypeEntry{4108, "Gehölz"},
    TypeEntry{4109, "Sonderkultur"},
    TypeEntry{4201, "Baum"},
    TypeEntry{4202, "Baumreihe"},
    TypeEntry{4203, "Hecke"},
    TypeEntry{5000, "Gewässer"},
    TypeEntry{5101, "Strom, Fluss, Bach"},
    TypeEntry{5112, "Binnensee, Stausee, Teich"},
    TypeEntry{6000, "Relief"},
    TypeEntry{7000, "Gebiete"},
};

std::string_view withoutBlanks(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return text;
}

// A number written whole, with optional blanks round it ("0065", " 6.5 "), or nothing.
template <typename Number>
std::optional<Number> number(std::string_view text) {
    text = withoutBlanks(text);
    Number value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// A width attribute in decimetres (EDBS and ATKIS Shape exports: BRF, BRV) or metres (NAS:
// breiteDerFahrbahn, breiteDesVerkehrsweges), when given and positive.
// Metres; a wider width attribute ("inf", a unit mistake) is unreadable and the class default holds.
constexpr double kWidestRibbon = 200;

std::optional<double> widthAttribute(const AtkisObject &object, const std::string &decimetres,
                                     const std::string &inMetres) {
    if (auto text = attribute(object, decimetres))
        if (auto value = number<long>(*text); value && *value > 0 && *value <= 10 * kWidestRibbon)
            return double(*value) / 10.0;
    if (auto text = attribute(object, inMetres))
        if (auto value = number<double>(*text); value && *value > 0 && *value <= kWidestRibbon) return *value;
    return std::nullopt;
}

}  // namespace

std::optional<std::string_view> attribute(const AtkisObject &object, const std::string &name) {
    auto it = object.attributes.find(name);
    if (it == object.attributes.end()) return std::nullopt;
    return it->second;
}

std::optional<long> attributeNumber(const AtkisObject &object, const std::string &name) {
    std::optional<std::string_view> text = attribute(object, name);
    return text ? number<long>(*text) : std::nullopt;
}

int trackCount(const AtkisObject &object) {
    for (const std::string &name : {std::string("GLS"), std::string("ANZAHLDERSTRECKENGLEISE")}) {
        std::optional<long> value = attributeNumber(object, name);
        if (!value || *value <= 0) continue;
        long tracks = *value >= 1000 ? *value / 1000 : *value;
        return int(std::clamp(tracks, 1L, 8L));
    }
    return 1;
}

std::string_view atkisTypeName(int type) {
    auto it = std::find_if(kTypes.begin(), kTypes.end(), [&](const TypeEntry &e) { return e.code == type; });
    return it == kTypes.end() ? std::string_view() : it->name;
}

LandClass landClass(const AtkisObject &object) {
    // ALK objects have no ATKIS Objektart (type 0): their Folie says what they are. The two the
    // EDBS description of LV Sachsen names: Folie 001 Flurstücke, Folie 011 Gebäude.
    if (object.type == 0 && object.typeName.starts_with("ALK ")) {
        auto folie = attribute(object, "FOLIE");
        if (folie == "011") return LandClass::Building;
        if (folie == "001") return LandClass::Parcel;
        return LandClass::Other;
    }
    // ALKIS (AAA) building footprints: Objektart 31001 AX_Gebaeude, in NAS by its class name.
    if (object.type == 31001 || object.typeName == "AX_Gebaeude") return LandClass::Building;
    switch (object.type) {
    case 3101: return LandClass::Road;
    case 3102: return LandClass::Path;
    case 3201:
    case 3203:
    case 3204: return LandClass::Rail;
    case 2101:
    case 2111:
    case 2112:
    case 2113:
    case 2114: return LandClass::Settlement;
    case 2227:
    case 4103: return LandClass::Park;
    case 4101:
    case 4109: return LandClass::Farmland;
    case 4102:
    case 4104:
    case 4105:
    case 4106: return LandClass::Grassland;
    case 4107: return LandClass::Forest;
    case 4108: return LandClass::Shrubs;
    case 5101: return LandClass::River;
    case 5112: return LandClass::Water;
    case 4201:
    case 4202: return LandClass::TreeRow;
    case 4203: return LandClass::Hedge;
    default: return LandClass::Other;
    }
}

std::string_view landClassName(LandClass c) {
    switch (c) {
    case LandClass::Other: return "other";
    case LandClass::Road: return "road";
    case LandClass::Path: return "path";
    case LandClass::Rail: return "rail";
    case LandClass::Settlement: return "settlement";
    case LandClass::Park: return "park";
    case LandClass::Farmland: return "farmland";
    case LandClass::Grassland: return "grassland";
    case LandClass::Forest: return "forest";
    case LandClass::Shrubs: return "shrubs";
    case LandClass::Water: return "water";
    case LandClass::River: return "river";
    case LandClass::TreeRow: return "tree_row";
    case LandClass::Hedge: return "hedge";
    case LandClass::CityStreet: return "city_street";
    case LandClass::Building: return "building";
    case LandClass::Parcel: return "parcel";
    }
    return "other";
}

TreeKind treeKind(const AtkisObject &object) {
    // ATKIS-OK VEG: 1000 Laubholz, 2000 Nadelholz, 3000 Laub- und Nadelholz. AAA
    // vegetationsmerkmal (NAS): 1100 Laubholz, 1200 Nadelholz, 1300 and its 13x0 variants mixed.
    std::optional<long> veg = attributeNumber(object, "VEG");
    if (veg == 1000) return TreeKind::Broadleaf;
    if (veg == 2000) return TreeKind::Conifer;
    std::optional<long> feature = attributeNumber(object, "VEGETATIONSMERKMAL");
    if (feature == 1100) return TreeKind::Broadleaf;
    if (feature == 1200) return TreeKind::Conifer;
    return TreeKind::Mixed;
}

double ribbonWidth(const AtkisObject &object) {
    if (auto width = widthAttribute(object, "BRF", "BREITEDERFAHRBAHN")) return *width;
    if (auto width = widthAttribute(object, "BRV", "BREITEDESVERKEHRSWEGES")) return *width;
    switch (landClass(object)) {
    case LandClass::Road: return 5.5;
    case LandClass::Path: return 2.5;
    case LandClass::Rail: return 4.5 * trackCount(object);
    default: return 0.0;
    }
}

}  // namespace veduta
