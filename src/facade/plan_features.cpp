#include "facade/plan_features.h"

#include <utility>

namespace veduta {

namespace {

// Who a piece of the outline belongs to: {false, module} or {true, PP connection}.
using Owner = std::pair<bool, int>;

Owner ownerOf(const WalkPiece &piece) {
    if (!piece.element.isPp) return {false, piece.element.index};
    // Case 7 (L800): the ends of a PP edge next to a docked module join that module's feature.
    if (piece.childAfter >= 0 && piece.childBefore < 0) return {false, piece.childAfter};
    if (piece.childBefore >= 0 && piece.childAfter < 0) return {false, piece.childBefore};
    return {true, piece.element.index};
}

// Where the features start: the first transition of the walk, or for a plan with one feature
// (case 1) the start of e1.
size_t firstFeatureStart(const std::vector<WalkPiece> &outline) {
    for (size_t i = 0; i < outline.size(); ++i)
        if (ownerOf(outline[i]) != ownerOf(outline[(i + outline.size() - 1) % outline.size()])) return i;
    for (size_t i = 0; i < outline.size(); ++i)
        if (outline[i].element.edge == 0 && outline[i].t0 == 0) return i;
    return 0;
}

}  // namespace

std::vector<Feature> planFeatures(const FloorPlan &plan) {
    const std::vector<WalkPiece> &outline = plan.outline();
    std::vector<Feature> features;
    size_t start = firstFeatureStart(outline);
    for (size_t k = 0; k < outline.size(); ++k) {
        const WalkPiece &piece = outline[(start + k) % outline.size()];
        Owner owner = ownerOf(piece);
        if (k == 0 || ownerOf(outline[(start + k - 1) % outline.size()]) != owner) {
            Feature feature;
            if (owner.first) {
                feature.ppConnection = owner.second;
            } else {
                feature.module = owner.second;
            }
            features.push_back(feature);
        }
        features.back().edges.push_back(piece);
    }
    return features;
}

std::vector<Vec2d> featureOutline(const std::vector<Feature> &features) {
    std::vector<Vec2d> outline;
    for (const Feature &feature : features)
        for (const WalkPiece &piece : feature.edges) outline.push_back(piece.from);
    return outline;
}

}  // namespace veduta
