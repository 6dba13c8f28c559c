#include "geodesy/map_projection.h"

#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

const Crs &projectedSceneCrs(const Georeference &scene) {
    const Crs &crs = crsByEpsg(scene.epsg);
    if (!crs.projected)
        throw std::invalid_argument(fmt::format("a scene's CRS is projected; EPSG:{} is not", crs.epsg));
    return crs;
}

}  // namespace

MapProjection::MapProjection(const Crs &source, const Georeference &scene) :
    source_(&source), scene_(&projectedSceneCrs(scene)), frame_{{scene.originEasting, scene.originNorthing}} {}

MapPoint MapProjection::toScene(const MapPoint &p) const {
    checkAxis(*source_, 0, p.easting);
    checkAxis(*source_, 1, p.northing);
    if (source_->epsg == scene_->epsg) return p;
    CrsCoordinate c = convert(*source_, *scene_, {p.easting, p.northing, 0});
    return {c.x, c.y};
}

MapPoint MapProjection::toLocal(const MapPoint &p) const {
    MapPoint s = toScene(p);
    return {s.easting - frame_.origin.easting, s.northing - frame_.origin.northing};
}

Vec3f MapProjection::toRender(const CrsCoordinate &p) const { return frame_.toLocal(toScene({p.x, p.y}), p.z); }

}  // namespace veduta
