// What an input error says, for tests that compare messages.
#pragma once

#include <functional>
#include <string>

#include "core/error.h"

namespace veduta::test {

// The message of the InputError that `call` throws, or "no error".
inline std::string inputErrorOf(const std::function<void()> &call) {
    try {
        call();
    } catch (const InputError &e) {
        return e.what();
    }
    return "no error";
}

}  // namespace veduta::test
