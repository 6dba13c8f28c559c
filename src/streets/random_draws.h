// The random numbers of a street L-system: U[a,b], random(a,b), the probability of an
// assignment and the choice among matching rules. Each is a pure function of the seed, the
// identity of the word being expanded and the draw's index within that expansion, so that a
// word expands the same way whatever was expanded before it (docs/street-rules.md).
#pragma once

#include <cstdint>

namespace veduta {

// Where draws come from: seeded hashes in generation, fixed values in tests.
class RandomDraws {
  public:
    virtual ~RandomDraws() = default;
    // The `index`th number in [0, 1) of the expansion of the word known by `word`.
    virtual float uniform(uint32_t word, uint32_t index) = 0;
};

// hashValues({seed, word, index, RandomStream::StreetRules}) as a float.
class SeededDraws final : public RandomDraws {
  public:
    explicit SeededDraws(uint32_t seed) : seed_(seed) {}
    float uniform(uint32_t word, uint32_t index) override;

  private:
    uint32_t seed_;
};

// The draws of one word's expansion, in the order the evaluator asks for them.
class WordDraws {
  public:
    WordDraws(RandomDraws &draws, uint32_t word) : draws_(draws), word_(word) {}
    float next() { return draws_.uniform(word_, index_++); }

  private:
    RandomDraws &draws_;
    uint32_t word_;
    uint32_t index_ = 0;
};

}  // namespace veduta
