// The random numbers of Schrader's plans (the thesis never seeds them, digest-003 §8.1.7): each
// draw is a pure function of the seed, the identity of the plan being made (a building's, a
// storey's), its stream, what the number is for and its index, so that a plan comes out the
// same whatever was planned before it and on any thread.
#pragma once

#include <cstdint>

#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

class PlanRandom {
  public:
    PlanRandom(uint32_t seed, uint32_t identity, RandomStream stream) :
        seed_(seed), identity_(identity), stream_(stream) {}

    // A number in [0, 1) for draw `index` of purpose `what`.
    double unit(uint32_t what, uint32_t index = 0) const {
        return bitsToUnitFloat(hashValues({seed_, identity_, streamTag(stream_), what, index}));
    }
    // rand(a, b) of the thesis: uniform in [a, b).
    double uniform(double a, double b, uint32_t what, uint32_t index = 0) const {
        return a + (b - a) * unit(what, index);
    }

  private:
    uint32_t seed_, identity_;
    RandomStream stream_;
};

}  // namespace veduta
