#include "geo/ribbon_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace veduta {

RibbonFrame::RibbonFrame(const Mesh &mesh) : mesh_(mesh) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    low_ = {kInfinity, kInfinity}, high_ = {-kInfinity, -kInfinity};
    size_t n = mesh.vertexCount() / 2;
    if (n < 2 || mesh.vertexCount() != 2 * n || mesh.triangleCount() != 2 * (n - 1)) return;
    for (size_t i = 0; i < n; ++i) {
        Vec2d left = plan(2 * i), right = plan(2 * i + 1);
        centre_.push_back((left + right) * 0.5);
        across_.push_back((left - right) * 0.5);
        along_.push_back(i == 0 ? 0 : along_.back() + veduta::length(centre_[i] - centre_[i - 1]));
        low_ = {std::min(low_.x, centre_[i].x), std::min(low_.y, centre_[i].y)};
        high_ = {std::max(high_.x, centre_[i].x), std::max(high_.y, centre_[i].y)};
    }
}

bool RibbonFrame::near(Vec2d p, double reach) const {
    return p.x >= low_.x - reach && p.x <= high_.x + reach && p.y >= low_.y - reach && p.y <= high_.y + reach;
}

Vec2d RibbonFrame::at(size_t i, double t, double k) const {
    Vec2d a = centre_[i] + across_[i] * k, b = centre_[i + 1] + across_[i + 1] * k;
    return a + (b - a) * t;
}

std::pair<size_t, double> RibbonFrame::pieceAt(double s) const {
    size_t i = size_t(std::upper_bound(along_.begin(), along_.end(), s) - along_.begin());
    i = std::clamp<size_t>(i, 1, along_.size() - 1) - 1;
    double span = along_[i + 1] - along_[i];
    return {i, span > 0 ? std::clamp((s - along_[i]) / span, 0.0, 1.0) : 0.0};
}

std::optional<double> RibbonFrame::diagonalCrossing(size_t i, double k) const {
    Vec2d from = centre_[i] - across_[i], diagonal = centre_[i + 1] + across_[i + 1] - from;
    Vec2d a = at(i, 0, k), b = at(i, 1, k) - a;
    double denominator = cross(b, diagonal);
    if (std::abs(denominator) < 1e-12) return std::nullopt;
    double t = -cross(a - from, diagonal) / denominator;
    if (!(t > 0 && t < 1)) return std::nullopt;
    return t;
}

double RibbonFrame::heightAt(size_t i, Vec2d p) const {
    double best = -std::numeric_limits<double>::infinity(), height = 0;
    for (size_t t = 2 * i; t < 2 * i + 2; ++t) {
        const uint32_t *v = &mesh_.indices[3 * t];
        Vec2d a = plan(v[0]), b = plan(v[1]), c = plan(v[2]);
        double area = cross(b - a, c - a);
        if (area == 0) continue;
        double wb = cross(p - a, c - a) / area, wc = cross(b - a, p - a) / area, wa = 1 - wb - wc;
        double inside = std::min({wa, wb, wc});
        if (inside > best) {
            best = inside;
            height = wa * mesh_.positions[v[0]].z + wb * mesh_.positions[v[1]].z + wc * mesh_.positions[v[2]].z;
        }
    }
    return height;
}

}  // namespace veduta
