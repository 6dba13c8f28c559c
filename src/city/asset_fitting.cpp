#include "city/asset_fitting.h"

#include <algorithm>

namespace veduta {

float depthScale(ModelType type, ZScale zScale, float sx, float sy) {
    switch (zScale) {
    case ZScale::None: return 1;
    case ZScale::Right: return sx;
    case ZScale::Up: return sy;
    case ZScale::Average: return (sx + sy) / 2;
    case ZScale::NotSet: break;
    }
    switch (type) {
    case ModelType::Horizontal: return sy;
    case ModelType::Vertical: return sx;
    case ModelType::HorizontalNoDepthScale:
    case ModelType::VerticalNoDepthScale: return 1;
    default: return (sx + sy) / 2;
    }
}

Transform modelToFacade(const Asset &model, const Terminal &terminal) {
    Vec3f extent = model.boundsMax - model.boundsMin;
    // A model flat in x or y (a wall quad seen edge-on cannot be) would divide by zero: keep it as is.
    float sx = extent.x > 0 ? terminal.size.x / extent.x : 1;
    float sy = extent.y > 0 ? terminal.size.y / extent.y : 1;
    float sz = depthScale(model.type, terminal.zScale, sx, sy);
    Vec3f centre{(model.boundsMin.x + model.boundsMax.x) / 2, (model.boundsMin.y + model.boundsMax.y) / 2, 0};
    return terminal.shapeToFacade * Transform::scale({sx, sy, sz}) * Transform::translate(-centre);
}

}  // namespace veduta
