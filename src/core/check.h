// Internal invariants: what must hold whatever the input, so that a failure is a bug in
// veduta, never a user's mistake (that is an InputError with its place). A failed check throws
// InternalError naming the source line, which the commands report with exit code 3; unlike
// assert() it stays on in release builds, where the renders run.
#pragma once

#include <stdexcept>
#include <string>

namespace veduta {

class InternalError : public std::logic_error {
  public:
    using std::logic_error::logic_error;
};

[[noreturn]] void failCheck(const char *file, int line, const char *condition, const std::string &message);

}  // namespace veduta

// VEDUTA_CHECK(condition, message): throws InternalError "file:line: internal error: message
// (condition)" when the condition is false. The message is only built then.
#define VEDUTA_CHECK(condition, message)                                                  \
    do {                                                                                  \
        if (!(condition)) ::veduta::failCheck(__FILE__, __LINE__, #condition, (message)); \
    } while (false)

// VEDUTA_UNREACHABLE(message): for a branch that the code before has ruled out.
#define VEDUTA_UNREACHABLE(message) ::veduta::failCheck(__FILE__, __LINE__, "unreachable", (message))
