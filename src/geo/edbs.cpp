#include "geo/edbs.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.h"
#include "core/input_file.h"

namespace veduta {

namespace {

constexpr size_t kMaxRecordLength = 2000;  // the format's limit, SA and SL included
constexpr size_t kHeaderLength = 36;       // SA SL OP QU IN
constexpr int kMaxContinuations = 1000;    // F records after one A record

// Sizes of the data groups without their repetition factors, and the least a repeated group
// can take, for checking a WHF against the bytes that are left before reading on.
constexpr size_t kPoint = 20;
constexpr size_t kLineFunction = 3 + 4 + 7 + 7 + 3 + 3 + 1 + 1;
constexpr size_t kFachparameter = 20;  // Rinner's edbs2arc; not in the Sachsen description
constexpr size_t kObjectFunction = 3 + 4 + 2 + 1 + 7 + 2 + 6 + 1;
constexpr size_t kInfo = 2 + 2 + 6 + 33 + 2 + 3;
constexpr size_t kWhf = 4;

bool isDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

long digits(std::string_view s) {
    long value = 0;
    for (char c : s) value = value * 10 + (c - '0');
    return value;
}

std::string trimmed(std::string_view s) {
    size_t first = s.find_first_not_of(' ');
    if (first == std::string_view::npos) return {};
    return std::string(s.substr(first, s.find_last_not_of(' ') - first + 1));
}

// Control characters and bytes outside ASCII shown as escapes, so messages stay one line.
std::string printable(std::string_view s) {
    std::string out;
    for (unsigned char c : s) out += c >= 32 && c < 127 ? std::string(1, char(c)) : fmt::format("\\x{:02x}", c);
    return out;
}

// Where a byte of a record's content came from: content offset → line and column.
struct Segment {
    size_t offset = 0;
    int line = 0;
    int column = 0;  // 1-based column of the segment's first byte
};

// One logical record: the header of its first physical record, the content (II) of all.
struct Record {
    std::string op, in;
    int number = 0;
    int line = 0;
    std::string content;
    std::vector<Segment> segments;
    int parts = 1;
};

// Reads the fields of one record's content, checking every length and repetition factor
// against what is left, so that no read goes past the end.
class FieldReader {
  public:
    FieldReader(const std::string &file, const Record &record) : file_(file), record_(record) {}

    size_t remaining() const { return record_.content.size() - pos_; }
    size_t position() const { return pos_; }
    std::string_view peek(size_t n) const { return std::string_view(record_.content).substr(pos_, n); }

    std::string_view take(size_t n, std::string_view what) {
        if (n > remaining())
            fail(pos_, fmt::format("{} needs {} characters, the record has {} left", what, n, remaining()));
        std::string_view field = std::string_view(record_.content).substr(pos_, n);
        pos_ += n;
        return field;
    }

    // A 4-digit repetition factor, checked against the bytes its groups need at least.
    int repeat(std::string_view what, size_t leastGroupSize) {
        size_t at = pos_;
        std::string_view field = take(kWhf, fmt::format("the repetition factor of {}", what));
        if (!isDigits(field))
            fail(at, fmt::format("repetition factor of {} is '{}', not 4 digits", what, printable(field)));
        int count = int(digits(field));
        if (size_t(count) * leastGroupSize > remaining())
            fail(at, fmt::format("{} × {} does not fit in the {} characters left", count, what, remaining()));
        return count;
    }

    // A repetition factor that the format fixes at 1.
    void one(std::string_view what, size_t groupSize) {
        size_t at = pos_;
        int count = repeat(what, groupSize);
        if (count != 1) fail(at, fmt::format("repetition factor of {} is {}, expected 1", what, count));
    }

    MapPoint point(std::string_view what, EdbsFile &file) {
        size_t at = pos_;
        std::string_view field = take(kPoint, what);
        EdbsCoordinates form = EdbsCoordinates::Alk;
        std::optional<MapPoint> p = decodeEdbsPoint(field, &form);
        if (!p) fail(at, fmt::format("{} '{}' is not a coordinate", what, printable(field)));
        ++(form == EdbsCoordinates::Alk ? file.alkPoints : file.atkisPoints);
        return *p;
    }

