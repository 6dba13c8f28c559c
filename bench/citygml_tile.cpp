// A synthetic CityGML 2.0 tile of the AdV LoD2 kind: one square kilometre of ETRS89 / UTM 32
// (easting 690000-691000, northing 5335000-5336000, DHHN2016 heights about 300 m on a gentle
// slope) with detached buildings in rows along a rotated street grid. Each building is a closed,
// outward-oriented solid of thematic surfaces (GroundSurface, WallSurface, RoofSurface) with a
// flat (AdV roofType 1000), gable (3100) or hip (3200) roof, the input of bench/twin_compare.sh.
//
// Usage: bench_citygml_tile OUT.gml [--buildings N] [--seed S]   (defaults 1500 and 1)
//
// The layout and every size come from a hash of the seed and an index (splitmix64), not from
// std:: distributions, whose output differs between standard libraries: the same N and S give
// the same file with any of them (corners are rounded to 2 mm, so a last-bit difference in a
// libm's sin and cos can at most move a corner by that).
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// The tile, in ETRS89 / UTM zone 32N.
constexpr double kEast0 = 690000, kNorth0 = 5335000, kTileSize = 1000;
constexpr const char *kSrsName = "urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH";

// The street grid: blocks of kBlockLength x kBlockDepth metres between streets kStreetWidth
// wide, each with two rows of buildings back to back, the fronts kSetback from the street.
constexpr double kStreetWidth = 10, kBlockLength = 100, kBlockDepth = 40, kSetback = 2;
constexpr double kMargin = 1;  // every footprint keeps this far inside the tile

uint64_t splitmix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// A number in [0, 1) for (seed, index, stream), the same on every platform.
double uniform(uint64_t seed, uint64_t index, uint64_t stream) {
    uint64_t h = splitmix64(splitmix64(splitmix64(seed) ^ index) ^ (stream * 0x2545f4914f6cdd1dULL));
    return double(h >> 11) * 0x1.0p-53;
}

double uniform(uint64_t seed, uint64_t index, uint64_t stream, double low, double high) {
    return low + (high - low) * uniform(seed, index, stream);
}

// Streams of the hash, one per choice.
enum Stream : uint64_t {
    GridAngle = 1,
    GridShiftX,
    GridShiftY,
    Frontage,
    Depth,
    Gap,
    Recess,
    WallHeight,
    RoofKind,
    RidgeHeight,
    RowStart,
};

struct Vec3 {
    double x, y, z;
};

// The terrain: about 300 m, rising 12 m to the east and 6 m to the north over the tile.
double groundHeight(double east, double north) { return 297 + 0.012 * (east - kEast0) + 0.006 * (north - kNorth0); }

// A footprint: four corners counter-clockwise from above, the first edge the longer one.
struct Footprint {
    std::array<Vec3, 4> corners;
};

