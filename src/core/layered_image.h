// An image as a compositor sees a multilayer EXR: float channels with names ("ViewLayer.Depth.Z"),
// over a data window that may be only part of the full (display) window, and named metadata.
// What a render develops its film into, what `veduta merge` reads and writes.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace veduta {

// A rectangle of pixels: x0 ≤ x < x1, y0 ≤ y < y1, (0, 0) being the full image's top-left pixel.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    size_t area() const { return empty() ? 0 : size_t(width()) * size_t(height()); }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool contains(const PixelWindow &w) const { return w.x0 >= x0 && w.x1 <= x1 && w.y0 >= y0 && w.y1 <= y1; }
    bool overlaps(const PixelWindow &w) const { return w.x0 < x1 && x0 < w.x1 && w.y0 < y1 && y0 < w.y1; }
    bool operator==(const PixelWindow &) const = default;
};

using Matrix44 = std::array<float, 16>;  // row-major, as OpenEXR's M44f attribute stores it
using MetadataValue = std::variant<std::string, int, double, Matrix44>;

struct LayeredImage {
    struct Channel {
        std::string name;
        std::vector<float> values;  // dataWindow.area() samples, the window's top row first
    };

    int fullWidth = 0, fullHeight = 0;  // the display window: (0, 0) to (fullWidth, fullHeight)
    PixelWindow dataWindow;
    std::vector<Channel> channels;
    std::map<std::string, MetadataValue> metadata;

    // A new zero-filled channel of dataWindow's size. The reference lasts only until the next
    // channel is added (the list may move); take pointers once all channels are there.
    std::vector<float> &addChannel(std::string name) {
        channels.push_back({std::move(name), std::vector<float>(dataWindow.area(), 0.0f)});
        return channels.back().values;
    }
    const Channel *find(std::string_view name) const {
        for (const Channel &c : channels) {
            if (c.name == name) return &c;
        }
        return nullptr;
    }
    Channel *find(std::string_view name) {
        return const_cast<Channel *>(static_cast<const LayeredImage *>(this)->find(name));
    }
};

}  // namespace veduta