    std::string_view digitsField(size_t n, std::string_view what) {
        size_t at = pos_;
        std::string_view field = take(n, what);
        if (!isDigits(field)) fail(at, fmt::format("{} '{}' is not {} digits", what, printable(field), n));
        return field;
    }

    void expectEnd(std::string_view what) {
        std::string_view rest = std::string_view(record_.content).substr(pos_);
        if (rest.find_first_not_of(' ') != std::string_view::npos)
            fail(pos_, fmt::format("{} characters left over after the {}", rest.size(), what));
    }

    [[noreturn]] void fail(size_t offset, const std::string &message) const {
        auto segment = std::prev(std::upper_bound(record_.segments.begin(), record_.segments.end(), offset,
                                                  [](size_t o, const Segment &s) { return o < s.offset; }));
        FileLoc loc{file_, segment->line, segment->column + int(offset - segment->offset)};
        throw InputError(loc, fmt::format("record {}: {}", record_.number, message));
    }

    EdbsSource source() const { return {record_.number, record_.line}; }

  private:
    const std::string &file_;
    const Record &record_;
    size_t pos_ = 0;
};

EdbsLineFunction readLineFunction(FieldReader &r) {
    EdbsLineFunction f;
    f.folie = std::string(r.take(3, "Folie"));
    f.type = std::string(r.take(4, "Objektart of the line"));
    f.right = trimmed(r.take(7, "Objektnummer (right)"));
    f.left = trimmed(r.take(7, "Objektnummer (left)"));
    f.rightPart = trimmed(r.take(3, "Objektteilnummer (right)"));
    f.leftPart = trimmed(r.take(3, "Objektteilnummer (left)"));
    r.take(2, "Linienteilung");
    int fachparameter = r.repeat("Fachparameter", kFachparameter);
    for (int i = 0; i < fachparameter; ++i) r.take(kFachparameter, "Fachparameter");
    return f;
}

// ULOB100F: one vector element from `start`, with its functions and Lageparameter.
void readLine(FieldReader &r, MapPoint start, EdbsFile &file) {
    r.one("Endpunkt der Linie", kPoint + 2);
    EdbsLine line;
    line.source = r.source();
    line.start = start;
    line.end = r.point("Endpunkt der Linie", file);
    line.geometryKind = int(digits(r.digitsField(2, "Art der Geometrie")));
    if (line.geometryKind != 11 && line.geometryKind != 15) ++file.curvedElements;
    int functions = r.repeat("Funktion der Linie", kWhf + kLineFunction + kWhf);
    for (int i = 0; i < functions; ++i) {
        r.one("Funktion der Linie", kLineFunction + kWhf);
        line.functions.push_back(readLineFunction(r));
    }
    int between = r.repeat("Lageparameter", kPoint);
    for (int i = 0; i < between; ++i) line.between.push_back(r.point("Lageparameter", file));
    file.lines.push_back(std::move(line));
}

EdbsInfo readInfo(FieldReader &r, EdbsFile &file) {
    EdbsInfo info;
    info.kind = std::string(r.take(2, "Art der Information"));
    info.mapType = std::string(r.take(2, "Kartentyp"));
    info.type = std::string(r.take(6, "Objektart of the information"));
    info.text = trimmed(r.take(33, "Text of the information"));
    info.geometryKind = std::string(r.take(2, "Art der Geometrieangabe"));
    info.part = trimmed(r.take(3, "Objektteilnummer of the information"));
    int geometry = r.repeat("Geometrieangabe", kPoint);
    for (int i = 0; i < geometry; ++i) {
        // A text's direction comes as "TT" and an angle in the place of a point.
        if (r.peek(2) == "TT") r.take(kPoint, "Geometrieangabe");
        else info.points.push_back(r.point("Geometrieangabe", file));
    }
    return info;
}

// ULOB200F: the object whose reference point is `reference`.
void readObject(FieldReader &r, MapPoint reference, EdbsFile &file) {
    r.one("Funktion des Objekts", kObjectFunction + kWhf);
    EdbsObject object;
    object.source = r.source();
    object.reference = reference;
    object.folie = std::string(r.take(3, "Folie"));
    object.type = std::string(r.digitsField(4, "Objektart"));
    object.actuality = std::string(r.take(2, "Aktualität"));
    size_t at = r.position();
    std::string_view geometry = r.take(1, "Objekttyp");
    if (geometry != "P" && geometry != "L" && geometry != "F")
        r.fail(at, fmt::format("Objekttyp '{}' is not P, L or F", printable(geometry)));
    object.geometry = geometry[0];
    object.id = trimmed(r.take(7, "Objektnummer"));
    object.modelType = std::string(r.take(2, "Modelltyp"));
    object.date = std::string(r.take(6, "Entstehungsdatum"));
    object.change = std::string(r.take(1, "Veränderungskennung"));
    int infos = r.repeat("Besondere Information", kWhf + kInfo + kWhf);
    for (int i = 0; i < infos; ++i) {
        r.one("Besondere Information", kInfo + kWhf);
        object.infos.push_back(readInfo(r, file));
    }
    file.objects.push_back(std::move(object));
}

void readGrundriss(FieldReader &r, EdbsFile &file) {
    int groups = r.repeat("ULOBNN", kWhf + kPoint + 1 + 2 * kWhf);
    for (int g = 0; g < groups; ++g) {
        r.one("Grundrisskennzeichen", kPoint + 1 + 2 * kWhf);
        MapPoint start = r.point("Grundrisskennzeichen", file);
        r.take(1, "Prüfzeichen");
        int lines = r.repeat("Endpunkt der Linie", kWhf + kPoint + 2 + 2 * kWhf);
        for (int i = 0; i < lines; ++i) readLine(r, start, file);
        int objects = r.repeat("Funktion des Objekts", kWhf + kObjectFunction + kWhf);
        for (int i = 0; i < objects; ++i) readObject(r, start, file);
    }
    r.expectEnd("Grundriss data");
}

void readAttributes(FieldReader &r, EdbsFile &file) {
    int groups = r.repeat("ULTANN", kWhf + 13 + kWhf);
    for (int g = 0; g < groups; ++g) {
        r.one("Attributkennzeichen", 13 + kWhf);
        EdbsAttributes attributes;
        attributes.source = r.source();
        attributes.id = trimmed(r.take(7, "Objektnummer"));
        attributes.part = trimmed(r.take(3, "Objektteilnummer"));
        r.take(1, "Prüfzeichen");
        r.take(2, "Aktualität");
        int count = r.repeat("Attribut", 4 + 7);
        for (int i = 0; i < count; ++i) {
            std::string name = trimmed(r.take(4, "Attributtyp"));
            std::string value = trimmed(r.take(7, "Attributwert"));
            attributes.values.emplace_back(std::move(name), std::move(value));
        }
        file.attributes.push_back(std::move(attributes));
    }
    r.expectEnd("Attribut data");
}

void readArea(FieldReader &r, EdbsFile &file) {
    MapPoint lowerLeft = r.point("lower left corner", file);
    MapPoint upperRight = r.point("upper right corner", file);
    file.area = std::pair(lowerLeft, upperRight);
}

void readText(FieldReader &r, EdbsFile &file) {
    int count = r.repeat("ULOTEX", 0);
    if (count > 0) file.texts.push_back(trimmed(r.take(r.remaining(), "text")));
}

void readRecord(const std::string &path, const Record &record, EdbsFile &file) {
    FieldReader r(path, record);
    const std::string &op = record.op;
    auto unsupportedInformation = [&] {
        r.fail(0, fmt::format("information '{}' of a {} record is not supported", printable(record.in), op));
    };
    if (op == "BSPE" || op == "FEIN") {
        if (record.in == "ULOBNN") readGrundriss(r, file);
        else if (record.in == "ULTANN") readAttributes(r, file);
        else unsupportedInformation();
    } else if (op == "BKRT") {
        if (record.in != "IBENKRT") unsupportedInformation();
        readArea(r, file);
    } else if (op == "BINF" || op == "OTEX") {
        if (record.in != "ULOTEX") unsupportedInformation();
        readText(r, file);
    }
    // AKND (the Auftragskennsatz) and AEND carry nothing veduta uses.
}

// The header fields of one physical record (columns 1–36), checked.
struct Header {
    std::string op, in;
    int number = 0;
    char continuation = ' ';
    std::string_view content;  // II, up to the search criterion
    int contentColumn = kHeaderLength + 1;
};

[[noreturn]] void recordError(const std::string &path, int line, int column, std::optional<int> number,
                              const std::string &message) {
    std::string what =
        number ? fmt::format("record {}: {}", *number, message) : fmt::format("record header: {}", message);
    throw InputError(FileLoc{path, line, column}, what);
}

Header readHeader(const std::string &path, std::string_view text, int line) {
    std::optional<int> number;
    if (text.size() >= 22 && isDigits(text.substr(16, 6))) number = int(digits(text.substr(16, 6)));
    auto fail = [&](int column, const std::string &message) { recordError(path, line, column, number, message); };
    if (text.size() > kMaxRecordLength)
        fail(kMaxRecordLength + 1,
             fmt::format("the record is {} characters long; EDBS allows {}", text.size(), kMaxRecordLength));
    if (text.substr(0, 4) != "EDBS") fail(1, "not an EDBS record: it does not start with 'EDBS'");
    if (text.size() < kHeaderLength)
        fail(int(text.size()) + 1,
             fmt::format("the record header needs {} characters, the record has {}", kHeaderLength, text.size()));
    if (!number) fail(17, fmt::format("record number '{}' is not 6 digits", printable(text.substr(16, 6))));
    if (!isDigits(text.substr(4, 4)))
        fail(5, fmt::format("length field '{}' is not 4 digits", printable(text.substr(4, 4))));
    size_t length = size_t(digits(text.substr(4, 4)));
    if (length != text.size() - 12)
        fail(5, fmt::format("length field says {} characters after it, the record has {}", length, text.size() - 12));
    if (!isDigits(text.substr(8, 4)))
        fail(9, fmt::format("search criterion address '{}' is not 4 digits", printable(text.substr(8, 4))));
    // The address counts from column 13 (the operation), 1-based; 0 when there is none.
    size_t search = size_t(digits(text.substr(8, 4)));
    size_t contentEnd = text.size();
    if (search != 0) {
        if (search < kHeaderLength - 12 + 1 || search > length + 1)
            fail(9, fmt::format("search criterion address {} lies outside the record's content", search));
        contentEnd = 12 + search - 1;
    }
    Header h;
    h.op = std::string(text.substr(12, 4));
    h.number = *number;
    h.continuation = text[22];
    h.in = trimmed(text.substr(28, 8));
    h.content = text.substr(kHeaderLength, contentEnd - kHeaderLength);
    static const std::vector<std::string> known{"AKND", "AEND", "BKRT", "BINF", "OTEX", "BSPE", "FEIN"};
    static const std::vector<std::string> updates{"FAEN", "FLOE", "FGEO"};
    if (std::find(updates.begin(), updates.end(), h.op) != updates.end())
        fail(13, fmt::format("operation {} is an update; veduta reads whole exports (BSPE, FEIN)", h.op));
    if (std::find(known.begin(), known.end(), h.op) == known.end())
        fail(13, fmt::format("unknown operation '{}'", printable(h.op)));
    if (std::string_view(" AFE").find(h.continuation) == std::string_view::npos)
        fail(23, fmt::format("continuation flag '{}' is not blank, A, F or E", printable(text.substr(22, 1))));
    return h;
}

// Joins continued records (A, F…, E) into logical records and reads each.
class RecordAssembler {
  public:
    RecordAssembler(const std::string &path, EdbsFile &file) : path_(path), file_(file) {}

