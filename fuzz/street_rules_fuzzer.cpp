// The street rule reader (docs/street-rules.md) on any text, and what it reads expanded four
// generations from its initial word, every query answered NORMAL with the angle turned a
// little, within a word budget: evaluation errors must be InputErrors too. Then the same rules
// grown under the local constraints inside a small window within limits, and the blocks of
// what they built found both ways, which must agree.
#include <span>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "streets/lsystem.h"
#include "streets/street_blocks.h"
#include "streets/street_builder.h"
#include "streets/street_rule_file.h"

namespace {

constexpr int kGenerations = 4;
constexpr size_t kMaxWords = 20000;

veduta::QueryResult answerQuery(char, std::span<float> inOut) {
    if (!inOut.empty()) inOut[0] += 1;
    return veduta::QueryResult::Normal;
}

void rewriteGenerations(const veduta::StreetRuleSet &rules) {
    using namespace veduta;
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
}

void growAndFindBlocks(const veduta::StreetRuleSet &rules) {
    using namespace veduta;
    SeededDraws seeded(7);
    WordGraph words(rules.initialWord);
    StreetBuilder streets(words);
    StreetGrowth growth(words, rules.rules, streets.nodeQuery(), seeded, &streets);
    GrowthLimits limits;
    limits.maxExpansions = 2000;
    limits.maxNodes = kMaxWords;
    growth.grow({{0, 0}, 200}, limits);
    std::vector<PlanarPoint> points;
    for (const StreetVertex &v : streets.graph().vertices()) points.push_back({v.position.x, v.position.y});
    std::vector<PlanarEdge> edges;
    for (const StreetEdge &e : streets.graph().edges())
        if (streets.graph().vertex(e.a).position.z == 0 && streets.graph().vertex(e.b).position.z == 0)
            edges.emplace_back(e.a, e.b);
    BlockResult walked = blocksByFaceWalk(points, edges);
    if (blocksByArrangement(points, edges).blocks != walked.blocks) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    fuzz::expectInputError([&] {
        StreetRuleSet rules = parseStreetRules(fuzz::inputText(data, size), "fuzz.rules");
        rewriteGenerations(rules);
        growAndFindBlocks(rules);
    });
    return 0;
}
