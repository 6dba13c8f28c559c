// EDBS, the "Einheitliche Datenbankschnittstelle" of ALK and ATKIS (Rilling 2006, §3.4 and LV
// Sachsen's "Beschreibung der EDBS-Schnittstelle", 2006): one record per line, records split
// over continuation records joined, Grundriss (ULOBNN) and Attribut (ULTANN) data read into
// plain structures (EdbsFile). toAtkis then assembles objects: the vector elements of each
// area object part chained into outlines, those of each line object part into polylines.
// docs/atkis.md describes what is supported and the layouts used.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geo/atkis.h"
#include "geodesy/map_point.h"

namespace veduta {

// Where something was read: the record number from the record's header and the line it
// starts on (continued records: the line of the A record).
struct EdbsSource {
    int record = 0;
    int line = 0;
};

// "Funktion der Linie": which objects a vector element belongs to, right and left of it.
struct EdbsLineFunction {
    std::string folie;                // 3 characters
    std::string type;                 // Objektart as written, 4 characters ("0233", "N231" for a line object)
    std::string right, left;          // Objektnummer, 7 characters, empty when blank
    std::string rightPart, leftPart;  // Objektteilnummer, blanks trimmed
};

// A vector element: "Grundrisskennzeichen" (start), Lageparameter, "Endpunkt der Linie".
struct EdbsLine {
    MapPoint start, end;
    std::vector<MapPoint> between;  // Lageparameter, in order from start to end
    int geometryKind = 0;           // Art der Geometrie: 11 straight line, 15 vector
    std::vector<EdbsLineFunction> functions;
    EdbsSource source;
};

// "Besondere Information" of an object: names, symbols and labels with their positions.
struct EdbsInfo {
    std::string kind;     // Art der Information, 2 characters
    std::string mapType;  // Kartentyp
    std::string type;     // Objektart bzw. Signaturnummer, 6 characters
    std::string text;     // 33 characters, trailing blanks trimmed
    std::string geometryKind;
    std::string part;              // Objektteilnummer
    std::vector<MapPoint> points;  // Geometrieangaben that are points ("TT" angles left out)
};

// "Funktion des Objekts" with its Grundrisskennzeichen as the reference point.
struct EdbsObject {
    std::string id;       // Objektnummer, 7 characters
    std::string type;     // Objektart, 4 digits
    char geometry = 'F';  // Objekttyp: P, L or F
    std::string folie, actuality, modelType, date, change;
    MapPoint reference;
    std::vector<EdbsInfo> infos;
    EdbsSource source;
};

// One "Attributkennzeichen" of ULTANN data with its attributes ("BRF" → "0065").
struct EdbsAttributes {
    std::string id, part;  // Objektnummer; Objektteilnummer, empty when blank
    std::vector<std::pair<std::string, std::string>> values;
    EdbsSource source;
};

// Coordinates come as 20 characters in one of two forms (docs/atkis.md): ALK's 1-km
// Nummerierungsbezirk with millimetres, ATKIS's 10-km one (blanks between) with centimetres.
enum class EdbsCoordinates { Alk, Atkis };

struct EdbsFile {
    std::string path;
    int records = 0;                                    // physical records (lines)
    std::map<std::string, int> recordCounts;            // "BSPE ULOBNN" → physical records
    bool hasEnd = false;                                // an AEND record closed the file
    std::optional<std::pair<MapPoint, MapPoint>> area;  // BKRT: lower left, upper right
    std::vector<std::string> texts;                     // BINF/OTEX ULOTEX texts
    std::vector<EdbsObject> objects;
    std::vector<EdbsLine> lines;
    std::vector<EdbsAttributes> attributes;
    int alkPoints = 0, atkisPoints = 0;  // coordinates read in either form
    int curvedElements = 0;              // elements whose Art der Geometrie is not 11 or 15

    // ATKIS when any coordinate came in the ATKIS form, else ALK.
    EdbsCoordinates coordinates() const { return atkisPoints > 0 ? EdbsCoordinates::Atkis : EdbsCoordinates::Alk; }
};

// Reads and checks every record; throws InputError (file:line:column: record N: what is wrong).
EdbsFile readEdbs(const std::filesystem::path &path);
// The same from text in memory; `name` stands for the file in messages.
EdbsFile parseEdbs(std::string_view text, const std::string &name);

// A point from its 20 characters, or nothing when they are in neither form.
std::optional<MapPoint> decodeEdbsPoint(std::string_view text, EdbsCoordinates *form = nullptr);

// What to do with an area or line object whose elements do not make it whole: BSPE output cut
// to a search rectangle, or a file cut short, leaves such objects (docs/atkis.md).
enum class IncompleteObjects { Error, Skip };

struct EdbsConversion {
    AtkisData atkis;
    std::vector<std::string> skipped;   // "record 12: area object A0000YU (…): outline does not close …"
    std::vector<std::string> warnings;  // holes dropped, degenerate outlines, unknown references
};

// Objects with their geometry and attributes. With IncompleteObjects::Error an area whose
// outline does not close (or an object without elements) throws InputError naming the object.
EdbsConversion toAtkis(const EdbsFile &file, IncompleteObjects incomplete = IncompleteObjects::Error);

}  // namespace veduta
