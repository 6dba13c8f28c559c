#include "streets/random_draws.h"

#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

float SeededDraws::uniform(uint32_t word, uint32_t index) {
    return bitsToUnitFloat(hashValues({seed_, word, index, streamTag(RandomStream::StreetRules)}));
}

}  // namespace veduta
