// Draws that are all one value, for the street tests that need to know what the rules chose.
#pragma once

#include "streets/random_draws.h"

namespace veduta::test {

class FixedDraws final : public RandomDraws {
  public:
    explicit FixedDraws(float value) : value_(value) {}
    float uniform(uint32_t, uint32_t) override { return value_; }

  private:
    float value_;
};

// Above Listing 4.2's probabilities 0.2: a = 0 and len stays as it is, a square grid.
inline constexpr float kSquareGridDraw = 0.99f;

}  // namespace veduta::test
