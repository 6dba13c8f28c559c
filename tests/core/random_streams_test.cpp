// The stream tags of core/random_streams.h: no two streams may draw the same numbers.
#include <gtest/gtest.h>

#include <set>

#include "core/random_streams.h"

namespace veduta {
namespace {

TEST(RandomStreams, EveryTagIsDistinct) {
    std::set<uint32_t> tags;
    for (RandomStream stream : kAllRandomStreams) {
        EXPECT_TRUE(tags.insert(streamTag(stream)).second) << "tag " << streamTag(stream) << " is used twice";
    }
    EXPECT_EQ(tags.size(), std::size(kAllRandomStreams));
}

}  // namespace
}  // namespace veduta
