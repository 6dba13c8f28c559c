#include "facade/building_structure.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <set>

#include <fmt/format.h>

#include "core/check.h"
#include "core/hash.h"
#include "core/polygon_area.h"
#include "core/word_hasher.h"
#include "facade/module_partition.h"

namespace veduta {

double ModuleStructure::height() const { return std::accumulate(storeyHeights.begin(), storeyHeights.end(), 0.0); }

int BuildingStructure::moduleIndex(const std::string &name, const FileLoc &loc) const {
    for (size_t m = 0; m < modules.size(); ++m)
        if (modules[m].name == name) return int(m);
    throw InputError(loc, fmt::format("no module is called '{}'", name));
}

size_t BuildingStructure::storeyCount() const {
    size_t most = 0;
    for (const ModuleStructure &m : modules) most = std::max(most, m.storeyHeights.size());
    return most;
}

int BuildingStructure::storeyRole(int storey) const {
    return storeyRoles.empty() ? storey : storeyRoles[size_t(storey)];
}

size_t BuildingStructure::boundStoreyCount() const { return storeyRoles.empty() ? storeyCount() : writtenStoreys; }

namespace {

// Which written storey each of `count` refitted ones repeats (refitStoreys).
std::vector<int> refittedRoles(size_t written, size_t count) {
    std::vector<int> roles{0};
    if (count == 1) return roles;
    const int top = int(written) - 1;
    for (size_t s = 1; s + 1 < count; ++s) roles.push_back(written <= 2 ? top : std::min(int(s), top - 1));
    roles.push_back(top);
    return roles;
}

void checkModule(const ModuleStructure &m) {
    const FileLoc &loc = m.module.loc;
    if (m.storeyHeights.empty()) throw InputError(loc, fmt::format("module '{}' has no storeys", m.name));
    if (m.storeyHeights.size() > kStructureStoreyLimit)
        throw InputError(loc,
                         fmt::format("module '{}' has {} storeys; at most {} are allowed", m.name,
                                     m.storeyHeights.size(), kStructureStoreyLimit));
    for (double h : m.storeyHeights)
        if (!(h >= 0.5 && h <= kStoreyHeightLimit))
            throw InputError(loc,
                             fmt::format("module '{}': a storey of {} m; storeys are 0.5 to {} m high", m.name, h,
                                         kStoreyHeightLimit));
    int edges = int(m.module.outline.size());
    std::vector<const EdgeSubdivision *> byEdge;
    for (const EdgeSubdivision &s : m.subdivisions) {
        if (s.edge < 0 || s.edge >= edges)
            throw InputError(s.loc, fmt::format("module '{}' has no edge {} (it has {})", m.name, s.edge, edges));
        if (!(s.from >= 0 && s.from < s.to && s.to <= 1))
            throw InputError(
                s.loc, fmt::format("the part [{}, {}] of an edge must satisfy 0 <= from < to <= 1", s.from, s.to));
        for (const EdgeSubdivision *t : byEdge)
            if (t->edge == s.edge && t->from < s.to && s.from < t->to)
                throw InputError(s.loc,
                                 fmt::format("the part [{}, {}] of edge {} overlaps [{}, {}] at {}", s.from, s.to,
                                             s.edge, t->from, t->to, t->loc.toString()));
        byEdge.push_back(&s);
    }
}

}  // namespace

void validateStructure(const BuildingStructure &structure) {
    if (structure.modules.empty()) throw InputError({}, "the structure has no modules");
    if (structure.modules.size() > kStructureModuleLimit)
        throw InputError(structure.modules[kStructureModuleLimit].module.loc,
                         fmt::format("more than {} modules", kStructureModuleLimit));
    std::set<std::string> names;
    for (const ModuleStructure &m : structure.modules) {
        if (!names.insert(m.name).second)
            throw InputError(m.module.loc, fmt::format("a second module called '{}'", m.name));
        checkModule(m);
    }
    for (const ModuleDock &d : structure.docks) {
        int docked = structure.moduleIndex(d.docked, d.loc);
        int dominant = structure.moduleIndex(d.dominant, d.loc);
        if (docked == dominant) throw InputError(d.loc, fmt::format("module '{}' is docked onto itself", d.docked));
    }
}

namespace {

void addRoof(WordHasher &h, const RoofStructure &r) {
    h.add(int(r.kind));
    const GeneralRoofParameters &g = r.general;
    for (double v : {double(g.edgeI), double(g.edgeJ), g.c, g.d, g.a, g.b, g.height, r.parapet.height, r.parapet.width})
        h.add(v);
}

}  // namespace

void refitStoreys(BuildingStructure &structure, size_t count) {
    VEDUTA_CHECK(count >= 1 && count <= kStructureStoreyLimit, "a storey count within the limits");
    const std::vector<double> written = structure.modules.front().storeyHeights;
    std::vector<int> roles = refittedRoles(written.size(), count);
    for (ModuleStructure &m : structure.modules) {
        VEDUTA_CHECK(m.storeyHeights == written, "every module with the same storeys");
        m.storeyHeights.clear();
        for (int r : roles) m.storeyHeights.push_back(written[size_t(r)]);
    }
    structure.writtenStoreys = written.size();
    structure.storeyRoles = std::move(roles);
}

size_t storeysNearest(const std::vector<double> &written, double eaves) {
    size_t best = 1;
    double bestMiss = INFINITY;
    for (size_t count = 1; count <= kStructureStoreyLimit; ++count) {
        double height = 0;
        for (int r : refittedRoles(written.size(), count)) height += written[size_t(r)];
        if (std::abs(height - eaves) < bestMiss) {
            best = count;
            bestMiss = std::abs(height - eaves);
        }
        if (height > eaves) break;
    }
    return best;
}

uint64_t structureHash(const BuildingStructure &structure) {
    WordHasher h;
    h.add(structure.modules.size());
    for (const ModuleStructure &m : structure.modules) {
        h.add(m.name);
        h.add(m.module.type);
        h.add(m.module.outline.size());
        for (Vec2d p : m.module.outline) h.add(p);
        h.add(m.storeyHeights.size());
        for (double s : m.storeyHeights) h.add(s);
        addRoof(h, m.roof);
        h.add(m.subdivisions.size());
        for (const EdgeSubdivision &s : m.subdivisions) {
            h.add(s.edge);
            h.add(s.from);
            h.add(s.to);
            h.add(s.slot);
        }
    }
    h.add(structure.storeyRoles.size());
    for (int r : structure.storeyRoles) h.add(r);
    h.add(structure.docks.size());
    for (const ModuleDock &d : structure.docks) {
        h.add(d.docked);
        h.add(d.dockedEdge);
        h.add(d.dominant);
        h.add(d.edge);
        h.add(d.a);
        h.add(d.b);
    }
    return h.value();
}

namespace {

// Where the footprint's corner `corner` went in the module's outline; -1 when it did not (a
// collinear corner removed).
int cornerIndex(const std::vector<Vec2d> &outline, Vec2d corner) {
    for (size_t i = 0; i < outline.size(); ++i)
        if (outline[i] == corner) return int(i);
    return -1;
}

// The prototype's roof and subdivisions, their edges renumbered from the footprint's to the module's.
void keepPrototypeEdges(const ModuleStructure &prototype, const std::vector<Vec2d> &footprint, const FileLoc &loc,
                        ModuleStructure &module) {
    const std::vector<Vec2d> &outline = module.module.outline;
    // A clockwise footprint's edge e runs backwards in the module: from corner e + 1.
    bool clockwise = signedArea(footprint) < 0;
    auto edge = [&](size_t footprintEdge) {
        size_t n = footprint.size(), start = clockwise ? (footprintEdge + 1) % n : footprintEdge;
        int i = footprintEdge < n ? cornerIndex(outline, footprint[start]) : -1;
        if (i < 0)
            throw InputError(loc,
                             fmt::format("edge {} of the prototype's roof or windows is not an edge of the "
                                         "footprint ({} corners, none collinear)",
                                         footprintEdge, outline.size()));
        return i;
    };
    module.roof = prototype.roof;
    if (prototype.roof.kind == RoofStructure::Kind::General) {
        module.roof.general.edgeI = size_t(edge(prototype.roof.general.edgeI));
        module.roof.general.edgeJ = size_t(edge(prototype.roof.general.edgeJ));
    }
    module.subdivisions = prototype.subdivisions;
    for (EdgeSubdivision &s : module.subdivisions) s.edge = edge(size_t(s.edge));
}

}  // namespace

BuildingStructure structureOnFootprint(const ModuleStructure &prototype, const std::vector<Vec2d> &footprint,
                                       const FileLoc &loc) {
    FloorPlan plan = partitionFootprint(footprint, prototype.module, loc);
    BuildingStructure structure;
    for (size_t m = 0; m < plan.modules().size(); ++m) {
        ModuleStructure module;
        module.name = plan.modules().size() == 1 ? prototype.name : fmt::format("{} {}", prototype.name, m + 1);
        module.module = plan.modules()[m];
        module.storeyHeights = prototype.storeyHeights;
        module.roof.kind = RoofStructure::Kind::Flat;
        module.roof.parapet = prototype.roof.parapet;
        module.roof.loc = prototype.roof.loc;
        structure.modules.push_back(std::move(module));
    }
    if (structure.modules.size() == 1) keepPrototypeEdges(prototype, footprint, loc, structure.modules[0]);
    for (const KkConnection &c : plan.kkConnections())
        structure.docks.push_back({structure.modules[size_t(c.docked)].name, c.dockedEdge,
                                   structure.modules[size_t(c.dominant)].name, c.edge, c.a, c.b, loc});
    validateStructure(structure);
    return structure;
}

}  // namespace veduta