// The footprints of the whole grid that lie inside the tile, in the order of the grid.
std::vector<Footprint> layOut(uint64_t seed) {
    const double angle = uniform(seed, 0, GridAngle, 8, 25) * kPi / 180;
    const double ux = std::cos(angle), uy = std::sin(angle);  // along the blocks
    const double vx = -uy, vy = ux;                           // across them
    const double pitchU = kBlockLength + kStreetWidth, pitchV = kBlockDepth + kStreetWidth;
    const double centreE = kEast0 + kTileSize / 2, centreN = kNorth0 + kTileSize / 2;
    const double shiftU = uniform(seed, 0, GridShiftX, 0, pitchU), shiftV = uniform(seed, 0, GridShiftY, 0, pitchV);
    const double reach = kTileSize * 0.75;  // half the tile's diagonal and more
    const int blocksU = int(std::ceil(reach / pitchU)), blocksV = int(std::ceil(reach / pitchV));
    // Corners on a 2 mm grid: the middle of a wall, where a gable's ridge ends, prints in
    // millimetres exactly, on the wall's line.
    auto world = [&](double u, double v) {
        auto grid = [](double metres) { return std::round(metres * 500) / 500; };
        return Vec3{grid(centreE + u * ux + v * vx), grid(centreN + u * uy + v * vy), 0};
    };
    auto inside = [](const Vec3 &p) {
        return p.x >= kEast0 + kMargin && p.x <= kEast0 + kTileSize - kMargin && p.y >= kNorth0 + kMargin &&
            p.y <= kNorth0 + kTileSize - kMargin;
    };
    std::vector<Footprint> footprints;
    uint64_t slot = 0;  // the index of each try, for its sizes
    for (int j = -blocksV; j <= blocksV; ++j) {
        for (int i = -blocksU; i <= blocksU; ++i) {
            // The block [u0, u0 + length] x [v0, v0 + depth] in the grid's frame.
            const double u0 = i * pitchU + shiftU - pitchU / 2 + kStreetWidth / 2;
            const double v0 = j * pitchV + shiftV - pitchV / 2 + kStreetWidth / 2;
            for (int row = 0; row < 2; ++row) {
                double u = u0 + uniform(seed, slot, RowStart, 0.5, 3);
                for (;;) {
                    ++slot;
                    const double frontage = uniform(seed, slot, Frontage, 8, 20);
                    const double depth = uniform(seed, slot, Depth, 8, 16);
                    const double recess = uniform(seed, slot, Recess, 0, 1.5);
                    if (u + frontage > u0 + kBlockLength) break;
                    // Row 0 fronts the street at v0, row 1 the one at v0 + depth of the block;
                    // their backs stay kBlockDepth - 2 (kSetback + 1.5 + 16) = 1 m or more apart.
                    const double front = row == 0 ? v0 + kSetback + recess : v0 + kBlockDepth - kSetback - recess;
                    const double back = row == 0 ? front + depth : front - depth;
                    const double vLow = std::min(front, back), vHigh = std::max(front, back);
                    Footprint f{
                        {world(u, vLow), world(u + frontage, vLow), world(u + frontage, vHigh), world(u, vHigh)}};
                    if (frontage < depth) std::rotate(f.corners.begin(), f.corners.begin() + 1, f.corners.end());
                    if (std::all_of(f.corners.begin(), f.corners.end(), inside)) footprints.push_back(f);
                    u += frontage + uniform(seed, slot, Gap, 1.5, 4);
                }
            }
        }
    }
    return footprints;
}

enum class Roof { Flat, Gable, Hip };

// One building's faces, each a ring counter-clockwise seen from outside (not closed).
struct Face {
    enum Kind { Ground, Wall, Roof } kind;
    std::vector<Vec3> ring;
};

struct Building {
    Roof roof;
    double ground, wallHeight, ridge;  // ridge: the highest point (the eaves for a flat roof)
    std::vector<Face> faces;
};

Building build(const Footprint &footprint, uint64_t seed, uint64_t index) {
    Building b;
    double ground = 1e300;
    for (const Vec3 &c : footprint.corners) ground = std::min(ground, groundHeight(c.x, c.y));
    b.ground = std::round(ground * 1000) / 1000;
    b.wallHeight = std::round(uniform(seed, index, WallHeight, 6, 18) * 100) / 100;
    double kind = uniform(seed, index, RoofKind);
    b.roof = kind < 0.25 ? Roof::Flat : kind < 0.7 ? Roof::Gable : Roof::Hip;
    const double eaves = b.ground + b.wallHeight;
    const double ridgeRise = b.roof == Roof::Flat ? 0 : std::round(uniform(seed, index, RidgeHeight, 2, 6) * 100) / 100;
    b.ridge = eaves + ridgeRise;

    std::array<Vec3, 4> low, top;
    for (size_t i = 0; i < 4; ++i) {
        low[i] = {footprint.corners[i].x, footprint.corners[i].y, b.ground};
        top[i] = {footprint.corners[i].x, footprint.corners[i].y, eaves};
    }
    auto lerp = [](const Vec3 &a, const Vec3 &c, double t) {
        return Vec3{a.x + (c.x - a.x) * t, a.y + (c.y - a.y) * t, a.z + (c.z - a.z) * t};
    };
    // The ridge runs along the long edges 0-1 and 2-3, over the middle of the short ones.
    Vec3 mid1 = lerp(top[1], top[2], 0.5), mid0 = lerp(top[0], top[3], 0.5);
    mid0.z = mid1.z = b.ridge;
    Vec3 ridge0 = mid0, ridge1 = mid1;
    if (b.roof == Roof::Hip) {
        // Hips at the pitch of the long slopes: the ridge stops half the short side from each
        // end, and at least 0.5 m short of the middle.
        const double longSide = std::hypot(top[1].x - top[0].x, top[1].y - top[0].y);
        const double shortSide = std::hypot(top[2].x - top[1].x, top[2].y - top[1].y);
        const double inset = std::min(shortSide / 2, longSide / 2 - 0.5) / longSide;
        ridge0 = lerp(mid0, mid1, inset);
        ridge1 = lerp(mid0, mid1, 1 - inset);
    }

    b.faces.push_back({Face::Ground, {low[0], low[3], low[2], low[1]}});  // facing down
    for (size_t i = 0; i < 4; ++i) {
        size_t next = (i + 1) % 4;
        Face wall{Face::Wall, {low[i], low[next], top[next]}};
        if (b.roof == Roof::Gable && i == 1) wall.ring.push_back(mid1);
        if (b.roof == Roof::Gable && i == 3) wall.ring.push_back(mid0);
        wall.ring.push_back(top[i]);
        b.faces.push_back(std::move(wall));
    }
    switch (b.roof) {
    case Roof::Flat: b.faces.push_back({Face::Roof, {top[0], top[1], top[2], top[3]}}); break;
    case Roof::Gable:
        b.faces.push_back({Face::Roof, {top[0], top[1], ridge1, ridge0}});
        b.faces.push_back({Face::Roof, {top[2], top[3], ridge0, ridge1}});
        break;
    case Roof::Hip:
        b.faces.push_back({Face::Roof, {top[0], top[1], ridge1, ridge0}});
        b.faces.push_back({Face::Roof, {top[1], top[2], ridge1}});
        b.faces.push_back({Face::Roof, {top[2], top[3], ridge0, ridge1}});
        b.faces.push_back({Face::Roof, {top[3], top[0], ridge0}});
        break;
    }
    return b;
}

