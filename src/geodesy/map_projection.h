// The one route from map coordinates to render coordinates (docs/coordinates.md): a point of
// some supported CRS, in double, is converted into the scene's CRS (geo/crs.h), made local to
// the scene origin in double (geo/local_frame.h), and only then made float. Every input with
// map coordinates takes it: ATKIS layers, georeferenced meshes, CityData, OpenStreetMap.
#pragma once

#include "core/vecmath.h"
#include "geodesy/crs.h"
#include "geodesy/georeference.h"
#include "geodesy/local_frame.h"
#include "geodesy/map_point.h"

namespace veduta {

// Data in the CRS `source` placed in a georeferenced scene. A geographic source takes
// longitude as x and latitude as y, as CrsCoordinate does.
class MapProjection {
  public:
    // Throws std::invalid_argument when the scene's CRS is not a supported projected one.
    MapProjection(const Crs &source, const Georeference &scene);

    const Crs &source() const { return *source_; }
    const Crs &sceneCrs() const { return *scene_; }
    const LocalFrame &frame() const { return frame_; }

    // The point in the scene's CRS. Throws std::out_of_range, saying why, when it cannot be a
    // point of the source (checkAxis): a GeoJSON's longitude read as a Gauss-Krüger Rechtswert.
    MapPoint toScene(const MapPoint &p) const;
    // Metres east and north of the scene origin, still double.
    MapPoint toLocal(const MapPoint &p) const;
    // The render-frame point: x, y local, z the height, which no conversion changes.
    Vec3f toRender(const CrsCoordinate &p) const;

  private:
    const Crs *source_;
    const Crs *scene_;
    LocalFrame frame_;
};

}  // namespace veduta
