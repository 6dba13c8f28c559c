#include <gtest/gtest.h>

#include <string>

#include "core/check.h"

namespace veduta {
namespace {

TEST(Check, PassingCheckDoesNothing) { EXPECT_NO_THROW(VEDUTA_CHECK(1 + 1 == 2, "arithmetic")); }

TEST(Check, FailingCheckNamesItsLineConditionAndMessage) {
    int line = 0;
    try {
        line = __LINE__ + 1;
        VEDUTA_CHECK(2 < 1, std::string("two is not below one"));
        FAIL() << "no exception";
    } catch (const InternalError &e) {
        std::string what = e.what();
        EXPECT_NE(
            what.find("check_test.cpp:" + std::to_string(line) + ": internal error: two is not below one (2 < 1)"),
            std::string::npos)
            << what;
    }
}

TEST(Check, UnreachableThrows) { EXPECT_THROW(VEDUTA_UNREACHABLE("ruled out above"), InternalError); }

}  // namespace
}  // namespace veduta