    void add(std::string_view text, int line) {
        Header h = readHeader(path_, text, line);
        ++file_.records;
        ++file_.recordCounts[h.op + " " + h.in];
        if (file_.hasEnd)
            recordError(path_, line, 13, h.number, fmt::format("a {} record after the end record (AEND)", h.op));
        bool continues = h.continuation == 'F' || h.continuation == 'E';
        if (pending_ && !continues)
            recordError(path_, pending_->line, 23, pending_->number,
                        fmt::format("continued record has no end record (E); record {} follows", h.number));
        if (!pending_ && continues)
            recordError(path_, line, 23, h.number,
                        fmt::format("continuation record ({}) without a start record (A)", h.continuation));
        if (continues) {
            if (h.op != pending_->op || h.in != pending_->in)
                recordError(path_, line, 13, h.number,
                            fmt::format("continuation record is {} {}, its start record {} is {} {}", h.op,
                                        printable(h.in), pending_->number, pending_->op, printable(pending_->in)));
            if (++pending_->parts > kMaxContinuations + 1)
                recordError(path_, line, 23, h.number,
                            fmt::format("more than {} continuation records after record {}", kMaxContinuations,
                                        pending_->number));
            append(*pending_, h, line);
        } else {
            pending_ = Record{h.op, h.in, h.number, line, {}, {}, 1};
            append(*pending_, h, line);
        }
        if (h.continuation == ' ' || h.continuation == 'E') {
            Record record = std::move(*pending_);
            pending_.reset();
            if (record.op == "AEND") file_.hasEnd = true;
            readRecord(path_, record, file_);
        }
    }

