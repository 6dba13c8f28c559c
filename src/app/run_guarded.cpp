#include "app/run_guarded.h"

#include <cstdio>
#include <exception>

#include "app/commands.h"
#include "core/error.h"

namespace veduta {

int runGuarded(const std::function<void()> &body) {
    try {
        body();
        return kExitOk;
    } catch (const InputError &e) {
        std::fprintf(stderr, "veduta: error: %s\n", e.what());
        return kExitBadInput;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "veduta: error: %s\n", e.what());
        return kExitFailure;
    }
}

}  // namespace veduta
