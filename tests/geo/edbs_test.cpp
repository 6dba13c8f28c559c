// The EDBS reader (src/geo/edbs.*, edbs_assembly.cpp, element_chaining.*): small EDBS texts
// written here, the ALK sample in ../shared/data when present, and corrupted copies.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "core/error.h"
#include "core/hash.h"
#include "geo/atkis.h"
#include "geo/edbs.h"
#include "geo/element_chaining.h"
#include "input_error.h"
#include "shared_data.h"

namespace veduta {
namespace {

// One record: the header with its length field, then the content.
std::string record(std::string_view op, int number, char continuation, std::string_view in, std::string_view content) {
    std::string body = fmt::format("{}{:06d}{} 0000{:<8}{}", op, number, continuation, in, content);
    return fmt::format("EDBS{:04d}0000{}", body.size(), body);
}

// A point in the ATKIS form (centimetres within a 10-km square) from metres.
std::string atkisPoint(double east, double north) {
    long e = std::lround(east * 100), n = std::lround(north * 100);
    return fmt::format("{:02d}{:02d}{:01d} {:01d} {:06d}{:06d}", e / 10'000'000, n / 10'000'000, (e / 1'000'000) % 10,
                       (n / 1'000'000) % 10, e % 1'000'000, n % 1'000'000);
}

struct Side {
    std::string id, part;
};

// ULOBNN content of one vector element from a to b (through `between`), bounding objects.
std::string element(MapPoint a, MapPoint b, const Side &right, const Side &left, std::string_view type = "4107",
                    const std::vector<MapPoint> &between = {}) {
    std::string content =
        fmt::format("00010001{}000010001{}1100010001001{}{:<7}{:<7}{:<3}{:<3}  0000", atkisPoint(a.easting, a.northing),
                    atkisPoint(b.easting, b.northing), type, right.id, left.id, right.part, left.part);
    content += fmt::format("{:04d}", between.size());
    for (const MapPoint &p : between) content += atkisPoint(p.easting, p.northing);
    return content + "0000";
}

// ULOBNN content of an object's function with its reference point.
std::string object(std::string_view id, std::string_view type, char geometry, MapPoint reference) {
    return fmt::format("00010001{}0000000010001001{}01{}{:<7}  060502 0000",
                       atkisPoint(reference.easting, reference.northing), type, geometry, id);
}

// ULTANN content: one Attributkennzeichen with its attributes.
std::string attributes(std::string_view id, std::string_view part,
                       const std::vector<std::pair<std::string, std::string>> &values) {
    std::string content = fmt::format("00010001{:<7}{:<3}001{:04d}", id, part, values.size());
    for (const auto &[name, value] : values) content += fmt::format("{:<4}{:<7}", name, value);
    return content;
}

// A file of records numbered from 1, with an Auftragskennsatz first and AEND last.
std::string file(const std::vector<std::pair<std::string, std::string>> &contents) {
    std::string text = record("AKND", 0, ' ', "ULQA0000", "0001test") + "\n";
    int number = 1;
    for (const auto &[in, content] : contents) text += record("BSPE", number++, ' ', in, content) + "\n";
    return text + record("AEND", 0, ' ', "", "") + "\n";
}

const MapPoint kA{3397000.00, 5579000.00}, kB{3397100.00, 5579000.00}, kC{3397100.00, 5579100.00},
    kD{3397000.00, 5579100.00}, kMid{3397050.00, 5579000.00};

// A square forest A B C D (anticlockwise), its elements shuffled and some reversed, the
// forest on the left of A→B and on the right of the reversed ones.
std::string forestFile(std::vector<std::pair<std::string, std::string>> extra = {}) {
    std::vector<std::pair<std::string, std::string>> contents{
        {"ULOBNN", element(kC, kB, {"W000001", ""}, {})},
        {"ULOBNN", object("W000001", "4107", 'F', {3397050, 5579050})},
        {"ULOBNN", element(kD, kA, {}, {"W000001", ""})},
        {"ULOBNN", element(kA, kB, {}, {"W000001", ""}, "4107", {kMid})},
        {"ULOBNN", element(kD, kC, {"W000001", ""}, {})},
        {"ULTANN", attributes("W000001", "", {{"VEG", "2000"}})},
    };
    contents.insert(contents.end(), extra.begin(), extra.end());
    return file(contents);
}

std::string errorOf(const std::string &text) {
    return test::inputErrorOf([&] { toAtkis(parseEdbs(text, "t.edbs")); });
}

TEST(Edbs, DecodesBothCoordinateForms) {
    EdbsCoordinates form = EdbsCoordinates::Atkis;
    std::optional<MapPoint> alk = decodeEdbsPoint("33559779597000489000", &form);
    ASSERT_TRUE(alk);
    EXPECT_EQ(alk->easting, 3397597.000);
    EXPECT_EQ(alk->northing, 5579489.000);
    EXPECT_EQ(form, EdbsCoordinates::Alk);
    std::optional<MapPoint> atkis = decodeEdbsPoint(atkisPoint(3397597.25, 5579489.5), &form);
    ASSERT_TRUE(atkis);
    EXPECT_EQ(atkis->easting, 3397597.25);
    EXPECT_EQ(atkis->northing, 5579489.5);
    EXPECT_EQ(form, EdbsCoordinates::Atkis);
    EXPECT_FALSE(decodeEdbsPoint("3355977959700048900X"));
    EXPECT_FALSE(decodeEdbsPoint("3355977959700048900"));
}

TEST(Edbs, ReadsRecordsAndAssemblesAnArea) {
    EdbsFile f = parseEdbs(forestFile(), "forest.edbs");
    EXPECT_EQ(f.records, 8);
    EXPECT_EQ(f.recordCounts.at("BSPE ULOBNN"), 5);
    EXPECT_EQ(f.recordCounts.at("BSPE ULTANN"), 1);
    EXPECT_TRUE(f.hasEnd);
    EXPECT_EQ(f.coordinates(), EdbsCoordinates::Atkis);
    ASSERT_EQ(f.lines.size(), 4u);
    EXPECT_EQ(f.lines[2].between, std::vector<MapPoint>{kMid});
    ASSERT_EQ(f.objects.size(), 1u);
    EXPECT_EQ(f.objects[0].source.record, 2);
    EXPECT_EQ(f.objects[0].geometry, 'F');

    EdbsConversion c = toAtkis(f);
    ASSERT_EQ(c.atkis.objects.size(), 1u);
    const AtkisObject &forest = c.atkis.objects[0];
    EXPECT_EQ(forest.id, "W000001");
    EXPECT_EQ(forest.type, 4107);
    EXPECT_EQ(forest.where, "forest.edbs: record 2");
    EXPECT_EQ(landClass(forest), LandClass::Forest);
    EXPECT_EQ(treeKind(forest), TreeKind::Conifer);
    ASSERT_EQ(forest.areas.size(), 1u);
    const MapRing &ring = forest.areas[0];
    ASSERT_EQ(ring.size(), 5u);  // A, mid, B, C, D in some rotation and direction
    for (const MapPoint &p : {kA, kMid, kB, kC, kD}) EXPECT_EQ(std::count(ring.begin(), ring.end(), p), 1);
    auto at = [&](size_t i) { return ring[i % ring.size()]; };
    size_t a = size_t(std::find(ring.begin(), ring.end(), kA) - ring.begin());
    EXPECT_TRUE((at(a + 1) == kMid && at(a + 2) == kB) || (at(a + 4) == kMid && at(a + 3) == kB));
}

TEST(Edbs, JoinsContinuationRecords) {
    std::string content = element(kA, kB, {}, {"W000001", ""}, "4107", {kMid, kMid, kMid});
    std::string whole = record("BSPE", 7, ' ', "ULOBNN", content) + "\n";
    std::string split = record("BSPE", 7, 'A', "ULOBNN", content.substr(0, 30)) + "\n" +
        record("BSPE", 8, 'F', "ULOBNN", content.substr(30, 40)) + "\n" +
        record("BSPE", 9, 'E', "ULOBNN", content.substr(70)) + "\n";
    EdbsFile one = parseEdbs(whole, "a"), three = parseEdbs(split, "b");
    ASSERT_EQ(three.lines.size(), 1u);
    EXPECT_EQ(three.records, 3);
    EXPECT_EQ(three.lines[0].start, one.lines[0].start);
    EXPECT_EQ(three.lines[0].end, one.lines[0].end);
    EXPECT_EQ(three.lines[0].between, one.lines[0].between);
    EXPECT_EQ(three.lines[0].source.record, 7);
    // An error in the F record's part is placed on its line.
    std::string bad = split;
    size_t at = bad.find('\n') + 1 + 36 + 5;  // in the end point, second line
    bad[at] = 'x';
    try {
        parseEdbs(bad, "b");
        FAIL() << "no error";
    } catch (const InputError &e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_NE(std::string(e.what()).find("record 7:"), std::string::npos) << e.what();
    }
}

TEST(Edbs, ContinuationErrors) {
    std::string a = record("BSPE", 1, 'A', "ULOBNN", "0000");
    std::string f = record("BSPE", 2, 'F', "ULOBNN", "");
    std::string e = record("BSPE", 3, 'E', "ULOBNN", "");
    EXPECT_NE(errorOf(e + "\n").find("without a start record"), std::string::npos);
    EXPECT_NE(errorOf(a + "\n" + f + "\n").find("record 1: continued record has no end record"), std::string::npos);
    EXPECT_NE(errorOf(a + "\n" + record("BSPE", 2, ' ', "ULOBNN", "0000") + "\n").find("no end record"),
              std::string::npos);
    EXPECT_NE(errorOf(a + "\n" + record("BSPE", 2, 'E', "ULTANN", "") + "\n")
                  .find("record 2: continuation record is BSPE ULTANN"),
              std::string::npos);
    EXPECT_EQ(errorOf(a + "\n" + f + "\n" + e + "\n"), "no error");
}

TEST(Edbs, RepetitionFactorZeroMeansAbsent) {
    // A Grundrisskennzeichen with no lines and no object; an object with no Besondere Information.
    std::string empty = fmt::format("00010001{}000000000", atkisPoint(3397000, 5579000));
    EdbsFile f = parseEdbs(file({{"ULOBNN", empty}, {"ULOBNN", "0000"}, {"ULTANN", "0000"}}), "z");
    EXPECT_TRUE(f.lines.empty());
    EXPECT_TRUE(f.objects.empty());
    EXPECT_TRUE(f.attributes.empty());
}

TEST(Edbs, WrongLengthFieldNamesTheRecord) {
    std::string text = forestFile();
    size_t third = text.find("EDBS", text.find("EDBS", text.find("EDBS") + 1) + 1);
    text[third + 7] = text[third + 7] == '9' ? '0' : char(text[third + 7] + 1);
    std::string message = errorOf(text);
    EXPECT_NE(message.find("t.edbs:3:5: record 2: length field says"), std::string::npos) << message;
}

TEST(Edbs, HeaderErrors) {
    EXPECT_NE(errorOf("EDBX00240000AEND000000  0000        \n").find("t.edbs:1:1: record 0: not an EDBS record"),
              std::string::npos);
    EXPECT_NE(errorOf("EDBS0024\n").find("t.edbs:1:9: record header: the record header needs 36"), std::string::npos);
    EXPECT_NE(errorOf(record("FLOE", 4, ' ', "ULOBNN", "0000") + "\n").find("record 4: operation FLOE is an update"),
              std::string::npos);
    EXPECT_NE(errorOf(record("XXXX", 4, ' ', "ULOBNN", "0000") + "\n").find("record 4: unknown operation"),
              std::string::npos);
    EXPECT_NE(errorOf(record("BSPE", 4, 'Q', "ULOBNN", "0000") + "\n").find("record 4: continuation flag"),
              std::string::npos);
    EXPECT_NE(errorOf(record("BSPE", 4, ' ', "ULO8ALK", "0000") + "\n").find("record 4: information 'ULO8ALK'"),
              std::string::npos);
    std::string longRecord = record("BINF", 4, ' ', "ULOTEX", "0001" + std::string(1970, 'x'));
    EXPECT_EQ(longRecord.size(), 2010u);
    EXPECT_NE(errorOf(longRecord + "\n").find("record 4: the record is 2010 characters long"), std::string::npos);
    EXPECT_NE(errorOf("").find("no EDBS records"), std::string::npos);
}

TEST(Edbs, ContentErrorsNameRecordAndColumn) {
    // Repetition factor far beyond what the record holds.
    std::string huge = record("BSPE", 12, ' ', "ULOBNN", "9999");
    EXPECT_NE(errorOf(huge + "\n").find("t.edbs:1:37: record 12: 9999 × ULOBNN does not fit"), std::string::npos);
    std::string broken = element(kA, kB, {}, {"W000001", ""});
    broken[8] = 'x';  // the start point
    EXPECT_NE(
        errorOf(record("BSPE", 12, ' ', "ULOBNN", broken) + "\n").find("t.edbs:1:45: record 12: Grundrisskennzeichen"),
        std::string::npos);
    std::string twice = element(kA, kB, {}, {"W000001", ""}).substr(0, 4) + "0002";
    EXPECT_NE(errorOf(record("BSPE", 12, ' ', "ULOBNN", twice) + "\n").find("record 12: "), std::string::npos);
    std::string leftOver = element(kA, kB, {}, {"W000001", ""}) + "junk";
    EXPECT_NE(errorOf(record("BSPE", 12, ' ', "ULOBNN", leftOver) + "\n").find("record 12: 4 characters left over"),
              std::string::npos);
    std::string badType = object("W000001", "4107", 'X', kA);
    EXPECT_NE(errorOf(record("BSPE", 12, ' ', "ULOBNN", badType) + "\n").find("record 12: Objekttyp 'X'"),
              std::string::npos);
}

TEST(Edbs, OpenOutlineIsAnErrorNamingTheObject) {
    std::string text = file({
        {"ULOBNN", object("W000002", "4107", 'F', kC)},
        {"ULOBNN", element(kA, kB, {}, {"W000002", ""})},
        {"ULOBNN", element(kC, kB, {"W000002", ""}, {})},
    });
    std::string message = errorOf(text);
    EXPECT_NE(message.find("t.edbs:2: record 1: area object W000002 (Objektart 4107): outline does not close"),
              std::string::npos)
        << message;
    EdbsConversion skipped = toAtkis(parseEdbs(text, "t.edbs"), IncompleteObjects::Skip);
    EXPECT_TRUE(skipped.atkis.objects.empty());
    ASSERT_EQ(skipped.skipped.size(), 1u);
    EXPECT_NE(skipped.skipped[0].find("W000002"), std::string::npos);
    // An area that no element bounds at all.
    std::string lonely = file({{"ULOBNN", object("W000003", "4107", 'F', kC)}});
    EXPECT_NE(errorOf(lonely).find("area object W000003 (Objektart 4107) has no line elements"), std::string::npos);
}

TEST(Edbs, DuplicateObjectIsAnError) {
    std::string text = forestFile({{"ULOBNN", object("W000001", "4107", 'F', kA)}});
    EXPECT_NE(errorOf(text).find("record 7: object W000001 is defined again (first in record 2)"), std::string::npos);
}

TEST(Edbs, LineObjectsAndPartAttributes) {
    // A road A→B→C in two parts: part 001 A-mid-B with BRF 0065, part 002 B-C with BRF 0080.
    std::string text = file({
        {"ULOBNN", object("S000001", "3101", 'L', kA)},
        {"ULOBNN", element(kB, kMid, {}, {"S000001", "001"}, "3101")},
        {"ULOBNN", element(kB, kC, {}, {"S000001", "002"}, "3101")},
        {"ULOBNN", element(kA, kMid, {}, {"S000001", "001"}, "3101")},
        {"ULTANN", attributes("S000001", "001", {{"BRF", "0065"}})},
        {"ULTANN", attributes("S000001", "002", {{"BRF", "0080"}})},
        {"ULTANN", attributes("S000001", "", {{"FSZ", "0002"}})},
    });
    EdbsConversion c = toAtkis(parseEdbs(text, "road.edbs"));
    ASSERT_EQ(c.atkis.objects.size(), 2u);
    const AtkisObject &first = c.atkis.objects[0], &second = c.atkis.objects[1];
    EXPECT_EQ(first.where, "road.edbs: record 1, part 001");
    EXPECT_EQ(ribbonWidth(first), 6.5);
    EXPECT_EQ(ribbonWidth(second), 8.0);
    EXPECT_EQ(first.attributes.at("FSZ"), "0002");
    ASSERT_EQ(first.lines.size(), 1u);
    MapLine expected{kA, kMid, kB}, reversed{kB, kMid, kA};
    EXPECT_TRUE(first.lines[0] == expected || first.lines[0] == reversed);
    ASSERT_EQ(second.lines.size(), 1u);
    EXPECT_EQ(second.lines[0].size(), 2u);
}

TEST(Edbs, HolesAreLeftOutWithAWarning) {
    const MapPoint h1{3397040, 5579040}, h2{3397060, 5579040}, h3{3397060, 5579060};
    std::string text = forestFile({
        {"ULOBNN", element(h1, h2, {}, {"W000001", ""})},
        {"ULOBNN", element(h3, h2, {"W000001", ""}, {})},
        {"ULOBNN", element(h3, h1, {}, {"W000001", ""})},
    });
    EdbsConversion c = toAtkis(parseEdbs(text, "t.edbs"));
    ASSERT_EQ(c.atkis.objects.size(), 1u);
    ASSERT_EQ(c.atkis.objects[0].areas.size(), 1u);
    EXPECT_EQ(c.atkis.objects[0].areas[0].size(), 5u);
    ASSERT_EQ(c.warnings.size(), 1u);
    EXPECT_NE(c.warnings[0].find("1 hole left out"), std::string::npos);
}

TEST(ElementChaining, ShuffledAndReversedElementsMakeOneRing) {
    // An L-shaped outline of six corners, each side an element, some with points between.
    std::vector<MapPoint> corners{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
    std::vector<MapLine> elements;
    for (size_t i = 0; i < corners.size(); ++i) {
        MapPoint a = corners[i], b = corners[(i + 1) % corners.size()];
        MapLine e{a, {(a.easting + b.easting) / 2, (a.northing + b.northing) / 2}, b};
        if (i % 2) std::reverse(e.begin(), e.end());
        elements.push_back(e);
    }
    for (uint32_t seed = 0; seed < 20; ++seed) {
        std::vector<MapLine> shuffled = elements;
        for (size_t i = shuffled.size(); i > 1; --i)
            std::swap(shuffled[i - 1], shuffled[hashValues({seed, uint32_t(i)}) % i]);
        RingChaining r = chainRings(shuffled);
        ASSERT_TRUE(r.closed);
        ASSERT_EQ(r.rings.size(), 1u);
        const MapRing &ring = r.rings[0];
        EXPECT_EQ(ring.size(), 12u);
        for (size_t i = 0; i < ring.size(); ++i) {
            EXPECT_NE(ring[i], ring[(i + 1) % ring.size()]);
            EXPECT_EQ(std::count(ring.begin(), ring.end(), ring[i]), 1);
        }
        // Neighbours in the ring are neighbours on the outline.
        for (size_t c = 0; c < corners.size(); ++c) {
            size_t at = size_t(std::find(ring.begin(), ring.end(), corners[c]) - ring.begin());
            MapPoint next = ring[(at + 2) % 12], previous = ring[(at + 10) % 12];
            MapPoint n1 = corners[(c + 1) % 6], n2 = corners[(c + 5) % 6];
            EXPECT_TRUE((next == n1 && previous == n2) || (next == n2 && previous == n1));
        }
    }
}

TEST(ElementChaining, OpenInputIsReportedNotLooped) {
    RingChaining r = chainRings({{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{0, 1}, {0, 0}}});
    EXPECT_FALSE(r.closed);
    EXPECT_EQ(r.unusedElements, 3u);
    EXPECT_TRUE(r.openEnd == MapPoint({1, 1}) || r.openEnd == MapPoint({0, 1}));
    // Duplicated elements close on themselves and enclose nothing.
    RingChaining twice = chainRings({{{0, 0}, {1, 0}}, {{1, 0}, {0, 0}}});
    EXPECT_TRUE(twice.closed);
    EXPECT_TRUE(twice.rings.empty());
}

TEST(ElementChaining, LinesRunFromLooseEnds) {
    std::vector<MapLine> lines = chainLines({{{2, 0}, {3, 0}}, {{1, 0}, {2, 0}}, {{1, 0}, {0, 0}}});
    ASSERT_EQ(lines.size(), 1u);
    MapLine forward{{0, 0}, {1, 0}, {2, 0}, {3, 0}}, backward(forward.rbegin(), forward.rend());
    EXPECT_TRUE(lines[0] == forward || lines[0] == backward);
    // Two pieces that do not meet stay two polylines.
    EXPECT_EQ(chainLines({{{0, 0}, {1, 0}}, {{5, 0}, {6, 0}}}).size(), 2u);
}

std::string readText(const std::filesystem::path &path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(EdbsSample, RecordCountsMatchTheManifest) {
    auto path = test::sharedDataFile("edbs/alk_muster_part1.edbs");
    if (!path) GTEST_SKIP() << "../shared/data is not here";
    EdbsFile f = readEdbs(*path);
    EXPECT_EQ(f.records, 3000);
    EXPECT_EQ(f.recordCounts.size(), 4u);
    EXPECT_EQ(f.recordCounts.at("AKND ULQA0000"), 1);
    EXPECT_EQ(f.recordCounts.at("BKRT IBENKRT"), 1);
    EXPECT_EQ(f.recordCounts.at("BINF ULOTEX"), 1);
    EXPECT_EQ(f.recordCounts.at("BSPE ULOBNN"), 2997);
    EXPECT_FALSE(f.hasEnd);
    EXPECT_EQ(f.coordinates(), EdbsCoordinates::Alk);
    EXPECT_EQ(f.atkisPoints, 0);
    EXPECT_EQ(f.lines.size(), 2870u);
    EXPECT_EQ(f.objects.size(), 1405u);
    ASSERT_TRUE(f.area);
    EXPECT_EQ(f.area->first, MapPoint({5491035.197, 5652672.881}));
    EXPECT_EQ(f.area->second, MapPoint({5496326.613, 5656065.261}));
    EXPECT_EQ(f.texts, std::vector<std::string>{"Daten aus kataster"});

    // The prefix cuts some outlines: the loader rejects them, info lists and leaves them out.
    EXPECT_THROW(toAtkis(f), InputError);
    EdbsConversion c = toAtkis(f, IncompleteObjects::Skip);
    EXPECT_EQ(c.skipped.size(), 51u);
    EXPECT_EQ(c.atkis.objects.size(), 1405u - 51u);
    // Three Flurstücke-like areas with an island; their outer outline stays.
    EXPECT_EQ(std::count_if(c.warnings.begin(), c.warnings.end(),
                            [](const std::string &w) { return w.find("1 hole left out") != std::string::npos; }),
              3);
    std::map<LandClass, int> classes;
    for (const AtkisObject &o : c.atkis.objects) {
        EXPECT_EQ(o.type, 0);  // ALK Objektarten are not ATKIS ones
        EXPECT_TRUE(o.typeName.starts_with("ALK "));
        for (const MapRing &ring : o.areas) EXPECT_GE(ring.size(), 3u);
        ++classes[landClass(o)];
    }
    // By their Folie: 001 Flurstücke, 011 Gebäude; the rest (texts, symbols, Nutzung) other.
    // Parcels: 129 of Objektart 0233 and 14 of 0239; buildings: 1003 × 13, 1004 × 5, 1101 × 2
    // (areas) and 1036 × 3 (points), as `veduta atkis info` counts the file's complete objects.
    EXPECT_EQ(classes[LandClass::Parcel], 143);
    EXPECT_EQ(classes[LandClass::Building], 23);
}

// Deterministic corruptions of a text: bytes replaced, a cut, records doubled or dropped.
std::string corrupt(const std::string &text, uint32_t seed) {
    std::string out = text;
    auto random = [&, n = 0u]() mutable { return hashValues({seed, n++}); };
    switch (random() % 5) {
    case 0:
        for (uint32_t i = 0, n = 1 + random() % 8; i < n && !out.empty(); ++i)
            out[random() % out.size()] = char(random() % 256);
        break;
    case 1:
        for (uint32_t i = 0, n = 1 + random() % 4; i < n && !out.empty(); ++i)
            out[random() % out.size()] = "0123456789 AFEx\n"[random() % 16];
        break;
    case 2: out.resize(random() % (out.size() + 1)); break;
    default: {
        std::vector<std::string> lines;
        std::istringstream in(out);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        if (lines.empty()) break;
        size_t at = random() % lines.size();
        if (random() % 2) lines.insert(lines.begin() + long(at), lines[at]);
        else lines.erase(lines.begin() + long(at));
        out.clear();
        for (const std::string &line : lines) out += line + "\n";
    }
    }
    return out;
}

TEST(EdbsRobustness, CorruptedFilesParseOrFailWithARecordNumber) {
    std::vector<std::string> bases{forestFile(),
                                   file({
                                       {"ULOBNN", object("S000001", "3101", 'L', kA)},
                                       {"ULOBNN", element(kB, kMid, {}, {"S000001", "001"}, "3101")},
                                       {"ULOBNN", element(kA, kMid, {}, {"S000001", "001"}, "3101", {kMid, kA})},
                                       {"ULTANN", attributes("S000001", "001", {{"BRF", "0065"}})},
                                   })};
    if (auto path = test::sharedDataFile("edbs/alk_muster_part1.edbs")) {
        std::string sample = readText(*path);
        size_t cut = 0;
        for (int i = 0; i < 300 && cut != std::string::npos; ++i) cut = sample.find('\n', cut + 1);
        bases.push_back(sample.substr(0, cut + 1));
    }
    auto start = std::chrono::steady_clock::now();
    int parsed = 0, failed = 0;
    for (uint32_t seed = 0; seed < 300; ++seed) {
        const std::string &base = bases[seed % bases.size()];
        std::string text = corrupt(base, seed);
        try {
            EdbsFile f = parseEdbs(text, "c.edbs");
            toAtkis(f, IncompleteObjects::Skip);
            toAtkis(f, IncompleteObjects::Error);
            ++parsed;
        } catch (const InputError &e) {
            std::string message = e.what();
            bool named =
                message.find(": record ") != std::string::npos || message.find("no EDBS records") != std::string::npos;
            EXPECT_TRUE(named) << "seed " << seed << ": " << message;
            ++failed;
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 10.0);
    EXPECT_GT(failed, 50);
    EXPECT_GT(parsed, 5);
    std::printf("corrupted EDBS: %d parsed, %d rejected, %.2f s\n", parsed, failed, seconds);
}

}  // namespace
}  // namespace veduta