    void finish() {
        if (pending_)
            recordError(path_, pending_->line, 23, pending_->number,
                        "continued record has no end record (E) before the end of the file");
    }

  private:
    static void append(Record &record, const Header &h, int line) {
        record.segments.push_back({record.content.size(), line, h.contentColumn});
        record.content.append(h.content);
    }

    const std::string &path_;
    EdbsFile &file_;
    std::optional<Record> pending_;
};

}  // namespace

std::optional<MapPoint> decodeEdbsPoint(std::string_view c, EdbsCoordinates *form) {
    if (c.size() != kPoint) return std::nullopt;
    auto part = [&](size_t at, size_t n) { return digits(c.substr(at, n)); };
    if (isDigits(c)) {
        // Rechts- and Hochwert interleaved: 100 km, 1 km, then millimetres within the kilometre.
        long east = part(0, 2) * 100'000'000 + part(4, 2) * 1'000'000 + part(8, 6);
        long north = part(2, 2) * 100'000'000 + part(6, 2) * 1'000'000 + part(14, 6);
        if (form) *form = EdbsCoordinates::Alk;
        return MapPoint{double(east) / 1000.0, double(north) / 1000.0};
    }
    if (isDigits(c.substr(0, 5)) && c[5] == ' ' && isDigits(c.substr(6, 1)) && c[7] == ' ' && isDigits(c.substr(8))) {
        // 100 km, 10 km (each followed by a blank), then centimetres within the 10 km.
        long east = part(0, 2) * 10'000'000 + part(4, 1) * 1'000'000 + part(8, 6);
        long north = part(2, 2) * 10'000'000 + part(6, 1) * 1'000'000 + part(14, 6);
        if (form) *form = EdbsCoordinates::Atkis;
        return MapPoint{double(east) / 100.0, double(north) / 100.0};
    }
    return std::nullopt;
}

EdbsFile parseEdbs(std::string_view text, const std::string &name) {
    EdbsFile file;
    file.path = name;
    RecordAssembler assembler(name, file);
    int line = 0;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        std::string_view record =
            text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
        start = end == std::string_view::npos ? text.size() : end + 1;
        ++line;
        if (!record.empty() && record.back() == '\r') record.remove_suffix(1);
        if (record.find_first_not_of(' ') == std::string_view::npos) {
            if (text.substr(start).find_first_not_of(" \r\n") == std::string_view::npos)
                break;  // blank lines at the end
            recordError(name, line, 1, std::nullopt, "empty line between records");
        }
        assembler.add(record, line);
    }
    assembler.finish();
    if (file.records == 0) throw InputError(FileLoc{name, 0, 0}, "no EDBS records");
    return file;
}

EdbsFile readEdbs(const std::filesystem::path &path) { return parseEdbs(readInputFile(path), path.string()); }

}  // namespace veduta
