// BeTA2007, the NTv2 grid that Germany's surveying authorities (AdV) define for DHDN ↔ ETRS89,
// read through PROJ from the grid file Debian's proj-data installs (BETA2007.gsb in PROJ's
// data folder). It covers Germany and a margin around it; see docs/coordinates.md.
#pragma once

#include <optional>

#include "geodesy/crs.h"

namespace veduta {

// Whether PROJ finds BETA2007.gsb (PROJ_DATA or PROJ's installed data folder).
bool beta2007Installed();

// The shift of a point on one datum to the other by BeTA2007's bilinear interpolation; the
// way back iterates to the point whose forward shift is the given one (PROJ's inverse, to
// about 1e−10°). std::nullopt when the point lies outside the grid or the grid is not
// installed. Safe to call from any thread: each thread keeps its own PROJ context.
std::optional<GeographicPoint> beta2007DhdnToEtrs89(const GeographicPoint &dhdn);
std::optional<GeographicPoint> beta2007Etrs89ToDhdn(const GeographicPoint &etrs89);

}  // namespace veduta
