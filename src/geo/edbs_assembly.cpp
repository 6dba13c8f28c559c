// toAtkis: EDBS records (edbs.cpp) assembled into ATKIS objects.
#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "core/error.h"
#include "geo/edbs.h"
#include "geo/element_chaining.h"

namespace veduta {

namespace {

using PartKey = std::pair<std::string, std::string>;  // Objektnummer, Objektteilnummer

std::string pointText(const MapPoint &p) { return fmt::format("({:.3f}, {:.3f})", p.easting, p.northing); }

MapLine elementPoints(const EdbsLine &line) {
    MapLine points{line.start};
    points.insert(points.end(), line.between.begin(), line.between.end());
    points.push_back(line.end);
    return points;
}

// Crossing number; a point on a vertex of the ring counts as neither inside nor outside.
std::optional<bool> inside(const MapPoint &p, const MapRing &ring) {
    bool in = false;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const MapPoint &a = ring[i], &b = ring[j];
        if (a == p) return std::nullopt;
        if ((a.northing > p.northing) != (b.northing > p.northing) &&
            p.easting < (b.easting - a.easting) * (p.northing - a.northing) / (b.northing - a.northing) + a.easting)
            in = !in;
    }
    return in;
}

// A ring lies in another when its vertices that are not shared with it are all inside.
bool liesIn(const MapRing &ring, const MapRing &other) {
    int in = 0;
    for (const MapPoint &p : ring) {
        std::optional<bool> side = inside(p, other);
        if (side == false) return false;
        in += side == true;
    }
    return in > 0;
}

// The elements of every object part, each element once per part; an element with the same
// part on both sides lies inside the area and is no part of its outline.
std::map<PartKey, std::vector<MapLine>> elementsByPart(const EdbsFile &file, std::set<std::string> &unknown,
                                                       const std::map<std::string, const EdbsObject *> &objects) {
    std::map<PartKey, std::vector<MapLine>> parts;
    for (const EdbsLine &line : file.lines) {
        std::set<PartKey> right, left;
        for (const EdbsLineFunction &f : line.functions) {
            if (!f.right.empty()) right.insert({f.right, f.rightPart});
            if (!f.left.empty()) left.insert({f.left, f.leftPart});
        }
        std::set<PartKey> sides = right;
        sides.insert(left.begin(), left.end());
        for (const PartKey &part : sides) {
            auto object = objects.find(part.first);
            if (object == objects.end()) {
                unknown.insert(part.first);
                continue;
            }
            bool bothSides = right.count(part) && left.count(part);
            if (bothSides && object->second->geometry == 'F') continue;
            parts[part].push_back(elementPoints(line));
        }
    }
    return parts;
}

class Assembler {
  public:
    Assembler(const EdbsFile &file, IncompleteObjects incomplete) : file_(file), incomplete_(incomplete) {}

    EdbsConversion run() {
        for (const EdbsObject &object : file_.objects) {
            auto [it, added] = objects_.emplace(object.id, &object);
            if (!added)
                throw InputError(FileLoc{file_.path, object.source.line, 0},
                                 fmt::format("record {}: object {} is defined again (first in record {})",
                                             object.source.record, object.id, it->second->source.record));
        }
        std::set<std::string> unknownInLines, unknownInAttributes;
        parts_ = elementsByPart(file_, unknownInLines, objects_);
        for (const EdbsAttributes &set : file_.attributes) {
            if (!objects_.count(set.id)) {
                unknownInAttributes.insert(set.id);
                continue;
            }
            auto &target = attributes_[{set.id, set.part}];
            for (const auto &[name, value] : set.values) target[name] = value;
        }
        noteUnknown(unknownInLines, "line elements name");
        noteUnknown(unknownInAttributes, "attribute records name");
        for (const EdbsObject &object : file_.objects) add(object);
        return std::move(result_);
    }

  private:
    void noteUnknown(const std::set<std::string> &ids, std::string_view what) {
        if (ids.empty()) return;
        result_.warnings.push_back(fmt::format("{}: {} {} object{} not in the file (the first: {})", file_.path, what,
                                               ids.size(), ids.size() == 1 ? "" : "s", *ids.begin()));
    }

    std::string label(const EdbsObject &object, const std::string &part) const {
        std::string kind = object.geometry == 'F' ? "area" : object.geometry == 'L' ? "line" : "point";
        std::string partText = part.empty() ? "" : fmt::format(" part {}", part);
        return fmt::format("{} object {}{} (Objektart {})", kind, object.id, partText, object.type);
    }

    // An object that cannot be made whole: an error, or left out and listed.
    void incomplete(const EdbsObject &object, const std::string &what) {
        std::string message = fmt::format("record {}: {}", object.source.record, what);
        if (incomplete_ == IncompleteObjects::Error)
            throw InputError(FileLoc{file_.path, object.source.line, 0}, message);
        result_.skipped.push_back(std::move(message));
    }

