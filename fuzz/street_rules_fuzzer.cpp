// The street rule reader (docs/street-rules.md) on any text, and what it reads expanded four
// generations from its initial word, every query answered NORMAL with the angle turned a
// little, within a word budget: evaluation errors must be InputErrors too.
#include <span>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "streets/lsystem.h"
#include "streets/street_rule_file.h"

namespace {

constexpr int kGenerations = 4;
constexpr size_t kMaxWords = 20000;

veduta::QueryResult answerQuery(char, std::span<float> inOut) {
    if (!inOut.empty()) inOut[0] += 1;
    return veduta::QueryResult::Normal;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    fuzz::expectInputError([&] {
        StreetRuleSet rules = parseStreetRules(fuzz::inputText(data, size), "fuzz.rules");
        SeededDraws seeded(7);
        std::vector<std::string> warnings;
        std::vector<Word> words = rules.initialWord;
        for (int generation = 0; generation < kGenerations && words.size() <= kMaxWords; ++generation) {
            std::vector<Word> next;
            for (size_t i = 0; i < words.size() && next.size() <= kMaxWords; ++i) {
                WordDraws draws(seeded, uint32_t(i));
                auto successor = expandWord(words, i, rules.rules, draws, answerQuery, warnings);
                if (successor) next.insert(next.end(), successor->begin(), successor->end());
                else next.push_back(words[i]);
            }
            words = std::move(next);
        }
        (void)toString(words);
    });
    return 0;
}
