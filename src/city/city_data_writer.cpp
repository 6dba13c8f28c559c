#include "city/city_data_writer.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <pugixml.hpp>

#include "core/atomic_file.h"

namespace veduta {

namespace {

// The ids of the points written, and the new points that block and lot corners need.
class PointTable {
  public:
    explicit PointTable(const CityData &city) {
        for (const CityPoint &p : city.points) {
            points_.push_back(p);
            byPlace_.emplace(Place{float(p.e), float(p.n), float(p.u)}, p.id);
            next_ = std::max(next_, p.id + 1);
        }
    }

    uint32_t idOf(const Vec2f &corner, float base) {
        auto [it, fresh] = byPlace_.emplace(Place{corner.x, corner.y, base}, next_);
        if (fresh) points_.push_back({next_++, corner.x, corner.y, base, {}});
        return it->second;
    }
    const std::vector<CityPoint> &points() const { return points_; }

  private:
    std::vector<CityPoint> points_;
    // A corner's point must have its block's height too (a block's points share one).
    using Place = std::tuple<float, float, float>;
    std::map<Place, uint32_t> byPlace_;
    uint32_t next_ = 0;
};

void addSettings(pugi::xml_node parent, const SettingsMap &settings) {
    if (settings.empty()) return;
    std::map<std::string, std::string> sorted;
    for (const auto &[name, value] : settings) sorted.emplace(name, value.text);
    pugi::xml_node node = parent.append_child("BuildingSettings");
    for (const auto &[name, text] : sorted) node.append_child(name.c_str()).text().set(text.c_str());
}

void addCorners(pugi::xml_node parent, const std::vector<Vec2f> &corners, const std::vector<bool> &streetEdges,
                float base, PointTable &table) {
    pugi::xml_node list = parent.append_child("Points");
    for (size_t i = 0; i < corners.size(); ++i) {
        pugi::xml_node point = list.append_child("Point");
        point.append_attribute("id").set_value(table.idOf(corners[i], base));
        if (i < streetEdges.size() && streetEdges[i]) point.append_attribute("streetEdge").set_value(1);
    }
}

// A value exactly, in its shortest digits: a float's (every coordinate and width veduta makes)
// as a float, so 12.3f is "12.3".
std::string number(double value) {
    if (double(float(value)) == value) return fmt::format("{}", float(value));
    return fmt::format("{}", value);
}

// A point's coordinate: local metres exactly; a map coordinate to 0.1 mm, without trailing
// zeros, rather than the float noise of its local part.
std::string coordinate(double local, double offset) {
    if (offset == 0) return number(local);
    std::string text = fmt::format("{:.4f}", offset + local);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
}

std::string ruleFilePath(const std::filesystem::path &rules, const std::filesystem::path &folder) {
    std::filesystem::path absolute = std::filesystem::absolute(rules).lexically_normal();
    std::filesystem::path base = std::filesystem::absolute(folder.empty() ? "." : folder).lexically_normal();
    std::filesystem::path relative = absolute.lexically_relative(base);
    bool under = !relative.empty() && *relative.begin() != "..";
    return (under ? relative : absolute).generic_string();
}

}  // namespace

std::string cityDataXml(const CityData &city, const CityDataWriting &writing, const std::filesystem::path &folder) {
    pugi::xml_document document;
    if (!writing.comment.empty())
        document.append_child(pugi::node_comment).set_value((" " + writing.comment + " ").c_str());
    pugi::xml_node root = document.append_child("CityData");
    PointTable table(city);
    pugi::xml_node blocks = root.append_child("Blocks");
    for (const CityBlock &block : city.blocks) {
        pugi::xml_node node = blocks.append_child("Block");
        addCorners(node, block.points, {}, block.base, table);
        if (!block.lots.empty()) {
            pugi::xml_node lots = node.append_child("Lots");
            for (const CityLot &lot : block.lots) {
                pugi::xml_node lotNode = lots.append_child("Lot");
                addCorners(lotNode, lot.points, lot.streetEdges, lot.base, table);
                addSettings(lotNode, lot.settings);
            }
        }
        addSettings(node, block.settings);
    }
    // The points go first, as in Bilke's listing, once the corners have added theirs.
    pugi::xml_node points = root.insert_child_before("Points", blocks);
    for (const CityPoint &p : table.points()) {
        pugi::xml_node point = points.append_child("Point");
        point.append_attribute("id").set_value(p.id);
        point.append_attribute("e").set_value(coordinate(p.e, writing.offset.east).c_str());
        point.append_attribute("n").set_value(coordinate(p.n, writing.offset.north).c_str());
        if (p.u != 0) point.append_attribute("u").set_value(number(p.u).c_str());
    }
    pugi::xml_node network = root.insert_child_before("StreetNetwork", blocks);
    pugi::xml_node streets = network.append_child("Streets");
    for (const CityStreet &s : city.streets) {
        pugi::xml_node street = streets.append_child("Street");
        street.append_attribute("id").set_value(s.id);
        street.append_attribute("startPoint").set_value(city.points.at(s.start).id);
        street.append_attribute("endPoint").set_value(city.points.at(s.end).id);
        if (s.width) street.append_attribute("width").set_value(number(*s.width).c_str());
    }
    network.append_child("Width").text().set(number(city.streetWidth).c_str());
    addSettings(root, city.settings);
    if (!city.ruleFiles.empty()) {
        pugi::xml_node rules = root.append_child("Rulefiles");
        for (const std::filesystem::path &file : city.ruleFiles)
            rules.append_child("Rulefile").text().set(ruleFilePath(file, folder).c_str());
    }
    std::ostringstream out;
    document.save(out, "  ");
    return out.str();
}

void writeCityData(const CityData &city, const CityDataWriting &writing, const std::filesystem::path &file) {
    std::string xml = cityDataXml(city, writing, file.parent_path());
    writeBytesAtomically(file, xml.data(), xml.size());
}

}  // namespace veduta