    AtkisObject base(const EdbsObject &object) const {
        AtkisObject a;
        a.id = object.id;
        // ALK Objektarten share the 4-digit range with ATKIS ones but mean other things.
        if (file_.coordinates() == EdbsCoordinates::Atkis) {
            a.type = std::stoi(object.type);
        } else {
            a.typeName = fmt::format("ALK {}", object.type);
            a.attributes["OBJART"] = object.type;
            a.attributes["FOLIE"] = object.folie;  // what ALK objects are classed by (landClass)
        }
        a.geometry = object.geometry == 'P' ? AtkisGeometry::Point
            : object.geometry == 'L'        ? AtkisGeometry::Line
                                            : AtkisGeometry::Area;
        a.where = fmt::format("{}: record {}", file_.path, object.source.record);
        return a;
    }

    // The outlines of one area part: rings inside another ring of the part are holes, dropped.
    std::vector<MapRing> outlines(const EdbsObject &object, const std::string &part, std::vector<MapRing> rings) {
        std::vector<bool> hole(rings.size(), false);
        for (size_t i = 0; i < rings.size(); ++i)
            for (size_t j = 0; j < rings.size() && !hole[i]; ++j) hole[i] = j != i && liesIn(rings[i], rings[j]);
        std::vector<MapRing> kept;
        for (size_t i = 0; i < rings.size(); ++i)
            if (!hole[i]) kept.push_back(std::move(rings[i]));
        size_t holes = rings.size() - kept.size();
        if (holes > 0)
            result_.warnings.push_back(fmt::format("{}: record {}: {}: {} hole{} left out (ATKIS areas have none)",
                                                   file_.path, object.source.record, label(object, part), holes,
                                                   holes == 1 ? "" : "s"));
        return kept;
    }

    // The geometry of every part of `object`, by part; false when it is incomplete.
    bool geometry(const EdbsObject &object, std::map<std::string, AtkisObject> &byPart) {
        auto first = parts_.lower_bound({object.id, ""});
        if (first == parts_.end() || first->first.first != object.id) {
            incomplete(object, fmt::format("{} has no line elements in the file", label(object, "")));
            return false;
        }
        for (auto it = first; it != parts_.end() && it->first.first == object.id; ++it) {
            const std::string &part = it->first.second;
            AtkisObject &target = byPart.try_emplace(part, base(object)).first->second;
            if (object.geometry == 'L') {
                target.lines = chainLines(it->second);
                continue;
            }
            RingChaining chained = chainRings(it->second);
            if (!chained.closed) {
                incomplete(object,
                           fmt::format("{}: outline does not close: it stops at {}, {} of its {} elements left over",
                                       label(object, part), pointText(chained.openEnd), chained.unusedElements,
                                       it->second.size()));
                return false;
            }
            target.areas = outlines(object, part, std::move(chained.rings));
            if (target.areas.empty())
                result_.warnings.push_back(fmt::format("{}: record {}: {}: its elements enclose nothing", file_.path,
                                                       object.source.record, label(object, part)));
        }
        return true;
    }

    void add(const EdbsObject &object) {
        auto own = attributes_.find({object.id, ""});
        auto withAttributes = [&](AtkisObject a, const std::string &part) {
            if (own != attributes_.end()) a.attributes.insert(own->second.begin(), own->second.end());
            if (auto it = attributes_.find({object.id, part}); !part.empty() && it != attributes_.end())
                for (const auto &[name, value] : it->second) a.attributes[name] = value;
            return a;
        };
        if (object.geometry == 'P') {
            AtkisObject a = withAttributes(base(object), "");
            a.points.push_back(object.reference);
            result_.atkis.objects.push_back(std::move(a));
            return;
        }
        std::map<std::string, AtkisObject> byPart;
        if (!geometry(object, byPart)) return;
        // Parts with attributes of their own (a new part starts where BRF changes) become
        // objects of their own; otherwise the parts make one object.
        bool ownParts = std::any_of(byPart.begin(), byPart.end(), [&](const auto &entry) {
            return !entry.first.empty() && attributes_.count({object.id, entry.first});
        });
        if (ownParts) {
            for (auto &[part, a] : byPart) {
                AtkisObject each = withAttributes(std::move(a), part);
                if (!part.empty()) each.where += fmt::format(", part {}", part);
                result_.atkis.objects.push_back(std::move(each));
            }
            return;
        }
        AtkisObject whole = withAttributes(base(object), "");
        for (auto &[part, a] : byPart) {
            whole.areas.insert(whole.areas.end(), a.areas.begin(), a.areas.end());
            whole.lines.insert(whole.lines.end(), a.lines.begin(), a.lines.end());
        }
        result_.atkis.objects.push_back(std::move(whole));
    }

    const EdbsFile &file_;
    IncompleteObjects incomplete_;
    std::map<std::string, const EdbsObject *> objects_;
    std::map<PartKey, std::vector<MapLine>> parts_;
    std::map<PartKey, std::map<std::string, std::string>> attributes_;
    EdbsConversion result_;
};

}  // namespace

EdbsConversion toAtkis(const EdbsFile &file, IncompleteObjects incomplete) { return Assembler(file, incomplete).run(); }

}  // namespace veduta