// Millimetres, as the AdV data gives them.
void appendNumber(std::string &out, double value) {
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 3);
    if (error != std::errc()) throw std::runtime_error("a coordinate does not print");
    out.append(buffer, end);
}

void appendPosList(std::string &out, const std::vector<Vec3> &ring) {
    for (size_t i = 0; i <= ring.size(); ++i) {
        const Vec3 &p = ring[i % ring.size()];  // the first point again closes the ring
        if (i > 0) out += ' ';
        appendNumber(out, p.x);
        out += ' ';
        appendNumber(out, p.y);
        out += ' ';
        appendNumber(out, p.z);
    }
}

int roofTypeCode(Roof roof) {
    switch (roof) {
    case Roof::Flat: return 1000;
    case Roof::Gable: return 3100;
    case Roof::Hip: return 3200;
    }
    return 1000;
}

void appendBuilding(std::string &out, const Building &b, uint64_t number) {
    const std::string id = "DEBW_LOD2_" + std::to_string(number);
    out += "  <core:cityObjectMember>\n    <bldg:Building gml:id=\"" + id + "\">\n";
    out += "      <bldg:function>31001_1000</bldg:function>\n";
    out += "      <bldg:roofType>" + std::to_string(roofTypeCode(b.roof)) + "</bldg:roofType>\n";
    out += "      <bldg:measuredHeight uom=\"urn:adv:uom:m\">";
    appendNumber(out, b.ridge - b.ground);
    out += "</bldg:measuredHeight>\n";
    out += "      <bldg:storeysAboveGround>" + std::to_string(std::lround(b.wallHeight / 3)) +
        "</bldg:storeysAboveGround>\n";
    size_t polygon = 0;
    for (const Face &face : b.faces) {
        const char *kind = face.kind == Face::Ground ? "GroundSurface"
            : face.kind == Face::Wall                ? "WallSurface"
                                                     : "RoofSurface";
        const std::string polygonId = id + "_poly_" + std::to_string(++polygon);
        out += "      <bldg:boundedBy>\n        <bldg:";
        out += kind;
        out += " gml:id=\"" + polygonId + "_surface\">\n";
        out += "          <bldg:lod2MultiSurface>\n            <gml:MultiSurface srsName=\"";
        out += kSrsName;
        out += "\" srsDimension=\"3\">\n";
        out += "              <gml:surfaceMember>\n                <gml:Polygon gml:id=\"" + polygonId + "\">\n";
        out += "                  <gml:exterior>\n                    <gml:LinearRing>\n";
        out += "                      <gml:posList srsDimension=\"3\">";
        appendPosList(out, face.ring);
        out += "</gml:posList>\n";
        out += "                    </gml:LinearRing>\n                  </gml:exterior>\n";
        out += "                </gml:Polygon>\n              </gml:surfaceMember>\n";
        out += "            </gml:MultiSurface>\n          </bldg:lod2MultiSurface>\n        </bldg:";
        out += kind;
        out += ">\n      </bldg:boundedBy>\n";
    }
    out += "    </bldg:Building>\n  </core:cityObjectMember>\n";
}

