// The building description language (digest-001 §1 "separation of building structure and style",
// §3, App. A L1737–1771): two texts in the block syntax of the small languages
// (description_text.h) that say what the thesis's world model says in ~200 kB of XML (L1562), the
// structure (building_structure.h) and a style with its bindings (building_style.h). A structure:
//
//   Module  { "Corps", "Haupthaus"; 0, 0; 30, 0; 30, 14; 0, 14; }  # name[, type]; corners x, y (m)
//   Storeys { "Corps"; 4.5; 4.0, 3; 3.2; }      # module; per item a height, or height, count
//   Roof    { "Corps"; hip, 3, 1, 5, 0.25; }    # module; one roof (below)
//   Dock    { "Ostflügel", 3, "Corps", 1, 0.1, 0.4; }  # docked, its edge, dominant, its edge, a, b
//   Windows { "Corps"; 0, 0.0, 0.5, 2; }        # module; per item edge, from, to, window slot
//
// Roofs (Defs 4.12, 4.13; Table 4.3): `general, e_i, e_j, c, d, a, b, h`, and the special cases
// `gable, e_i, e_j, h` (c = d = 0.5, a = 0, b = 1), `hip, e_i, e_j, h, inset` (c = d = 0.5,
// a = inset, b = 1 − inset, 0 < inset < 0.5), `pyramid, e_i, e_j, h` (c = d = 0.5, a = b = 0.5),
// `shed, e, h` (L963: i = j = e, c = 0, d = 1, a = 0, b = 1: the ridge stands h over edge e, whose
// vertical quad is the roof's one interface, §8 row 5) and `flat, h, w` (parapet height, width).
// A style:
//
//   Style { "klassisch";
//     walls, 0.8, 0.6, 4;               # Unterteilung: corner width, ZWE width, wall:ZWE ratio
//     masonry, plain;                   # or bricks, "f", m per unit; ashlar, "f", m per unit;
//                                       #    cyclopean, "f" (metres)
//     window, 0, 1.2, 2.2, 0.9, 1, 1;   # slot, width, height, sill, dist left, dist right
//     door, 1, 1.4, 2.8, 1, 1;          # slot, width, height, dist left, dist right
//     casing, 0, gesims, 0.15, 0.05, 0.05;  # slot, einfach|gesims|doppelgesims|klinker, size,
//                                       #    thickness, overhang (m)
//     frame, 0, 0.06, -0.05, -0.1;      # slot, thickness, overhang, pane depth (m)
//     apron, 0, 0.5, 0.025;             # slot, height (0.1–10 m), depth (0–1 m): a window's
//                                       #    ornamented panel below it (apron_ornament.h)
//     band, 0.0, 0.08, "cornice.txt";   # Wandpartition [vStart, vStop] of the storey, its Gesims
//     bands, none;                      # no bands here (ends the chain's search for bands)
//     material, wall, "putz";           # stylePartName (quoted where not a word:
//                                       #    "roof-side"), scene material
//   }
//   Bind { building, "klassisch"; storey, 0, "rustika"; module, "Ostflügel", "schlicht"; }
//
// Choices where the thesis is open:
// * A module without a Roof block has a flat roof with ParapetParameters' 1 m × 0.3 m parapet: a
//   flat roof needs no edges chosen, and 1 m is the usual parapet (Attika) of a flat roof, 0.3 m
//   a wall's thickness. Every module needs a Storeys block: its height is its storeys'.
// * Blocks may come in any order; one Storeys, Roof and Windows block per module, any number of
//   Dock blocks and items. Items of a Style may come in any order; a single-valued one (walls,
//   masonry, bands none, a slot's window, casing, frame or apron, a part's material) given twice is an
//   error, as is `band` beside `bands, none`.
// * Casing (Def 5.14, FTStock): every edge has the item's thickness bf (a fraction of the opening
//   across the edge, casings.h) and overhang, except a door's threshold, which has none (doors
//   ignore their bottom edge, L1520). `size` is the top edge's band F_Kantenzug (Def 5.13): with
//   the default dominance (bottom and top) only they may have one, and the bottom is the sill. A
//   gesims (a hood cornice over the window) may have a straight band at least bf deep; a
//   doppelgesims must have a band at least 2·bf deep, which gets a triangular gable (the pediment
//   of classicist windows, Fig. 5.41), the tympanum between its two cornices; einfach and klinker
//   have no band (size 0), and klinker takes casings.h's bricks (0.25 m, 2 cm overhang, 1 cm
//   joints), which the thesis's Klinker concept gives no place here.
// * A casing, frame or apron names a slot whose window or door is in the same Style: the thesis
//   hangs them on their FensterTuer (hat_FTStock, hat_Fensterrahmen), so they are not inherited
//   alone. A door has no apron.
// * Named files are read through the caller's `readFile` once per name and parsed once per use,
//   so every style that names one shares one description (shared_ptr). Their errors are the
//   file's own, at its line and column.
// * Bounds: sizes and coordinates at most kBuildingSizeLimit metres, slots in [0,
//   kWindowSlotLimit), modules, storeys and styles within building_structure.h's and
//   building_style.h's limits, at most kModuleCornerLimit corners to a module.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "core/error.h"
#include "facade/building_structure.h"
#include "facade/building_style.h"

namespace veduta {

inline constexpr double kBuildingSizeLimit = 1e4;  // metres: any length, coordinate or height
inline constexpr size_t kModuleCornerLimit = 1000;

// Reads a structure and validates it (validateStructure). Throws InputError "file:line:col: …".
BuildingStructure parseBuildingStructure(std::string_view text, const std::string &file);

// The text of a file that a style names (`name` as written, `loc` where): the caller resolves
// the name and bounds the size; it throws InputError at `loc` when it cannot.
using DescribedFileReader = std::function<std::string(const std::string &name, const FileLoc &loc)>;

// Reads a style with its bindings and the masonry and cornice files it names. Throws InputError
// "file:line:col: …"; a named file's errors are at its own place.
BuildingStyle parseBuildingStyle(std::string_view text, const std::string &file, const DescribedFileReader &readFile);

}  // namespace veduta
