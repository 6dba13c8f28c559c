// The check of every number option on the command line.
#pragma once

#include <CLI/CLI.hpp>

namespace veduta {

// A finite number in [min, max]. CLI::Range and CLI::PositiveNumber let "nan" through (every
// comparison with NaN is false), and "inf" past an open end.
CLI::Validator finiteIn(double min, double max);

}  // namespace veduta
