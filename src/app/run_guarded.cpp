#include "app/run_guarded.h"

#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <string>

#include "app/commands.h"
#include "core/error.h"
#include "core/memory_limit.h"

namespace veduta {

int runGuarded(const std::function<void()> &body) {
    try {
        body();
        return kExitOk;
    } catch (const InputError &e) {
        std::fprintf(stderr, "veduta: error: %s\n", e.what());
        return kExitBadInput;
    } catch (const std::bad_alloc &) {
        std::optional<uint64_t> limit = memoryLimit();
        std::fprintf(stderr, "veduta: error: memory ran out%s\n",
                     limit ? (" at veduta's budget of " + memorySizeText(*limit) +
                              " (VEDUTA_MAX_MEMORY sets it; docs/reliability.md)")
                                 .c_str()
                           : "");
        return kExitFailure;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "veduta: error: %s\n", e.what());
        return kExitFailure;
    }
}

int runApp(CLI::App &app, int argc, char **argv, const int &exitCode) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success &e) {
        return app.exit(e);
    } catch (const CLI::ParseError &e) {
        app.exit(e);
        return kExitBadUsage;
    }
    return exitCode;
}

}  // namespace veduta
