#include "geo/road_style.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace veduta {

namespace {

// RMS line widths: Schmalstrich and Breitstrich, wider on motorways; the Haltlinie.
constexpr double kNarrow = 0.12, kNarrowMotorway = 0.15;
constexpr double kWideMotorway = 0.30;
constexpr double kStopLine = 0.50;
constexpr double kEdgeClearance = 0.05;       // from the carriageway's edge to its edge line
constexpr double kMotorwayMedian = 1.5;       // half the median; ATKIS puts a motorway's axis in it
constexpr double kNarrowestMarkedRoad = 5.5;  // RMS: centre lines on carriageways this wide and wider

RoadRank rankOf(const AtkisObject &object) {
    switch (landClass(object)) {
    case LandClass::Path: return RoadRank::Path;
    case LandClass::Rail: return RoadRank::Rail;
    default: break;
    }
    // Widmung (WDM in EDBS and Shape, widmung in NAS).
    std::optional<long> dedication = attributeNumber(object, "WDM");
    if (!dedication) dedication = attributeNumber(object, "WIDMUNG");
    switch (dedication.value_or(0)) {
    case 1301: return RoadRank::Motorway;
    case 1303: return RoadRank::Federal;
    case 1305: return RoadRank::State;
    case 1306: return RoadRank::District;
    case 1307: return RoadRank::Municipal;
    default: return RoadRank::Unclassified;
    }
}

std::string lowerCase(std::string_view text) {
    std::string lower(text);
    for (char &c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    return lower;
}

// The surface named in words (BEF or OFM as text, OSM's surface); the class's usual one
// otherwise. Codes are not read: the code lists differ between ATKIS-OK versions.
Pavement pavementOf(const AtkisObject &object, RoadRank rank) {
    if (rank == RoadRank::Rail) return Pavement::Ballast;
    struct Word {
        std::string_view word;
        Pavement pavement;
    };
    constexpr std::array kWords{
        Word{"pflaster", Pavement::Cobbles}, Word{"sett", Pavement::Cobbles},     Word{"cobble", Pavement::Cobbles},
        Word{"paving", Pavement::Cobbles},   Word{"beton", Pavement::Concrete},   Word{"concrete", Pavement::Concrete},
        Word{"asphalt", Pavement::Asphalt},  Word{"bitum", Pavement::Asphalt},    Word{"schotter", Pavement::Gravel},
        Word{"kies", Pavement::Gravel},      Word{"gravel", Pavement::Gravel},    Word{"unbefestigt", Pavement::Gravel},
        Word{"unpaved", Pavement::Gravel},   Word{"compacted", Pavement::Gravel},
    };
    for (const char *name : {"OFM", "OBERFLAECHENMATERIAL", "BEF", "BEFESTIGUNG", "SURFACE"}) {
        std::optional<std::string_view> text = attribute(object, name);
        if (!text) continue;
        std::string lower = lowerCase(*text);
        for (const Word &w : kWords) {
            if (lower.find(w.word) != std::string::npos) return w.pavement;
        }
    }
    return rank == RoadRank::Path ? Pavement::Gravel : Pavement::Asphalt;
}

// FSZ (anzahlDerFahrstreifen in NAS, lanes in OSM) when it fits the width at 2.25 m or more a
// lane; otherwise what the width holds. The digest warns that FSZ is sometimes wrong.
int lanesOf(const AtkisObject &object, RoadRank rank, double width) {
    for (const char *name : {"FSZ", "ANZAHLDERFAHRSTREIFEN", "LANES"}) {
        std::optional<long> lanes = attributeNumber(object, name);
        if (lanes && *lanes >= 1 && *lanes <= 8 && width / double(*lanes) >= 2.25) return int(*lanes);
    }
    if (rank == RoadRank::Path || rank == RoadRank::Rail) return 1;
    if (rank == RoadRank::Motorway) return 2 * std::clamp(int((width / 2 - kMotorwayMedian) / 3.5), 1, 4);
    return width >= 12 ? 4 : 2;
}

// Both sides' lines: the edge lines and the lane lines between the lanes of one direction,
// whose lanes fill [inner, half] left and right of the centre.
void addSideLines(RoadStyle &style, double inner, double half, int lanesEachWay, const MarkingLine &laneLine,
                  double edgeWidth) {
    double lane = (half - inner) / lanesEachWay;
    for (double side : {1.0, -1.0}) {
        if (edgeWidth > 0) style.lines.push_back({side * (half - kEdgeClearance - edgeWidth / 2), edgeWidth, 0, 0});
        for (int k = 1; k < lanesEachWay; ++k) {
            MarkingLine line = laneLine;
            line.offset = side * (inner + k * lane);
            style.lines.push_back(line);
        }
    }
}

void addLines(RoadStyle &style) {
    double half = style.width / 2;
    int lanesEachWay = std::max(1, style.lanes / 2);
    switch (style.rank) {
    case RoadRank::Path:
    case RoadRank::Rail: return;
    case RoadRank::Motorway: {
        MarkingLine laneLine{0, kNarrowMotorway, 6, 12};
        for (double side : {1.0, -1.0})
            style.lines.push_back({side * (kMotorwayMedian + kNarrowMotorway / 2), kNarrowMotorway, 0, 0});
        addSideLines(style, kMotorwayMedian, half, lanesEachWay, laneLine, kWideMotorway);
        return;
    }
    case RoadRank::Federal:
    case RoadRank::State:
    case RoadRank::District: {  // Leitlinien of the open road, and edge lines
        if (style.width < kNarrowestMarkedRoad) return;
        MarkingLine laneLine{0, kNarrow, 6, 12};
        style.lines.push_back(lanesEachWay > 1 ? MarkingLine{0, kNarrow, 0, 0} : laneLine);
        addSideLines(style, 0, half, lanesEachWay, laneLine, kNarrow);
        return;
    }
    case RoadRank::Municipal:
    case RoadRank::Unclassified: {  // Leitlinien of a town, no edge lines
        if (style.width < kNarrowestMarkedRoad || style.lanes < 2) return;
        MarkingLine laneLine{0, kNarrow, 3, 6};
        style.lines.push_back(lanesEachWay > 1 ? MarkingLine{0, kNarrow, 0, 0} : laneLine);
        addSideLines(style, 0, half, lanesEachWay, laneLine, 0);
        return;
    }
    }
}

}  // namespace

RoadStyle roadStyle(const AtkisObject &object) {
    RoadStyle style;
    style.rank = rankOf(object);
    style.width = ribbonWidth(object);
    style.pavement = pavementOf(object, style.rank);
    style.lanes = lanesOf(object, style.rank, style.width);
    if (style.rank == RoadRank::Rail) style.tracks = trackCount(object);
    addLines(style);
    bool stops = style.rank != RoadRank::Motorway && style.rank != RoadRank::Path && style.rank != RoadRank::Rail;
    style.stopLineWidth = stops && style.width >= kNarrowestMarkedRoad ? kStopLine : 0;
    return style;
}

std::string_view roadRankName(RoadRank rank) {
    switch (rank) {
    case RoadRank::Motorway: return "motorway";
    case RoadRank::Federal: return "federal";
    case RoadRank::State: return "state";
    case RoadRank::District: return "district";
    case RoadRank::Municipal: return "municipal";
    case RoadRank::Unclassified: return "unclassified";
    case RoadRank::Path: return "path";
    case RoadRank::Rail: return "rail";
    }
    return "unclassified";
}

std::string_view pavementName(Pavement pavement) {
    switch (pavement) {
    case Pavement::Asphalt: return "asphalt";
    case Pavement::Cobbles: return "cobbles";
    case Pavement::Concrete: return "concrete";
    case Pavement::Gravel: return "gravel";
    case Pavement::Ballast: return "ballast";
    }
    return "asphalt";
}

}  // namespace veduta
