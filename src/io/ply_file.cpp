#include "io/ply_file.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"

namespace veduta {

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> plyType(std::string_view name) {
    static const std::pair<std::string_view, PlyType> names[] = {
        {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
        {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
        {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
        {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64}};
    for (auto [n, type] : names)
        if (n == name) return type;
    return std::nullopt;
}

size_t typeSize(PlyType type) {
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    }
    return 0;
}

template <typename T>
double fromBytes(const unsigned char *bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return double(value);
}

double binaryValue(PlyType type, const unsigned char *bytes) {
    switch (type) {
    case PlyType::Int8: return fromBytes<int8_t>(bytes);
    case PlyType::UInt8: return fromBytes<uint8_t>(bytes);
    case PlyType::Int16: return fromBytes<int16_t>(bytes);
    case PlyType::UInt16: return fromBytes<uint16_t>(bytes);
    case PlyType::Int32: return fromBytes<int32_t>(bytes);
    case PlyType::UInt32: return fromBytes<uint32_t>(bytes);
    case PlyType::Float32: return fromBytes<float>(bytes);
    case PlyType::Float64: return fromBytes<double>(bytes);
    }
    return 0;
}

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;
    std::optional<PlyType> countType;  // set for a list
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
    int line = 0;  // of its header line

    std::optional<size_t> property(std::initializer_list<std::string_view> names) const {
        for (size_t i = 0; i < properties.size(); ++i)
            if (!properties[i].countType && std::find(names.begin(), names.end(), properties[i].name) != names.end())
                return i;
        return std::nullopt;
    }
};

std::vector<std::string> words(const std::string &line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// A vertex's properties that the mesh keeps, by their place in the element.
struct VertexLayout {
    size_t x = 0, y = 0, z = 0;
    std::optional<size_t> nx, ny, nz, u, v;
};

class PlyReader {
  public:
    explicit PlyReader(const std::filesystem::path &file) : file_(file), in_(file, std::ios::binary) {}

    MapMesh read() {
        if (!in_) failFile("cannot open the file");
        readHeader();
        for (const PlyElement &e : elements_) readElement(e);
        for (uint32_t index : mesh_.indices)
            if (index >= mesh_.positions.size())
                failFile(
                    fmt::format("a face refers to vertex {}, beyond the {} vertices", index, mesh_.positions.size()));
        if (mesh_.indices.empty()) failFile("mesh file holds no triangles");
        return std::move(mesh_);
    }

  private:
    // At the line being read (the header, an ASCII body) or the byte (a binary body).
    [[noreturn]] void fail(const std::string &message) const {
        if (inBody_ && format_ != PlyFormat::Ascii)
            throw InputError({file_.string()}, fmt::format("byte {} of the binary body: {}", offset_, message));
        throw InputError({file_.string(), line_, 0}, message);
    }
    [[noreturn]] void failFile(const std::string &message) const { throw InputError({file_.string()}, message); }

    std::string nextLine() {
        std::string line;
        if (!std::getline(in_, line))
            fail(inBody_ ? "the file ends before its last element" : "the header has no end_header");
        ++line_;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return line;
    }

    void readHeader() {
        if (nextLine() != "ply") fail("not a PLY file: it does not start with 'ply'");
        bool formatGiven = false;
        for (;;) {
            std::vector<std::string> w = words(nextLine());
            if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
            if (w[0] == "end_header") break;
            if (w[0] == "format") {
                if (w.size() != 3 || w[2] != "1.0") fail("the format line reads 'format <kind> 1.0'");
                if (w[1] == "ascii") format_ = PlyFormat::Ascii;
                else if (w[1] == "binary_little_endian") format_ = PlyFormat::LittleEndian;
                else if (w[1] == "binary_big_endian") format_ = PlyFormat::BigEndian;
                else fail(fmt::format("unknown PLY format '{}'", w[1]));
                formatGiven = true;
            } else if (w[0] == "element") {
                uint64_t count = 0;
                if (w.size() != 3 || std::from_chars(w[2].data(), w[2].data() + w[2].size(), count).ec != std::errc())
                    fail("an element line reads 'element <name> <count>'");
                elements_.push_back({w[1], count, {}, line_});
            } else if (w[0] == "property") {
                if (elements_.empty()) fail("a property before any element");
                elements_.back().properties.push_back(property(w));
            } else {
                fail(fmt::format("unknown header line '{}'", w[0]));
            }
        }
        if (!formatGiven) fail("the header gives no format");
        checkCounts();
        inBody_ = true;
    }

    // Every item of an element takes a byte of the body at least (an ASCII value two): a
    // count the file cannot hold, or items without properties, which the body would not even
    // be read for, are refused before they are looped over.
    void checkCounts() {
        std::error_code error;
        uint64_t bytes = std::filesystem::file_size(file_, error);
        const int endHeader = line_;
        for (const PlyElement &e : elements_) {
            if (e.count == 0) continue;
            line_ = e.line;  // the message's place
            if (e.properties.empty())
                fail(fmt::format("the element '{}' has {} items but no properties", e.name, e.count));
            if (!error && e.count > bytes)
                fail(fmt::format("the element '{}' promises {} items, more than the file's {} bytes can hold", e.name,
                                 e.count, bytes));
        }
        line_ = endHeader;
    }

    PlyProperty property(const std::vector<std::string> &w) const {
        auto type = [&](const std::string &name) {
            std::optional<PlyType> t = plyType(name);
            if (!t) fail(fmt::format("unknown property type '{}'", name));
            return *t;
        };
        if (w.size() == 5 && w[1] == "list") return {w[4], type(w[3]), type(w[2])};
        if (w.size() == 3) return {w[2], type(w[1]), std::nullopt};
        fail("a property line reads 'property <type> <name>' or 'property list <count type> <type> <name>'");
    }

    double value(PlyType type) { return format_ == PlyFormat::Ascii ? asciiValue() : binaryValueAt(type); }

    double asciiValue() {
        while (word_ >= words_.size()) {
            words_ = words(nextLine());
            word_ = 0;
        }
        const std::string &w = words_[word_++];
        double v = 0;
        auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), v);
        if (error != std::errc() || end != w.data() + w.size()) fail(fmt::format("'{}' is not a number", w));
        return v;
    }

    double binaryValueAt(PlyType type) {
        unsigned char bytes[8];
        size_t size = typeSize(type);
        if (!in_.read(reinterpret_cast<char *>(bytes), std::streamsize(size)))
            fail("the file ends before its last element");
        offset_ += size;
        if ((format_ == PlyFormat::BigEndian) != (std::endian::native == std::endian::big))
            std::reverse(bytes, bytes + size);
        return binaryValue(type, bytes);
    }

    void readElement(const PlyElement &e) {
        std::optional<VertexLayout> vertex;
        if (e.name == "vertex") vertex = layout(e);
        std::vector<double> values(e.properties.size());
        std::vector<uint32_t> polygon;
        for (uint64_t item = 0; item < e.count; ++item) {
            polygon.clear();
            for (size_t p = 0; p < e.properties.size(); ++p) {
                const PlyProperty &property = e.properties[p];
                if (!property.countType) {
                    values[p] = value(property.type);
                    continue;
                }
                double count = value(*property.countType);
                bool corners =
                    e.name == "face" && (property.name == "vertex_indices" || property.name == "vertex_index");
                for (double k = 0; k < count; ++k) {
                    double index = value(property.type);
                    if (corners) {
                        // NaN fails this too; a float index may be any number.
                        if (!(index >= 0 && index < 4294967296.0))
                            fail(fmt::format("face {} refers to vertex {}", item, index));
                        polygon.push_back(uint32_t(index));
                    }
                }
            }
            if (vertex) addVertex(*vertex, values);
            for (size_t k = 2; k < polygon.size(); ++k)
                mesh_.indices.insert(mesh_.indices.end(), {polygon[0], polygon[k - 1], polygon[k]});
        }
    }

    VertexLayout layout(const PlyElement &e) {
        std::optional<size_t> x = e.property({"x"}), y = e.property({"y"}), z = e.property({"z"});
        if (!x || !y || !z)
            throw InputError({file_.string(), e.line, 0}, "the vertex element needs the properties x, y and z");
        VertexLayout l{*x,
                       *y,
                       *z,
                       e.property({"nx"}),
                       e.property({"ny"}),
                       e.property({"nz"}),
                       e.property({"u", "s", "texture_u", "texture_s"}),
                       e.property({"v", "t", "texture_v", "texture_t"})};
        allNormals_ = l.nx && l.ny && l.nz;
        allUvs_ = l.u && l.v;
        return l;
    }

    void addVertex(const VertexLayout &l, const std::vector<double> &values) {
        mesh_.positions.push_back({values[l.x], values[l.y], values[l.z]});
        if (allNormals_) mesh_.normals.push_back({float(values[*l.nx]), float(values[*l.ny]), float(values[*l.nz])});
        if (allUvs_) mesh_.uvs.push_back({float(values[*l.u]), float(values[*l.v])});
    }

    const std::filesystem::path &file_;
    std::ifstream in_;
    PlyFormat format_ = PlyFormat::Ascii;
    std::vector<PlyElement> elements_;
    MapMesh mesh_;
    int line_ = 0;  // the line last read
    bool inBody_ = false;
    uint64_t offset_ = 0;  // bytes read of a binary body
    std::vector<std::string> words_;
    size_t word_ = 0;
    bool allNormals_ = false, allUvs_ = false;  // the vertex element has them
};

}  // namespace

MapMesh readPlyFile(const std::filesystem::path &file) { return PlyReader(file).read(); }

}  // namespace veduta
