// The ground a grown town's streets may not cross (StreetEnvironment, streets/street_builder.h):
// a slope steeper than a street may climb on the DGM, the edge of the DGM, and the ATKIS areas
// of water and forest. docs/generate.md, "On real terrain".
#pragma once

#include <optional>
#include <vector>

#include "city/city_data.h"
#include "geo/atkis.h"
#include "geo/generate_landscape.h"
#include "geo/height_grid.h"
#include "geodesy/local_frame.h"
#include "streets/street_builder.h"

namespace veduta {

struct GroundLimits {
    // Rise over run along a street: RASt 06 allows up to 12 % on access streets (8 % on main ones).
    float maxGrade = 0.12f;
    float step = 5;  // metres between the places sampled along a street
};

class GroundEnvironment final : public StreetEnvironment {
  public:
    // `grid` (null: no terrain) and `frame` are the scene's; `obstacles` are rings in its local
    // frame; `centre` is where the rules' origin lies in it (growCity's centre). The grid and
    // the frame must outlive the environment.
    GroundEnvironment(const HeightGrid *grid, const LocalFrame &frame, std::vector<LocalPolygon> obstacles,
                      Vec2d centre, GroundLimits limits = {});

    // Sampled every `step` along the street: the length up to the last place before one inside
    // an obstacle, off the DGM, or past a stretch steeper than maxGrade.
    float freeLength(const Vec3f &start, const Vec3f &direction, float length) const override;

  private:
    bool inObstacle(const Vec2d &p) const;
    std::optional<double> heightAt(const Vec2d &p) const;

    const HeightGrid *grid_;
    LocalFrame frame_;
    std::vector<LocalPolygon> obstacles_;
    std::vector<std::pair<Vec2d, Vec2d>> boxes_;  // each obstacle's, low and high corners
    Vec2d centre_;
    GroundLimits limits_;
};

// The outlines of the ATKIS areas no street crosses: water, standing and flowing, and forest.
std::vector<LocalPolygon> streetObstacles(const std::vector<AtkisObject> &objects, const LocalFrame &frame);

// Polylines of the local frame as roads a town grows onto (CityGrowth::roads): in metres from
// `centre`, cut at the circle of `reach` round it: each run of a line inside the circle, a piece
// crossing the circle ending on it.
std::vector<std::vector<Vec2f>> roadsInWindow(const std::vector<std::vector<Vec2d>> &lines, Vec2d centre, double reach);

// The streets of a CityData (an OpenStreetMap file's highways, importOsm) as lines of its frame,
// for roadsInWindow.
std::vector<std::vector<Vec2d>> streetLines(const CityData &data);

// The roads already on the map of an ATKIS landscape: its road lines (LandClass::Road) in the
// window, as roadsInWindow cuts them.
std::vector<std::vector<Vec2f>> existingRoads(const std::vector<AtkisObject> &objects, const LocalFrame &frame,
                                              Vec2d centre, double reach);

}  // namespace veduta
