// Runs a command's body and turns exceptions into a message on stderr and an exit code.
#pragma once

#include <functional>

namespace veduta {

int runGuarded(const std::function<void()> &body);

}  // namespace veduta
