// Numbers, points and strings fed in order into one 64-bit state: the identity hashes of what a
// generator built (a building structure, a masonry shader), which say when a result would change.
#pragma once

#include <bit>
#include <cstdint>
#include <string>

#include "core/hash.h"
#include "core/vecmath.h"

namespace veduta {

class WordHasher {
  public:
    void add(uint64_t v) { h_ = mix64(h_ ^ mix64(v + 0x9e3779b97f4a7c15ull)); }
    void add(int v) { add(uint64_t(int64_t(v))); }
    // -0 and 0 are one number.
    void add(double v) { add(std::bit_cast<uint64_t>(v == 0 ? 0.0 : v)); }
    void add(const std::string &s) {
        add(s.size());
        add(uint64_t(hashString(s)));
    }
    void add(Vec2d p) {
        add(p.x);
        add(p.y);
    }
    uint64_t value() const { return h_; }

  private:
    uint64_t h_ = 0x243f6a8885a308d3ull;
};

}  // namespace veduta
