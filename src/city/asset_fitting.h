// Fitting a model into its terminal's scope (Bilke's Shape::GetTransformMatrix, Bilke 2009
// §4): the model's bounding box is stretched over the scope, centre to centre in width and
// height, and its depth follows the model type or the inherited z_scale.
#pragma once

#include "city/assets.h"
#include "city/derivation.h"

namespace veduta {

// The depth scale for a model stretched by (sx, sy): with z_scale unset, HORIZONTAL models
// keep their profile (sz = sy), VERTICAL ones follow their width (sz = sx), the no-depth-scale
// variants keep their depth (1), and the rest take the mean; an explicit z_scale says none
// (1), right (sx), up (sy) or average.
float depthScale(ModelType type, ZScale zScale, float sx, float sy);

// Model frame → facade frame for `terminal`: shapeToFacade · S(sx, sy, sz) · T(−centre), the
// wall plane (model z = 0) kept in place.
Transform modelToFacade(const Asset &model, const Terminal &terminal);

}  // namespace veduta
