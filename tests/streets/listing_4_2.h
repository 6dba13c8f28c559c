// Goitowski 2010, Listing 4.2 verbatim: the Manhattan street rules, which the tests of the rule
// reader and of the growth both read.
#pragma once

namespace veduta::test {

inline constexpr const char *kListing42 = R"(#define ProbChangeStreetAngle 0.20
#define DevStreetAngle 10
#define ProbChangeStreetLength 0.20

o: S(10)
p1: S(len) > ?I(a,len,insertion) : insertion == NORMAL {a = ProbChangeStreetAngle ? U[-DevStreetAngle,DevStreetAngle] : 0.0; len = ProbChangeStreetLength ? U[0.5*len,1.5*len] : len;} -> &(a)F(len)[+(80)P][&(90)S(len)][&(-90)S(len)]&(a)S(len)
p2: S(len) > ?I(a,len,insertion) : insertion == NN || insertion == INTSCT || insertion == FWD_INTSCT -> &(a)F(len)
)";

}  // namespace veduta::test
