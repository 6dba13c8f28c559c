#include "core/check.h"

#include <fmt/format.h>

namespace veduta {

void failCheck(const char *file, int line, const char *condition, const std::string &message) {
    throw InternalError(fmt::format("{}:{}: internal error: {} ({})", file, line, message, condition));
}

}  // namespace veduta
