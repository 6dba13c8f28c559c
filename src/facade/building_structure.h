// The structure of a Finkenzeller building (digest-001 §3, "Structure concepts"; App. A,
// L1737–1771): floor-plan modules docked by KK connections, each with its storeys (Grundsteine),
// its roof (Dach) and the subdivisions of its edges (PolygonKantenUnterteilung) into window slots.
// The structure says where things are; what they look like is the style's (building_style.h),
// bound to it by names and slot numbers only, so that one structure renders in several styles and
// its hash stays the same across them (§8 row 18).
//
// Choices where the thesis is open:
// * Storeys belong to modules, counted from the ground: storey s of a building is every module
//   with more than s storeys. The thesis's inter_Verbindung (a module docked onto the storey
//   below) is this with each module's own storey heights.
// * A window slot is an integer. The thesis's example `{([0,0.5],2),([0.5,1.0],4)}` names window
//   styles by number in the structure; the style says what each number looks like. Slot 0 is
//   every edge that no subdivision names.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "facade/floor_plan.h"
#include "facade/general_roof.h"

namespace veduta {

// Dach: the general roof of a module (Table 4.3), or a flat roof with a parapet.
struct RoofStructure {
    enum class Kind { General, Flat };
    Kind kind = Kind::General;
    GeneralRoofParameters general;
    ParapetParameters parapet;
    FileLoc loc;
};

// PolygonKantenUnterteilung: the part [from, to] of a module's edge (in the edge's parameter)
// shows window slot `slot`.
struct EdgeSubdivision {
    int edge = 0;
    double from = 0, to = 1;
    int slot = 0;
    FileLoc loc;
};

struct ModuleStructure {
    std::string name;  // what styles and docks call it
    FloorPlanModule module;
    std::vector<double> storeyHeights;  // Grundsteine, from the ground up, metres
    RoofStructure roof;
    std::vector<EdgeSubdivision> subdivisions;

    double height() const;  // the eaves: every storey's height summed
};

// KK docking by module names: module `docked`'s edge `dockedEdge` lies on [a, b] of edge `edge`
// of module `dominant` (Def 4.3; floor_plan.h says how the docked edge is turned).
struct ModuleDock {
    std::string docked;
    int dockedEdge = 0;
    std::string dominant;
    int edge = 0;
    double a = 0, b = 1;
    FileLoc loc;
};

inline constexpr size_t kStructureModuleLimit = 1000;
inline constexpr size_t kStructureStoreyLimit = 200;
inline constexpr double kStoreyHeightLimit = 100;  // metres; the least is 0.5 m

struct BuildingStructure {
    std::vector<ModuleStructure> modules;
    std::vector<ModuleDock> docks;
    // Storeys refitted to a count (refitStoreys): storey s of the building repeats storey
    // storeyRoles[s] of the structure as written, which had `writtenStoreys`; a style binds
    // those (building_style.h). Empty: every storey is as written.
    std::vector<int> storeyRoles;
    size_t writtenStoreys = 0;

    // The module called `name`; an InputError at `loc` when there is none.
    int moduleIndex(const std::string &name, const FileLoc &loc) const;
    size_t storeyCount() const;        // the most storeys of any module
    int storeyRole(int storey) const;  // the written storey that a style's binding names
    size_t boundStoreyCount() const;   // the storeys a style may bind: as written
};

// Throws InputError at the offending place for names used twice, docks naming unknown modules,
// storey counts and heights out of bounds, subdivisions outside [0, 1] or overlapping on one edge.
void validateStructure(const BuildingStructure &structure);

// The structure of a building on `footprint` (digest-001 §9: city data's outlines into modules):
// the footprint split into convex modules docked on their shared edges (module_partition.h), each
// with the storeys of `prototype`. A footprint that is one module keeps the prototype's roof and
// edge subdivisions, their edges numbered as the footprint's (edge 0 from its first corner, as the
// footprint is given: the street side in a scene); one split into several gets flat roofs with the
// prototype's parapet, since a roof edge of the prototype names no edge of a piece.
BuildingStructure structureOnFootprint(const ModuleStructure &prototype, const std::vector<Vec2d> &footprint,
                                       const FileLoc &loc);

// Storey subdivision and repetition (§2.2) for data that counts a building's storeys or gives its
// height: every module of a one-storey-list structure (as structureOnFootprint makes) gets `count`
// storeys. The ground storey and the top one stay as written; between them come the written middle
// storeys, the last of them repeated upward where the count asks for more, the upper ones left out
// where it asks for fewer (one storey: the ground storey alone). A structure of two storeys repeats
// its top one. `count` is at least 1 and at most kStructureStoreyLimit.
void refitStoreys(BuildingStructure &structure, size_t count);

// The storey count whose refitted storeys (refitStoreys of `written`) reach nearest `eaves` metres;
// the fewer storeys on a tie.
size_t storeysNearest(const std::vector<double> &written, double eaves);

// A hash of everything the structure says, and nothing else: not the places, not any style.
uint64_t structureHash(const BuildingStructure &structure);

}  // namespace veduta