uint64_t parseNumber(std::string_view option, const char *text, uint64_t low, uint64_t high) {
    uint64_t value = 0;
    std::string_view s(text);
    auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (s.empty() || error != std::errc() || end != s.data() + s.size() || value < low || value > high)
        throw std::invalid_argument(std::string(option) + " takes a whole number from " + std::to_string(low) + " to " +
                                    std::to_string(high) + ", not '" + std::string(s) + "'");
    return value;
}

int run(int argc, char **argv) {
    std::filesystem::path output;
    uint64_t count = 1500, seed = 1;
    for (int i = 1; i < argc; ++i) {
        std::string_view arg(argv[i]);
        if ((arg == "--buildings" || arg == "--seed") && i + 1 < argc) {
            if (arg == "--buildings") count = parseNumber(arg, argv[++i], 1, 1000000);
            else seed = parseNumber(arg, argv[++i], 0, UINT64_MAX);
        } else if (arg == "-h" || arg == "--help") {
            std::printf("usage: %s OUT.gml [--buildings N] [--seed S]   (defaults N=1500, S=1)\n", argv[0]);
            return 0;
        } else if (!arg.starts_with("-") && output.empty()) {
            output = arg;
        } else {
            throw std::invalid_argument("unexpected argument '" + std::string(arg) +
                                        "'; usage: bench_citygml_tile OUT.gml [--buildings N] [--seed S]");
        }
    }
    if (output.empty()) throw std::invalid_argument("usage: bench_citygml_tile OUT.gml [--buildings N] [--seed S]");

    const std::vector<Footprint> slots = layOut(seed);
    if (count > slots.size())
        throw std::invalid_argument("at most " + std::to_string(slots.size()) +
                                    " buildings fit on the tile with seed " + std::to_string(seed) + ", not " +
                                    std::to_string(count));
    // N of the slots, spread evenly over the tile.
    std::vector<Building> buildings;
    buildings.reserve(count);
    double low = 1e300, high = -1e300;
    size_t polygons = 0;
    for (uint64_t n = 0; n < count; ++n) {
        const Footprint &f = slots[size_t(n * slots.size() / count)];
        buildings.push_back(build(f, seed, n));
        low = std::min(low, buildings.back().ground);
        high = std::max(high, buildings.back().ridge);
        polygons += buildings.back().faces.size();
    }

    std::string text;
    text.reserve(count * 8000);
    text += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    text +=
        "<core:CityModel xmlns:core=\"http://www.opengis.net/citygml/2.0\" "
        "xmlns:bldg=\"http://www.opengis.net/citygml/building/2.0\" xmlns:gml=\"http://www.opengis.net/gml\">\n";
    text += "  <gml:name>veduta synthetic LoD2 tile 690_5335, seed " + std::to_string(seed) + "</gml:name>\n";
    text += "  <gml:boundedBy>\n    <gml:Envelope srsName=\"";
    text += kSrsName;
    text += "\" srsDimension=\"3\">\n      <gml:lowerCorner>";
    text += std::to_string(int(kEast0)) + " " + std::to_string(int(kNorth0)) + " ";
    appendNumber(text, low);
    text += "</gml:lowerCorner>\n      <gml:upperCorner>";
    text += std::to_string(int(kEast0 + kTileSize)) + " " + std::to_string(int(kNorth0 + kTileSize)) + " ";
    appendNumber(text, high);
    text += "</gml:upperCorner>\n    </gml:Envelope>\n  </gml:boundedBy>\n";
    for (uint64_t n = 0; n < count; ++n) appendBuilding(text, buildings[size_t(n)], n + 1);
    text += "</core:CityModel>\n";

    // A temporary beside the output, renamed over it: a reader never sees half a file.
    std::filesystem::path temporary = output;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw std::runtime_error("cannot write " + temporary.string());
        }
    }
    std::error_code renamed;
    std::filesystem::rename(temporary, output, renamed);
    if (renamed) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error("cannot rename " + temporary.string() + " to " + output.string() + ": " +
                                 renamed.message());
    }
    std::printf("%s: %llu buildings, %zu polygons (%zu places on the tile, seed %llu)\n", output.string().c_str(),
                static_cast<unsigned long long>(count), polygons, slots.size(), static_cast<unsigned long long>(seed));
    return 0;
}

}  // namespace

int main(int argc, char **argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "bench_citygml_tile: error: %s\n", e.what());
        return 1;
    }
}
